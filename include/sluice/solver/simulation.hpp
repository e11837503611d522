#pragma once
// A simulation: the scene (particles, grid, walls) plus the step graph that advances it. Its
// scheme (WCSPH or projection, src/solver/schemes/) declares the stages and binds the physics
// to the runtime's (stage, group) nodes; the physics itself lives in include/sluice/physics/,
// the scheduling in tasks/.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/checkpoint.hpp"
#include "sluice/physics/density.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/momentum.hpp"
#include "sluice/physics/reflection.hpp"
#include "sluice/physics/riemann.hpp"
#include "sluice/physics/timestep.hpp"
#include "sluice/physics/wall_loads.hpp"
#include "sluice/physics/walls.hpp"
#include "sluice/solver/halo_plan.hpp"
#include "sluice/solver/neighbour_lists.hpp"
#include "sluice/solver/pressure_solve.hpp"
#include "sluice/solver/rank_exchange.hpp"
#include "sluice/solver/state_check.hpp"
#include "sluice/solver/step_report.hpp"
#include "sluice/solver/step_units.hpp"
#include "sluice/solver/wall_motion.hpp"
#include "sluice/tasks/balance_policy.hpp"
#include "sluice/tasks/comm.hpp"
#include "sluice/tasks/decomposition.hpp"
#include "sluice/tasks/profile.hpp"
#include "sluice/tasks/rank_layout.hpp"
#include "sluice/tasks/step_graph.hpp"
#include "sluice/tasks/trace.hpp"

#include <tbb/task_arena.h>

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace sluice {

struct SimulationOptions {
    int threads = 0;    // worker threads of this rank (0 = all allowed)
    bool trace = false; // record every task and message for --trace
    std::size_t trace_max_events = 4000000;
    bool log_rebalances = false; // print each rebalance on rank 0
    // Debug (--debug-fail-rank/--debug-fail-step): a task of this rank throws in this step, to
    // test that one rank's failure brings every rank down with its message. -1 = never.
    int debug_fail_rank = -1;
    long debug_fail_step = -1;
};

// Requests a rank can make between steps; every rank sees the union over all ranks after the
// next step (they travel in the step's all-gather), so all act on them at the same step.
enum StepRequest : unsigned {
    request_stop = 1u,       // write a checkpoint and stop (signal or stop file)
    request_checkpoint = 2u, // write a checkpoint (wall-clock interval, decided by rank 0)
};

// One rebalance of the cut points between ranks (logged and written into summary.json).
struct RebalanceRecord {
    long step = 0;
    double imbalance_before = 0; // measured max/mean busy time over the window
    double predicted_after = 0;  // from the measured group costs and the new cuts
    std::uint64_t particles_moved = 0;
    double seconds = 0;
    bool at_rebuild = true; // false: between rebuilds, by the positions of the last rebuild
};

// Balance measured over one window of steps (the "imbalance curve").
using BalanceSample = tasks::BalanceSample;

template <int D>
class StepScheme; // src/solver/step_scheme.hpp

// A simulation on this rank: its particles (plus halo copies of its neighbours'), the
// grid, and the step graph that advances them. On several MPI ranks every rank holds one of
// these; collective member functions are marked.
template <int D>
class Simulation {
public:
    // Collective. With `resume`, the state is the checkpoint's instead of the case's initial
    // state: every rank passes its share of the particles (read_checkpoint's, any split in
    // curve order), and the shares are sent to the ranks that own them.
    explicit Simulation(const CaseConfig& cfg, SimulationOptions opts = {},
                        const Checkpoint<D>* resume = nullptr);
    ~Simulation();

    // Advances one time step. Collective. Throws RunError (a particle left the healthy range)
    // or InternalError (a task threw) on every rank together, before the failing step's state
    // is swapped in.
    void step();
    // Before step(): the caller will not read the state after this step (no probe, snapshot
    // or checkpoint due, another step follows unless the agreed requests say otherwise), so
    // the next step's graph may start while this step's agreement travels (docs/
    // ARCHITECTURE.md, "Time step"). The same on every rank. Reset by each step().
    void allow_run_ahead(bool allow) { run_ahead_allowed_ = allow; }
    // The time after the next step (the clock's t + dt, as the step will add it).
    [[nodiscard]] double next_time() const { return clock_.time + clock_.dt; }

    // Everything but the particles that a checkpoint needs to continue bitwise.
    [[nodiscard]] SolverState solver_state() const;

    // Steps that began with a neighbour-list rebuild (every step when numerics.neighbour_skin
    // is 0).
    [[nodiscard]] long list_rebuilds() const { return neighbours_.rebuilds; }

    // Adds StepRequest flags to this rank's report of the next step.
    void post_request(unsigned flags) { requests_local_ |= flags; }
    // Union of the flags every rank posted before the last step.
    [[nodiscard]] unsigned agreed_requests() const { return requests_agreed_; }
    // domain.particle_exit = "remove": fluid particles removed after the last step, and in the
    // whole run (over every rank, the same on each; a restart carries the total on).
    [[nodiscard]] std::int64_t removed_last_step() const { return leaving_agreed_; }
    [[nodiscard]] std::int64_t removed_particles() const { return removed_; }

    [[nodiscard]] double time() const { return clock_.time; }
    [[nodiscard]] long steps() const { return clock_.steps; }
    [[nodiscard]] double dt() const { return clock_.dt; }
    // This rank's particles [0, owned()) followed by halo copies. On one rank: all of them.
    [[nodiscard]] const Particles<D>& particles() const { return P_; }
    [[nodiscard]] Particles<D>& particles() { return P_; }
    [[nodiscard]] std::size_t owned() const { return owned_; }
    // Every rank's particles, in (cell key, id) order, on rank 0 (empty elsewhere; on one rank
    // a copy of particles()). Collective. For tests: a run never gathers (output is written by
    // every rank, src/io/h5_parallel.hpp; totals in src/solver/run_totals.hpp).
    [[nodiscard]] Particles<D> gather_particles() const { return ranks_.gather(P_, owned_); }
    [[nodiscard]] const tasks::Comm& comm() const { return comm_; }
    // Whether every peer's halo message will hold what this rank's plan expects (an extra
    // count round; for tests). Collective.
    [[nodiscard]] bool halo_plan_agrees() const { return ranks_.halo_counts_agree(); }
    [[nodiscard]] const tasks::RankLayout& rank_layout() const { return ranks_.layout(); }
    [[nodiscard]] int threads() const { return threads_; }
    [[nodiscard]] const tasks::RankProfile& profile() const { return profile_; }
    [[nodiscard]] const std::vector<RebalanceRecord>& rebalances() const { return rebalances_; }
    [[nodiscard]] const std::vector<BalanceSample>& balance_history() const {
        return balance_.history();
    }
    // Writes the --trace file (collective); no-op unless opts.trace.
    void write_trace(const std::string& path) const;
    // Test hook: delay the reported arrival of every halo message by `seconds`.
    void inject_receive_delay(double seconds) { receive_delay_ = seconds; }
    [[nodiscard]] const CellGrid<D>& grid() const { return grid_; }
    [[nodiscard]] const AnyKernel<D>& kernel() const { return kernel_; }
    // The radius within which the kernel is non-zero [m].
    [[nodiscard]] Real kernel_support() const {
        return std::visit([](const auto& k) { return k.support(); }, kernel_);
    }
    [[nodiscard]] const Eos& eos() const { return eos_; }
    // The momentum equation's parameters (the wall-load probes use the same pair terms).
    [[nodiscard]] const MomentumParams<D>& momentum() const { return momentum_; }
    [[nodiscard]] const CaseConfig& config() const { return cfg_; }
    // The moving wall objects (empty when every wall is fixed).
    [[nodiscard]] const WallMotion<D>& motion() const { return *motion_; }
    [[nodiscard]] const tasks::StepGraph& graph() const { return *graph_; }
    [[nodiscard]] int decompositions() const { return decompositions_; }
    [[nodiscard]] double h() const { return h_; }

    // Stability limits of the initial state at rest (gravity as the only force).
    [[nodiscard]] TimeStepLimits limits_at_rest() const;
    // Limits measured on the last step.
    [[nodiscard]] const TimeStepLimits& last_limits() const { return limits_; }

    // Busy seconds per stage summed over all steps (across re-decompositions), and the
    // stage names in graph order.
    [[nodiscard]] const std::vector<double>& stage_busy_seconds() const { return stage_busy_; }
    [[nodiscard]] std::vector<std::string> stage_names() const;

    // Projection scheme (docs/PROJECTION.md): the last step's pressure solve and totals over
    // the run; null with the WCSPH scheme.
    [[nodiscard]] const PressureSolveRecord* last_pressure_solve() const;
    [[nodiscard]] const PressureSolveTotals* pressure_solve_totals() const;
    // The last step's wall collisions of this rank's fluid particles (projection scheme; none
    // with WCSPH): what the force probes add to the interpolated pressure's load.
    [[nodiscard]] std::span<const WallContact<D>> wall_contacts() const;
    // The lowest pressure the scheme applies to the fluid (the projection scheme under a free
    // surface: 0, its correction applies no tension; otherwise -infinity): the probes read
    // each particle's pressure above it.
    [[nodiscard]] Real applied_pressure_floor() const;

    // Seconds spent in rebinning and re-decomposition between steps, summed over the run.
    [[nodiscard]] double rebin_seconds_total() const { return rebin_seconds_; }
    // Steps whose graph ran ahead of the previous step's agreement, and of them those
    // discarded (a failure, a rebuild, a rebalance or a request) and run again.
    [[nodiscard]] long steps_run_ahead() const { return ahead_steps_; }
    [[nodiscard]] long steps_run_ahead_discarded() const { return ahead_discarded_; }

private:
    // The parts of step(), in order.
    // the scheme's graphs (`gate` opens the step graph's gated stage); a task's error, or empty
    std::string run_graphs(const tasks::StepGraph::GatePoll& gate);
    void add_node_times(long step); // per stage and group, into the profile (and the trace)
    void advance_time();            // buffers swapped, t and dt advance
    void advance_clock();           // t and dt advance (advance_time without the swap)
    void between_steps();           // the lists rebuilt, or the ranks rebalanced, when due
    void change_layout();           // between_steps after the balancer's judgement
    // The next step's graph run while this step's agreement travels; the agreement completes
    // inside it (step_agreement.cpp).
    void run_ahead(double t_graph);
    [[nodiscard]] bool can_run_ahead() const;
    void rebin_and_decompose();
    void rebuild();
    // New cut points between ranks, gathered and decided identically on every rank.
    struct PlannedCut {
        tasks::BalancePlan plan;
        double t0 = 0; // when planning began (the rebalance's time includes it)
    };
    std::optional<PlannedCut> plan_rebalance();
    void apply_rebalance(const PlannedCut& cut, bool at_rebuild);
    bool rebalance_between_rebuilds();
    // The step's agreement between ranks (step_agreement.cpp): this rank's report leaves as
    // soon as the graph is done; agree_on_step() collects every rank's and throws on every
    // rank if any failed.
    void post_step_report(const std::string& task_error);
    void agree_on_step();
    // The two halves of agree_on_step: the reports reduced (the agreed values set unless a
    // rank failed; returns the first failing rank and its StepFailure, or -1), and the
    // failure raised on every rank (collective: the failing rank's message is broadcast).
    struct StepFailed {
        int rank = -1;
        std::int64_t kind = 0;
    };
    StepFailed reduce_reports(const std::vector<tasks::Bytes>& all);
    [[noreturn]] void raise_failure(const StepFailed& failed, const std::string& own_message);
    void build_graph();

    // The case's scheme (numerics.scheme), given the units it uses of the state below.
    std::unique_ptr<StepScheme<D>> make_scheme();

    CaseConfig cfg_;
    Particles<D> P_;
    CellGrid<D> grid_;
    CellRanges ranges_;
    std::vector<CellOccupancy> occupied_;
    Rebinner<D> rebinner_;
    std::vector<CellIndex> occupied_cells_; // occupied cells at the last adjacency check
    AnyKernel<D> kernel_;
    Eos eos_;
    MomentumParams<D> momentum_;
    TimeStepParams ts_params_;
    Reflector<D> walls_;                    // reflective walls
    std::unique_ptr<WallMotion<D>> motion_; // prescribed motion of wall objects
    Vec<D> domain_lo_, domain_hi_;
    StateBounds<D> bounds_; // healthy range of a fluid particle's state
    double h_ = 0;

    tasks::GroupTopology topo_;
    std::unique_ptr<tasks::StepGraph> graph_;
    int decompositions_ = 0;
    int target_groups_ = 1;

    GroupResults results_;         // per group, what the step's last stage found
    NeighbourLists<D> neighbours_; // per group, filled by its first stage; Verlet lists
    Real disp2_max_ = 0;           // largest squared displacement, all ranks, last step

    StepClock clock_; // t, dt, dt_prev, steps, u_max: the same on every rank
    TimeStepLimits limits_;
    double rebin_seconds_ = 0;
    std::vector<double> stage_busy_;

    // Distribution over ranks.
    SimulationOptions opts_;
    int threads_ = 1;
    std::unique_ptr<tbb::task_arena> arena_;
    tasks::Comm comm_;
    RankExchange<D> ranks_; // cut points, peers, halo plan, particles changing owner
    std::size_t owned_ = 0;
    std::vector<tasks::MessageRecord> between_; // communication outside the last graph
    tasks::RankProfile profile_;
    std::unique_ptr<tasks::TraceRecorder> trace_;
    double receive_delay_ = 0;
    unsigned requests_local_ = 0, requests_agreed_ = 0;
    // domain.particle_exit = "remove": fluid particles outside the domain after the last step
    // (every rank's, agreed), removed at the rebuild that follows; and the run's total.
    std::int64_t leaving_local_ = 0; // this rank's share of leaving_agreed_
    std::int64_t leaving_agreed_ = 0, removed_ = 0;
    std::optional<PendingStepReport> report_; // between post_step_report and agree_on_step
    bool run_ahead_allowed_ = false;
    bool ran_ahead_ = false;  // the next step's graph has run (its agreement is to come)
    std::string ahead_error_; // a task's error in that graph
    long ahead_steps_ = 0, ahead_discarded_ = 0;

    // Balancer: this rank measures and moves, the policy decides.
    std::vector<double> group_busy_; // per group, summed since the graph was built
    long graph_steps_ = 0;
    std::vector<double> last_busy_; // per rank, busy seconds of the last step
    tasks::BalancePolicy balance_;
    std::vector<RebalanceRecord> rebalances_;
    bool force_regroup_ = false;

    // Last member: its graphs live in arena_ and are destroyed first.
    std::unique_ptr<StepScheme<D>> scheme_;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

} // namespace sluice
