#pragma once
// What a finished (or stopped) run reports: returned by run_case (solver/run.hpp) and recorded
// in summary.json (io/summary.hpp). Here, in io, so that the summary's writer needs nothing of
// the solver.
#include <cstddef>
#include <cstdint>
#include <string>

namespace sluice {

struct RunResult {
    std::int64_t steps = 0;
    double simulated_time = 0;
    double wall_seconds = 0;
    std::size_t particles = 0; // fluid + wall
    std::size_t fluid_particles = 0;
    double particle_steps_per_second = 0;
    double mass_initial = 0, mass_final = 0;
    // domain.particle_exit = "remove": fluid particles that left the domain, over the whole run
    // (a restart's segments included); their mass is missing from mass_final.
    std::int64_t fluid_removed = 0;
    // Stopped early on request (signal or stop file) after writing `checkpoint`.
    bool stopped = false;
    std::string stop_reason; // rank 0: "SIGTERM", "SIGINT", "the stop file", ...
    std::string checkpoint;
};

} // namespace sluice
