#pragma once
// Coarse level of the projection scheme's two-level preconditioner (docs/PROJECTION.md,
// "Preconditioner"): the particles are grouped into aggregates of cells of the cell grid, P is
// piecewise constant on them (1 where a particle's row is not a Dirichlet row), R = P^T, and
// the coarse operator A_c = R A P (Galerkin) is a small sparse non-symmetric matrix that every
// rank assembles from the same entries in the same order and factorises redundantly
// (Eigen's SparseLU, COLAMD ordering).
#include "sluice/core/cell_grid.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace sluice {

// One entry of A_c (or of a part of it): row and column are aggregate numbers.
struct CoarseEntry {
    std::int32_t row = 0, col = 0;
    double value = 0;
};

// Sorts the entries by (row, column), stably, and sums those with equal positions in the
// order they came: the same entries in the same order give the same bits.
void merge_coarse_entries(std::vector<CoarseEntry>& entries);

class CoarseSystem {
public:
    CoarseSystem();
    ~CoarseSystem();
    CoarseSystem(CoarseSystem&&) noexcept;
    CoarseSystem& operator=(CoarseSystem&&) noexcept;
    CoarseSystem(const CoarseSystem&) = delete;
    CoarseSystem& operator=(const CoarseSystem&) = delete;

    // Assembles the size x size matrix from `entries` (duplicates summed in their order) and
    // factorises it. False when it is singular: solve() then does nothing useful (ready() is
    // false and the caller leaves the coarse level out).
    bool factor(int size, std::span<const CoarseEntry> entries);
    // b <- A_c^{-1} b.
    void solve(std::span<double> b) const;
    [[nodiscard]] bool ready() const;
    [[nodiscard]] int size() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Key of the aggregate holding x: the cell grid's cells taken `per_axis` at a time along each
// axis (1: one cell, 2: 2^D cells), numbered row-major on the coarsened grid. It depends on x
// and the grid only, so every rank gives a particle the same key.
template <int D>
std::uint64_t aggregate_key(const CellGrid<D>& grid, const Vec<D>& x, int per_axis) {
    const std::array<int, D> c = grid.coords(x);
    std::uint64_t key = 0;
    for (int d = D - 1; d >= 0; --d) {
        const auto dim = static_cast<std::uint64_t>((grid.dims[d] + per_axis - 1) / per_axis);
        key = key * dim + static_cast<std::uint64_t>(c[static_cast<std::size_t>(d)] / per_axis);
    }
    return key;
}

} // namespace sluice
