#pragma once
// Cell groups: runs of micro-cells along the Morton curve. A group owns a half-open range of
// Morton keys, so every cell (occupied or not) belongs to exactly one group; only occupied
// cells cost anything. Groups are cut so that each carries about the same cost.
//
// The runtime knows cells, keys and costs; it knows nothing of what is computed in a cell.
#include "sluice/core/cell_grid.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sluice::tasks {

// An occupied cell and its cost (e.g. particle count) in Morton order.
struct OccupiedCell {
    MortonKey key;
    CellIndex cell;
    double cost;
};

struct GroupTopology {
    // Group g covers Morton keys [key_begin[g], key_begin[g+1]); the last group is unbounded.
    std::vector<MortonKey> key_begin;
    // Occupied cells of each group, in Morton order (refreshed every step).
    std::vector<std::vector<CellIndex>> cells;
    // Groups whose cells are adjacent to a cell of g (g itself excluded), sorted.
    std::vector<std::vector<int>> neighbours;

    [[nodiscard]] int group_count() const { return static_cast<int>(key_begin.size()); }
    [[nodiscard]] int group_of(MortonKey k) const;
};

// How many cell groups a rank holding `particles` cuts its cells into: enough for groups of
// about `per_group` particles (runtime.particles_per_group), and at least 8 per worker thread,
// so that the threads finish each stage of the step graph together (Tak's (2024) 6,859-particle
// box at 1x2: 8 groups 29.5 s, 16 groups 25.0 s, medians of three interleaved runs;
// perf/strong_scaling/README.md, 2026-11-27), but no more than that floor needs groups of
// fewer than kMinGroupParticles particles (scheduling a task costs microseconds); never
// fewer than 4 per thread (the earlier floor, kept as it was for one thread: the projection
// scheme's results follow the grouping, docs/PROJECTION.md §2).
inline constexpr std::size_t kMinGroupParticles = 250;
[[nodiscard]] int target_group_count(std::size_t particles, std::size_t per_group, int threads);

// Cuts the Morton-ordered occupied cells into `groups` runs of nearly equal cost.
std::vector<MortonKey> cut_by_cost(const std::vector<OccupiedCell>& occupied, int groups);

// Fills topo.cells from the occupied cells (keeps topo.key_begin).
void assign_cells(const std::vector<OccupiedCell>& occupied, GroupTopology& topo);

// Group adjacency from cell adjacency on the grid: g and g' are neighbours when an occupied
// cell of g is adjacent (periodic wrap included) to an occupied cell of g'.
template <int D>
std::vector<std::vector<int>> group_adjacency(const CellGrid<D>& grid,
                                              const std::vector<OccupiedCell>& occupied,
                                              const GroupTopology& topo);

// True when every adjacency in `needed` is also in `have` (a graph built for `have` then
// still orders every pair of tasks that touch the same particles).
bool adjacency_covers(const std::vector<std::vector<int>>& have,
                      const std::vector<std::vector<int>>& needed);

} // namespace sluice::tasks
