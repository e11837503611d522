#pragma once
// The fluid's spacing over every rank: core/neighbour_census.hpp's counts and, when asked,
// each owned fluid particle's distance to its nearest fluid neighbour, without gathering the
// particles on one rank (private to src/solver). run_totals (summary.json, the end-of-run log
// line) and the snapshots (their spacing attributes and field) read it.
#include "sluice/core/neighbour_census.hpp"
#include "sluice/solver/simulation.hpp"

#include <vector>

namespace sluice {

// A fluid particle is crowded when its nearest fluid neighbour is closer than half the
// initial spacing (run_report.cpp's sentences say "dx/2": change them together).
inline Real crowded_below(double dx) {
    return Real(0.5 * dx);
}

struct SpacingCensus {
    NeighbourCensus census; // every rank's counts together; the least of the closest pairs
    // Per owned particle, in this rank's order, when asked: the distance to the nearest fluid
    // neighbour [m] of a fluid particle, infinity when none lies within the support; NaN for a
    // wall particle.
    std::vector<Real> nearest;
};

// Collective. Each rank counts the particles in the cells it owns, by their current positions,
// with neighbours from the adjacent cells, whose particles every rank sends to the owners of
// those cells; the integer counts add up exactly, and the closest fluid pair is the least of
// the ranks'. With `per_particle`, the owner of a particle's cell sends its nearest distance
// back to the rank that holds the particle (between rebuilds the two may differ), so every
// value comes from the same neighbour set, whatever the layout.
template <int D>
SpacingCensus spacing_census(const Simulation<D>& sim, Real support, Real crowded,
                             bool per_particle);

extern template SpacingCensus spacing_census<2>(const Simulation<2>&, Real, Real, bool);
extern template SpacingCensus spacing_census<3>(const Simulation<3>&, Real, Real, bool);

} // namespace sluice
