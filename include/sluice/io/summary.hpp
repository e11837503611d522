#pragma once
// summary.json: the record of a finished run. Written only at a successful end, atomically
// (temporary file + rename), so its presence means the results folder is complete.
#include "sluice/io/case_config.hpp"
#include "sluice/io/run_result.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace sluice {

// The summary as JSON. Keys: case, description, source_file, dimension, particles,
// fluid_particles, steps, simulated_time, end_time, wall_seconds, particle_steps_per_second,
// threads, ranks, version, git_revision, precision (the build's sluice::Real: "double" or
// "float"), mass_initial, mass_final, mass_relative_change, fluid_particles_removed (those that
// left the domain under domain.particle_exit = "remove", over the whole run), and `extra` (an
// object; e.g. stage timings added by the solver). Non-finite numbers become null.
nlohmann::json make_summary(const CaseConfig& cfg, const RunResult& result, int threads, int ranks,
                            const nlohmann::json& extra = nlohmann::json::object());

// Writes make_summary(...) to <out_dir>/summary.json. Throws std::runtime_error on failure.
void write_summary(const std::string& out_dir, const CaseConfig& cfg, const RunResult& result,
                   int threads, int ranks, const nlohmann::json& extra = nlohmann::json::object());

} // namespace sluice
