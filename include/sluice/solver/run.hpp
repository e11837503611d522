#pragma once
// Entry points the command line calls: describe a case, run it.
#include "sluice/io/case_config.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sluice {

struct RunOptions {
    std::string out_dir; // results folder (created; snapshots/, probes/, summary.json)
    int threads = 0;     // 0 = all hardware threads
    bool quiet = false;  // no progress output
    bool verbose = false;
    std::string trace_path; // --trace: Chrome/Perfetto trace of every task and message
};

struct RunResult {
    std::int64_t steps = 0;
    double simulated_time = 0;
    double wall_seconds = 0;
    std::size_t particles = 0; // fluid + wall
    std::size_t fluid_particles = 0;
    double particle_steps_per_second = 0;
    double mass_initial = 0, mass_final = 0;
};

// What `sluice info` prints: derived without running a step.
struct CaseInfo {
    std::size_t fluid_particles = 0;
    std::size_t wall_particles = 0;
    double memory_bytes = 0; // estimate of the particle state
    double h = 0;            // smoothing length [m]
    double support = 0;      // kernel support radius [m]
    double dt_estimate = 0;  // time step the run starts with [s] (fixed, or dt_stable)
    double dt_stable = 0;    // stable time step at rest [s]
    double dt_acoustic = 0, dt_viscous = 0, dt_force = 0;
    std::size_t cells = 0;            // micro-cells of the grid
    std::vector<std::string> physics; // human-readable list of what is switched on
};

CaseInfo describe_case(const CaseConfig& cfg);

// Runs the case to its end time; on several MPI ranks every rank calls it (collective) and
// rank 0 writes all output. Throws sluice::RunError on a physical failure (NaN,
// blow-up) after writing a last snapshot; throws sluice::CaseError for a case the solver
// refuses (e.g. a fixed dt above the stability limit).
RunResult run_case(const CaseConfig& cfg, const RunOptions& opts);

} // namespace sluice
