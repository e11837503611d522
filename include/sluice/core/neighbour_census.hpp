#pragma once
// Neighbour counts of a particle set, by kind: how many (i, j) pairs within the kernel support
// a step's neighbour loops visit (benchmarks turn them into achieved interactions per second),
// and how evenly the fluid is spaced: fluid particles crowded onto a fluid neighbour, fluid
// particles alone, and the closest fluid pair. Computed on a copy outside the time loop; the
// solver never calls it while stepping.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <span>

namespace sluice {

// Ordered pairs (i, j), i != j, with |x_i - x_j| < support, by the kinds of i and j.
struct NeighbourCensus {
    std::uint64_t fluid = 0, wall = 0;             // particles of each kind
    std::uint64_t fluid_fluid = 0, fluid_wall = 0; // i fluid; j fluid / wall
    std::uint64_t wall_fluid = 0, wall_wall = 0;   // i wall; j fluid / wall
    // Spacing of the fluid. A WCSPH fluid without particle shifting can crowd: particles close
    // in on a neighbour (tensile instability, disorder after an impact) long before anything
    // else shows it, and such clumps are where violent runs blow up (docs/IMPACT_LOADS.md,
    // "Particle spacing"). Exact counts, so they add over any partition of the cells.
    std::uint64_t fluid_crowded = 0; // fluid particles with a fluid neighbour closer than `crowded`
    std::uint64_t fluid_isolated = 0; // fluid particles with no fluid neighbour within the support
    Real closest_fluid_pair = std::numeric_limits<Real>::infinity(); // [m]; inf: no fluid pair
};

// Counts over P (periodic images included); a fluid particle is crowded when its nearest fluid
// neighbour lies closer than `crowded` (the run uses half the initial spacing).
template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, const Particles<D>& P, Real support,
                                 Real crowded);

// The same over positions and kinds alone, but only particles i in cells whose Morton key
// `counted` accepts are counted (with their neighbours j among all the particles given): over
// a partition of the cells the counts add up to the whole set's, each part seeing every
// particle of the cells adjacent to its own. Sorts copies of x and kind by cell (no copy of
// the other fields). When `nearest` is given (x.size() entries), each counted fluid particle's
// entry is set to the distance to its nearest fluid neighbour, infinity when it has none
// within the support; the other entries are left as they are.
template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, std::span<const Vec<D>> x,
                                 std::span<const Kind> kind, Real support, Real crowded,
                                 const std::function<bool(MortonKey)>& counted,
                                 std::span<Real> nearest = {});

extern template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, const Particles<2>&, Real,
                                                    Real);
extern template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, const Particles<3>&, Real,
                                                    Real);
extern template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, std::span<const Vec<2>>,
                                                    std::span<const Kind>, Real, Real,
                                                    const std::function<bool(MortonKey)>&,
                                                    std::span<Real>);
extern template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, std::span<const Vec<3>>,
                                                    std::span<const Kind>, Real, Real,
                                                    const std::function<bool(MortonKey)>&,
                                                    std::span<Real>);

} // namespace sluice
