// The coarse operator of the two-level preconditioner (coarse_system.hpp): assembled from
// entries, factorised by Eigen's supernodal SparseLU with the COLAMD ordering (A_c is not
// symmetric, as the WMLS Laplacian and the wall rows are not).
#include "sluice/solver/coarse_system.hpp"

#include <Eigen/SparseLU>

#include <algorithm>

namespace sluice {

void merge_coarse_entries(std::vector<CoarseEntry>& entries) {
    std::stable_sort(entries.begin(), entries.end(),
                     [](const CoarseEntry& a, const CoarseEntry& b) {
                         return a.row != b.row ? a.row < b.row : a.col < b.col;
                     });
    std::size_t last = 0;
    for (std::size_t q = 1; q < entries.size(); ++q) {
        if (entries[q].row == entries[last].row && entries[q].col == entries[last].col) {
            entries[last].value += entries[q].value;
            continue;
        }
        entries[++last] = entries[q];
    }
    if (!entries.empty())
        entries.resize(last + 1);
}

struct CoarseSystem::Impl {
    Eigen::SparseMatrix<double> matrix;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    std::vector<Eigen::Triplet<double>> triplets;
    bool ok = false;
    int size = 0;
};

CoarseSystem::CoarseSystem() : impl_(std::make_unique<Impl>()) {}
CoarseSystem::~CoarseSystem() = default;
CoarseSystem::CoarseSystem(CoarseSystem&&) noexcept = default;
CoarseSystem& CoarseSystem::operator=(CoarseSystem&&) noexcept = default;

bool CoarseSystem::factor(int size, std::span<const CoarseEntry> entries) {
    Impl& m = *impl_;
    m.ok = false;
    m.size = size;
    if (size <= 0)
        return false;
    m.triplets.clear();
    m.triplets.reserve(entries.size());
    for (const CoarseEntry& e : entries)
        m.triplets.emplace_back(e.row, e.col, e.value);
    m.matrix.resize(size, size);
    m.matrix.setFromTriplets(m.triplets.begin(), m.triplets.end());
    m.matrix.makeCompressed();
    m.lu.analyzePattern(m.matrix);
    m.lu.factorize(m.matrix);
    m.ok = m.lu.info() == Eigen::Success;
    return m.ok;
}

void CoarseSystem::solve(std::span<double> b) const {
    const Impl& m = *impl_;
    if (!m.ok || static_cast<int>(b.size()) != m.size)
        return;
    Eigen::Map<Eigen::VectorXd> v(b.data(), static_cast<Eigen::Index>(b.size()));
    const Eigen::VectorXd z = m.lu.solve(v);
    v = z;
}

bool CoarseSystem::ready() const {
    return impl_->ok;
}

int CoarseSystem::size() const {
    return impl_->size;
}

} // namespace sluice
