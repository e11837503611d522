#include "sluice/tasks/decomposition.hpp"

#include <algorithm>
#include <unordered_map>

namespace sluice::tasks {

int GroupTopology::group_of(MortonKey k) const {
    const auto it = std::upper_bound(key_begin.begin(), key_begin.end(), k);
    return it == key_begin.begin() ? 0 : static_cast<int>(it - key_begin.begin()) - 1;
}

int target_group_count(std::size_t particles, std::size_t per_group, int threads) {
    const auto ceil_div = [](std::size_t a, std::size_t b) { return (a + b - 1) / b; };
    const std::size_t t = static_cast<std::size_t>(std::max(1, threads));
    const std::size_t by_size = ceil_div(particles, std::max<std::size_t>(1, per_group));
    // One thread has nothing to balance: its floor stays 4 (and its grouping as before).
    const std::size_t balance =
        t == 1 ? 4 : std::max(4 * t, std::min(8 * t, ceil_div(particles, kMinGroupParticles)));
    return static_cast<int>(std::max(by_size, balance));
}

std::vector<MortonKey> cut_by_cost(const std::vector<OccupiedCell>& occupied, int groups) {
    std::vector<MortonKey> begin{0};
    if (occupied.empty() || groups <= 1)
        return begin;
    double total = 0;
    for (const auto& c : occupied)
        total += c.cost;
    const double target = total / groups;
    double acc = 0;
    for (std::size_t i = 0; i < occupied.size(); ++i) {
        // Start a new group at cell i when the groups so far have reached their share.
        if (acc >= target * static_cast<double>(begin.size()) &&
            static_cast<int>(begin.size()) < groups && i > 0)
            begin.push_back(occupied[i].key);
        acc += occupied[i].cost;
    }
    return begin;
}

void assign_cells(const std::vector<OccupiedCell>& occupied, GroupTopology& topo) {
    topo.cells.assign(topo.key_begin.size(), {});
    std::size_t g = 0;
    for (const auto& c : occupied) {
        while (g + 1 < topo.key_begin.size() && c.key >= topo.key_begin[g + 1])
            ++g;
        topo.cells[g].push_back(c.cell);
    }
}

template <int D>
std::vector<std::vector<int>> group_adjacency(const CellGrid<D>& grid,
                                              const std::vector<OccupiedCell>& occupied,
                                              const GroupTopology& topo) {
    std::unordered_map<CellIndex, int> group_of_cell;
    group_of_cell.reserve(occupied.size() * 2);
    for (int g = 0; g < topo.group_count(); ++g)
        for (CellIndex c : topo.cells[g])
            group_of_cell.emplace(c, g);
    std::vector<std::vector<int>> adj(topo.key_begin.size());
    NeighbourCell<D> nbr[D == 2 ? 9 : 27];
    for (int g = 0; g < topo.group_count(); ++g) {
        for (CellIndex c : topo.cells[g]) {
            const int n = adjacent_cells(grid, c, nbr);
            for (int k = 0; k < n; ++k) {
                const auto it = group_of_cell.find(nbr[k].cell);
                if (it != group_of_cell.end() && it->second != g)
                    adj[g].push_back(it->second);
            }
        }
        std::sort(adj[g].begin(), adj[g].end());
        adj[g].erase(std::unique(adj[g].begin(), adj[g].end()), adj[g].end());
    }
    return adj;
}

bool adjacency_covers(const std::vector<std::vector<int>>& have,
                      const std::vector<std::vector<int>>& needed) {
    if (have.size() != needed.size())
        return false;
    for (std::size_t g = 0; g < needed.size(); ++g)
        if (!std::includes(have[g].begin(), have[g].end(), needed[g].begin(), needed[g].end()))
            return false;
    return true;
}

template std::vector<std::vector<int>>
group_adjacency<2>(const CellGrid<2>&, const std::vector<OccupiedCell>&, const GroupTopology&);
template std::vector<std::vector<int>>
group_adjacency<3>(const CellGrid<3>&, const std::vector<OccupiedCell>&, const GroupTopology&);

} // namespace sluice::tasks
