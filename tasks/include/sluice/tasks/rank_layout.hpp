#pragma once
// Ranks own contiguous runs of the Morton curve: rank r owns the cells whose keys lie in
// [key_begin[r], key_begin[r+1]) (the last rank's range is unbounded). Everything a rank needs
// to know about its neighbours follows from these cut points and the grid: which ranks are
// its peers, which of its cells are halo cells of a peer, where a particle that moved belongs.
//
// Like the rest of tasks/, this knows cells, keys and costs, never what is computed in a cell.
#include "sluice/core/cell_grid.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace sluice::tasks {

struct RankLayout {
    std::vector<MortonKey> key_begin{0}; // one cut point per rank, key_begin[0] == 0

    [[nodiscard]] int ranks() const { return static_cast<int>(key_begin.size()); }
    [[nodiscard]] int rank_of(MortonKey k) const;
    [[nodiscard]] bool owns(int rank, MortonKey k) const { return rank_of(k) == rank; }
};

// A unit of work along the curve: its first key and its cost (measured seconds, or particles
// when nothing has been measured). Units are given in key order.
struct CurveUnit {
    MortonKey key;
    double cost;
};

// Cut points that split `units` into `ranks` contiguous runs of nearly equal cost; cuts fall
// on unit boundaries. Ranks that get no unit own an empty key range.
RankLayout cut_ranks(const std::vector<CurveUnit>& units, int ranks);

// Cut points that split the grid's key space into equal key ranges, whatever the particles
// (a deliberately naive decomposition, to exercise the balancer).
template <int D>
RankLayout cut_ranks_by_key(const CellGrid<D>& grid, int ranks);

// Max over ranks of cost divided by the mean (1 = perfect balance); 1 when nothing costs.
double imbalance(const std::vector<double>& cost_per_rank);

// The keys [first, last) of `rank`'s range (the last rank's ends at the largest key).
[[nodiscard]] MortonKey range_begin(const RankLayout& layout, int rank);
[[nodiscard]] MortonKey range_end(const RankLayout& layout, int rank);

// Calls visit(cell) for every cell of the grid whose key lies in [first, last), once each, in
// no particular order. The work is proportional to those cells (plus the depth of the key
// tree along the range's two ends), not to the grid: the range is split into the aligned
// blocks of the Morton tree, and each block inside it is a box of cells (no O(grid)
// scan per rank at a rebalance).
template <int D, class Visit>
void for_each_cell_in_keys(const CellGrid<D>& grid, MortonKey first, MortonKey last, Visit&& visit);

// Ranks owning a cell adjacent (periodic wrap included) to a cell of `rank`'s range, sorted.
// Symmetric (s is a peer of r iff r is one of s). It depends only on the grid and the cut
// points, not on where particles are, so both sides of every exchange agree on it without
// talking. Work: the cells of `rank`'s range, not the grid.
template <int D>
std::vector<int> peers_of(const CellGrid<D>& grid, const RankLayout& layout, int rank);

// peers_of for every rank (O(grid): for tests and small grids).
template <int D>
std::vector<std::vector<int>> peer_ranks(const CellGrid<D>& grid, const RankLayout& layout);

// The ranks within two peer steps of `rank` (its peers and their peers, itself excluded),
// sorted, from the peer lists of `rank` and of its peers (the others are not read).
// Symmetric like the peers. It holds every rank that can own
// a cell adjacent to a cell of one of `rank`'s peers: the ranks a migration can change the
// halo of (RankExchange::migrate tells them in its one round).
std::vector<int> two_step_ranks(const std::vector<std::vector<int>>& peers, int rank);

// The ranks other than `owner` whose range holds a cell adjacent to `cell` (periodic wrap
// included), sorted, into `out`: the ranks that `cell` is a halo cell of while `owner` owns it.
template <int D>
void adjacent_owners(const CellGrid<D>& grid, const RankLayout& layout, CellIndex cell, int owner,
                     std::vector<int>& out);

// For each occupied cell of `rank` (in key order), the peers whose range holds an adjacent
// cell: out[k] lists the peer indices (positions in `peers`) cell k is a halo cell of.
template <int D>
std::vector<std::vector<int>> halo_targets(const CellGrid<D>& grid, const RankLayout& layout,
                                           int rank, const std::vector<int>& peers,
                                           const std::vector<CellIndex>& occupied_cells);

template <int D, class Visit>
void for_each_cell_in_keys(const CellGrid<D>& grid, MortonKey first, MortonKey last,
                           Visit&& visit) {
    if (first >= last)
        return;
    // The root block: 2^top cells along every axis cover the grid (keys interleave the axes'
    // bits, axis 0 lowest, so a block of level L is 2^L cells per axis and 2^(D L) keys).
    int top = 0;
    for (int d = 0; d < D; ++d)
        while ((1 << top) < grid.dims[d])
            ++top;
    const auto descend = [&](const auto& self, const std::array<int, D>& origin, int level,
                             MortonKey key0) -> void {
        const MortonKey span = MortonKey{1} << (D * level);
        if (key0 >= last || key0 + span <= first)
            return;
        for (int d = 0; d < D; ++d)
            if (origin[d] >= grid.dims[d])
                return; // a block past the grid's end holds no cell
        if (first <= key0 && key0 + span <= last) {
            // Inside the range: the block's cells within the grid, a box.
            std::array<int, D> hi{};
            for (int d = 0; d < D; ++d)
                hi[d] = std::min(grid.dims[d], origin[d] + (1 << level));
            std::array<int, D> c = origin;
            while (true) {
                visit(grid.linear(c));
                int d = 0;
                while (d < D && ++c[d] == hi[d]) {
                    c[d] = origin[d];
                    ++d;
                }
                if (d == D)
                    return;
            }
        }
        // Straddles an end of the range: its 2^D children, child k offset along axis d by bit d.
        const int half = level - 1;
        for (int k = 0; k < (1 << D); ++k) {
            std::array<int, D> o = origin;
            for (int d = 0; d < D; ++d)
                o[d] += ((k >> d) & 1) << half;
            self(self, o, half, key0 + (static_cast<MortonKey>(k) << (D * half)));
        }
    };
    descend(descend, std::array<int, D>{}, top, 0);
}

} // namespace sluice::tasks
