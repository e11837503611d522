#include "sluice/core/neighbour_census.hpp"

#include "sluice/core/neighbourhood.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sluice {

template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, const Particles<D>& P, Real support,
                                 Real crowded) {
    return count_neighbours<D>(grid, P.x, P.kind, support, crowded, [](MortonKey) { return true; });
}

template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, std::span<const Vec<D>> x,
                                 std::span<const Kind> kind, Real support, Real crowded,
                                 const std::function<bool(MortonKey)>& counted,
                                 std::span<Real> nearest_out) {
    if (!nearest_out.empty() && nearest_out.size() != x.size())
        throw std::invalid_argument("count_neighbours: `nearest` must have an entry per particle");
    // Positions and kinds sorted by cell (the order inside a cell does not change a count),
    // through a sort of (cell, index) pairs: memory per particle, none per cell of the grid.
    const std::size_t n = x.size();
    std::vector<std::pair<CellIndex, std::uint32_t>> by_cell(n);
    for (std::size_t i = 0; i < n; ++i)
        by_cell[i] = {grid.linear(grid.coords(x[i])), static_cast<std::uint32_t>(i)};
    std::sort(by_cell.begin(), by_cell.end());
    CellRanges ranges;
    std::vector<CellIndex> occupied;
    for (std::size_t i = 0; i < n; ++i)
        if (i == 0 || by_cell[i].first != by_cell[i - 1].first)
            occupied.push_back(by_cell[i].first);
    ranges.reset(occupied.size());
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i + 1;
        while (j < n && by_cell[j].first == by_cell[i].first)
            ++j;
        ranges.set(by_cell[i].first, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
        i = j;
    }
    std::vector<Vec<D>> xs(n);
    std::vector<Kind> ks(n);
    std::vector<std::uint32_t> given; // sorted place -> index in x (only for nearest_out)
    if (!nearest_out.empty())
        given.resize(n);
    for (std::size_t at = 0; at < n; ++at) {
        const std::uint32_t i = by_cell[at].second;
        xs[at] = x[i];
        ks[at] = kind[i];
        if (!given.empty())
            given[at] = i;
    }
    by_cell = {};
    const Neighbourhood<D> nb{&grid, &ranges, std::span<const Vec<D>>(xs), support};
    NeighbourCensus census;
    for (const CellIndex c : occupied) {
        if (!counted(grid.morton(grid.unlinear(c))))
            continue;
        const AdjacentCells<D> adj = nb.adjacent(c);
        for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
            const bool i_fluid = ks[i] == Kind::fluid;
            (i_fluid ? census.fluid : census.wall) += 1;
            std::uint64_t to_fluid = 0, to_wall = 0;
            Real nearest_fluid2 = std::numeric_limits<Real>::infinity();
            nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>&, Real r2) {
                if (j == i)
                    return;
                const bool j_fluid = ks[j] == Kind::fluid;
                (j_fluid ? to_fluid : to_wall) += 1;
                if (j_fluid)
                    nearest_fluid2 = std::min(nearest_fluid2, r2);
            });
            (i_fluid ? census.fluid_fluid : census.wall_fluid) += to_fluid;
            (i_fluid ? census.fluid_wall : census.wall_wall) += to_wall;
            if (!i_fluid)
                continue;
            const Real nearest = std::sqrt(nearest_fluid2); // inf when to_fluid == 0
            if (!given.empty())
                nearest_out[given[i]] = nearest;
            if (to_fluid == 0) {
                ++census.fluid_isolated;
                continue;
            }
            census.closest_fluid_pair = std::min(census.closest_fluid_pair, nearest);
            if (nearest < crowded)
                ++census.fluid_crowded;
        }
    }
    return census;
}

template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, const Particles<2>&, Real, Real);
template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, const Particles<3>&, Real, Real);
template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, std::span<const Vec<2>>,
                                             std::span<const Kind>, Real, Real,
                                             const std::function<bool(MortonKey)>&,
                                             std::span<Real>);
template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, std::span<const Vec<3>>,
                                             std::span<const Kind>, Real, Real,
                                             const std::function<bool(MortonKey)>&,
                                             std::span<Real>);

} // namespace sluice
