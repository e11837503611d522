// The WCSPH scheme: its stages, declared once each as a row of stage_table (name, what the
// stage computes, how far it reads, the halo field its results travel as), and the stage
// bodies: what each node (stage, cell group) of the step graph computes, calling the
// formulas of include/sluice/physics/ (density.hpp, walls.hpp, momentum.hpp, riemann.hpp,
// shifting.hpp, integrator.hpp, drift.hpp). The graph and its halo exchanges follow from the
// rows alone.
#include "wcsph_scheme.hpp"

#include "../../vec_triple.hpp"

#include "sluice/physics/acoustic_damper.hpp"
#include "sluice/physics/body_load.hpp"
#include "sluice/physics/continuity_lanes.hpp"
#include "sluice/physics/damping_zone.hpp"
#include "sluice/physics/density.hpp"
#include "sluice/physics/drift.hpp"
#include "sluice/physics/integrator.hpp"
#include "sluice/physics/riemann.hpp"
#include "sluice/physics/shifting.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace sluice {

template <int D>
WcsphScheme<D>::WcsphScheme(const CaseParams<D>& params, Particles<D>& P, const RankCells<D>& cells,
                            NeighbourLists<D>& neighbours, const StepClock& clock,
                            GroupResults& results, const RankLink& rank, long fail_step)
    : case_(params), P_(P), cells_(cells), neighbours_(neighbours), clock_(clock),
      results_(results), rank_(rank), fail_step_(fail_step) {
    const CaseConfig& cfg = case_.cfg;
    continuity_ = cfg.density == DensityScheme::continuity;
    delta_h_c0_ = continuity_ ? cfg.delta_sph * case_.h * cfg.sound_speed : 0.0;
    diffusion_ = DensityDiffusionParams<D>{Real(delta_h_c0_), cfg.density_diffusion,
                                           Real(cfg.rho0) * case_.momentum.gravity /
                                               Real(cfg.sound_speed * cfg.sound_speed)};
    density_gradient_ = delta_h_c0_ > 0 && cfg.density_diffusion == DensityDiffusion::antuono;
    riemann_dissipation_ = cfg.dissipation == Dissipation::riemann;
    riemann_ = RiemannParams<D>{case_.momentum.gravity,      Real(cfg.rho0),
                                Real(cfg.sound_speed),       Real(3),
                                case_.momentum.mu,           case_.momentum.h,
                                case_.momentum.wall_viscous, case_.momentum.p_floor};
    momentum_lanes_ = acceleration_uses_lanes<D>() && !riemann_dissipation_;
    damper_nu_ = Real(acoustic_damper_viscosity(cfg.acoustic_damper, case_.h, cfg.sound_speed));
    for (const DampingZoneConfig& z : cfg.damping_zones) {
        DampingZone<D> zone;
        zone.start = to_vec<D>(z.start);
        const Vec<D> along = to_vec<D>(z.end) - zone.start;
        zone.length = along.norm();
        zone.direction = along / zone.length;
        zone.sigma_max = Real(z.strength);
        damping_.push_back(zone);
    }
    halo_ = std::make_unique<HaloFields<D>>(P_, cells_.ranges, cells_.grid, rank_.plan, skin() > 0);
}

enum class WcsphStage : std::uint8_t { density, walls, accel, kick, drift };

template <int D>
std::vector<typename WcsphScheme<D>::Stage> WcsphScheme<D>::stage_table() {
    using tasks::Reach;
    // Each row: the stage, and the halo field its results travel as (the particles it
    // carries, the arrays it copies: what the next stages read of a neighbour). Before the
    // first stage the state travels.
    std::vector<Stage> rows;
    HaloField pressure{"pressure", std::nullopt, {halo_column(P_.p), halo_column(P_.volume)}};
    if (!continuity_) // summation density
        pressure.columns.push_back(halo_column(P_.rho));
    if (density_gradient_)
        pressure.columns.push_back(halo_column(P_.grad_rho));
    // p/rho^2 is read only by the acceleration: in the record when it has one.
    if (momentum_lanes_)
        pressure.columns.push_back(halo_column(momentum_records_));
    else
        pressure.columns.push_back(halo_column(P_.p_over_rho2));
    rows.push_back({{"density", Reach::neighbourhood, pressure}, StageKind::density});
    if (case_.cfg.walls == WallModel::dummy) {
        HaloField walls{
            "walls",
            Kind::wall,
            {halo_column(P_.p), halo_column(P_.rho), halo_column(P_.mass), halo_column(P_.v_bc)}};
        if (momentum_lanes_)
            walls.columns.push_back(halo_column(momentum_records_));
        rows.push_back({{"walls", Reach::neighbourhood, walls}, StageKind::walls});
    }
    rows.push_back({{"accel", Reach::neighbourhood, std::nullopt}, StageKind::accel});
    // The continuity rate reads the neighbours' kicked velocities; summation needs nothing.
    std::optional<HaloField> velocity;
    // Moving walls' mid-step velocities travel too (fixed walls' are zero).
    if (continuity_)
        velocity = HaloField{"velocity",
                             case_.motion.empty() ? std::optional<Kind>(Kind::fluid) : std::nullopt,
                             {halo_column(P_.v_half)}};
    rows.push_back({{"kick", Reach::self, velocity}, StageKind::kick});
    rows.push_back({{"drift", continuity_ ? Reach::neighbourhood : Reach::self, std::nullopt},
                    StageKind::drift});
    // The first stage that reads the clock's agreed values: the kick (dt), or the
    // acceleration when it computes the shifting displacement (u_max and dt). The stages
    // before it read only the state, so they may run ahead of the previous step's agreement.
    const StageKind gated = case_.cfg.shifting > 0 ? StageKind::accel : StageKind::kick;
    for (Stage& r : rows)
        r.row.gated = r.kind == gated;
    return rows;
}

template <int D>
std::unique_ptr<tasks::StepGraph> WcsphScheme<D>::build_graph(const GraphSite& site) {
    std::vector<StageRow> rows;
    stage_kinds_.clear();
    for (const Stage& s : stage_table()) {
        rows.push_back(s.row);
        stage_kinds_.push_back(s.kind);
    }
    return graph_of_rows<D>(
        rows, halo_->state(), [this](int stage, int group) { run_stage(stage, group); }, site,
        *halo_);
}

template <int D>
void WcsphScheme<D>::run(tasks::StepGraph& graph, const tasks::StepGraph::GatePoll& gate) {
    halo_->record_halo_cells(neighbours_.rebuilt);
    if (momentum_lanes_) // the halo's size is known before the graph runs
        momentum_records_.resize(P_.size());
    graph.run(gate);
}

// The arrays that the stages before the gated one write for owned particles: density (ρ with
// summation, ∇ρ, p, p/ρ², m/ρ), walls (the wall particles' p, ρ, mass, v_bc) and, when it
// runs before the gate (no shifting), the acceleration. `f(live, kept)` for each; one list,
// so that keep_ahead and restore_ahead cannot disagree on it.
template <int D>
template <class F>
void WcsphScheme<D>::each_ahead_array(F&& f) {
    f(P_.rho, kept_.rho);
    f(P_.p, kept_.p);
    f(P_.p_over_rho2, kept_.p_over_rho2);
    f(P_.volume, kept_.volume);
    if (density_gradient_)
        f(P_.grad_rho, kept_.grad_rho);
    if (case_.cfg.walls == WallModel::dummy) {
        f(P_.mass, kept_.mass);
        f(P_.v_bc, kept_.v_bc);
    }
    if (case_.cfg.shifting <= 0)
        f(P_.a, kept_.a);
    if (momentum_lanes_)
        f(momentum_records_, kept_momentum_records_);
}

template <int D>
void WcsphScheme<D>::keep_ahead(std::size_t owned) {
    each_ahead_array([owned](const auto& live, auto& kept) {
        kept.assign(live.begin(), live.begin() + static_cast<std::ptrdiff_t>(owned));
    });
}

template <int D>
void WcsphScheme<D>::restore_ahead(std::size_t owned) {
    each_ahead_array([owned](auto& live, const auto& kept) {
        if (kept.size() != owned)
            throw std::logic_error("restore_ahead: not what keep_ahead kept");
        std::copy(kept.begin(), kept.end(), live.begin());
    });
}

template <int D>
void WcsphScheme<D>::run_stage(int stage, int group) {
    std::visit([&](const auto& k) { run_stage_with(k, stage, group); }, case_.kernel);
}

template <int D>
template <class K>
void WcsphScheme<D>::run_stage_with(const K& kernel, int stage, int group) {
    Neighbourhood<D> nb{&cells_.grid, &cells_.ranges, std::span<const Vec<D>>(P_.x),
                        kernel.support()};
    NeighbourList<D>& list = neighbours_.lists[static_cast<std::size_t>(group)];
    // The first stage finds the group's neighbours once; every later stage of the step reuses
    // them (positions do not change within a step).
    if (stage == 0) {
        // The kernel by value: see Neighbourhood::kernel_factors.
        const auto factor = [kernel](Real r2) { return grad_factor(kernel, r2); };
        // Wall centres list only fluid partners: nothing reads wall-wall pairs.
        const auto partial = [this](std::uint32_t i) { return P_.kind[i] == Kind::wall; };
        const auto wanted = [this](std::uint32_t j) { return P_.kind[j] == Kind::fluid; };
        const auto& group_cells = cells_.topo.cells[static_cast<std::size_t>(group)];
        if (neighbours_.skin <= 0) {
            nb.build_list(group_cells, list, factor, partial, wanted);
        } else {
            NeighbourList<D>& wide = neighbours_.wide[static_cast<std::size_t>(group)];
            if (neighbours_.rebuilt) {
                // Built from the positions of the rebuild (equal to x, except in the first
                // step after a restart).
                Neighbourhood<D> within_skin = nb;
                within_skin.x = std::span<const Vec<D>>(P_.x_ref);
                within_skin.support = nb.support + neighbours_.skin;
                within_skin.build_list(
                    group_cells, wide, [](Real r2) { return r2; }, partial, wanted);
            }
            nb.select_pairs(wide, list, factor);
        }
    }
    nb.list = &list;
    const auto& cells = cells_.topo.cells[static_cast<std::size_t>(group)];
    const StageKind kind = stage_kinds_[static_cast<std::size_t>(stage)];
    switch (kind) {
    case StageKind::density:
        for (CellIndex c : cells) {
            if (case_.cfg.density == DensityScheme::summation) {
                summation_density(nb, kernel, c, P_, std::span<Real>(P_.rho));
            } else if (density_gradient_) {
                renormalised_density_gradient(nb, kernel, c, P_, std::span<Vec<D>>(P_.grad_rho));
            }
            equation_of_state(nb, case_.eos, c, P_, std::span<Real>(P_.p),
                              std::span<Real>(P_.p_over_rho2), std::span<Real>(P_.volume));
            if (damper_nu_ > 0)
                apply_acoustic_damper(nb, kernel, damper_nu_, c, P_, std::span<Real>(P_.p),
                                      std::span<Real>(P_.p_over_rho2));
            if (momentum_lanes_) // wall particles in the walls stage, once their state is known
                for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i)
                    if (P_.kind[i] == Kind::fluid)
                        write_momentum_neighbour(P_, case_.momentum.p_floor, i,
                                                 momentum_records_[i]);
        }
        break;
    case StageKind::walls:
        if (case_.motion.empty()) {
            for (CellIndex c : cells)
                dummy_wall_state(nb, kernel, case_.eos, case_.momentum.gravity, case_.cfg.no_slip,
                                 Real(std::pow(case_.cfg.dx, D)), c, P_);
        } else {
            const MovingWalls<D> moving{case_.motion, case_.motion.frames().now, P_.id};
            for (CellIndex c : cells)
                dummy_wall_state(nb, kernel, case_.eos, case_.momentum.gravity, case_.cfg.no_slip,
                                 Real(std::pow(case_.cfg.dx, D)), c, P_, moving);
        }
        if (momentum_lanes_)
            for (CellIndex c : cells)
                for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i)
                    if (P_.kind[i] == Kind::wall)
                        write_momentum_neighbour(P_, case_.momentum.p_floor, i,
                                                 momentum_records_[i]);
        break;
    case StageKind::accel:
        for (CellIndex c : cells) {
            if (riemann_dissipation_)
                riemann_acceleration(nb, kernel, riemann_, c, P_, std::span<Vec<D>>(P_.a));
            else if (momentum_lanes_)
                acceleration_lanes(nb, case_.momentum, c, P_, momentum_records_.data(),
                                   std::span<Vec<D>>(P_.a));
            else
                acceleration(nb, kernel, case_.momentum, c, P_, std::span<Vec<D>>(P_.a));
            if (case_.cfg.shifting > 0) {
                const ShiftingParams sp{
                    Real(case_.cfg.shifting * clock_.u_max * case_.h * clock_.dt),
                    kernel.W(Real(case_.cfg.dx)), Real(0.1 * case_.cfg.dx)};
                particle_shift(nb, kernel, sp, c, P_, std::span<Vec<D>>(P_.shift));
            }
        }
        if (!case_.motion.bodies().empty())
            sum_body_loads(nb, kernel, cells, results_.body_loads[static_cast<std::size_t>(group)]);
        break;
    case StageKind::kick:
        // v_half is read by other groups only in their drift, which waits for this kick.
        for (CellIndex c : cells)
            for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i)
                if (P_.kind[i] == Kind::fluid)
                    P_.v_half[i] =
                        kick<D>(P_.v_half[i], P_.a[i], Real(clock_.dt_prev), Real(clock_.dt));
        if (!damping_.empty()) // the sponge layers: exact relaxation over the step
            for (CellIndex c : cells)
                for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i)
                    if (P_.kind[i] == Kind::fluid)
                        for (const DampingZone<D>& z : damping_)
                            P_.v_half[i] *= z.factor(P_.x[i], Real(clock_.dt));
        if (!case_.motion.empty()) { // a moving wall's velocity at the middle of the step
            const auto& mid = case_.motion.frames().mid;
            for (CellIndex c : cells)
                for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i)
                    if (const int k = case_.motion.object_of(P_.id[i]); k >= 0)
                        P_.v_half[i] = from_pose_point<D>(mid[static_cast<std::size_t>(k)].velocity(
                            case_.motion.body_point(k, P_.id[i])));
        }
        break;
    case StageKind::drift: {
        if (clock_.steps + 1 == fail_step_ && group == 0)
            throw std::runtime_error(fmt::format("deliberate failure of rank {} in step {} "
                                                 "(--debug-fail-rank/--debug-fail-step)",
                                                 rank_.comm.rank(), clock_.steps + 1));
        TimeStepExtremes extremes;
        const Real dt = Real(clock_.dt);
        Real speed = 0, disp2 = 0;
        std::int64_t leaving = 0;
        std::string failure;
        const bool moving_walls = !case_.motion.empty();
        const std::vector<Pose>* end = moving_walls ? &case_.motion.frames().end : nullptr;
        for (CellIndex c : cells) {
            if (riemann_dissipation_)
                riemann_continuity_rate(nb, kernel, riemann_, c, P_,
                                        std::span<const Vec<D>>(P_.v_half),
                                        std::span<Real>(P_.drho), moving_walls);
            else if (continuity_ && momentum_lanes_) // the records hold x, rho, m, wall
                continuity_rate_lanes(nb, diffusion_, c, P_, momentum_records_.data(),
                                      std::span<const Vec<D>>(P_.v_half), std::span<Real>(P_.drho),
                                      moving_walls);
            else if (continuity_)
                continuity_rate(nb, kernel, diffusion_, c, P_, std::span<const Vec<D>>(P_.v_half),
                                std::span<Real>(P_.drho), moving_walls);
            for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
                // v_half stays as kicked: other groups' continuity rates read it in this stage.
                P_.v_half_next[i] = P_.v_half[i];
                if (P_.kind[i] != Kind::fluid) {
                    P_.x_next[i] = P_.x[i];
                    P_.v_next[i] = P_.v[i];
                    P_.rho_next[i] = P_.rho[i];
                    if (const int k = moving_walls ? case_.motion.object_of(P_.id[i]) : -1;
                        k >= 0) { // where its object's motion puts it at the end of the step
                        const Pose& pose = (*end)[static_cast<std::size_t>(k)];
                        const Eigen::Vector3d& x0 = case_.motion.body_point(k, P_.id[i]);
                        P_.x_next[i] = from_pose_point<D>(pose.position(x0));
                        P_.v_next[i] = from_pose_point<D>(pose.velocity(x0));
                        disp2 = std::max(disp2, (P_.x_next[i] - P_.x_ref[i]).squaredNorm());
                    }
                    continue;
                }
                auto [x, v, rho] = leapfrog_drift<D>(
                    P_.x[i], P_.v_half_next[i], P_.a[i], P_.rho[i],
                    continuity_ ? &P_.drho[i] : nullptr,
                    case_.cfg.shifting > 0 ? &P_.shift[i] : nullptr, dt, case_.walls);
                cells_.grid.wrap(x);
                P_.x_next[i] = x;
                P_.v_next[i] = v;
                P_.rho_next[i] = rho;
                const Real v_norm = v.norm();
                extremes.add(case_.eos.sound_speed(rho), v_norm, P_.a[i].squaredNorm());
                speed = std::max(speed, v_norm);
                disp2 = std::max(disp2, (x - P_.x_ref[i]).squaredNorm());
                if (case_.bounds.remove_outside && outside_domain(case_.bounds, x))
                    ++leaving;
                if (failure.empty() && !state_healthy(case_.bounds, x, v, rho)) {
                    const std::string what = state_fault(case_.bounds, x, v, rho);
                    if (!what.empty())
                        failure = fmt::format(
                            "particle {} reached {} at step {}, t = {:.6g} s: x = [{}], v = [{}], "
                            "rho = {:.6g}",
                            P_.id[i], what, clock_.steps + 1, clock_.time + clock_.dt,
                            fmt::join(x.data(), x.data() + D, ", "),
                            fmt::join(v.data(), v.data() + D, ", "), rho);
                }
            }
        }
        results_.limits[static_cast<std::size_t>(group)] = extremes.limits(case_.time_step);
        results_.speed[static_cast<std::size_t>(group)] = speed;
        results_.disp2[static_cast<std::size_t>(group)] = disp2;
        results_.leaving[static_cast<std::size_t>(group)] = leaving;
        results_.failure[static_cast<std::size_t>(group)] = std::move(failure);
        break;
    }
    }
}

template <int D>
template <class K>
void WcsphScheme<D>::sum_body_loads(const Neighbourhood<D>& nb, const K& kernel,
                                    const std::vector<CellIndex>& cells, BodyLoadSums& sums) const {
    // The free bodies' wall particles of this group: each one's share of its body's force,
    // and its moment about the body's centre of mass where the step starts.
    const WallMotion<D>& motion = case_.motion;
    const auto& now = motion.frames().now;
    sums.reset(motion.bodies().size());
    for (CellIndex c : cells) {
        const AdjacentCells<D> adj = nb.adjacent(c);
        for (std::uint32_t j = nb.begin(c), stop = nb.end(c); j < stop; ++j) {
            if (P_.kind[j] != Kind::wall)
                continue;
            const int b = motion.body_of(P_.id[j]);
            if (b < 0)
                continue;
            const auto f = fluid_force_on_wall_particle(nb, kernel, case_.momentum, adj, j, P_);
            const Pose& pose = now[static_cast<std::size_t>(motion.body_object(std::size_t(b)))];
            const Eigen::Vector3d r = to_pose_point<D>(P_.x[j]) - (pose.centre + pose.d);
            Eigen::Vector3d f3 = Eigen::Vector3d::Zero();
            for (int d = 0; d < D; ++d)
                f3[d] = f[d];
            sums.add(static_cast<std::size_t>(b), f3, r.cross(f3));
        }
    }
}

template class WcsphScheme<2>;
template class WcsphScheme<3>;

} // namespace sluice
