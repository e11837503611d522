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
    // Positions and kinds sorted by cell (a counting sort; the order inside a cell does not
    // change a count): 21-29 bytes per particle, not a copy of every field.
    const std::size_t n = x.size();
    std::vector<CellIndex> cell(n);
    CellRanges ranges;
    ranges.begin.assign(grid.cell_count(), 0);
    ranges.end.assign(grid.cell_count(), 0);
    for (std::size_t i = 0; i < n; ++i) {
        cell[i] = grid.linear(grid.coords(x[i]));
        ++ranges.end[cell[i]];
    }
    std::uint32_t running = 0;
    std::vector<CellIndex> occupied;
    for (CellIndex c = 0; c < grid.cell_count(); ++c) {
        ranges.begin[c] = running;
        running += ranges.end[c];
        ranges.end[c] = ranges.begin[c];
        if (running > ranges.begin[c])
            occupied.push_back(c);
    }
    std::vector<Vec<D>> xs(n);
    std::vector<Kind> ks(n);
    std::vector<std::uint32_t> given; // sorted place -> index in x (only for nearest_out)
    if (!nearest_out.empty())
        given.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t at = ranges.end[cell[i]]++;
        xs[at] = x[i];
        ks[at] = kind[i];
        if (!given.empty())
            given[at] = static_cast<std::uint32_t>(i);
    }
    cell = {};
    const Neighbourhood<D> nb{&grid, &ranges, std::span<const Vec<D>>(xs), support};
    NeighbourCensus census;
    for (const CellIndex c : occupied) {
        if (!counted(grid.morton(grid.unlinear(c))))
            continue;
        const AdjacentCells<D> adj = nb.adjacent(c);
        for (std::uint32_t i = nb.begin(c); i < nb.end(c); ++i) {
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
