#include "sluice/tasks/rank_layout.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace sluice::tasks {

int RankLayout::rank_of(MortonKey k) const {
    const auto it = std::upper_bound(key_begin.begin(), key_begin.end(), k);
    return it == key_begin.begin() ? 0 : static_cast<int>(it - key_begin.begin()) - 1;
}

RankLayout cut_ranks(const std::vector<CurveUnit>& units, int ranks) {
    RankLayout layout;
    layout.key_begin.assign(1, 0);
    double total = 0;
    for (const auto& u : units)
        total += u.cost;
    // Rank r starts at the first unit whose cost prefix reaches r/R of the total; the cut is
    // moved back one unit when that lands closer to the ideal point.
    std::vector<double> prefix(units.size() + 1, 0.0);
    for (std::size_t i = 0; i < units.size(); ++i)
        prefix[i + 1] = prefix[i] + units[i].cost;
    std::size_t next = 1; // first unit index a new cut may use
    for (int r = 1; r < ranks; ++r) {
        const double ideal = total * r / ranks;
        std::size_t i = next;
        while (i < units.size() && prefix[i] < ideal)
            ++i;
        // prefix[i] is the cost before unit i: cutting at i-1 instead is better when it lands
        // closer to the ideal point (and past the previous cut).
        if (i > next && (i == units.size() || ideal - prefix[i - 1] < prefix[i] - ideal))
            --i;
        if (i >= units.size()) {
            // No unit left: this and later ranks own empty ranges past the last key.
            const MortonKey past = units.empty() ? 1 : units.back().key + 1;
            layout.key_begin.push_back(std::max(past, layout.key_begin.back() + 1));
            continue;
        }
        layout.key_begin.push_back(std::max(units[i].key, layout.key_begin.back() + 1));
        next = i + 1;
    }
    return layout;
}

template <int D>
RankLayout cut_ranks_by_key(const CellGrid<D>& grid, int ranks) {
    std::array<int, D> top{};
    for (int d = 0; d < D; ++d)
        top[d] = grid.dims[d] - 1;
    const MortonKey end = grid.morton(top) + 1;
    RankLayout layout;
    for (int r = 1; r < ranks; ++r)
        layout.key_begin.push_back(
            std::max<MortonKey>(end / static_cast<MortonKey>(ranks) * static_cast<MortonKey>(r),
                                layout.key_begin.back() + 1));
    return layout;
}

double imbalance(const std::vector<double>& cost_per_rank) {
    if (cost_per_rank.empty())
        return 1.0;
    const double total = std::accumulate(cost_per_rank.begin(), cost_per_rank.end(), 0.0);
    if (total <= 0)
        return 1.0;
    return *std::max_element(cost_per_rank.begin(), cost_per_rank.end()) /
           (total / static_cast<double>(cost_per_rank.size()));
}

MortonKey range_begin(const RankLayout& layout, int rank) {
    return layout.key_begin[static_cast<std::size_t>(rank)];
}

MortonKey range_end(const RankLayout& layout, int rank) {
    return rank + 1 < layout.ranks() ? layout.key_begin[static_cast<std::size_t>(rank) + 1]
                                     : std::numeric_limits<MortonKey>::max();
}

template <int D>
std::vector<int> peers_of(const CellGrid<D>& grid, const RankLayout& layout, int rank) {
    std::vector<int> out;
    if (layout.ranks() <= 1)
        return out;
    std::vector<int> owners;
    for_each_cell_in_keys(grid, range_begin(layout, rank), range_end(layout, rank),
                          [&](CellIndex c) {
                              adjacent_owners(grid, layout, c, rank, owners);
                              out.insert(out.end(), owners.begin(), owners.end());
                          });
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

template <int D>
std::vector<std::vector<int>> peer_ranks(const CellGrid<D>& grid, const RankLayout& layout) {
    std::vector<std::vector<int>> peers(static_cast<std::size_t>(layout.ranks()));
    for (int r = 0; r < layout.ranks(); ++r)
        peers[static_cast<std::size_t>(r)] = peers_of(grid, layout, r);
    return peers;
}

std::vector<int> two_step_ranks(const std::vector<std::vector<int>>& peers, int rank) {
    std::vector<int> out;
    for (int p : peers[static_cast<std::size_t>(rank)]) {
        out.push_back(p);
        for (int q : peers[static_cast<std::size_t>(p)])
            if (q != rank)
                out.push_back(q);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

template <int D>
void adjacent_owners(const CellGrid<D>& grid, const RankLayout& layout, CellIndex cell, int owner,
                     std::vector<int>& out) {
    out.clear();
    NeighbourCell<D> nbr[D == 2 ? 9 : 27];
    const int n = adjacent_cells(grid, cell, nbr);
    for (int m = 0; m < n; ++m) {
        const int o = layout.rank_of(grid.morton(grid.unlinear(nbr[m].cell)));
        if (o != owner)
            out.push_back(o);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

template <int D>
std::vector<std::vector<int>> halo_targets(const CellGrid<D>& grid, const RankLayout& layout,
                                           int rank, const std::vector<int>& peers,
                                           const std::vector<CellIndex>& occupied_cells) {
    std::vector<std::vector<int>> out(occupied_cells.size());
    std::vector<int> owners;
    for (std::size_t k = 0; k < occupied_cells.size(); ++k) {
        adjacent_owners(grid, layout, occupied_cells[k], rank, owners);
        // Ranks and peer indices are in the same (sorted) order.
        for (int o : owners)
            out[k].push_back(
                static_cast<int>(std::lower_bound(peers.begin(), peers.end(), o) - peers.begin()));
    }
    return out;
}

template RankLayout cut_ranks_by_key<2>(const CellGrid<2>&, int);
template RankLayout cut_ranks_by_key<3>(const CellGrid<3>&, int);
template std::vector<int> peers_of<2>(const CellGrid<2>&, const RankLayout&, int);
template std::vector<int> peers_of<3>(const CellGrid<3>&, const RankLayout&, int);
template std::vector<std::vector<int>> peer_ranks<2>(const CellGrid<2>&, const RankLayout&);
template std::vector<std::vector<int>> peer_ranks<3>(const CellGrid<3>&, const RankLayout&);
template void adjacent_owners<2>(const CellGrid<2>&, const RankLayout&, CellIndex, int,
                                 std::vector<int>&);
template void adjacent_owners<3>(const CellGrid<3>&, const RankLayout&, CellIndex, int,
                                 std::vector<int>&);
template std::vector<std::vector<int>> halo_targets<2>(const CellGrid<2>&, const RankLayout&, int,
                                                       const std::vector<int>&,
                                                       const std::vector<CellIndex>&);
template std::vector<std::vector<int>> halo_targets<3>(const CellGrid<3>&, const RankLayout&, int,
                                                       const std::vector<int>&,
                                                       const std::vector<CellIndex>&);

} // namespace sluice::tasks
