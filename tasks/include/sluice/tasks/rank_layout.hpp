#pragma once
// Ranks own contiguous runs of the Morton curve: rank r owns the cells whose keys lie in
// [key_begin[r], key_begin[r+1]) (the last rank's range is unbounded). Everything a rank needs
// to know about its neighbours follows from these cut points and the grid: which ranks are
// its peers, which of its cells are halo cells of a peer, where a particle that moved belongs.
//
// Like the rest of tasks/, this knows cells, keys and costs, never what is computed in a cell.
#include "sluice/core/cell_grid.hpp"

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

// Ranks owning a cell adjacent (periodic wrap included) to a cell of `rank`'s range, for
// every rank: peers[r] is sorted and symmetric (s in peers[r] iff r in peers[s]). It depends
// only on the grid and the cut points, not on where particles are, so both sides of every
// exchange agree on it without talking.
template <int D>
std::vector<std::vector<int>> peer_ranks(const CellGrid<D>& grid, const RankLayout& layout);

// The ranks within two peer steps of `rank` (its peers and their peers, itself excluded),
// sorted, from peer_ranks' lists. Symmetric like the peers. It holds every rank that can own
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

} // namespace sluice::tasks
