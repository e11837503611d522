#pragma once
// Fixed-order neighbour iteration over the cell-sorted particle arrays. This order (adjacent
// cells in the order of adjacent_cells(), particles inside a cell by id) is what makes every
// neighbour sum, and so the whole result, independent of threads, groups and ranks.
#include "sluice/core/cell_grid.hpp"

#include <span>

namespace sluice {

// The adjacent cells of one cell, computed once and reused for all its particles.
template <int D>
struct AdjacentCells {
    NeighbourCell<D> cell[D == 2 ? 9 : 27];
    int count = 0;
};

template <int D>
struct Neighbourhood {
    const CellGrid<D>* grid = nullptr;
    const CellRanges* cells = nullptr;
    std::span<const Vec<D>> x;
    Real support = 0;

    [[nodiscard]] AdjacentCells<D> adjacent(CellIndex c) const {
        AdjacentCells<D> a;
        a.count = adjacent_cells(*grid, c, a.cell);
        return a;
    }

    // Calls f(j, dx, r2) for every particle j (i itself included) with |x_i - x_j| < support,
    // where dx = x_i - x_j with the periodic image applied. `adj` are the adjacent cells of
    // the cell holding i.
    template <class F>
    void for_each_neighbour(const AdjacentCells<D>& adj, std::uint32_t i, F&& f) const {
        const Real support2 = support * support;
        const Vec<D> xi = x[i];
        for (int k = 0; k < adj.count; ++k) {
            const CellIndex nc = adj.cell[k].cell;
            const Vec<D> xis = xi + adj.cell[k].shift;
            const std::uint32_t e = cells->end[nc];
            for (std::uint32_t j = cells->begin[nc]; j < e; ++j) {
                const Vec<D> dx = xis - x[j];
                const Real r2 = dx.squaredNorm();
                if (r2 < support2)
                    f(j, dx, r2);
            }
        }
    }

    [[nodiscard]] std::uint32_t begin(CellIndex c) const { return cells->begin[c]; }
    [[nodiscard]] std::uint32_t end(CellIndex c) const { return cells->end[c]; }
};

} // namespace sluice
