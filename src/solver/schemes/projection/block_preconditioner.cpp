// Per-group factorisations for the block-Jacobi preconditioner (block_preconditioner.hpp):
// Eigen's supernodal SparseLU with the COLAMD fill-reducing ordering (the blocks are not
// symmetric: the WMLS Laplacian rows and the wall rows are not), or ILU(0) on the block's
// compressed rows in the particles' order.
#include "sluice/solver/block_preconditioner.hpp"

#include <Eigen/SparseLU>

#include <cmath>
#include <vector>

namespace sluice {

struct BlockFactor::Impl {
    BlockMethod method = BlockMethod::lu;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    // ILU(0): L (unit diagonal, strictly lower part) and U (upper part with the diagonal) in
    // the pattern of the block, row-major, columns sorted; diag[i] = position of (i, i).
    Eigen::SparseMatrix<double, Eigen::RowMajor> ilu;
    std::vector<Eigen::Index> diag;
    std::vector<Eigen::Index> mark; // scratch: position of column j in the current row, or -1
    bool ok = false;
    long rows = 0;
};

BlockFactor::BlockFactor() : impl_(std::make_unique<Impl>()) {}
BlockFactor::~BlockFactor() = default;
BlockFactor::BlockFactor(BlockFactor&&) noexcept = default;
BlockFactor& BlockFactor::operator=(BlockFactor&&) noexcept = default;

namespace {

// ILU(0) in place (Saad 2003, Algorithm 10.4, "IKJ" variant): for each row i, for each k < i
// in its pattern, a_ik /= a_kk, then a_ij -= a_ik a_kj for the j > k of row k that are in row
// i's pattern. False on a zero or non-finite pivot.
bool ilu0(Eigen::SparseMatrix<double, Eigen::RowMajor>& m, std::vector<Eigen::Index>& diag,
          std::vector<Eigen::Index>& mark) {
    const Eigen::Index n = m.rows();
    const int* outer = m.outerIndexPtr();
    const int* col = m.innerIndexPtr();
    double* val = m.valuePtr();
    diag.assign(static_cast<std::size_t>(n), -1);
    mark.assign(static_cast<std::size_t>(n), -1);
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index q = outer[i]; q < outer[i + 1]; ++q) {
            mark[static_cast<std::size_t>(col[q])] = q;
            if (col[q] == i)
                diag[static_cast<std::size_t>(i)] = q;
        }
        if (diag[static_cast<std::size_t>(i)] < 0)
            return false;
        for (Eigen::Index q = outer[i]; q < outer[i + 1] && col[q] < i; ++q) {
            const Eigen::Index k = col[q];
            val[q] /= val[diag[static_cast<std::size_t>(k)]];
            for (Eigen::Index r = diag[static_cast<std::size_t>(k)] + 1; r < outer[k + 1]; ++r)
                if (const Eigen::Index at = mark[static_cast<std::size_t>(col[r])]; at >= 0)
                    val[at] -= val[q] * val[r];
        }
        for (Eigen::Index q = outer[i]; q < outer[i + 1]; ++q)
            mark[static_cast<std::size_t>(col[q])] = -1;
        const double pivot = val[diag[static_cast<std::size_t>(i)]];
        if (pivot == 0 || !std::isfinite(pivot))
            return false;
    }
    return true;
}

} // namespace

bool BlockFactor::factor(const Eigen::SparseMatrix<double>& block, BlockMethod method) {
    Impl& m = *impl_;
    m.ok = false;
    m.method = method;
    m.rows = static_cast<long>(block.rows());
    if (block.rows() == 0)
        return true;
    if (method == BlockMethod::ilu0) {
        m.ilu = block; // row-major copy, columns sorted
        m.ilu.makeCompressed();
        m.ok = ilu0(m.ilu, m.diag, m.mark);
        return m.ok;
    }
    m.lu.analyzePattern(block);
    m.lu.factorize(block);
    m.ok = m.lu.info() == Eigen::Success;
    return m.ok;
}

void BlockFactor::solve(Eigen::Ref<Eigen::VectorXd> x) const {
    const Impl& m = *impl_;
    if (!m.ok || x.size() == 0)
        return;
    if (m.method == BlockMethod::lu) {
        const Eigen::VectorXd z = m.lu.solve(x);
        x = z;
        return;
    }
    const Eigen::Index n = m.ilu.rows();
    const int* outer = m.ilu.outerIndexPtr();
    const int* col = m.ilu.innerIndexPtr();
    const double* val = m.ilu.valuePtr();
    for (Eigen::Index i = 0; i < n; ++i) { // L z = x, unit diagonal
        double s = x[i];
        for (Eigen::Index q = outer[i]; q < m.diag[static_cast<std::size_t>(i)]; ++q)
            s -= val[q] * x[col[q]];
        x[i] = s;
    }
    for (Eigen::Index i = n - 1; i >= 0; --i) { // U x = z
        const Eigen::Index d = m.diag[static_cast<std::size_t>(i)];
        double s = x[i];
        for (Eigen::Index q = d + 1; q < outer[i + 1]; ++q)
            s -= val[q] * x[col[q]];
        x[i] = s / val[d];
    }
}

bool BlockFactor::ready() const {
    return impl_->ok;
}

long BlockFactor::size() const {
    return impl_->rows;
}

} // namespace sluice
