#pragma once
// The run's particle totals for summary.json (particle counts, fluid mass, neighbour census)
// at the start and the end, without gathering the particles on rank 0 (private to src/solver).
#include "sluice/core/id_order_sum.hpp"
#include "sluice/core/neighbour_census.hpp"
#include "sluice/solver/simulation.hpp"

#include <cstdint>

namespace sluice {

struct RunTotals {
    std::uint64_t particles = 0, fluid = 0; // every rank's owned particles together
    Real mass = 0;                          // fluid mass in id order: rank 0 only
    NeighbourCensus census; // pairs within `support` and fluid spacing, every rank's together
};

// Collective. Counts and census on every rank; the mass on rank 0 (which receives 16 bytes per
// fluid particle: the ids and masses that Particles::total_mass sums, in its order, so the
// figure has the same bits on any layout). The census: spacing_census (spacing_census.hpp),
// or `known` when the caller holds this state's census with the same support and threshold
// (a snapshot just written took it: RunOutputs::spacing_at).
template <int D>
RunTotals run_totals(const Simulation<D>& sim, Real support, Real crowded,
                     const NeighbourCensus* known = nullptr);

extern template RunTotals run_totals<2>(const Simulation<2>&, Real, Real, const NeighbourCensus*);
extern template RunTotals run_totals<3>(const Simulation<3>&, Real, Real, const NeighbourCensus*);

} // namespace sluice
