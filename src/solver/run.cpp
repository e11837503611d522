// run_case / describe_case: the driver loop around a Simulation (output cadence, probes,
// progress, summary). No physics here.
#include "sluice/solver/run.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/io/probe_writer.hpp"
#include "sluice/io/progress.hpp"
#include "sluice/io/snapshot_writer.hpp"
#include "sluice/io/summary.hpp"
#include "sluice/physics/initial_conditions.hpp"
#include "sluice/physics/probes.hpp"
#include "sluice/solver/simulation.hpp"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sluice {

namespace {

const char* kernel_name(KernelType k) {
    switch (k) {
    case KernelType::quintic:
        return "Morris quintic spline (support 3h)";
    case KernelType::wendland_c2:
        return "Wendland C2 (support 2h)";
    case KernelType::cubic_spline:
        return "cubic spline (support 2h)";
    }
    return "?";
}

// Bytes of particle state per particle (the arrays of Particles<D>).
std::size_t bytes_per_particle(int dim) {
    const std::size_t vec = static_cast<std::size_t>(dim) * sizeof(Real);
    return 8 * vec + 5 * sizeof(Real) + sizeof(ParticleId) + sizeof(Kind);
}

template <int D>
double probe_value(const Simulation<D>& sim, const ProbeConfig& probe) {
    const auto& P = sim.particles();
    const double dx = sim.config().dx;
    switch (probe.type) {
    case ProbeType::pressure: {
        Vec<D> point;
        for (int d = 0; d < D; ++d)
            point[d] = probe.position[d];
        return pressure_probe(P, sim.kernel(), point);
    }
    case ProbeType::water_level:
        return water_level(P, dx, probe.x);
    case ProbeType::surge_front:
        return surge_front(P, dx);
    }
    return std::nan("");
}

template <int D>
RunResult run_impl(const CaseConfig& cfg, const RunOptions& opts, int threads) {
    namespace fs = std::filesystem;
    using Clock = std::chrono::steady_clock;
    Simulation<D> sim(cfg); // refuses an unrunnable case before anything is written

    fs::create_directories(opts.out_dir);
    fs::remove(fs::path(opts.out_dir) / "summary.json"); // an old summary would look complete
    std::unique_ptr<SnapshotWriter<D>> snapshots;
    if (cfg.snapshots)
        snapshots = std::make_unique<SnapshotWriter<D>>(opts.out_dir, cfg.fields);
    ProbeWriter probe_files(opts.out_dir, cfg.probes);

    const double out_every = cfg.output_interval > 0 ? cfg.output_interval : cfg.end_time;
    std::vector<double> probe_every, probe_next;
    for (const auto& p : cfg.probes) {
        probe_every.push_back(p.interval > 0 ? p.interval : out_every);
        probe_next.push_back(0.0);
    }
    double out_next = 0.0;
    double last_output_time = -1;
    auto sample = [&](bool force) {
        const double t = sim.time();
        for (std::size_t k = 0; k < cfg.probes.size(); ++k)
            if (force || t >= probe_next[k] - 1e-12 * cfg.end_time) {
                probe_files.write(k, t, probe_value(sim, cfg.probes[k]));
                while (probe_next[k] <= t + 1e-12 * cfg.end_time)
                    probe_next[k] += probe_every[k];
            }
        if (force || t >= out_next - 1e-12 * cfg.end_time) {
            if (snapshots && t != last_output_time)
                snapshots->write(sim.particles(), t, sim.steps());
            last_output_time = t;
            while (out_next <= t + 1e-12 * cfg.end_time)
                out_next += out_every;
        }
    };

    RunResult result;
    result.particles = sim.particles().size();
    result.fluid_particles = sim.particles().count(Kind::fluid);
    result.mass_initial = sim.particles().total_mass();

    Progress progress(cfg.end_time, opts.quiet);
    const auto t0 = Clock::now();
    sample(false);
    while (sim.time() < cfg.end_time * (1 - 1e-12)) {
        try {
            sim.step();
        } catch (const RunError& e) {
            // The state is the last good one: the failing step never swapped its buffers in.
            std::string where;
            if (snapshots)
                where = ", last good state in " +
                        snapshots->write(sim.particles(), sim.time(), sim.steps());
            progress.finish();
            throw RunError(std::string(e.what()) + where);
        }
        const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
        progress.update(sim.steps(), sim.time(), sim.dt(),
                        static_cast<double>(result.particles) * static_cast<double>(sim.steps()) /
                            wall);
        sample(false);
    }
    if (sim.time() != last_output_time)
        sample(true);
    progress.finish();

    result.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    result.steps = sim.steps();
    result.simulated_time = sim.time();
    result.particle_steps_per_second = static_cast<double>(result.particles) *
                                       static_cast<double>(result.steps) / result.wall_seconds;
    result.mass_final = sim.particles().total_mass();

    nlohmann::json extra;
    nlohmann::json stages = nlohmann::json::object();
    const auto names = sim.stage_names();
    for (std::size_t s = 0; s < names.size() && s < sim.stage_busy_seconds().size(); ++s)
        stages[names[s]] = sim.stage_busy_seconds()[s];
    const auto& graph = sim.graph();
    extra["stage_busy_seconds"] = stages;
    extra["rebin_seconds"] = sim.rebin_seconds_total();
    extra["cell_groups"] = graph.group_count();
    extra["decompositions"] = sim.decompositions();
    extra["last_dt"] = sim.dt();
    write_summary(opts.out_dir, cfg, result, threads, 1, extra);
    return result;
}

} // namespace

CaseInfo describe_case(const CaseConfig& cfg) {
    CaseInfo info;
    info.h = cfg.h_over_dx * cfg.dx;
    info.support = kernel_support_factor(cfg.kernel) * info.h;
    const int layers = wall_layers(info.support, cfg.dx);
    info.fluid_particles = count_fluid_particles(cfg);
    info.wall_particles = count_wall_particles(cfg, layers);
    info.memory_bytes = static_cast<double>((info.fluid_particles + info.wall_particles) *
                                            bytes_per_particle(cfg.dimension));
    double g = 0, vmax = 0;
    for (int d = 0; d < cfg.dimension; ++d)
        g += cfg.gravity[d] * cfg.gravity[d];
    for (const auto& b : cfg.blocks) {
        double v2 = 0;
        for (int d = 0; d < cfg.dimension; ++d)
            v2 += b.velocity[d] * b.velocity[d];
        vmax = std::max(vmax, std::sqrt(v2) + b.amplitude);
    }
    const TimeStepParams prm{info.h, cfg.viscosity / cfg.rho0, cfg.cfl, cfg.viscous_cfl,
                             cfg.force_cfl};
    const TimeStepLimits l = particle_time_step(prm, cfg.sound_speed, vmax, std::sqrt(g));
    info.dt_acoustic = l.acoustic;
    info.dt_viscous = l.viscous;
    info.dt_force = l.force;
    info.dt_estimate = cfg.fixed_dt ? *cfg.fixed_dt : l.min();
    info.cells = 1;
    for (int d = 0; d < cfg.dimension; ++d) {
        const double wall = cfg.walls == WallModel::dummy ? layers * cfg.dx : 0.0;
        const double extent = cfg.periodic[d]
                                  ? cfg.domain_hi[d] - cfg.domain_lo[d]
                                  : std::max(cfg.domain_hi[d], cfg.tank_hi[d] + wall) -
                                        std::min(cfg.domain_lo[d], cfg.tank_lo[d] - wall) +
                                        2 * info.support;
        info.cells *= static_cast<std::size_t>(std::max(1.0, std::floor(extent / info.support)));
    }

    auto& ph = info.physics;
    ph.push_back(fmt::format("kernel: {}, h = {:.4g} m ({} dx)", kernel_name(cfg.kernel), info.h,
                             cfg.h_over_dx));
    if (cfg.density == DensityScheme::summation)
        ph.push_back("density: summation");
    else
        ph.push_back(cfg.delta_sph > 0 ? fmt::format("density: continuity + delta-SPH (delta = {})",
                                                     cfg.delta_sph)
                                       : std::string("density: continuity"));
    ph.push_back(
        cfg.eos == EosType::linear
            ? fmt::format("EOS: linear, c0 = {} m/s", cfg.sound_speed)
            : fmt::format("EOS: Tait (gamma = {}), c0 = {} m/s", cfg.gamma, cfg.sound_speed));
    if (cfg.background_pressure != 0)
        ph.push_back(fmt::format("background pressure: {} Pa", cfg.background_pressure));
    if (cfg.viscosity > 0)
        ph.push_back(fmt::format("laminar viscosity (Morris): mu = {} Pa s", cfg.viscosity));
    if (cfg.artificial_viscosity > 0)
        ph.push_back(
            fmt::format("artificial viscosity (Monaghan): alpha = {}", cfg.artificial_viscosity));
    if (g > 0)
        ph.push_back(fmt::format("body force: |g| = {:.4g} m/s^2", std::sqrt(g)));
    if (cfg.walls == WallModel::dummy)
        ph.push_back(fmt::format("walls: dummy particles (Adami 2012), {} layers, {}", layers,
                                 cfg.no_slip ? "no-slip" : "free-slip"));
    else if (cfg.walls == WallModel::reflective)
        ph.push_back(fmt::format("walls: reflective planes, restitution {}", cfg.restitution));
    std::string periodic;
    for (int d = 0; d < cfg.dimension; ++d)
        if (cfg.periodic[d])
            periodic += "xyz"[d];
    if (!periodic.empty())
        ph.push_back("periodic along: " + periodic);
    ph.push_back(cfg.fixed_dt ? fmt::format("time step: fixed {:.4g} s", *cfg.fixed_dt)
                              : std::string("time step: adaptive (CFL, viscous, force limits)"));
    return info;
}

RunResult run_case(const CaseConfig& cfg, const RunOptions& opts) {
    const int threads = opts.threads > 0 ? opts.threads : tbb::info::default_concurrency();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads));
    if (cfg.dimension == 2)
        return run_impl<2>(cfg, opts, threads);
    return run_impl<3>(cfg, opts, threads);
}

} // namespace sluice
