// Per-group factorisations for the block-Jacobi preconditioner (block_preconditioner.hpp):
// Eigen's supernodal SparseLU with the COLAMD fill-reducing ordering (the blocks are not
// symmetric: the WMLS Laplacian rows and the wall rows are not), or ILU(0) on the block's
// compressed rows in the particles' order.
#include "sluice/solver/block_preconditioner.hpp"

#include <Eigen/SparseLU>

#include <cmath>
#include <utility>
#include <vector>

namespace sluice {

struct BlockFactor::Impl {
    BlockMethod method = BlockMethod::lu;
    Eigen::SparseMatrix<double> colmajor; // the block for SparseLU
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    // ILU(0): L (unit diagonal, strictly lower part) and U (upper part with the diagonal) in
    // the pattern of the block, compressed rows; diag[i] = position of (i, i).
    BlockRows ilu;
    std::vector<int> diag;
    std::vector<int> mark; // scratch: position of column j in the current row, or -1
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
// i's pattern. False on a missing, zero or non-finite pivot.
bool ilu0(BlockRows& m, std::vector<int>& diag, std::vector<int>& mark) {
    const int n = m.rows();
    const int* outer = m.outer.data();
    const int* col = m.col.data();
    double* val = m.val.data();
    diag.assign(static_cast<std::size_t>(n), -1);
    mark.assign(static_cast<std::size_t>(n), -1);
    for (int i = 0; i < n; ++i) {
        for (int q = outer[i]; q < outer[i + 1]; ++q) {
            mark[static_cast<std::size_t>(col[q])] = q;
            if (col[q] == i)
                diag[static_cast<std::size_t>(i)] = q;
        }
        if (diag[static_cast<std::size_t>(i)] < 0)
            return false;
        for (int q = outer[i]; q < outer[i + 1] && col[q] < i; ++q) {
            const int k = col[q];
            val[q] /= val[diag[static_cast<std::size_t>(k)]];
            for (int r = diag[static_cast<std::size_t>(k)] + 1; r < outer[k + 1]; ++r)
                if (const int at = mark[static_cast<std::size_t>(col[r])]; at >= 0)
                    val[at] -= val[q] * val[r];
        }
        for (int q = outer[i]; q < outer[i + 1]; ++q)
            mark[static_cast<std::size_t>(col[q])] = -1;
        const double pivot = val[diag[static_cast<std::size_t>(i)]];
        if (pivot == 0 || !std::isfinite(pivot))
            return false;
    }
    return true;
}

} // namespace

bool BlockFactor::factor(const Eigen::SparseMatrix<double>& block, BlockMethod method) {
    Eigen::SparseMatrix<double, Eigen::RowMajor> rows = block; // columns sorted
    rows.makeCompressed();
    BlockRows b;
    b.outer.assign(rows.outerIndexPtr(), rows.outerIndexPtr() + rows.rows() + 1);
    b.col.assign(rows.innerIndexPtr(), rows.innerIndexPtr() + rows.nonZeros());
    b.val.assign(rows.valuePtr(), rows.valuePtr() + rows.nonZeros());
    return factor(b, method);
}

bool BlockFactor::factor(BlockRows& block, BlockMethod method) {
    Impl& m = *impl_;
    m.ok = false;
    m.method = method;
    m.rows = block.rows();
    std::swap(m.ilu, block);
    if (m.rows == 0)
        return true;
    if (method == BlockMethod::ilu0) {
        m.ok = ilu0(m.ilu, m.diag, m.mark);
        return m.ok;
    }
    const auto n = static_cast<Eigen::Index>(m.rows);
    m.colmajor = Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>>(
        n, n, static_cast<Eigen::Index>(m.ilu.val.size()), m.ilu.outer.data(), m.ilu.col.data(),
        m.ilu.val.data());
    m.lu.analyzePattern(m.colmajor);
    m.lu.factorize(m.colmajor);
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
    const int n = m.ilu.rows();
    const int* outer = m.ilu.outer.data();
    const int* col = m.ilu.col.data();
    const double* val = m.ilu.val.data();
    const int* diag = m.diag.data();
    double* v = x.data();
    for (int i = 0; i < n; ++i) { // L z = x, unit diagonal
        double s = v[i];
        for (int q = outer[i]; q < diag[i]; ++q)
            s -= val[q] * v[col[q]];
        v[i] = s;
    }
    for (int i = n - 1; i >= 0; --i) { // U x = z
        const int d = diag[i];
        double s = v[i];
        for (int q = d + 1; q < outer[i + 1]; ++q)
            s -= val[q] * v[col[q]];
        v[i] = s / val[d];
    }
}

bool BlockFactor::ready() const {
    return impl_->ok;
}

long BlockFactor::size() const {
    return impl_->rows;
}

} // namespace sluice
