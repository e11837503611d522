// run_case / describe_case: the driver loop around a Simulation (output cadence, probes,
// progress, summary). No physics here.
#include "sluice/solver/run.hpp"

#include "sluice/core/neighbour_census.hpp"
#include "sluice/io/checkpoint.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/io/progress.hpp"
#include "sluice/io/run_log.hpp"
#include "sluice/io/snapshot_writer.hpp"
#include "sluice/solver/simulation.hpp"
#include "sluice/tasks/step_graph.hpp"

#include "memory_use.hpp"
#include "run_outputs.hpp"
#include "run_report.hpp"
#include "run_requests.hpp"
#include "run_totals.hpp"
#include "spacing_census.hpp"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <optional>

namespace sluice {

namespace {

// The results folder a restart continues must still hold what the checkpoint says was written
// (every rank checks, so all refuse together).
void check_restart_folder(const CaseConfig& cfg, const std::string& out_dir,
                          const OutputState& out) {
    namespace fs = std::filesystem;
    const std::string ckpt = checkpoint_path(out_dir);
    if (out.probe_next.size() != cfg.probes.size())
        throw CaseError(ckpt, "",
                        fmt::format("cannot continue: it records {} probes, the case has {}",
                                    out.probe_next.size(), cfg.probes.size()));
    if (cfg.snapshots)
        for (std::size_t k = 0; k < out.snapshot_time.size(); ++k) {
            const fs::path snap = fs::path(out_dir) / SnapshotWriter<2>::relative_path(k);
            if (!fs::is_regular_file(snap))
                throw CaseError(ckpt, "",
                                fmt::format("cannot continue: snapshot {} of the run it records "
                                            "is missing",
                                            snap.string()));
        }
    for (std::size_t k = 0; k < cfg.probes.size(); ++k) {
        const fs::path csv = fs::path(out_dir) / "probes" / (cfg.probes[k].name + ".csv");
        std::error_code ec;
        const auto size = fs::file_size(csv, ec);
        if (ec || size < out.probe_bytes[k])
            throw CaseError(ckpt, "",
                            fmt::format("cannot continue: probe file {} is missing or shorter "
                                        "than when the checkpoint was written",
                                        csv.string()));
    }
}

// The projection scheme's pressure-solve totals, and SOR's dropped relaxation, in the log.
template <int D>
void log_solver_totals(const Simulation<D>& sim, RunLog& log) {
    const PressureSolveTotals* pt = sim.pressure_solve_totals();
    if (pt == nullptr)
        return;
    if (pt->solves > 0)
        log.info("pressure solves: {} steps, {:.1f} iterations per step on average, at most {}; "
                 "largest final relative residual {:.3e}; {:.3f} s in the solver",
                 pt->solves, static_cast<double>(pt->iterations) / static_cast<double>(pt->solves),
                 pt->max_iterations, pt->max_residual, pt->seconds);
    if (pt->relaxation_dropped > 0)
        log.warn("SOR: the over-relaxed sweep diverged in {} of {} solves, which went on with "
                 "relaxation 1 (docs/PROJECTION.md, \"SOR\"); a smaller projection.relaxation "
                 "avoids the wasted sweeps",
                 pt->relaxation_dropped, pt->solves);
}

// "N fluid particle(s) left the domain and was/were removed": the per-step and the run's line.
std::string left_and_removed(std::int64_t n) {
    return fmt::format("{} fluid particle{} left the domain and {} removed", n, n == 1 ? "" : "s",
                       n == 1 ? "was" : "were");
}

// The fluid's spacing at the end of a run, in the log: a warning where it is crowded.
void log_end_spacing(const NeighbourCensus& census, Real dx, RunLog& log) {
    const std::string spacing =
        fmt::format("fluid spacing at the end: {}", spacing_sentence(census, dx));
    if (crowded_warning(census))
        log.warn("{} (docs/IMPACT_LOADS.md, \"Particle spacing\")", spacing);
    else
        log.info("{}", spacing);
}

// domain.particle_exit = "remove": the particles the last step removed, in the log (the first
// removal on the console too). A run whose fluid has all left stops: nothing is left to run.
template <int D>
void report_removed(const Simulation<D>& sim, std::uint64_t fluid_at_start,
                    std::int64_t removed_before, RunLog& log) {
    const std::int64_t n = sim.removed_last_step();
    if (n == 0)
        return;
    const std::int64_t total = sim.removed_particles();
    const std::string line = fmt::format("step {}, t = {:.6g} s: {} ({} in the run)", sim.steps(),
                                         sim.time(), left_and_removed(n), total);
    if (total - removed_before == n)
        log.warn("{} (domain.particle_exit = \"remove\"; later removals go to the log file "
                 "only)",
                 line);
    else
        log.file_only(line);
    if (static_cast<std::uint64_t>(total - removed_before) >= fluid_at_start)
        throw RunError(fmt::format("every fluid particle has left the domain by step {}, t = "
                                   "{:.6g} s (domain.particle_exit = \"remove\"): nothing is "
                                   "left to simulate",
                                   sim.steps(), sim.time()));
}

template <int D>
RunResult run_impl(const CaseConfig& cfg, const RunOptions& opts, int threads) {
    using Clock = std::chrono::steady_clock;
    SimulationOptions so;
    so.threads = threads;
    so.trace = !opts.trace_path.empty();
    so.log_rebalances = !opts.quiet;
    so.debug_fail_rank = opts.debug_fail_rank;
    so.debug_fail_step = opts.debug_fail_step;
    // A restart: every rank reads the checkpoint's header and an even share of its particles
    // (collective); the Simulation sends the shares to the ranks that own them.
    const bool resumed = !opts.restart_dir.empty();
    std::optional<Checkpoint<D>> resume;
    if (resumed) {
        resume = read_checkpoint<D>(checkpoint_path(opts.restart_dir), cfg.fingerprint);
        check_restart_folder(cfg, opts.out_dir, resume->output);
    }
    // Refuses an unrunnable case before anything is written.
    Simulation<D> sim(cfg, so, resume ? &*resume : nullptr);
    const bool root = sim.comm().rank() == 0;
    const OutputState start = resume ? resume->output : OutputState{};
    const long start_step = sim.steps();
    resume.reset();

    LogOptions lo;
    lo.dir = (std::filesystem::path(opts.out_dir) / "logs").string();
    lo.rank = sim.comm().rank();
    lo.console = root;
    lo.quiet = opts.quiet;
    lo.verbose = opts.verbose;
    RunLog log(lo);
    log.info("case {} ({}): rank {} of {}, {} worker threads, {} particles on this rank, "
             "results in {}",
             cfg.name, cfg.source_file, sim.comm().rank(), sim.comm().size(), threads, sim.owned(),
             opts.out_dir);
    // Peak resident memory of this rank at three points (perf/memory reads these lines).
    const auto log_memory = [&log](const char* when) {
        const ResidentMemory m = resident_memory();
        log.file_only(fmt::format("memory: peak resident {:.1f} MiB {} (resident now {:.1f} MiB)",
                                  static_cast<double>(m.peak) / (1 << 20), when,
                                  static_cast<double>(m.now) / (1 << 20)));
    };
    log_memory("after the initial state");

    RunOutputs<D> outputs(cfg, opts.out_dir, resumed ? &start : nullptr, sim.time(), root, log);

    RunResult result;
    // Neighbour pairs by kind at the start and the end (outside the timed loop, without a
    // gather: run_totals.hpp): the benchmarks turn them into achieved interactions per second
    // per stage.
    RunFigures figures;
    figures.support = sim.kernel_support();
    figures.crowded = crowded_below(cfg.dx);
    figures.start_step = start_step;
    figures.resumed = resumed;
    figures.earlier_wall_seconds = start.wall_seconds;
    figures.threads = threads;
    // The initial state's probes and snapshot, before the totals: the snapshot's spacing
    // census is the one the totals want (not taken twice), and the time loop's wall time
    // starts after it, as it starts after the rest of the start-up.
    outputs.sample(sim, false);
    const RunTotals at_start =
        run_totals<D>(sim, figures.support, figures.crowded, outputs.spacing_at(sim.steps()));
    result.particles = at_start.particles;
    result.fluid_particles = at_start.fluid;
    result.mass_initial = at_start.mass;
    figures.census_start = at_start.census;
    log_memory("after start-up");
    const std::uint64_t total_particles = result.particles;
    const std::int64_t removed_before = sim.removed_particles(); // by earlier segments
    double particle_steps = 0;

    // Wall time of this segment's time loop so far; earlier segments' is start.wall_seconds
    // (from the checkpoint), so summary.json can report the whole run's.
    Clock::time_point t0;
    const auto loop_seconds = [&t0] {
        return std::chrono::duration<double>(Clock::now() - t0).count();
    };

    Progress progress(cfg.end_time, opts.quiet || !root, opts.verbose);
    progress.log_to([&log](const std::string& line) { log.file_only(line); });
    // One origin for the task clock of every rank: each rank's origin was its own first use of
    // the clock (tens of ms apart), so a trace could not lay the ranks' tasks side by side
    // (perf/strong_scaling/between_steps.py compared durations only). Rank 0's, broadcast
    // after a barrier, so that on one node a message's post and completion compare exactly
    // (perf/strong_scaling/critical_path.py).
    sim.comm().barrier();
    tasks::share_clock_origin(sim.comm());
    t0 = Clock::now();
    RunRequests requests(opts.out_dir, cfg.checkpoint_every_minutes, root);
    while (sim.time() < cfg.end_time * (1 - 1e-12)) {
        // Requests go into the next step's reduction, so every rank acts on them together.
        sim.post_request(requests.pending());
        // Whether the loop below reads nothing of the state after this step and another step
        // follows: then the next step's graph may start while this step's agreement travels
        // (the agreed requests, which only the agreement knows, make it stop and run the
        // step again). Every rank decides the same.
        {
            const double t_next = sim.next_time();
            const bool last = !(t_next < cfg.end_time * (1 - 1e-12));
            const bool checkpoint = cfg.checkpoint_every_steps > 0 &&
                                    (sim.steps() + 1) % cfg.checkpoint_every_steps == 0;
            sim.allow_run_ahead(cfg.run_ahead && !last && !checkpoint && outputs.quiet_at(t_next));
        }
        // Particle-steps of this segment, with the particles each step started with:
        // domain.particle_exit = "remove" lowers the count during the run.
        particle_steps += static_cast<double>(
            total_particles - static_cast<std::uint64_t>(sim.removed_particles() - removed_before));
        try {
            sim.step();
            report_removed(sim, at_start.fluid, removed_before, log);
        } catch (const RunError& e) {
            // Every rank got the error from the same step; the state is the last good one
            // (the failing step never swapped its buffers in).
            const std::string where = outputs.last_snapshot(sim, "last good state");
            // Crowded particles are where violent runs blow up (docs/IMPACT_LOADS.md,
            // "Particle spacing"): the last good state's spacing goes with the message.
            const std::string spacing = fmt::format(
                "; at the last good state {}", spacing_sentence(outputs.last_spacing(), cfg.dx));
            progress.finish();
            log.file_only(fmt::format("the run failed: {}{}{}", e.what(), where, spacing));
            throw RunError(std::string(e.what()) + where + spacing);
        } catch (const InternalError& e) {
            const std::string where = outputs.last_snapshot(sim, "state before the failing step");
            progress.finish();
            throw InternalError(std::string(e.what()) + where);
        }
        if (const PressureSolveRecord* ps = sim.last_pressure_solve())
            log.debug(
                "step {}: pressure solve {} iterations, relative residual {:.3e}, {:.2f} ms{}",
                sim.steps(), ps->iterations, ps->residual, ps->seconds * 1e3,
                ps->free_level
                    ? fmt::format(", no free surface: source shift {:.3e} Pa", ps->source_shift)
                    : std::string());
        const double wall = loop_seconds();
        progress.update(sim.steps(), sim.time(), sim.dt(), particle_steps / wall);
        outputs.sample(sim, false);
        const unsigned agreed = sim.agreed_requests();
        const bool stop = (agreed & request_stop) != 0;
        if (stop || (agreed & request_checkpoint) != 0 ||
            (cfg.checkpoint_every_steps > 0 && sim.steps() % cfg.checkpoint_every_steps == 0)) {
            outputs.write_checkpoint(sim, start.wall_seconds + loop_seconds());
            requests.checkpoint_written();
        }
        if (stop) {
            progress.finish();
            if (root) {
                requests.remove_stop_file();
                result.stop_reason = requests.stop_reason();
            }
            result.stopped = true;
            result.steps = sim.steps();
            result.simulated_time = sim.time();
            result.wall_seconds = loop_seconds();
            result.checkpoint = outputs.checkpoint_file();
            return result;
        }
    }
    outputs.finish(sim);
    progress.finish();

    result.wall_seconds = loop_seconds();
    result.steps = sim.steps();
    result.simulated_time = sim.time();
    result.particle_steps_per_second = particle_steps / result.wall_seconds;
    log_memory("after the time loop");
    const RunTotals at_end =
        run_totals<D>(sim, figures.support, figures.crowded, outputs.spacing_at(sim.steps()));
    result.mass_final = at_end.mass;
    result.fluid_removed = sim.removed_particles();
    if (result.fluid_removed > 0)
        log.info("{} over the run (domain.particle_exit = \"remove\"; summary.json: "
                 "fluid_particles_removed, and their mass is missing from mass_final)",
                 left_and_removed(result.fluid_removed));
    figures.census_end = at_end.census;
    log_end_spacing(at_end.census, cfg.dx, log);
    log_memory("at the end");
    if (!opts.trace_path.empty())
        sim.write_trace(opts.trace_path);
    log_solver_totals(sim, log);
    log.info("done: {} steps to t = {:.6g} s in {:.2f} s wall, {:.3g} particle-steps/s, {} "
             "decompositions, {} rebalances",
             result.steps, result.simulated_time, result.wall_seconds,
             result.particle_steps_per_second, sim.decompositions(), sim.rebalances().size());
    write_run_summary(sim, cfg, opts.out_dir, opts.quiet, result, figures);
    return result;
}

} // namespace

RunResult run_case(const CaseConfig& cfg, const RunOptions& opts) {
    const int threads = opts.threads > 0 ? opts.threads : tbb::info::default_concurrency();
    // On several ranks the main thread drives MPI: the arena has one slot more than workers.
    const bool parallel = tasks::Comm::world().parallel();
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                              static_cast<std::size_t>(threads + (parallel ? 1 : 0)));
    if (cfg.dimension == 2)
        return run_impl<2>(cfg, opts, threads);
    return run_impl<3>(cfg, opts, threads);
}

} // namespace sluice
