#pragma once
// Integer cells of a hash grid, for measurements that bucket particles without the solver's
// cell grid (probes.cpp: bulk detection and levels; wall_loads.cpp: fluid around the walls).
#include "sluice/core/types.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sluice {

template <int D>
using CellKey = std::array<std::int64_t, D>;

// FNV-1a over the cell's coordinates.
template <int D>
struct CellKeyHash {
    std::size_t operator()(const CellKey<D>& k) const {
        std::uint64_t h = 1469598103934665603ULL;
        for (auto c : k)
            h = (h ^ static_cast<std::uint64_t>(c)) * 1099511628211ULL;
        return static_cast<std::size_t>(h);
    }
};

// Integer cell of a position for cells of edge 1/inv_size; false for positions no cell can
// hold (NaN, or so far away that the index would overflow).
template <int D>
bool cell_key_of(const Vec<D>& x, Real inv_size, CellKey<D>& out) {
    for (int a = 0; a < D; ++a) {
        const Real c = std::floor(x[a] * inv_size);
        if (!(std::abs(c) < 1e15))
            return false;
        out[static_cast<std::size_t>(a)] = static_cast<std::int64_t>(c);
    }
    return true;
}

// The 3^D offsets from a cell to itself and its neighbours, in a fixed order.
template <int D>
std::vector<CellKey<D>> cell_neighbour_offsets() {
    std::vector<CellKey<D>> out;
    const int total = D == 2 ? 9 : 27;
    for (int code = 0; code < total; ++code) {
        CellKey<D> o{};
        int rest = code;
        for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a) {
            o[a] = rest % 3 - 1;
            rest /= 3;
        }
        out.push_back(o);
    }
    return out;
}

} // namespace sluice
