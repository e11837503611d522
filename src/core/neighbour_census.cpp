#include "sluice/core/neighbour_census.hpp"

#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"

#include <span>
#include <utility>
#include <vector>

namespace sluice {

template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, Particles<D> P, Real support) {
    return count_neighbours<D>(grid, std::move(P), support, [](MortonKey) { return true; });
}

template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, Particles<D> P, Real support,
                                 const std::function<bool(MortonKey)>& counted) {
    CellRanges ranges;
    std::vector<CellOccupancy> occupied;
    rebin(grid, P, ranges, occupied);
    const Neighbourhood<D> nb{&grid, &ranges, std::span<const Vec<D>>(P.x), support};
    NeighbourCensus n;
    for (const CellOccupancy& o : occupied) {
        if (!counted(o.key))
            continue;
        const AdjacentCells<D> adj = nb.adjacent(o.cell);
        for (std::uint32_t i = nb.begin(o.cell); i < nb.end(o.cell); ++i) {
            const bool i_fluid = P.kind[i] == Kind::fluid;
            (i_fluid ? n.fluid : n.wall) += 1;
            std::uint64_t to_fluid = 0, to_wall = 0;
            nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>&, Real) {
                if (j != i)
                    (P.kind[j] == Kind::fluid ? to_fluid : to_wall) += 1;
            });
            (i_fluid ? n.fluid_fluid : n.wall_fluid) += to_fluid;
            (i_fluid ? n.fluid_wall : n.wall_wall) += to_wall;
        }
    }
    return n;
}

template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, Particles<2>, Real);
template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, Particles<3>, Real);
template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, Particles<2>, Real,
                                             const std::function<bool(MortonKey)>&);
template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, Particles<3>, Real,
                                             const std::function<bool(MortonKey)>&);

} // namespace sluice
