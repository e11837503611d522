#pragma once
// The distributed start: each rank builds only the particles of its own part of the
// curve, never the whole set. A first pass over the case's particles (initial_state.hpp's
// visitors) stores nothing but a count per grid cell; from those counts every rank computes the
// cut points that distributing the whole set would give (tasks::cut_ranks over the occupied
// cells in Morton order, which is what the Rebinner lists for every particle); a second pass
// keeps the rank's own. Both passes run the same generator, so ids, positions and fields are
// bit for bit those of add_fluid_blocks / add_wall_particles. Memory: O(grid cells + own
// particles); time: every rank visits every site twice.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/tasks/rank_layout.hpp"

#include <cstddef>
#include <vector>

namespace sluice {

// The case's initial particles counted per cell, without storing them.
struct InitialCensus {
    std::vector<tasks::CurveUnit> cells; // occupied cells in Morton order, cost = particles
    std::size_t particles = 0;
    Real max_speed = 0; // largest |v| over every particle
};

// Fluid blocks, then (walls.model = "dummy") `layers` of wall particles, as the Simulation
// builds them.
template <int D>
InitialCensus initial_census(const CaseConfig& cfg, const Eos& eos, int layers,
                             const CellGrid<D>& grid);

// Cut points for `ranks` ranks: equal particle counts (runtime.initial_decomposition =
// "balanced") or equal key ranges ("key-range"). One rank: the whole curve, no census read.
template <int D>
tasks::RankLayout initial_layout(const CaseConfig& cfg, const CellGrid<D>& grid,
                                 const InitialCensus& census, int ranks);

struct InitialShare {
    tasks::RankLayout layout; // the same on every rank
    Real max_speed = 0;       // over every particle of the case, not only the share
};

// Appends to P the case's particles whose cell `rank` owns under the initial cut points (on one
// rank: all of them, with no census pass). P == nullptr keeps none: a restart needs only the
// start's largest speed for the checks of the case, and it takes its cuts from the checkpoint.
template <int D>
InitialShare initial_share(const CaseConfig& cfg, const Eos& eos, int layers,
                           const CellGrid<D>& grid, int rank, int ranks, Particles<D>* P);

} // namespace sluice
