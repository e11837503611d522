#pragma once
// Entry points the command line calls: describe a case, run it.
#include "sluice/io/case_config.hpp"
#include "sluice/io/memory_estimate.hpp"
#include "sluice/io/run_result.hpp"

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
    // --restart: continue from <restart_dir>/checkpoint.h5 (out_dir must be the same folder).
    std::string restart_dir;
    // --debug-fail-rank/--debug-fail-step: a task of that rank throws in that step (-1: never).
    int debug_fail_rank = -1;
    long debug_fail_step = -1;
};

// What `sluice info` prints: derived without running a step.
struct CaseInfo {
    std::size_t fluid_particles = 0;
    std::size_t wall_particles = 0;
    MemoryEstimate memory;  // per rank, for the rank count describe_case was given
    double h = 0;           // smoothing length [m]
    double support = 0;     // kernel support radius [m]
    double dt_estimate = 0; // time step the run starts with [s] (fixed, or dt_stable)
    double dt_stable = 0;   // stable time step at rest [s]
    double dt_acoustic = 0, dt_viscous = 0, dt_force = 0;
    std::size_t cells = 0;             // micro-cells of the grid
    std::vector<std::string> physics;  // human-readable list of what is switched on
    std::vector<std::string> geometry; // the walls, obstacles and blocks as built
};

// `ranks`: the MPI ranks the memory estimate is for.
CaseInfo describe_case(const CaseConfig& cfg, int ranks = 1);

// Runs the case to its end time, or from a checkpoint on (opts.restart_dir); on several MPI
// ranks every rank calls it (collective) and rank 0 writes all output. Writes checkpoints as
// the case's [checkpoint] table says, and on SIGTERM/SIGINT or a file <out_dir>/stop writes one
// and returns early with `stopped` set. Throws sluice::RunError on a physical failure (NaN,
// blow-up) and sluice::InternalError when a task threw, both after writing a last snapshot;
// throws sluice::CaseError for a case the solver refuses (e.g. a fixed dt above the stability
// limit) or a checkpoint that cannot continue it.
RunResult run_case(const CaseConfig& cfg, const RunOptions& opts);

} // namespace sluice
