#pragma once
// Cartesian grid of micro-cells whose edge is at least the kernel support, so that all
// neighbours of a particle lie in its own cell and the 3^D adjacent ones. Cells are ordered
// along a Morton (Z-order) curve; particles are sorted by (Morton key, id).
#include "sluice/core/types.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sluice {

// Linear (row-major) index of a cell in the whole grid, 64-bit so that grids beyond 2^32 cells
// work; a rank stores per-cell data only for the cells it holds (CellRanges, cell_ranges.hpp).
using CellIndex = std::uint64_t;
using MortonKey = std::uint64_t;

// Spreads the low bits of v so that they occupy every D-th bit.
inline MortonKey spread_bits_2(std::uint32_t v) {
    MortonKey x = v;
    x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
    x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
    x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
    x = (x | (x << 2)) & 0x3333333333333333ull;
    x = (x | (x << 1)) & 0x5555555555555555ull;
    return x;
}
inline MortonKey spread_bits_3(std::uint32_t v) {
    MortonKey x = v & 0x1FFFFF; // 21 bits per axis
    x = (x | (x << 32)) & 0x1F00000000FFFFull;
    x = (x | (x << 16)) & 0x1F0000FF0000FFull;
    x = (x | (x << 8)) & 0x100F00F00F00F00Full;
    x = (x | (x << 4)) & 0x10C30C30C30C30C3ull;
    x = (x | (x << 2)) & 0x1249249249249249ull;
    return x;
}

template <int D>
struct CellGrid {
    Vec<D> lo = Vec<D>::Zero();     // lower corner of the grid
    Vec<D> length = Vec<D>::Zero(); // extent along each axis
    Vec<D> edge = Vec<D>::Zero();   // cell edge per axis (>= support)
    Vec<D> inv_edge = Vec<D>::Zero();
    std::array<int, D> dims{}; // cells per axis
    std::array<bool, D> periodic{};

    // Grid covering [lo, hi] with cells of edge >= min_edge. Periodic axes get an edge that
    // divides the length exactly (and need at least 3 cells so that no cell is its own
    // neighbour twice).
    static CellGrid make(const Vec<D>& lo, const Vec<D>& hi, Real min_edge,
                         const std::array<bool, D>& periodic);

    [[nodiscard]] bool any_periodic() const {
        for (int d = 0; d < D; ++d)
            if (periodic[d])
                return true;
        return false;
    }

    [[nodiscard]] std::size_t cell_count() const {
        std::size_t n = 1;
        for (int d = 0; d < D; ++d)
            n *= static_cast<std::size_t>(dims[d]);
        return n;
    }

    // Integer coordinates of the cell holding x (clamped to the grid on open axes).
    [[nodiscard]] std::array<int, D> coords(const Vec<D>& x) const {
        std::array<int, D> c{};
        for (int d = 0; d < D; ++d) {
            int k = static_cast<int>(std::floor((x[d] - lo[d]) * inv_edge[d]));
            c[d] = k < 0 ? 0 : (k >= dims[d] ? dims[d] - 1 : k);
        }
        return c;
    }

    [[nodiscard]] CellIndex linear(const std::array<int, D>& c) const {
        std::size_t idx = 0;
        for (int d = D - 1; d >= 0; --d)
            idx = idx * static_cast<std::size_t>(dims[d]) + static_cast<std::size_t>(c[d]);
        return static_cast<CellIndex>(idx);
    }

    [[nodiscard]] std::array<int, D> unlinear(CellIndex idx) const {
        std::array<int, D> c{};
        std::size_t r = idx;
        for (int d = 0; d < D; ++d) {
            c[d] = static_cast<int>(r % static_cast<std::size_t>(dims[d]));
            r /= static_cast<std::size_t>(dims[d]);
        }
        return c;
    }

    [[nodiscard]] MortonKey morton(const std::array<int, D>& c) const {
        if constexpr (D == 2)
            return spread_bits_2(static_cast<std::uint32_t>(c[0])) |
                   (spread_bits_2(static_cast<std::uint32_t>(c[1])) << 1);
        else
            return spread_bits_3(static_cast<std::uint32_t>(c[0])) |
                   (spread_bits_3(static_cast<std::uint32_t>(c[1])) << 1) |
                   (spread_bits_3(static_cast<std::uint32_t>(c[2])) << 2);
    }

    // Wraps x into the grid along periodic axes.
    void wrap(Vec<D>& x) const {
        for (int d = 0; d < D; ++d) {
            if (!periodic[d])
                continue;
            if (x[d] < lo[d])
                x[d] += length[d];
            else if (x[d] >= lo[d] + length[d])
                x[d] -= length[d];
        }
    }

    // Minimum-image displacement a - b (periodic axes only).
    [[nodiscard]] Vec<D> displacement(const Vec<D>& a, const Vec<D>& b) const {
        Vec<D> d = a - b;
        for (int k = 0; k < D; ++k)
            if (periodic[k])
                d[k] -= length[k] * std::round(d[k] / length[k]);
        return d;
    }
};

// One cell adjacent to (or equal to) a given cell, with the shift to add to x_i - x_j for
// the periodic image.
template <int D>
struct NeighbourCell {
    CellIndex cell;
    Vec<D> shift;
};

// Adjacent cells of c (itself included) in a fixed order: offsets -1..1, last axis slowest.
template <int D>
int adjacent_cells(const CellGrid<D>& grid, CellIndex c, NeighbourCell<D>* out);

extern template struct CellGrid<2>;
extern template struct CellGrid<3>;

} // namespace sluice
