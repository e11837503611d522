#include "sluice/solver/simulation.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/physics/density.hpp"
#include "sluice/physics/initial_conditions.hpp"
#include "sluice/physics/integrator.hpp"
#include "sluice/physics/shifting.hpp"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>

namespace sluice {

namespace {

template <int D>
Vec<D> to_vec(const Triple& t) {
    Vec<D> v;
    for (int d = 0; d < D; ++d)
        v[d] = t[d];
    return v;
}

template <int D>
std::vector<Plane<D>> reflective_planes(const CaseConfig& cfg) {
    std::vector<Plane<D>> planes;
    if (cfg.walls == WallModel::reflective) {
        static constexpr const char* names[3][2] = {{"x-", "x+"}, {"y-", "y+"}, {"z-", "z+"}};
        for (int d = 0; d < D; ++d)
            for (int side = 0; side < 2; ++side) {
                const std::string face = names[d][side];
                if (std::find(cfg.tank_faces.begin(), cfg.tank_faces.end(), face) ==
                    cfg.tank_faces.end())
                    continue;
                Plane<D> pl;
                pl.point[d] = side == 0 ? cfg.tank_lo[d] : cfg.tank_hi[d];
                pl.normal[d] = side == 0 ? 1.0 : -1.0;
                planes.push_back(pl);
            }
    }
    for (const WallPlane& wp : cfg.planes) {
        Plane<D> pl{to_vec<D>(wp.point), to_vec<D>(wp.normal)};
        pl.normal.normalize();
        planes.push_back(pl);
    }
    return planes;
}

} // namespace

template <int D>
Simulation<D>::Simulation(const CaseConfig& cfg)
    : cfg_(cfg), kernel_(make_kernel<D>(cfg.kernel, cfg.h_over_dx * cfg.dx)) {
    h_ = cfg.h_over_dx * cfg.dx;
    const double support = kernel_support_factor(cfg.kernel) * h_;
    eos_ = Eos{cfg.eos, cfg.rho0, cfg.sound_speed, cfg.gamma, cfg.background_pressure};

    momentum_.gravity = to_vec<D>(cfg.gravity);
    momentum_.mu = cfg.viscosity;
    momentum_.alpha = cfg.artificial_viscosity;
    momentum_.c0 = cfg.sound_speed;
    momentum_.h = h_;
    continuity_ = cfg.density == DensityScheme::continuity;
    delta_h_c0_ = continuity_ ? cfg.delta_sph * h_ * cfg.sound_speed : 0.0;
    momentum_.wall_viscous = cfg.no_slip;
    momentum_.p_floor = cfg.background_pressure;

    ts_params_ =
        TimeStepParams{h_, cfg.viscosity / cfg.rho0, cfg.cfl, cfg.viscous_cfl, cfg.force_cfl};
    planes_ = reflective_planes<D>(cfg);

    add_fluid_blocks<D>(cfg, eos_, P_);
    const int layers = wall_layers(support, cfg.dx);
    if (cfg.walls == WallModel::dummy)
        add_wall_particles<D>(cfg, layers, P_);
    // A fluid particle may sit inside the dummy-wall layers for a moment; it has escaped only
    // once it is behind all of them.
    escape_margin_ = cfg.walls == WallModel::dummy ? layers * cfg.dx : 0.0;
    for (std::size_t i = 0; i < P_.size(); ++i)
        P_.p[i] = eos_.pressure(P_.rho[i]);

    // The grid covers the domain; open axes get room for wall layers and one support more.
    domain_lo_ = to_vec<D>(cfg.domain_lo);
    domain_hi_ = to_vec<D>(cfg.domain_hi);
    Vec<D> lo = domain_lo_, hi = domain_hi_;
    std::array<bool, D> periodic{};
    for (int d = 0; d < D; ++d) {
        periodic[d] = cfg.periodic[d];
        if (periodic[d])
            continue;
        double wall = cfg.walls == WallModel::dummy ? layers * cfg.dx : 0.0;
        lo[d] = std::min(lo[d], cfg.tank_lo[d] - wall) - support;
        hi[d] = std::max(hi[d], cfg.tank_hi[d] + wall) + support;
    }
    try {
        grid_ = CellGrid<D>::make(lo, hi, support, periodic);
    } catch (const std::invalid_argument& e) {
        throw CaseError(cfg.source_file, "domain.periodic", e.what());
    }

    const TimeStepLimits rest = limits_at_rest();
    if (cfg.fixed_dt) {
        if (*cfg.fixed_dt > rest.min())
            throw CaseError(cfg.source_file, "numerics.dt",
                            fmt::format("fixed time step {:.4g} s exceeds the stability limit "
                                        "{:.4g} s (acoustic {:.4g} s, viscous {:.4g} s, force "
                                        "{:.4g} s); remove numerics.dt to let the solver choose",
                                        *cfg.fixed_dt, rest.min(), rest.acoustic, rest.viscous,
                                        rest.force));
        dt_ = *cfg.fixed_dt;
    } else {
        dt_ = rest.min();
    }
    limits_ = rest;
    for (std::size_t i = 0; i < P_.size(); ++i)
        u_max_ = std::max(u_max_, P_.v[i].norm());

    const std::size_t n = P_.size();
    const auto per_group = static_cast<std::size_t>(std::max(1, cfg.particles_per_group));
    const int by_size = static_cast<int>((n + per_group - 1) / per_group);
    // Groups are independent of the thread count for results; more groups than threads let
    // TBB balance inside a rank.
    target_groups_ = std::max(by_size, 4 * tbb::this_task_arena::max_concurrency());
    rebin_and_decompose();
}

template <int D>
TimeStepLimits Simulation<D>::limits_at_rest() const {
    Real g = 0;
    for (int d = 0; d < D; ++d)
        g += cfg_.gravity[d] * cfg_.gravity[d];
    Real vmax = 0;
    for (std::size_t i = 0; i < P_.size(); ++i)
        vmax = std::max(vmax, P_.v[i].norm());
    return particle_time_step(ts_params_, cfg_.sound_speed, vmax, std::sqrt(g));
}

template <int D>
void Simulation<D>::rebin_and_decompose() {
    rebin(grid_, P_, ranges_, occupied_);
    std::vector<tasks::OccupiedCell> occ;
    occ.reserve(occupied_.size());
    for (const auto& c : occupied_)
        occ.push_back({c.key, c.cell, static_cast<double>(c.count)});

    // A particle can enter a new cell without changing the sort order, so the occupied set
    // and the group adjacency are checked every step.
    bool regroup = !graph_;
    if (graph_) {
        tasks::assign_cells(occ, topo_);
        const auto needed = tasks::group_adjacency(grid_, occ, topo_);
        regroup = !tasks::adjacency_covers(graph_->neighbours(), needed);
        if (!regroup) {
            // Re-cut when a group has drifted far above its share of particles.
            const double mean = static_cast<double>(P_.size()) / topo_.group_count();
            double worst = 0;
            for (const auto& cells : topo_.cells) {
                double c = 0;
                for (CellIndex cell : cells)
                    c += ranges_.end[cell] - ranges_.begin[cell];
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
    }
}

template <int D>
void Simulation<D>::build_graph() {
    using tasks::Reach;
    std::vector<tasks::StageSpec> specs;
    stage_kinds_.clear();
    specs.push_back({"density", Reach::neighbourhood});
    stage_kinds_.push_back(StageKind::density);
    if (cfg_.walls == WallModel::dummy) {
        specs.push_back({"walls", Reach::neighbourhood});
        stage_kinds_.push_back(StageKind::walls);
    }
    specs.push_back({"accel", Reach::neighbourhood});
    stage_kinds_.push_back(StageKind::accel);
    specs.push_back({"kick", Reach::self});
    stage_kinds_.push_back(StageKind::kick);
    // The continuity rate reads the neighbours' kicked velocities; summation needs nothing.
    specs.push_back({"drift", continuity_ ? Reach::neighbourhood : Reach::self});
    stage_kinds_.push_back(StageKind::drift);
    group_limits_.assign(topo_.neighbours.size(), {});
    group_failure_.assign(topo_.neighbours.size(), {});
    group_speed_.assign(topo_.neighbours.size(), 0.0);
    lists_.resize(topo_.neighbours.size());
    graph_ = std::make_unique<tasks::StepGraph>(
        specs, topo_.neighbours, [this](int stage, int group) { run_stage(stage, group); });
}

template <int D>
void Simulation<D>::run_stage(int stage, int group) {
    std::visit([&](const auto& k) { run_stage_with(k, stage, group); }, kernel_);
}

template <int D>
template <class K>
void Simulation<D>::run_stage_with(const K& kernel, int stage, int group) {
    Neighbourhood<D> nb{&grid_, &ranges_, std::span<const Vec<D>>(P_.x), kernel.support()};
    NeighbourList<D>& list = lists_[static_cast<std::size_t>(group)];
    // The first stage finds the group's neighbours once; every later stage of the step reuses
    // them (positions do not change within a step).
    if (stage == 0)
        nb.build_list(topo_.cells[static_cast<std::size_t>(group)], list);
    nb.list = &list;
    const auto& cells = topo_.cells[static_cast<std::size_t>(group)];
    const StageKind kind = stage_kinds_[static_cast<std::size_t>(stage)];
    switch (kind) {
    case StageKind::density:
        for (CellIndex c : cells) {
            if (cfg_.density == DensityScheme::summation) {
                summation_density(nb, kernel, c, P_, std::span<Real>(P_.rho));
            } else if (delta_h_c0_ > 0) {
                renormalised_density_gradient(nb, kernel, c, P_, std::span<Vec<D>>(P_.grad_rho));
            }
            equation_of_state(nb, eos_, c, P_, std::span<Real>(P_.p));
        }
        break;
    case StageKind::walls:
        for (CellIndex c : cells)
            dummy_wall_state(nb, kernel, eos_, momentum_.gravity, cfg_.no_slip,
                             std::pow(cfg_.dx, D), c, P_);
        break;
    case StageKind::accel:
        for (CellIndex c : cells) {
            acceleration(nb, kernel, momentum_, c, P_, std::span<Vec<D>>(P_.a));
            if (cfg_.shifting > 0) {
                const ShiftingParams sp{cfg_.shifting * u_max_ * h_ * dt_, kernel.W(cfg_.dx),
                                        0.1 * cfg_.dx};
                particle_shift(nb, kernel, sp, c, P_, std::span<Vec<D>>(P_.shift));
            }
        }
        break;
    case StageKind::kick:
        // v_half is read by other groups only in their drift, which waits for this kick.
        for (CellIndex c : cells)
            for (std::uint32_t i = nb.begin(c); i < nb.end(c); ++i)
                if (P_.kind[i] == Kind::fluid)
                    P_.v_half[i] = kick<D>(P_.v_half[i], P_.a[i], dt_prev_, dt_);
        break;
    case StageKind::drift: {
        TimeStepLimits lim;
        Real speed = 0;
        std::string failure;
        for (CellIndex c : cells) {
            if (continuity_)
                continuity_rate(nb, kernel, delta_h_c0_, c, P_, std::span<const Vec<D>>(P_.v_half),
                                std::span<Real>(P_.drho));
            for (std::uint32_t i = nb.begin(c); i < nb.end(c); ++i) {
                if (P_.kind[i] != Kind::fluid) {
                    P_.x_next[i] = P_.x[i];
                    P_.v_next[i] = P_.v[i];
                    P_.rho_next[i] = P_.rho[i];
                    continue;
                }
                Vec<D> x = drift<D>(P_.x[i], P_.v_half[i], dt_);
                if (cfg_.shifting > 0)
                    x += P_.shift[i];
                Vec<D> v = velocity_estimate<D>(P_.v_half[i], P_.a[i], dt_);
                const Real rho = continuity_ ? P_.rho[i] + dt_ * P_.drho[i] : P_.rho[i];
                if (!planes_.empty())
                    reflect(planes_, cfg_.restitution, x, P_.v_half[i], v);
                grid_.wrap(x);
                P_.x_next[i] = x;
                P_.v_next[i] = v;
                P_.rho_next[i] = rho;
                lim = min(lim, particle_time_step(ts_params_, eos_.sound_speed(rho), v.norm(),
                                                  P_.a[i].norm()));
                speed = std::max(speed, v.norm());
                if (failure.empty()) {
                    bool bad = !std::isfinite(rho) || rho <= 0 || !x.allFinite() || !v.allFinite();
                    const char* what = "a non-finite or non-positive state";
                    for (int d = 0; d < D && !bad; ++d)
                        if (!grid_.periodic[d] && (x[d] < domain_lo_[d] - escape_margin_ ||
                                                   x[d] > domain_hi_[d] + escape_margin_)) {
                            bad = true;
                            what = "a position outside the domain";
                        }
                    if (bad)
                        failure = fmt::format(
                            "particle {} reached {} at step {}, t = {:.6g} s: x = [{}], v = [{}], "
                            "rho = {:.6g}",
                            P_.id[i], what, steps_ + 1, time_ + dt_,
                            fmt::join(x.data(), x.data() + D, ", "),
                            fmt::join(v.data(), v.data() + D, ", "), rho);
                }
            }
        }
        group_limits_[static_cast<std::size_t>(group)] = lim;
        group_speed_[static_cast<std::size_t>(group)] = speed;
        group_failure_[static_cast<std::size_t>(group)] = std::move(failure);
        break;
    }
    }
}

template <int D>
void Simulation<D>::step() {
    graph_->run();
    // The stage layout is fixed for a case, so totals carry over when the graph is rebuilt.
    stage_busy_.resize(static_cast<std::size_t>(graph_->stage_count()), 0.0);
    for (int s = 0; s < graph_->stage_count(); ++s)
        for (int g = 0; g < graph_->group_count(); ++g)
            stage_busy_[static_cast<std::size_t>(s)] += graph_->node_seconds(s, g);
    for (const std::string& f : group_failure_)
        if (!f.empty())
            throw RunError(f);
    P_.swap_buffers();
    TimeStepLimits lim;
    for (const auto& l : group_limits_)
        lim = min(lim, l);
    limits_ = lim;
    u_max_ = *std::max_element(group_speed_.begin(), group_speed_.end());
    time_ += dt_;
    ++steps_;
    dt_prev_ = dt_;
    if (!cfg_.fixed_dt)
        dt_ = lim.min();
    const auto t0 = std::chrono::steady_clock::now();
    rebin_and_decompose();
    rebin_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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
