// summary.json, written atomically at the end of a successful run.
#include "sluice/io/summary.hpp"

#include "sluice/core/types.hpp"
#include "sluice/version.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace sluice {

nlohmann::json make_summary(const CaseConfig& cfg, const RunResult& r, int threads, int ranks,
                            const nlohmann::json& extra) {
    nlohmann::json j;
    j["case"] = cfg.name;
    j["description"] = cfg.description;
    j["source_file"] = cfg.source_file;
    j["dimension"] = cfg.dimension;
    j["particles"] = r.particles;
    j["fluid_particles"] = r.fluid_particles;
    j["steps"] = r.steps;
    j["simulated_time"] = r.simulated_time;
    j["end_time"] = cfg.end_time;
    j["wall_seconds"] = r.wall_seconds;
    j["particle_steps_per_second"] = r.particle_steps_per_second;
    j["threads"] = threads;
    j["ranks"] = ranks;
    j["version"] = sluice::version;
    j["git_revision"] = sluice::git_revision;
    j["precision"] = single_precision ? "float" : "double"; // SLUICE_PRECISION
    j["mass_initial"] = r.mass_initial;
    j["mass_final"] = r.mass_final;
    // Relative mass drift: zero for a conservative scheme, the first thing to look at.
    j["mass_relative_change"] =
        r.mass_initial != 0 ? (r.mass_final - r.mass_initial) / r.mass_initial : 0.0;
    j["fluid_particles_removed"] = r.fluid_removed; // domain.particle_exit = "remove"
    j["extra"] = extra.is_null() ? nlohmann::json::object() : extra;
    return j;
}

void write_summary(const std::string& out_dir, const CaseConfig& cfg, const RunResult& result,
                   int threads, int ranks, const nlohmann::json& extra) {
    const auto dir = std::filesystem::path(out_dir);
    const auto tmp = dir / ".summary.json.tmp";
    const auto final_path = dir / "summary.json";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << make_summary(cfg, result, threads, ranks, extra).dump(2) << '\n';
        out.flush();
        if (!out)
            throw std::runtime_error("cannot write " + tmp.string());
    }
    std::error_code ec;
    std::filesystem::rename(tmp, final_path, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw std::runtime_error("cannot write " + final_path.string() + ": " + ec.message());
    }
}

} // namespace sluice
