// run_case / describe_case: the driver loop around a Simulation (output cadence, probes,
// progress, summary). No physics here.
#include "sluice/solver/run.hpp"

#include "sluice/core/neighbour_census.hpp"
#include "sluice/io/checkpoint.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/io/probe_writer.hpp"
#include "sluice/io/progress.hpp"
#include "sluice/io/run_log.hpp"
#include "sluice/io/snapshot_writer.hpp"
#include "sluice/io/summary.hpp"
#include "sluice/solver/output_schedule.hpp"
#include "sluice/solver/simulation.hpp"

#include "memory_use.hpp"
#include "probe_sampling.hpp"
#include "run_report.hpp"
#include "run_totals.hpp"
#include "stop_signals.hpp"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <nlohmann/json.hpp>
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

template <int D>
RunResult run_impl(const CaseConfig& cfg, const RunOptions& opts, int threads) {
    namespace fs = std::filesystem;
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

    const fs::path stop_file = fs::path(opts.out_dir) / "stop";
    const std::string checkpoint_file = checkpoint_path(opts.out_dir);
    LogOptions lo;
    lo.dir = (fs::path(opts.out_dir) / "logs").string();
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

    std::unique_ptr<SnapshotWriter<D>> snapshots;
    std::unique_ptr<ProbeWriter> probe_files;
    if (root) {
        fs::create_directories(opts.out_dir);
        fs::remove(fs::path(opts.out_dir) / "summary.json"); // an old summary would look complete
        fs::remove(stop_file);                               // it stopped an earlier run
        if (!resumed)
            fs::remove(checkpoint_file); // an earlier run's: its snapshots are going
        discard_partial_checkpoint(checkpoint_file);
    }
    // Every rank writes its slice of each snapshot (rank 0 alone touches the folder).
    if (cfg.snapshots) {
        std::vector<typename SnapshotWriter<D>::Earlier> earlier;
        for (std::size_t k = 0; k < start.snapshot_time.size(); ++k)
            earlier.push_back({start.snapshot_time[k], start.snapshot_particles[k]});
        snapshots = resumed ? std::make_unique<SnapshotWriter<D>>(opts.out_dir, cfg.fields, earlier)
                            : std::make_unique<SnapshotWriter<D>>(opts.out_dir, cfg.fields);
    }
    if (root) {
        probe_files =
            resumed ? std::make_unique<ProbeWriter>(opts.out_dir, cfg.probes, start.probe_bytes)
                    : std::make_unique<ProbeWriter>(opts.out_dir, cfg.probes, D);
    }

    OutputSchedule schedule(cfg);
    if (resumed)
        schedule.resume(start, sim.time());
    // Every rank takes the same decisions (same time). The probes are evaluated where the
    // particles are (probe_sampling.hpp); each rank writes its own particles into a snapshot.
    auto sample = [&](bool force) {
        const double t = sim.time();
        const OutputSchedule::Due due = schedule.due(t, force);
        if (!due.probes.empty()) {
            const auto rows = sample_probes(sim, due.probes);
            if (root)
                for (std::size_t n = 0; n < due.probes.size(); ++n)
                    probe_files->write(due.probes[n], t, rows[n]);
        }
        if (due.snapshot) {
            const std::string file = snapshots->write(sim.particles(), sim.owned(), t, sim.steps());
            if (root)
                log.debug("snapshot {} at t = {:.6g} s (step {})", file, t, sim.steps());
        }
        schedule.done(due, t);
    };

    RunResult result;
    // Neighbour pairs by kind at the start and the end (outside the timed loop, without a
    // gather: run_totals.hpp): the benchmarks turn them into achieved interactions per second
    // per stage.
    const Real support = std::visit([](const auto& k) { return k.support(); }, sim.kernel());
    const RunTotals at_start = run_totals<D>(sim, support);
    result.particles = at_start.particles;
    result.fluid_particles = at_start.fluid;
    result.mass_initial = at_start.mass;
    const NeighbourCensus census_start = at_start.census;
    log_memory("after start-up");
    const std::uint64_t total_particles = result.particles;

    // Wall time of this segment's time loop so far; earlier segments' is start.wall_seconds
    // (from the checkpoint), so summary.json can report the whole run's.
    Clock::time_point t0;
    const auto loop_seconds = [&t0] {
        return std::chrono::duration<double>(Clock::now() - t0).count();
    };

    // Collective: every rank writes its particles; the rest is rank 0's.
    auto write_checkpoint_now = [&] {
        CheckpointHeader c;
        if (!root) {
            write_checkpoint<D>(checkpoint_file, c, sim.particles(), sim.owned());
            return;
        }
        c.case_fingerprint = cfg.fingerprint;
        c.ranks = sim.comm().size();
        c.solver = sim.solver_state();
        c.output.out_next = schedule.out_next();
        c.output.last_output_time = schedule.last_output_time();
        c.output.wall_seconds = start.wall_seconds + loop_seconds();
        c.output.probe_next = schedule.probe_next();
        c.output.probe_bytes = probe_files->bytes();
        if (snapshots)
            for (const auto& w : snapshots->written()) {
                c.output.snapshot_time.push_back(w.time);
                c.output.snapshot_particles.push_back(w.particles);
            }
        write_checkpoint<D>(checkpoint_file, c, sim.particles(), sim.owned());
    };
    // After a failed step every rank holds the state before it: write it for inspection
    // (collective: every rank gets the error from the same step).
    auto last_snapshot = [&](const std::string& label) {
        if (!snapshots) // snapshots are off: this one is written all the same
            snapshots = std::make_unique<SnapshotWriter<D>>(opts.out_dir, cfg.fields);
        const std::string file =
            snapshots->write(sim.particles(), sim.owned(), sim.time(), sim.steps());
        return root ? fmt::format(", {} in {}", label, file) : std::string();
    };

    Progress progress(cfg.end_time, opts.quiet || !root, opts.verbose);
    progress.log_to([&log](const std::string& line) { log.file_only(line); });
    t0 = Clock::now();
    const StopSignals signals;
    auto last_checkpoint = Clock::now(), last_stop_check = Clock::now();
    bool stop_file_seen = false;
    sample(false);
    while (sim.time() < cfg.end_time * (1 - 1e-12)) {
        // Requests go into the next step's reduction, so every rank acts on them together.
        if (StopSignals::received() != 0)
            sim.post_request(request_stop);
        if (root) {
            const auto now = Clock::now();
            if (now - last_stop_check >= std::chrono::milliseconds(200)) { // few stat calls
                last_stop_check = now;
                stop_file_seen = fs::exists(stop_file);
            }
            if (stop_file_seen)
                sim.post_request(request_stop);
            if (cfg.checkpoint_every_minutes > 0 &&
                std::chrono::duration<double>(now - last_checkpoint).count() >=
                    60 * cfg.checkpoint_every_minutes)
                sim.post_request(request_checkpoint);
        }
        try {
            sim.step();
        } catch (const RunError& e) {
            // Every rank got the error from the same step; the state is the last good one
            // (the failing step never swapped its buffers in).
            const std::string where = last_snapshot("last good state");
            progress.finish();
            log.file_only(fmt::format("the run failed: {}{}", e.what(), where));
            throw RunError(std::string(e.what()) + where);
        } catch (const InternalError& e) {
            const std::string where = last_snapshot("state before the failing step");
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
        progress.update(sim.steps(), sim.time(), sim.dt(),
                        static_cast<double>(total_particles) *
                            static_cast<double>(sim.steps() - start_step) / wall);
        sample(false);
        const unsigned requests = sim.agreed_requests();
        const bool stop = (requests & request_stop) != 0;
        if (stop || (requests & request_checkpoint) != 0 ||
            (cfg.checkpoint_every_steps > 0 && sim.steps() % cfg.checkpoint_every_steps == 0)) {
            write_checkpoint_now();
            last_checkpoint = Clock::now();
        }
        if (stop) {
            progress.finish();
            if (root) {
                fs::remove(stop_file);
                const char* why = StopSignals::received() == SIGTERM  ? "SIGTERM"
                                  : StopSignals::received() == SIGINT ? "SIGINT"
                                  : stop_file_seen                    ? "the stop file"
                                                                      : "a signal to another rank";
                result.stop_reason = why;
            }
            result.stopped = true;
            result.steps = sim.steps();
            result.simulated_time = sim.time();
            result.wall_seconds = loop_seconds();
            result.checkpoint = checkpoint_file;
            return result;
        }
    }
    if (sim.time() != schedule.last_output_time())
        sample(true);
    progress.finish();

    result.wall_seconds = loop_seconds();
    result.steps = sim.steps();
    result.simulated_time = sim.time();
    result.particle_steps_per_second = static_cast<double>(total_particles) *
                                       static_cast<double>(result.steps - start_step) /
                                       result.wall_seconds;
    log_memory("after the time loop");
    const RunTotals at_end = run_totals<D>(sim, support);
    result.mass_final = at_end.mass;
    const NeighbourCensus census_end = at_end.census;
    log_memory("at the end");
    if (!opts.trace_path.empty())
        sim.write_trace(opts.trace_path);
    if (const PressureSolveTotals* pt = sim.pressure_solve_totals(); pt && pt->solves > 0)
        log.info("pressure solves: {} steps, {:.1f} iterations per step on average, at most {}; "
                 "largest final relative residual {:.3e}; {:.3f} s in the solver",
                 pt->solves, static_cast<double>(pt->iterations) / static_cast<double>(pt->solves),
                 pt->max_iterations, pt->max_residual, pt->seconds);
    if (const PressureSolveTotals* pt = sim.pressure_solve_totals();
        pt && pt->relaxation_dropped > 0)
        log.warn("SOR: the over-relaxed sweep diverged in {} of {} solves, which went on with "
                 "relaxation 1 (docs/PROJECTION.md, \"SOR\"); a smaller projection.relaxation "
                 "avoids the wasted sweeps",
                 pt->relaxation_dropped, pt->solves);
    log.info("done: {} steps to t = {:.6g} s in {:.2f} s wall, {:.3g} particle-steps/s, {} "
             "decompositions, {} rebalances",
             result.steps, result.simulated_time, result.wall_seconds,
             result.particle_steps_per_second, sim.decompositions(), sim.rebalances().size());

    // Per-rank profile to rank 0.
    const auto mine = profile_numbers(sim);
    const auto gathered = sim.comm().gather(std::span<const std::byte>(
        reinterpret_cast<const std::byte*>(mine.data()), mine.size() * sizeof(double)));
    const double rebin_seconds = sim.rebin_seconds_total(); // rank 0's
    if (!root)
        return result;

    std::vector<std::vector<double>> per_rank;
    for (const auto& b : gathered) {
        std::vector<double> v(b.size() / sizeof(double));
        std::memcpy(v.data(), b.data(), b.size());
        per_rank.push_back(std::move(v));
    }
    const auto names = sim.stage_names();
    const nlohmann::json parallel =
        parallel_report(names, per_rank, !opts.quiet && sim.comm().parallel());

    nlohmann::json extra;
    const auto& graph = sim.graph();
    extra["stage_busy_seconds"] = parallel["total"]["stage_busy_seconds"];
    extra["rebin_seconds"] = rebin_seconds;
    extra["cell_groups"] = graph.group_count();
    extra["decompositions"] = sim.decompositions();
    extra["list_rebuilds"] = sim.list_rebuilds();
    extra["last_dt"] = sim.dt();
    if (resumed)
        extra["restarted_from_step"] = start_step;
    // wall_seconds covers this segment; this, every segment since step 0.
    extra["wall_seconds_all_segments"] = start.wall_seconds + result.wall_seconds;
    extra["parallel"] = parallel;
    extra["neighbours"] = {{"support", support},
                           {"start", census_json(census_start)},
                           {"end", census_json(census_end)}};
    nlohmann::json rebal = nlohmann::json::array();
    for (const auto& r : sim.rebalances())
        rebal.push_back({{"step", r.step},
                         {"imbalance_before", r.imbalance_before},
                         {"predicted_after", r.predicted_after},
                         {"particles_moved", r.particles_moved},
                         {"seconds", r.seconds},
                         {"at_rebuild", r.at_rebuild}});
    extra["rebalances"] = rebal;
    nlohmann::json hist = nlohmann::json::array();
    for (const auto& h : sim.balance_history())
        hist.push_back({{"step", h.step}, {"imbalance", h.imbalance}});
    extra["imbalance_history"] = hist;
    write_summary(opts.out_dir, cfg, result, threads, sim.comm().size(), extra);
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
