#pragma once
// Two of the rank's units that a scheme's stages read or write (docs/ARCHITECTURE.md, "The
// rank's units"): the step clock, which every rank holds alike, and the per-group results of
// a step, which the step's agreement reduces over groups and ranks.
#include "sluice/core/types.hpp"
#include "sluice/physics/timestep.hpp"
#include "sluice/solver/body_load_sums.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sluice {

// Where the run is in time, the same on every rank (agreed in the step's all-gather): with
// the last step's limits, what a checkpoint's SolverState holds.
struct StepClock {
    double time = 0;    // t of the state [s]
    double dt = 0;      // the step being taken (or next) [s]
    double dt_prev = 0; // the step before (the kick uses (dt_prev + dt)/2) [s]
    long steps = 0;     // steps taken
    Real u_max = 0;     // largest fluid speed of the last step, all ranks (shifting's scale)
};

// Per cell group, what the last stage of a step (drift, correct) found; the step's agreement
// (step_agreement.cpp) reduces them over the groups and the ranks.
struct GroupResults {
    std::vector<TimeStepLimits> limits;   // time-step limits of the group's particles
    std::vector<std::string> failure;     // the first unhealthy particle's message, or empty
    std::vector<Real> speed;              // largest fluid speed (shifting's velocity scale)
    std::vector<Real> disp2;              // largest squared displacement from x_ref (Verlet)
    std::vector<std::int64_t> leaving;    // fluid particles that left the domain (to be removed)
    std::vector<BodyLoadSums> body_loads; // the fluid's load on each free body (wall_motion.hpp)

    void assign(std::size_t groups) {
        body_loads.assign(groups, {});
        limits.assign(groups, {});
        failure.assign(groups, {});
        speed.assign(groups, 0.0);
        disp2.assign(groups, 0.0);
        leaving.assign(groups, 0);
    }
};

} // namespace sluice
