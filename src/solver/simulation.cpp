#include "sluice/solver/simulation.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/io/wall_extent.hpp"
#include "sluice/physics/acoustic_damper.hpp"
#include "sluice/solver/initial_share.hpp"
#include "sluice/solver/initial_state.hpp"
#include "sluice/solver/particle_exit.hpp"
#include "sluice/solver/reflective_walls.hpp"

#include "schemes/projection/projection_scheme.hpp"
#include "schemes/wcsph/wcsph_scheme.hpp"
#include "step_scheme.hpp"
#include "vec_triple.hpp"

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <stdexcept>

namespace sluice {

template <int D>
std::unique_ptr<StepScheme<D>> Simulation<D>::make_scheme() {
    // References: the parameters set after this call (time-step, walls, bounds) are read
    // only by the stages.
    const CaseParams<D> params{cfg_,   kernel_,  eos_,    momentum_, ts_params_,
                               walls_, *motion_, bounds_, h_};
    const RankCells<D> cells{grid_, ranges_, topo_};
    const RankLink rank{comm_, ranks_.plan(), between_, receive_delay_};
    switch (cfg_.scheme) {
    case Scheme::wcsph: {
        // --debug-fail-rank/--debug-fail-step: the step in which this rank's drift throws.
        const long fail_step = comm_.rank() == opts_.debug_fail_rank ? opts_.debug_fail_step : -1;
        return std::make_unique<WcsphScheme<D>>(params, P_, cells, neighbours_, clock_, results_,
                                                rank, fail_step);
    }
    case Scheme::projection:
        return std::make_unique<ProjectionScheme<D>>(params, P_, cells, neighbours_, clock_,
                                                     results_, rank);
    }
    throw InternalError("unknown numerics.scheme");
}

template <int D>
Simulation<D>::~Simulation() {
    graph_.reset(); // before the arena and the halo it uses
}

template <int D>
Simulation<D>::Simulation(const CaseConfig& cfg, SimulationOptions opts,
                          const Checkpoint<D>* resume)
    : cfg_(cfg), kernel_(make_kernel<D>(cfg.kernel, Real(cfg.h_over_dx * cfg.dx))),
      opts_(std::move(opts)), comm_(tasks::Comm::world()), ranks_(comm_, grid_) {
    h_ = cfg.h_over_dx * cfg.dx;
    const double support = kernel_support_factor(cfg.kernel) * h_;
    eos_ = Eos{cfg.eos, Real(cfg.rho0), Real(cfg.sound_speed), Real(cfg.gamma),
               Real(cfg.background_pressure)};

    momentum_.gravity = to_vec<D>(cfg.gravity);
    momentum_.mu = Real(cfg.viscosity);
    momentum_.alpha = Real(cfg.artificial_viscosity);
    momentum_.c0 = Real(cfg.sound_speed);
    momentum_.h = Real(h_);
    momentum_.wall_viscous = cfg.no_slip;
    momentum_.wall_artificial = cfg.wall_artificial_viscosity;
    momentum_.p_floor = Real(cfg.background_pressure);
    motion_ = std::make_unique<WallMotion<D>>(cfg, eos_, wall_layers(support, cfg.dx));
    scheme_ = make_scheme();
    neighbours_.skin = scheme_->skin();

    // The acoustic damper is a (bulk) viscosity: it limits the step like the fluid's own.
    const double nu = cfg.viscosity / cfg.rho0 +
                      acoustic_damper_viscosity(cfg.acoustic_damper, h_, cfg.sound_speed);
    ts_params_ = TimeStepParams{h_, nu, cfg.cfl, cfg.viscous_cfl, cfg.force_cfl};
    walls_ = reflective_walls<D>(cfg);

    const int layers = wall_layers(support, cfg.dx);
    // A fluid particle may sit inside the dummy-wall layers for a moment; it has escaped only
    // once it is behind all of them.
    const Real escape_margin = cfg.walls == WallModel::dummy ? Real(layers * cfg.dx) : Real(0);

    // The grid covers the domain; open axes get room for wall layers and one support more.
    domain_lo_ = to_vec<D>(cfg.domain_lo);
    domain_hi_ = to_vec<D>(cfg.domain_hi);
    for (int d = 0; d < D; ++d) {
        bounds_.lo[d] = domain_lo_[d] - escape_margin;
        bounds_.hi[d] = domain_hi_[d] + escape_margin;
        bounds_.periodic[static_cast<std::size_t>(d)] = cfg.periodic[static_cast<std::size_t>(d)];
    }
    bounds_.max_speed = Real(cfg.max_speed);
    bounds_.min_density = Real(cfg.min_density);
    bounds_.max_density = Real(cfg.max_density);
    bounds_.remove_outside = cfg.particle_exit == ParticleExit::remove;
    Vec<D> lo = domain_lo_, hi = domain_hi_;
    std::array<bool, D> periodic{};
    for (int d = 0; d < D; ++d) {
        periodic[d] = cfg.periodic[d];
        if (periodic[d])
            continue;
        const AxisExtent e = wall_extent(cfg, static_cast<std::size_t>(d));
        lo[d] = Real(e.lo - support);
        hi[d] = Real(e.hi + support);
    }
    try {
        // With a Verlet skin a cell must hold every pair within support + skin of the sort.
        grid_ = CellGrid<D>::make(lo, hi, Real(support + neighbours_.skin), periodic);
    } catch (const std::invalid_argument& e) {
        throw CaseError(cfg.source_file, "domain.periodic", e.what());
    }
    // This rank builds only the particles of its part of the curve (a restart none: they come
    // from the checkpoint); the largest initial speed is the whole case's.
    const InitialShare share = initial_share<D>(cfg, eos_, layers, grid_, comm_.rank(),
                                                comm_.size(), resume != nullptr ? nullptr : &P_);
    ranks_.set_layout(share.layout);
    clock_.u_max = share.max_speed;
    for (std::size_t i = 0; i < P_.size(); ++i)
        P_.p[i] = eos_.pressure(P_.rho[i]);

    const TimeStepLimits rest = limits_at_rest();
    if (cfg.fixed_dt) {
        if (*cfg.fixed_dt > rest.min())
            throw CaseError(cfg.source_file, "numerics.dt",
                            fmt::format("fixed time step {:.4g} s exceeds the stability limit "
                                        "{:.4g} s (acoustic {:.4g} s, viscous {:.4g} s, force "
                                        "{:.4g} s); remove numerics.dt to let the solver choose",
                                        *cfg.fixed_dt, rest.min(), rest.acoustic, rest.viscous,
                                        rest.force));
        clock_.dt = *cfg.fixed_dt;
    } else {
        clock_.dt = rest.min();
    }
    limits_ = rest;
    if (resume != nullptr) {
        // The case was checked above on its initial state, exactly as when the checkpoint's run
        // started; from here on the checkpoint's state replaces it.
        P_ = resume->particles;
        const SolverState& st = resume->solver;
        clock_.time = st.time;
        clock_.steps = static_cast<long>(st.step);
        clock_.dt = st.dt;
        clock_.dt_prev = st.dt_prev;
        clock_.u_max = Real(st.u_max);
        limits_ = TimeStepLimits{st.limit_acoustic, st.limit_viscous, st.limit_force};
        removed_ = st.fluid_removed;
        if (!motion_->bodies().empty())
            motion_->restore_body_state(st.bodies);
    }

    // Neighbour lists rely on fluid particles coming first in every cell (build_list): fluid
    // ids below wall ids, as the initial conditions number them.
    {
        ParticleId max_fluid = 0, min_wall = std::numeric_limits<ParticleId>::max();
        for (std::size_t i = 0; i < P_.size(); ++i)
            if (P_.kind[i] == Kind::fluid)
                max_fluid = std::max(max_fluid, P_.id[i]);
            else
                min_wall = std::min(min_wall, P_.id[i]);
        if (P_.count(Kind::fluid) > 0 && P_.count(Kind::wall) > 0 && max_fluid > min_wall)
            throw InternalError("wall particles must be numbered after every fluid particle");
    }

    // Worker threads of this rank. On several ranks the main thread drives MPI and the
    // arena gets one slot more for it (run_case raises TBB's global limit to match).
    const auto allowed = static_cast<int>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    threads_ = opts_.threads > 0 ? opts_.threads
                                 : std::max(1, std::min(allowed, tbb::info::default_concurrency()) -
                                                   (comm_.parallel() ? 1 : 0));
    arena_ = std::make_unique<tbb::task_arena>(threads_ + (comm_.parallel() ? 1 : 0), 1);
    balance_ = tasks::BalancePolicy(
        {cfg.rebalance_window, cfg.rebalance_threshold, cfg.rebalance_every}, comm_.size());
    scheme_->start();

    // A restart sorts, distributes and groups the particles by the positions of the last
    // rebuild, so that the Verlet lists of its first step are those of the interrupted run and
    // it goes on bitwise (a fresh start has x_ref = x).
    if (resume != nullptr)
        std::swap(P_.x, P_.x_ref);
    ranks_.distribute(P_, resume != nullptr,
                      cfg.initial_decomposition == InitialDecomposition::key_range);
    // The WCSPH scheme's results do not depend on the grouping; more groups than threads let
    // TBB balance inside a rank.
    target_groups_ = tasks::target_group_count(
        P_.size(), static_cast<std::size_t>(std::max(1, cfg.particles_per_group)), threads_);
    rebin_and_decompose();
    if (resume != nullptr)
        std::swap(P_.x, P_.x_ref);
    else
        P_.x_ref = P_.x;
    neighbours_.rebuilt = true;
}

template <int D>
TimeStepLimits Simulation<D>::limits_at_rest() const {
    double g = 0;
    for (int d = 0; d < D; ++d)
        g += cfg_.gravity[d] * cfg_.gravity[d];
    // The clock's u_max is the initial state's largest speed over every rank (initial_share).
    return particle_time_step(ts_params_, scheme_->cfl_speed(), clock_.u_max, std::sqrt(g));
}

template <int D>
void Simulation<D>::rebin_and_decompose() {
    // Here P_ holds exactly this rank's particles (no halo).
    rebinner_(grid_, P_, ranges_, occupied_);
    owned_ = P_.size();
    std::vector<tasks::OccupiedCell> occ;
    occ.reserve(occupied_.size());
    for (const auto& c : occupied_)
        occ.push_back({c.key, c.cell, static_cast<double>(c.count)});
    if (comm_.parallel())
        if (auto counts = ranks_.plan_halo(P_, ranges_, occupied_, owned_))
            between_.push_back(*counts);

    // A particle can enter a new cell without changing the sort order, so the occupied set,
    // the group adjacency and the groups facing each peer are checked every step.
    // When the same cells are occupied as at the last check, the adjacency cannot have
    // changed (particles only moved between occupied cells), and that check was 5 % of a
    // 2-D dam-break step.
    bool same_cells = occupied_cells_.size() == occupied_.size();
    for (std::size_t k = 0; same_cells && k < occupied_.size(); ++k)
        same_cells = occupied_cells_[k] == occupied_[k].cell;
    if (!same_cells) {
        occupied_cells_.resize(occupied_.size());
        for (std::size_t k = 0; k < occupied_.size(); ++k)
            occupied_cells_[k] = occupied_[k].cell;
    }
    bool regroup = !graph_ || force_regroup_;
    if (!regroup) {
        tasks::assign_cells(occ, topo_);
        if (!same_cells) {
            const auto needed = tasks::group_adjacency(grid_, occ, topo_);
            regroup = !tasks::adjacency_covers(graph_->neighbours(), needed);
            if (!regroup && comm_.parallel())
                regroup = !tasks::adjacency_covers(graph_->halo().boundary,
                                                   ranks_.boundary_groups(topo_));
        }
        if (!regroup) {
            // Re-cut when a group has drifted far above its share of particles.
            const double mean = static_cast<double>(owned_) / topo_.group_count();
            double worst = 0;
            for (const auto& cells : topo_.cells) {
                double c = 0;
                for (CellIndex cell : cells)
                    c += ranges_.end(cell) - ranges_.begin(cell);
                worst = std::max(worst, c);
            }
            regroup = worst > 2 * mean;
        }
    }
    if (regroup) {
        const int groups = std::min<int>(target_groups_, static_cast<int>(occ.size()));
        topo_.key_begin = tasks::cut_by_cost(occ, std::max(1, groups));
        tasks::assign_cells(occ, topo_);
        topo_.neighbours = tasks::group_adjacency(grid_, occ, topo_);
        build_graph();
        ++decompositions_;
        force_regroup_ = false;
    }
}

template <int D>
void Simulation<D>::rebuild() {
    // Between rebuilds the particles stay where the last sort put them (each within skin/2 of
    // where it was sorted), halo plans and groups stay, and no particle changes owner.
    P_.resize(owned_); // drop the halo copies: they are received afresh next step
    if (leaving_agreed_ > 0) {
        const auto removed = static_cast<std::int64_t>(remove_outside_domain(P_, bounds_));
        if (removed != leaving_local_)
            throw std::logic_error(fmt::format("rank {} removed {} particles outside the domain, "
                                               "its drift counted {}",
                                               comm_.rank(), removed, leaving_local_));
    }
    if (comm_.parallel()) {
        const auto cut = balance_.due() != tasks::BalanceDue::no ? plan_rebalance() : std::nullopt;
        if (cut)
            apply_rebalance(*cut, true);
        else
            between_.push_back(ranks_.migrate(P_));
    }
    balance_.clear_due();
    rebin_and_decompose();
    std::copy(P_.x.begin(), P_.x.end(), P_.x_ref.begin());
}

template <int D>
void Simulation<D>::build_graph() {
    // The scheme declares the stages (and their halo exchanges); the per-group results of a
    // step are everyone's.
    const std::size_t groups = topo_.neighbours.size();
    results_.assign(groups);
    neighbours_.resize(groups);
    group_busy_.assign(groups, 0.0);
    graph_steps_ = 0;

    GraphSite site{&topo_.neighbours, comm_.parallel(), {}, {}, arena_.get()};
    if (comm_.parallel()) {
        site.peers = ranks_.peers();
        site.boundary = ranks_.boundary_groups(topo_);
    }
    graph_.reset(); // the old graph lives in the arena too
    graph_ = scheme_->build_graph(site);
    graph_->inject_receive_delay(receive_delay_);
}

template <int D>
void Simulation<D>::step() {
    // The step graph of docs/ARCHITECTURE.md ("Schemes"); the same for every scheme.
    // When this step's graph ran ahead in the last call (run_ahead), only its report is left.
    std::string task_error;
    const long this_step = clock_.steps + 1;
    if (ran_ahead_) {
        ran_ahead_ = false;
        task_error = std::move(ahead_error_);
        ahead_error_.clear();
    } else {
        neighbours_.count_step();
        task_error = run_graphs({});
    }
    const double t_graph = tasks::clock_seconds();
    // The report leaves now; the bookkeeping below runs while it travels.
    post_step_report(task_error);
    add_node_times(this_step);
    if (trace_)
        trace_->add_work(this_step + 1, "bookkeeping", t_graph, tasks::clock_seconds());
    const bool ahead = run_ahead_allowed_ && can_run_ahead();
    run_ahead_allowed_ = false;
    if (ahead) {
        run_ahead(t_graph); // the next step's graph; throws like agree_on_step
        return;
    }
    agree_on_step(); // throws on every rank if anything failed on any
    advance_time();
    between_steps();
    profile_.between_wall += tasks::clock_seconds() - t_graph;
}

template <int D>
bool Simulation<D>::can_run_ahead() const {
    // Several ranks (one has no reduction to wait for), a scheme whose step graph has a gated
    // stage, and Verlet lists that can outlive a step. The same on every rank.
    return comm_.parallel() && graph_->gate_stage() >= 0 && neighbours_.skin > 0;
}

template <int D>
std::string Simulation<D>::run_graphs(const tasks::StepGraph::GatePoll& gate) {
    graph_->inject_receive_delay(receive_delay_);
    if (!motion_->empty()) // the walls' poses for this step, read by its stages
        motion_->prepare(clock_.time, clock_.dt_prev, clock_.dt);
    try {
        // A throwing task does not stop the graph: its messages still go out, so every rank
        // completes the step and learns of the error in the step's agreement.
        scheme_->run(*graph_, gate);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

template <int D>
void Simulation<D>::add_node_times(long step) {
    // The stage layout is fixed for a case, so totals carry over when the graph is rebuilt.
    stage_busy_.resize(static_cast<std::size_t>(graph_->stage_count()), 0.0);
    for (int s = 0; s < graph_->stage_count(); ++s)
        for (int g = 0; g < graph_->group_count(); ++g) {
            const double t = graph_->node_seconds(s, g);
            stage_busy_[static_cast<std::size_t>(s)] += t;
            group_busy_[static_cast<std::size_t>(g)] += t;
        }
    ++graph_steps_;
    profile_.add_step(*graph_, between_);
    if (opts_.trace) {
        if (!trace_)
            trace_ = std::make_unique<tasks::TraceRecorder>(comm_.rank(), stage_names(),
                                                            opts_.trace_max_events);
        trace_->add_step(step, *graph_, between_);
    }
    between_.clear();
}

template <int D>
void Simulation<D>::advance_time() {
    P_.swap_buffers();
    advance_clock();
}

template <int D>
void Simulation<D>::advance_clock() {
    clock_.time += clock_.dt;
    ++clock_.steps;
    clock_.dt_prev = clock_.dt;
    if (!cfg_.fixed_dt)
        clock_.dt = limits_.min();
}

template <int D>
void Simulation<D>::between_steps() {
    if (comm_.parallel())
        balance_.add_step(clock_.steps, last_busy_);
    change_layout();
}

template <int D>
void Simulation<D>::change_layout() {
    // A particle that left the domain (domain.particle_exit = "remove") goes at a rebuild:
    // every rank knows the global count from the step's agreement, so all rebuild together.
    removed_ += leaving_agreed_;
    if (neighbours_.expire(disp2_max_, leaving_agreed_ > 0)) {
        const auto t0 = std::chrono::steady_clock::now();
        const double t1 = tasks::clock_seconds();
        rebuild();
        rebin_seconds_ +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (trace_)
            trace_->add_work(clock_.steps + 1, "rebuild", t1, tasks::clock_seconds());
    } else if (balance_.due() == tasks::BalanceDue::now) {
        neighbours_.rebuilt = rebalance_between_rebuilds();
    }
}

template <int D>
SolverState Simulation<D>::solver_state() const {
    SolverState s;
    s.time = clock_.time;
    s.step = clock_.steps;
    s.dt = clock_.dt;
    s.dt_prev = clock_.dt_prev;
    s.u_max = clock_.u_max;
    s.limit_acoustic = limits_.acoustic;
    s.limit_viscous = limits_.viscous;
    s.limit_force = limits_.force;
    s.fluid_removed = removed_;
    s.bodies = motion_->body_state();
    return s;
}

template <int D>
const PressureSolveRecord* Simulation<D>::last_pressure_solve() const {
    return scheme_->last_pressure_solve();
}

template <int D>
const PressureSolveTotals* Simulation<D>::pressure_solve_totals() const {
    return scheme_->pressure_solve_totals();
}

template <int D>
std::span<const WallContact<D>> Simulation<D>::wall_contacts() const {
    return scheme_->wall_contacts();
}

template <int D>
Real Simulation<D>::applied_pressure_floor() const {
    return scheme_->applied_pressure_floor();
}

template <int D>
void Simulation<D>::write_trace(const std::string& path) const {
    if (opts_.trace && trace_)
        trace_->write(comm_, path);
}

template <int D>
std::vector<std::string> Simulation<D>::stage_names() const {
    std::vector<std::string> names;
    for (const auto& spec : graph_->stages())
        names.push_back(spec.name);
    return names;
}

template class Simulation<2>;
template class Simulation<3>;

} // namespace sluice
