// The `sluice` command line: run a case, describe a case, check a case, print the case schema.
// Exit codes: 0 success, 1 unexpected failure, 2 bad case file, bad command line or a
// checkpoint that cannot continue the case, 3 the run failed physically (RunError),
// 4 stopped on request (SIGTERM/SIGINT or a stop file) after writing a checkpoint.
#include "sluice/core/types.hpp"
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/io/memory_estimate.hpp"
#include "sluice/solver/case_check.hpp"
#include "sluice/solver/case_memory.hpp"
#include "sluice/solver/run.hpp"
#include "sluice/tasks/comm.hpp"
#include "sluice/version.hpp"

#define TBB_PREVIEW_WAITING_FOR_WORKERS 1
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

constexpr int kExitFailure = 1, kExitCaseError = 2, kExitRunError = 3, kExitStopped = 4;

enum class Command { run, info, check };

// Started by mpirun/mpiexec (Open MPI, or a PMI launcher such as srun)?
bool launched_by_mpi() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (std::getenv(v) != nullptr)
            return true;
    return false;
}

std::string version_string() {
    const std::string rev = sluice::git_revision;
    return fmt::format("sluice {} ({}{})", sluice::version, rev.empty() ? "unknown revision" : rev,
                       sluice::single_precision ? ", single precision" : "");
}

using sluice::human_bytes;

// The memory estimate per rank by term (sluice/io/memory_estimate.hpp).
void print_memory(const sluice::MemoryEstimate& m, const sluice::MemoryLimit& limit) {
    fmt::print("memory      ~{} per rank on {} rank{}{}; limit {} ({})\n", human_bytes(m.total()),
               m.ranks, m.ranks == 1 ? "" : "s", m.ranks == 1 ? "" : " (the busiest rank)",
               human_bytes(limit.bytes), limit.source);
    fmt::print("  process   {} (libraries, MPI, TBB and HDF5 runtimes)\n", human_bytes(m.baseline));
    fmt::print(
        "  particles {} ({:.0f} per rank, {:.0f} of them fluid: state, neighbour lists, sort "
        "buffers)\n",
        human_bytes(m.particles), m.particles_per_rank, m.fluid_per_rank);
    if (m.ranks > 1) {
        fmt::print("  halo      {} ({:.0f} copies of other ranks' particles)\n",
                   human_bytes(m.halo), m.halo_particles);
        fmt::print("  totals    {} (rank 0 only: every fluid particle's id and mass)\n",
                   human_bytes(m.totals));
    }
    fmt::print("  grid      {} (the cells this rank's particles and halo copies occupy)\n",
               human_bytes(m.grid));
}

void print_info(const sluice::CaseConfig& cfg, const sluice::CaseInfo& info,
                const sluice::MemoryLimit& limit) {
    fmt::print("case        {}  ({})\n", cfg.name, cfg.source_file);
    if (!cfg.description.empty())
        fmt::print("            {}\n", cfg.description);
    fmt::print("dimension   {}-D\n", cfg.dimension);
    fmt::print("particles   {} fluid + {} wall = {}\n", info.fluid_particles, info.wall_particles,
               info.fluid_particles + info.wall_particles);
    print_memory(info.memory, limit);
    fmt::print("h           {:.6g} m  (dx = {:.6g} m, h/dx = {:.6g})\n", info.h, cfg.dx,
               cfg.h_over_dx);
    fmt::print("support     {:.6g} m (kernel: see physics)\n", info.support);
    if (cfg.fixed_dt)
        fmt::print("dt          {:.4g} s fixed  (stable estimate {:.4g} s)\n", *cfg.fixed_dt,
                   info.dt_stable);
    else
        fmt::print("dt          {:.4g} s  (~{:.0f} steps to t = {:.6g} s)\n", info.dt_estimate,
                   info.dt_estimate > 0 ? cfg.end_time / info.dt_estimate : 0.0, cfg.end_time);
    fmt::print("  limits    acoustic {:.4g} s, viscous {:.4g} s, body force {:.4g} s\n",
               info.dt_acoustic, info.dt_viscous, info.dt_force);
    fmt::print("cells       {}\n", info.cells);
    fmt::print("physics\n");
    for (const auto& p : info.physics)
        fmt::print("  - {}\n", p);
    fmt::print("geometry    as built (wall surface: its fluid-side layer -/+ dx/2)\n");
    for (const auto& g : info.geometry)
        fmt::print("  - {}\n", g);
}

// Adds the case file argument and --set, shared by `run` and `info`.
void add_case_options(CLI::App* cmd, std::string& case_path, std::vector<std::string>& sets) {
    cmd->add_option("case", case_path, "Case file (TOML, see docs/CASE_REFERENCE.md)")->required();
    // One key=value per --set, so a following positional is never swallowed.
    cmd->add_option("--set", sets,
                    "Override a case value, e.g. --set numerics.kernel=wendland_c2 "
                    "(repeatable)")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
}

} // namespace

void print_warnings(const std::vector<sluice::CaseWarning>& warnings) {
    for (const auto& w : warnings)
        fmt::print(stderr, "sluice: warning: key '{}': {}\n", w.key, w.message);
}

namespace fs = std::filesystem;

// Why nothing can be written into the folder `dir`, or empty: creates and removes a probe
// file in it (permission bits alone do not tell, e.g. for root or on /proc).
std::string folder_unwritable(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        return fmt::format("'{}' is not a folder", dir.string());
    const fs::path probe = dir / fmt::format(".sluice-write-check-{}", ::getpid());
    std::FILE* f = std::fopen(probe.c_str(), "wx");
    if (f == nullptr)
        return fmt::format("'{}' is not writable ({})", dir.string(), std::strerror(errno));
    std::fclose(f);
    fs::remove(probe, ec);
    return {};
}

// Why the results folder `out` cannot be created or written, or empty. Creates nothing: the
// nearest existing folder on its path must be writable.
std::string out_dir_problem(const std::string& out) {
    std::error_code ec;
    fs::path p = fs::absolute(out, ec).lexically_normal();
    if (ec)
        return ec.message();
    if (!p.has_filename()) // "dir/": the folder itself
        p = p.parent_path();
    fs::path q = p;
    // status() reports "not found" for a missing entry and for a path under a regular file.
    while (fs::status(q, ec).type() == fs::file_type::not_found && q.has_relative_path())
        q = q.parent_path();
    if (q != p && !fs::is_directory(q, ec))
        return fmt::format("'{}' is not a folder", q.string());
    return folder_unwritable(q);
}

// Why the --trace file `trace` cannot be written, or empty. The trace is written at the end of
// the run (as trace + ".tmp", renamed), into its folder or into the results folder `out`
// that the run creates; an existing trace file is left as it is here.
std::string trace_problem(const std::string& trace, const std::string& out) {
    std::error_code ec;
    const fs::path t = fs::absolute(trace, ec).lexically_normal();
    if (ec)
        return ec.message();
    if (!t.has_filename() || fs::is_directory(t, ec))
        return "it is a folder, not a file";
    const fs::path dir = t.parent_path();
    const fs::path out_abs = fs::absolute(out, ec).lexically_normal();
    if (dir == out_abs || (!out_abs.has_filename() && dir == out_abs.parent_path()))
        return out_dir_problem(out); // the run creates it; refused under --out if not
    return folder_unwritable(dir);
}

// Refuses (CaseError, exit code 2) a results folder or trace file that the run could not
// write, before anything is run or written. Rank 0 writes them, so rank 0 decides and every
// rank learns the verdict (collective: every rank calls it at the same point).
void check_outputs(const sluice::tasks::Comm& world, const sluice::RunOptions& opts) {
    std::string option, problem;
    if (world.rank() == 0) {
        if (problem = out_dir_problem(opts.out_dir); !problem.empty())
            option = fmt::format("option --{} '{}'", opts.restart_dir.empty() ? "out" : "restart",
                                 opts.out_dir);
        else if (!opts.trace_path.empty()) {
            if (problem = trace_problem(opts.trace_path, opts.out_dir); !problem.empty())
                option = fmt::format("option --trace '{}'", opts.trace_path);
        }
    }
    if (world.parallel()) {
        option = world.broadcast(option, 0);
        problem = world.broadcast(problem, 0);
    }
    if (!problem.empty())
        throw sluice::CaseError(option, "", "cannot be written: " + problem);
}

// What `sluice run` was given besides the case.
struct RunFlags {
    std::string out_dir, trace, restart;
    int threads = 0;
    bool quiet = false, verbose = false;
    int debug_fail_rank = -1;
    long debug_fail_step = -1;
    int ranks = 1;          // info/check: the ranks the memory estimate is for
    std::string max_memory; // --max-memory SIZE per rank (empty: this machine's memory)
};

// Ranks of this run on this machine, which share its memory (Open MPI, MPICH); 1 outside MPI.
int ranks_on_this_machine(const sluice::tasks::Comm& world) {
    for (const char* v : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
        if (const char* n = std::getenv(v); n != nullptr && std::atoi(n) > 0)
            return std::atoi(n);
    return world.parallel() ? world.size() : 1;
}

// The memory one rank may use: --max-memory, else this machine's share; rank 0's verdict for
// every rank (collective), so that machines of different sizes cannot split the ranks.
sluice::MemoryLimit rank_memory_limit(const sluice::tasks::Comm& world, const RunFlags& flags,
                                      int ranks_here) {
    const auto max_memory =
        flags.max_memory.empty() ? std::nullopt : sluice::parse_memory_size(flags.max_memory);
    sluice::MemoryLimit limit = sluice::memory_limit(max_memory, ranks_here);
    if (world.parallel()) {
        limit.bytes = std::stod(world.broadcast(fmt::format("{}", limit.bytes), 0));
        limit.source = world.broadcast(limit.source, 0);
    }
    return limit;
}

// Reads the case and runs, describes or checks it; returns the process exit code.
int execute(Command command, const std::string& case_path, const std::vector<std::string>& sets,
            const RunFlags& flags) {
    const sluice::tasks::Comm world = sluice::tasks::Comm::world();
    const bool root = world.rank() == 0;
    try {
        // Everything is validated here, before the solver creates the results folder.
        const sluice::CaseConfig cfg = sluice::read_case(case_path, sets);
        // The memory per rank: a run's own communicator, else --ranks. Checked once before the
        // particles are counted (a shaped block's count visits its lattice box), then exactly.
        const bool running = command == Command::run;
        const int ranks = running ? world.size() : flags.ranks;
        const sluice::MemoryLimit limit =
            rank_memory_limit(world, flags, running ? ranks_on_this_machine(world) : 1);
        sluice::check_memory(cfg, sluice::case_memory_before_counting(cfg, ranks), limit);
        const sluice::CaseInfo info = sluice::describe_case(cfg, ranks);
        sluice::check_memory(cfg, info.memory, limit);
        sluice::check_runnable(cfg, info);
        const auto warnings = sluice::case_warnings(cfg, info);
        if (command == Command::run) {
            if (!flags.quiet && root)
                print_warnings(warnings);
            sluice::RunOptions opts;
            // A restart continues in the folder it restarts from.
            opts.out_dir = !flags.restart.empty()  ? flags.restart
                           : flags.out_dir.empty() ? "results/" + cfg.name
                                                   : flags.out_dir;
            opts.threads = flags.threads;
            opts.quiet = flags.quiet;
            opts.verbose = flags.verbose;
            opts.trace_path = flags.trace;
            opts.restart_dir = flags.restart;
            opts.debug_fail_rank = flags.debug_fail_rank;
            opts.debug_fail_step = flags.debug_fail_step;
            check_outputs(world, opts);
            const sluice::RunResult result = sluice::run_case(cfg, opts);
            if (result.stopped) {
                if (root)
                    fmt::print(stderr,
                               "sluice: stopped by {} after step {}, t = {:.6g} s; checkpoint "
                               "written to {}\nsluice: continue with: sluice run {} --restart "
                               "{} (plus the same --set options)\n",
                               result.stop_reason, result.steps, result.simulated_time,
                               result.checkpoint, cfg.source_file, opts.out_dir);
                return kExitStopped;
            }
            if (!flags.quiet && !flags.verbose && root) // --verbose: the log said it already
                fmt::print(stderr,
                           "sluice: done: {} steps to t = {:.6g} s in {:.1f} s; results in {}\n",
                           result.steps, result.simulated_time, result.wall_seconds, opts.out_dir);
        } else if (root) {
            if (command == Command::info)
                print_info(cfg, info, limit);
            else
                fmt::print("{}: ok ({} particles, dt {:.4g} s)\n", case_path,
                           info.fluid_particles + info.wall_particles, info.dt_estimate);
            print_warnings(warnings);
        }
    } catch (const sluice::CaseError& e) {
        // Every rank reads the same case and refuses it the same way.
        if (root)
            fmt::print(stderr, "sluice: error: {}\n", e.what());
        return kExitCaseError;
    } catch (const sluice::RunError& e) {
        // Raised on every rank together (the failure is part of the step's reduction).
        if (root)
            fmt::print(stderr, "sluice: error: the run failed: {}\n", e.what());
        return kExitRunError;
    } catch (const sluice::InternalError& e) {
        // Also raised on every rank together: nobody is left waiting, no abort needed.
        if (root)
            fmt::print(stderr, "sluice: error: the run failed: {}\n", e.what());
        return kExitFailure;
    } catch (const std::exception& e) {
        fmt::print(stderr, "sluice: error: {}{}\n",
                   world.parallel() ? fmt::format("rank {}: ", world.rank()) : std::string(),
                   e.what());
        // Only this rank knows: take the others down instead of leaving them waiting.
        if (world.parallel())
            world.abort(kExitFailure);
        return kExitFailure;
    }
    return 0;
}

int main(int argc, char** argv) {
    CLI::App app{"sluice: particle (SPH) solver for free-surface flow", "sluice"};
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return fmt::format("sluice: error: {}\nRun with --help for more information.\n", e.what());
    });
    app.set_version_flag("--version", version_string());
    app.require_subcommand(1);

    std::string case_path;
    std::vector<std::string> sets;
    RunFlags flags;

    CLI::App* run = app.add_subcommand("run", "Run a case to its end time");
    add_case_options(run, case_path, sets);
    auto* out_option =
        run->add_option("--out", flags.out_dir, "Results folder (default: results/<case name>)");
    run->add_option("--restart", flags.restart,
                    "Continue the run whose results folder is DIR from DIR/checkpoint.h5, "
                    "writing on into DIR")
        ->type_name("DIR")
        ->excludes(out_option);
    run->add_option("--threads", flags.threads, "Worker threads (0 = all hardware threads)")
        ->check(CLI::Range(0, 65536));
    run->add_option("--debug-fail-rank", flags.debug_fail_rank,
                    "Debug: make a task of this rank throw (with --debug-fail-step)")
        ->check(CLI::Range(0, 1 << 24))
        ->group("Debug");
    run->add_option("--debug-fail-step", flags.debug_fail_step,
                    "Debug: the step (from 1) in which that task throws")
        ->check(CLI::Range(1L, 1L << 40))
        ->group("Debug");
    run->add_option("--trace", flags.trace,
                    "Write a Chrome/Perfetto trace of every task and message (JSON; open in "
                    "ui.perfetto.dev or chrome://tracing)")
        ->type_name("FILE.json");
    auto* quiet_flag =
        run->add_flag("--quiet,-q", flags.quiet,
                      "Nothing on the terminal but errors (logs/rank_N.log is still written)");
    run->add_flag("--verbose,-v", flags.verbose,
                  "Every log line on the terminal (snapshots written, ...) and debug lines in "
                  "logs/rank_N.log; progress as plain lines")
        ->excludes(quiet_flag);

    CLI::App* info = app.add_subcommand("info", "Describe a case without running it, with "
                                                "warnings about slow or inaccurate settings");
    add_case_options(info, case_path, sets);
    CLI::App* check = app.add_subcommand(
        "check", "Validate a case without running it (exit code 0: it would run, 2: refused)");
    add_case_options(check, case_path, sets);
    for (CLI::App* cmd : {info, check})
        cmd->add_option("--ranks", flags.ranks,
                        "MPI ranks the memory estimate per rank is for (default 1)")
            ->check(CLI::Range(1, 1 << 24));
    for (CLI::App* cmd : {run, info, check})
        cmd->add_option("--max-memory", flags.max_memory,
                        "Memory one rank may use, e.g. 4GiB, 512MiB, 2e9 (default: this "
                        "machine's MemTotal shared by the run's ranks on it); a case whose "
                        "estimate per rank is larger is refused")
            ->type_name("SIZE")
            ->check([](const std::string& v) {
                return sluice::parse_memory_size(v)
                           ? std::string()
                           : std::string("not a size (e.g. 4GiB, 512MiB, 2e9 bytes)");
            });
    CLI::App* schema = app.add_subcommand(
        "schema", "Print every key a case file may hold (table, key, type, unit, default, range, "
                  "the scheme it applies to, doc) as JSON");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help / --version exit 0; every usage error is a bad command line: 2.
        return app.exit(e) == 0 ? 0 : kExitCaseError;
    }
    if (schema->parsed()) {
        fmt::print("{}", sluice::case_schema_json());
        return 0;
    }
    const Command command = run->parsed()    ? Command::run
                            : info->parsed() ? Command::info
                                             : Command::check;

    // MPI only where it is needed: a run, or any command under mpirun. Starting it costs
    // ~0.3 s, which checking many case files need not pay.
    std::optional<sluice::tasks::MpiSession> mpi;
    if (command == Command::run || launched_by_mpi()) {
        try {
            mpi.emplace(&argc, &argv);
        } catch (const std::exception& e) {
            fmt::print(stderr, "sluice: error: {}\n", e.what());
            return kExitFailure;
        }
    }

    // Join oneTBB's worker threads before exit (sanitizers otherwise report their state).
    tbb::task_scheduler_handle workers{tbb::attach{}};
    const int code = execute(command, case_path, sets, flags);
    if (sluice::tasks::Comm::world().parallel())
        // oneTBB 2021.8 can wait forever in finalize() for a worker that an arena fed from
        // outside (the MPI main thread) left asleep; the workers die with the process anyway.
        workers.release();
    else
        tbb::finalize(workers, std::nothrow);
    return code;
}
