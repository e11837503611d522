#pragma once
// Neighbour counts of a particle set, by kind: how many (i, j) pairs within the kernel support
// a step's neighbour loops visit. A diagnostic for benchmarks (achieved interactions per
// second), computed on a copy outside the time loop; the solver never calls it while stepping.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"

#include <cstdint>
#include <functional>
#include <span>

namespace sluice {

// Ordered pairs (i, j), i != j, with |x_i - x_j| < support, by the kinds of i and j.
struct NeighbourCensus {
    std::uint64_t fluid = 0, wall = 0;             // particles of each kind
    std::uint64_t fluid_fluid = 0, fluid_wall = 0; // i fluid; j fluid / wall
    std::uint64_t wall_fluid = 0, wall_wall = 0;   // i wall; j fluid / wall
};

// Counts over P (periodic images included).
template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, const Particles<D>& P, Real support);

// The same over positions and kinds alone, but only particles i in cells whose Morton key
// `counted` accepts are counted (with their neighbours j among all the particles given): over
// a partition of the cells the counts add up to the whole set's, each part seeing every
// particle of the cells adjacent to its own. Sorts copies of x and kind by cell (no copy of
// the other fields).
template <int D>
NeighbourCensus count_neighbours(const CellGrid<D>& grid, std::span<const Vec<D>> x,
                                 std::span<const Kind> kind, Real support,
                                 const std::function<bool(MortonKey)>& counted);

extern template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, const Particles<2>&, Real);
extern template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, const Particles<3>&, Real);
extern template NeighbourCensus count_neighbours<2>(const CellGrid<2>&, std::span<const Vec<2>>,
                                                    std::span<const Kind>, Real,
                                                    const std::function<bool(MortonKey)>&);
extern template NeighbourCensus count_neighbours<3>(const CellGrid<3>&, std::span<const Vec<3>>,
                                                    std::span<const Kind>, Real,
                                                    const std::function<bool(MortonKey)>&);

} // namespace sluice
