// The projection scheme's binding to the runtime (docs/PROJECTION.md): its stages, declared
// once each as rows of its three graphs' tables, their bodies, and the step around the
// pressure solve (projection_solver.cpp). The formulas are in
// include/sluice/physics/projection.hpp, wmls.hpp and drift.hpp.
#include "projection_scheme.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/physics/drift.hpp"
#include "sluice/physics/projection.hpp"
#include "sluice/physics/selected_operators.hpp"
#include "sluice/physics/shifting.hpp"
#include "sluice/physics/wmls.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <limits>

namespace sluice {

namespace {

// Offsets of the full lattice of spacing dx within re of a particle, itself excluded.
template <int D>
std::vector<Vec<D>> lattice_offsets(Real dx, Real re) {
    std::vector<Vec<D>> out;
    const int m = static_cast<int>(std::ceil(re / dx));
    std::array<int, 3> k{};
    const int n = 2 * m + 1;
    const int total = D == 2 ? n * n : n * n * n;
    for (int idx = 0; idx < total; ++idx) {
        int r = idx;
        Vec<D> o;
        for (int d = 0; d < D; ++d) {
            k[static_cast<std::size_t>(d)] = r % n - m;
            r /= n;
            o[d] = Real(k[static_cast<std::size_t>(d)]) * dx;
        }
        const Real len = o.norm();
        if (len > 0 && len < re)
            out.push_back(o);
    }
    return out;
}

// x_j - x_i for pair p of particle i's list, with the periodic image of j nearest to i.
template <int D>
Vec<D> pair_offset(const NeighbourList<D>& list, const std::vector<Vec<D>>& x, std::uint32_t i,
                   std::uint32_t p) {
    Vec<D> dx = x[i] - x[list.j[p]];
    if (list.periodic)
        dx += list.shift[p];
    return -dx;
}

// Particle shifting (docs/PROJECTION.md, "Particle shifting"; fickian_shift) of the
// fluid particles of a group, from the positions at the start of the step, over the step's
// neighbour list (every particle within re, fluid and wall, each of volume dx^D). Near the
// free surface: a P5 row or a kernel sum below 0.95 (as WCSPH's particle_shift).
template <int D, class K>
void shift_group(const K& kernel, const NeighbourList<D>& list, const Particles<D>& P,
                 const std::vector<PpeRow>& row, Real coefficient, Real dx, Real max_shift,
                 std::vector<Vec<D>>& shift) {
    const Real volume = D == 2 ? dx * dx : dx * dx * dx;
    const Real w_dx = kernel.W(dx);
    const std::uint32_t lo = list.first;
    const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
    for (std::uint32_t i = lo; i < hi; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const std::uint32_t k = i - lo;
        Vec<D> grad_c = Vec<D>::Zero(), grad_plain = Vec<D>::Zero();
        Real completeness = 0;
        for (std::uint32_t p = list.offset[k]; p < list.offset[k + 1]; ++p) {
            Vec<D> r = P.x[i] - P.x[list.j[p]];
            if (list.periodic)
                r += list.shift[p];
            const Real len = r.norm();
            const Real w = kernel.W(len);
            completeness += volume * w;
            if (len <= 0)
                continue;
            const Vec<D> grad_w = grad_W<D>(kernel, r, len);
            grad_c += shift_pair_term<D>(grad_w, w, w_dx, volume);
            grad_plain += volume * grad_w;
        }
        const bool near_surface = row[i] == PpeRow::surface || completeness < Real(0.95);
        shift[i] = fickian_shift<D>(coefficient, grad_c, near_surface, grad_plain, max_shift);
    }
}

} // namespace

template <int D>
void ProjectionScheme<D>::init_projection() {
    proj_ = std::make_unique<ProjectionData<D>>();
    ProjectionData<D>& d = *proj_;
    d.re = Real(kernel_support_factor(case_.cfg.kernel) * case_.h);
    d.surface_diameter = Real(case_.cfg.projection.surface_diameter_over_dx * case_.cfg.dx);
    d.collision_distance = Real(wall_collision_distance_over_dx * case_.cfg.dx);
    d.selections = {case_.cfg.neighbours.gradient, case_.cfg.neighbours.laplacian,
                    case_.cfg.neighbours.free_surface};
    d.deviation_weight = case_.cfg.projection.deviation_weight == DeviationWeight::smooth
                             ? LsWeight::smooth
                             : LsWeight::pnu_mps;
    const std::vector<Vec<D>> lattice = lattice_offsets<D>(Real(case_.cfg.dx), d.re);
    for (const Vec<D>& o : lattice) {
        d.n0 += ls_weight(o.norm(), d.re, d.weight);
        d.n0_deviation += ls_weight(o.norm(), d.re, d.deviation_weight);
    }
    const auto st = wmls_stencil<D>(lattice, d.re, d.weight);
    d.lattice_sum = st.laplacian.sum();
    // Incompressible: every fluid particle keeps rho0 and the volume dx^D.
    const Real volume = Real(std::pow(case_.cfg.dx, D));
    for (std::size_t i = 0; i < P_.size(); ++i)
        if (P_.kind[i] == Kind::fluid) {
            P_.rho[i] = Real(case_.cfg.rho0);
            P_.mass[i] = Real(case_.cfg.rho0) * volume;
        }
    // No skin: the state carries no reference positions.
    for (auto* halo : {&d.main_halo, &d.solver_halo, &d.correct_halo})
        *halo = std::make_unique<HaloFields<D>>(P_, cells_.ranges, cells_.grid, rank_.plan, false);
}

template <int D>
std::unique_ptr<tasks::StepGraph> ProjectionScheme<D>::build_graph(const GraphSite& site) {
    using tasks::Reach;
    ProjectionData<D>& d = *proj_;
    d.groups.resize(site.neighbours->size());
    // The stages of the three graphs, one row each, with the halo field each sends.
    const std::vector<StageRow> main{{"stencil", Reach::neighbourhood,
                                      HaloField{"u_star", std::nullopt, {halo_column(d.u_star)}}},
                                     {"ppe_source", Reach::neighbourhood, std::nullopt}};
    const std::vector<StageRow> solver{
        {"ppe_prepare", Reach::self, HaloField{"iterate", std::nullopt, {halo_column(d.y)}}},
        {"ppe_apply", Reach::neighbourhood, std::nullopt}};
    const std::vector<StageRow> correct{{"correct", Reach::neighbourhood, std::nullopt}};
    // The old graphs live in the arena too.
    d.solver_graph.reset();
    d.correct_graph.reset();
    auto graph = graph_of_rows<D>(
        main, d.main_halo->state(),
        [this](int stage, int group) {
            std::visit([&](const auto& k) { projection_stage(k, stage, group); }, case_.kernel);
        },
        site, *d.main_halo);
    d.solver_graph = graph_of_rows<D>(
        solver, std::nullopt, [this](int stage, int group) { solver_stage(stage, group); }, site,
        *d.solver_halo);
    // The correction reads the neighbours' pressures, the solution of the solve.
    d.correct_graph = graph_of_rows<D>(
        correct, HaloField{"pressure", std::nullopt, {halo_column(P_.p)}},
        [this](int, int group) { correct_stage(group); }, site, *d.correct_halo);
    return graph;
}

// Stage 0 "stencil": neighbour list, WMLS coefficients, free surface, number density, wall
// rows (P6) and the predictor (P1). Stage 1 "ppe_source": the source (P3) and the scaled
// fluid rows (P4, P5); it reads the neighbours' u*.
template <int D>
template <class K>
void ProjectionScheme<D>::projection_stage(const K& kernel, int stage, int group) {
    ProjectionData<D>& d = *proj_;
    if (d.failed)
        return;
    const auto gi = static_cast<std::size_t>(group);
    Neighbourhood<D> nb{&cells_.grid, &cells_.ranges, std::span<const Vec<D>>(P_.x),
                        kernel.support()};
    NeighbourList<D>& list = neighbours_.lists[gi];
    ProjectionGroup<D>& G = d.groups[gi];
    const auto& cells = cells_.topo.cells[gi];
    const Real re = d.re;
    const LsWeight weight = d.weight;
    if (stage == 0) {
        nb.build_list(
            cells, list, [re, weight](Real r2) { return ls_weight(std::sqrt(r2), re, weight); },
            [this](std::uint32_t i) { return P_.kind[i] == Kind::wall; },
            [this](std::uint32_t j) { return P_.kind[j] == Kind::fluid; });
        G.lap.resize(list.pairs);
        G.grad.resize(list.pairs);
        if (case_.cfg.projection.correction_gradient == CorrectionGradient::first_order)
            G.grad_correct.resize(list.pairs);
        G.a.resize(list.pairs);
    }
    const auto offset_of = [&](std::uint32_t i, std::uint32_t p) {
        return pair_offset<D>(list, P_.x, i, p);
    };
    for (CellIndex c : cells)
        for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
            const std::uint32_t k = i - list.first;
            const std::uint32_t b = list.offset[k], e = list.offset[k + 1];
            if (stage == 0 && P_.kind[i] == Kind::wall) {
                // P6: Adami's extrapolation as a row of the system, smooth weights.
                Real wsum = 0, rhs = 0;
                for (std::uint32_t p = b; p < e; ++p) {
                    const Vec<D> off = offset_of(i, p);
                    const Real w = ls_weight(off.norm(), re, LsWeight::smooth);
                    G.a[p] = w;
                    wsum += w;
                    rhs += w * wall_row_term<D>(Real(case_.cfg.rho0), case_.momentum.gravity, -off);
                }
                for (std::uint32_t p = b; p < e; ++p)
                    G.a[p] = wsum > 0 ? G.a[p] / wsum : 0;
                d.row[i] = wsum > 0 ? PpeRow::wall : PpeRow::surface;
                d.bhat[i] = wsum > 0 ? rhs / wsum : 0;
                // The wall row says dp/dn = rho0 g.n = rho0/dt (u*_w - u_w).n: the divergence
                // of u* must see the same u*_w = u_w + dt g (docs/PROJECTION.md, "Walls").
                d.u_star[i] = P_.v[i] + clock_.dt * case_.momentum.gravity;
                continue;
            }
            if (P_.kind[i] == Kind::wall)
                continue;
            if (stage == 0) {
                G.scratch_offsets.clear();
                G.scratch_pairs.clear();
                // n: the operators' (PNU-MPS) weight, for the surface criterion; n_dev: the
                // density-deviation term's (P3; projection.deviation_weight).
                Real n = 0, n_dev = 0;
                const bool smooth_deviation = d.deviation_weight != d.weight;
                // Fluid-fluid collision on the velocities at the start of the step
                // (docs/PROJECTION.md, "Collisions").
                Vec<D> v_i = P_.v[i];
                for (std::uint32_t p = b; p < e; ++p) {
                    G.lap[p] = 0;
                    G.grad[p].setZero();
                    const std::uint32_t j = list.j[p];
                    if (j == i)
                        continue;
                    const Vec<D> off = offset_of(i, p);
                    G.scratch_offsets.push_back(off);
                    G.scratch_pairs.push_back(p);
                    n += list.factor[p];
                    if (smooth_deviation)
                        n_dev += ls_weight(off.norm(), re, d.deviation_weight);
                    if (case_.cfg.projection.fluid_collision && P_.kind[j] == Kind::fluid)
                        v_i += collision_velocity_change<D>(
                            P_.v[i], P_.v[j], off, d.collision_distance,
                            fluid_collision_restitution, Real(clock_.dt));
                }
                d.number_density[i] = smooth_deviation ? n_dev : n;
                // The WMLS fits and the surface test, each over its operator's neighbours
                // ([neighbours.<operator>]; all of them with radius selection).
                const std::span<const Vec<D>> offsets(G.scratch_offsets);
                const std::size_t count = offsets.size();
                const bool first_order =
                    case_.cfg.projection.correction_gradient == CorrectionGradient::first_order;
                G.scratch_grad.resize(count);
                G.scratch_lap.resize(count);
                G.scratch_linear.resize(first_order ? count : 0);
                const auto ops = selected_operators<D>(
                    offsets, d.selections, re, Real(case_.cfg.dx), weight, d.surface_diameter,
                    std::span<Vec<D>>(G.scratch_grad), std::span<Real>(G.scratch_lap),
                    std::span<Vec<D>>(G.scratch_linear), G.scratch_ops);
                Vec<D> lap_u = Vec<D>::Zero();
                for (std::size_t m = 0; m < count; ++m) {
                    const std::uint32_t p = G.scratch_pairs[m];
                    G.lap[p] = G.scratch_lap[m];
                    G.grad[p] = G.scratch_grad[m];
                    lap_u += G.lap[p] * (P_.v[list.j[p]] - P_.v[i]);
                }
                if (first_order) {
                    // P7's gradient from the first-order fit; where that is singular too,
                    // the second-order coefficients stay.
                    for (std::uint32_t p = b; p < e; ++p)
                        G.grad_correct[p] = G.grad[p];
                    if (ops.linear_ok)
                        for (std::size_t m = 0; m < count; ++m)
                            G.grad_correct[G.scratch_pairs[m]] = G.scratch_linear[m];
                }
                const bool surface = !ops.ok || ops.free_surface ||
                                     below_surface_density(
                                         n, d.n0, Real(case_.cfg.projection.surface_density_ratio));
                d.row[i] = surface ? PpeRow::surface : PpeRow::fluid;
                // A stencil that cannot fit second derivatives gives no viscous term.
                d.u_star[i] = predicted_velocity<D>(v_i, ops.laplacian_ok ? lap_u : Vec<D>::Zero(),
                                                    Real(case_.cfg.viscosity / case_.cfg.rho0),
                                                    case_.momentum.gravity, Real(clock_.dt));
                continue;
            }
            // Stage 1.
            Real sum = 0, div = 0;
            for (std::uint32_t p = b; p < e; ++p) {
                sum += G.lap[p];
                div += G.grad[p].dot(d.u_star[list.j[p]] - d.u_star[i]);
            }
            if (d.row[i] == PpeRow::fluid && sum <= ppe_min_diagonal_fraction * d.lattice_sum)
                d.row[i] = PpeRow::surface;
            if (d.row[i] == PpeRow::surface) {
                for (std::uint32_t p = b; p < e; ++p)
                    G.a[p] = 0;
                d.bhat[i] = 0;
                continue;
            }
            const Real src =
                ppe_source(Real(case_.cfg.rho0), Real(clock_.dt), Real(case_.cfg.projection.gamma),
                           div, d.number_density[i], d.n0_deviation);
            for (std::uint32_t p = b; p < e; ++p)
                G.a[p] = G.lap[p] / sum;
            d.bhat[i] = -src / sum;
        }
    if (stage == 1 && case_.cfg.projection.solver == PressureSolver::bicgstab &&
        (case_.cfg.projection.preconditioner == PressurePreconditioner::block_ilu0 ||
         case_.cfg.projection.preconditioner == PressurePreconditioner::block_lu))
        factor_block(group);
}

// The wall collision of fluid particle i after P7 (docs/PROJECTION.md, "Wall collision";
// projection.hpp): its velocity after it; the momentum it gave the walls is recorded in
// `contacts`, at the nearest wall particle it collided with.
template <int D>
Vec<D> ProjectionScheme<D>::collide_with_walls(std::uint32_t i, const NeighbourList<D>& list,
                                               std::uint32_t b, std::uint32_t e, Vec<D> v,
                                               std::vector<WallContact<D>>& contacts) const {
    const ProjectionData<D>& d = *proj_;
    const Real distance = d.collision_distance, dt = Real(clock_.dt);
    const auto record = [&](std::uint32_t j, const Vec<D>& before) {
        contacts.push_back({P_.id[i], P_.id[j], P_.x[j], P_.mass[i] * (before - v) / dt});
    };
    if (case_.cfg.projection.wall_collision == WallCollision::line_of_centres) {
        // Along the line of centres to each wall particle in turn (before 2026-11-28).
        for (std::uint32_t p = b; p < e; ++p) {
            const std::uint32_t j = list.j[p];
            if (P_.kind[j] != Kind::wall)
                continue;
            const Vec<D> before = v;
            v = wall_collision<D>(v, pair_offset<D>(list, P_.x, i, p), distance, dt);
            if (v != before)
                record(j, before);
        }
        return v;
    }
    // The nearest wall particle the step would bring within the distance names the contact.
    Real nearest = std::numeric_limits<Real>::infinity();
    std::uint32_t hit = 0;
    for (std::uint32_t p = b; p < e; ++p) {
        const std::uint32_t j = list.j[p];
        if (P_.kind[j] != Kind::wall)
            continue;
        const Vec<D> off = pair_offset<D>(list, P_.x, i, p);
        const Real r = off.norm();
        // Equal distances (a lattice) name the smaller id, whatever the list's order.
        const bool nearer = r < nearest || (r == nearest && P_.id[j] < P_.id[hit]);
        if (nearer && wall_collides<D>(v, off, distance, dt)) {
            nearest = r;
            hit = j;
        }
    }
    if (!std::isfinite(nearest))
        return v;
    // Only a colliding particle needs the wall's normal, from all its wall neighbours.
    Vec<D> centre = Vec<D>::Zero();
    for (std::uint32_t p = b; p < e; ++p)
        if (P_.kind[list.j[p]] == Kind::wall) {
            const Vec<D> off = pair_offset<D>(list, P_.x, i, p);
            centre -= ls_weight(off.norm(), d.re, LsWeight::smooth) * off;
        }
    const Vec<D> before = v;
    v = wall_normal_collision<D>(v, wall_normal_at<D>(centre));
    // Backstop, for corners: a wall particle already within the distance and still approached
    // on the line of centres stops that approach.
    for (std::uint32_t p = b; p < e; ++p)
        if (P_.kind[list.j[p]] == Kind::wall)
            v = wall_collision<D>(v, pair_offset<D>(list, P_.x, i, p), distance);
    if (v != before)
        record(hit, before);
    return v;
}

// Stage "correct": velocity correction (P7) and position update (P8), state checks and the
// time-step limits of the next step.
template <int D>
void ProjectionScheme<D>::correct_stage(int group) {
    ProjectionData<D>& d = *proj_;
    const auto gi = static_cast<std::size_t>(group);
    const NeighbourList<D>& list = neighbours_.lists[gi];
    ProjectionGroup<D>& G = d.groups[gi];
    G.contacts.clear();
    const std::vector<Vec<D>>& grad_coefficient =
        case_.cfg.projection.correction_gradient == CorrectionGradient::first_order ? G.grad_correct
                                                                                    : G.grad;
    const std::uint32_t lo = list.first;
    const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
    TimeStepLimits lim;
    Real speed = 0;
    std::int64_t leaving = 0;
    std::string failure;
    const Real g_norm = case_.momentum.gravity.norm();
    const PressureLevel level = d.free_level ? PressureLevel::free : PressureLevel::surface;
    const bool hydrostatic_reference =
        case_.cfg.projection.correction_reference == CorrectionReference::hydrostatic;
    const Real rho0 = Real(case_.cfg.rho0);
    const Vec<D>& gravity = case_.momentum.gravity;
    // Particle shifting, D = A h^2 per step (not scaled by the flow speed: still water needs
    // it too), added to P8's displacement.
    const bool shifting = case_.cfg.projection.shifting > 0 && !d.failed;
    if (shifting)
        std::visit(
            [&](const auto& kernel) {
                shift_group<D>(kernel, list, P_, d.row,
                               Real(case_.cfg.projection.shifting * case_.h * case_.h),
                               Real(case_.cfg.dx), Real(0.1 * case_.cfg.dx), P_.shift);
            },
            case_.kernel);
    for (std::uint32_t i = lo; i < hi; ++i) {
        if (P_.kind[i] != Kind::fluid || d.failed) {
            P_.x_next[i] = P_.x[i];
            P_.v_next[i] = P_.v[i];
            P_.v_half_next[i] = P_.v_half[i];
            P_.rho_next[i] = P_.rho[i];
            continue;
        }
        const std::uint32_t k = i - lo;
        // P7 with the stabilised gradient (docs/PROJECTION.md, P7): the reference is the
        // smallest positive pressure around i (surface particles, at 0, are not a reference
        // for their interior neighbours), less its hydrostatic difference from i with
        // correction_reference = "hydrostatic", which also floors the walls' pressures at the
        // hydrostatic continuation of i's.
        const Real p_i = gradient_pressure(P_.p[i], level);
        Real p_ref = p_i;
        if (hydrostatic_reference) {
            for (std::uint32_t p = list.offset[k]; p < list.offset[k + 1]; ++p)
                p_ref = hydrostatic_gradient_reference(
                    p_ref, P_.p[list.j[p]], rho0 * gravity.dot(pair_offset<D>(list, P_.x, i, p)),
                    level);
            p_ref = clamp_gradient_reference(p_ref, level);
        } else
            for (std::uint32_t p = list.offset[k]; p < list.offset[k + 1]; ++p)
                p_ref = gradient_reference(p_ref, P_.p[list.j[p]], level);
        Vec<D> grad = Vec<D>::Zero();
        for (std::uint32_t p = list.offset[k]; p < list.offset[k + 1]; ++p) {
            const std::uint32_t j = list.j[p];
            Real pj = gradient_pressure(P_.p[j], level);
            if (hydrostatic_reference && level == PressureLevel::surface &&
                P_.kind[j] == Kind::wall)
                pj = wall_gradient_pressure(P_.p[j], p_i,
                                            rho0 * gravity.dot(pair_offset<D>(list, P_.x, i, p)));
            grad += grad_coefficient[p] * (pj - p_ref);
        }
        Vec<D> v = collide_with_walls(
            i, list, list.offset[k], list.offset[k + 1],
            corrected_velocity<D>(d.u_star[i], grad, rho0, Real(clock_.dt)), G.contacts);
        Vec<D> x = projection_drift<D>(P_.x[i], v, Real(clock_.dt), case_.walls,
                                       shifting ? &P_.shift[i] : nullptr);
        cells_.grid.wrap(x);
        P_.a[i] = (v - P_.v[i]) / clock_.dt;
        P_.v_half_next[i] = v;
        P_.x_next[i] = x;
        P_.v_next[i] = v;
        P_.rho_next[i] = P_.rho[i];
        // The force limit sees at least gravity, which the predictor integrates explicitly.
        lim = min(lim,
                  particle_time_step(case_.time_step, cfl_sound_speed(true, case_.cfg.sound_speed),
                                     v.norm(), std::max(P_.a[i].norm(), g_norm)));
        speed = std::max(speed, v.norm());
        if (case_.bounds.remove_outside && outside_domain(case_.bounds, x))
            ++leaving;
        if (failure.empty()) {
            const std::string what = state_fault(case_.bounds, x, v, P_.rho[i]);
            if (!what.empty())
                failure = fmt::format("particle {} reached {} at step {}, t = {:.6g} s: x = [{}], "
                                      "v = [{}]",
                                      P_.id[i], what, clock_.steps + 1, clock_.time + clock_.dt,
                                      fmt::join(x.data(), x.data() + D, ", "),
                                      fmt::join(v.data(), v.data() + D, ", "));
        }
    }
    results_.limits[gi] = lim;
    results_.speed[gi] = speed;
    results_.leaving[gi] = leaving;
    results_.failure[gi] = std::move(failure);
}

template <int D>
void ProjectionScheme<D>::run_projection(tasks::StepGraph& graph) {
    ProjectionData<D>& d = *proj_;
    d.resize(P_.size());
    d.failed = false;
    d.main_halo->record_halo_cells(neighbours_.rebuilt);
    for (tasks::StepGraph* g : {d.solver_graph.get(), d.correct_graph.get()})
        g->inject_receive_delay(rank_.receive_delay);
    // A task that throws must not leave peers waiting: every rank runs every graph and every
    // reduction of the solve; the error is raised after the last one.
    std::string error;
    try {
        graph.run();
    } catch (const std::exception& e) {
        error = e.what();
        d.failed = true;
    }
    const std::string unconverged = solve_pressure(error);
    try {
        d.correct_graph->run();
    } catch (const std::exception& e) {
        if (error.empty())
            error = e.what();
    }
    d.contacts.clear();
    for (const ProjectionGroup<D>& G : d.groups)
        d.contacts.insert(d.contacts.end(), G.contacts.begin(), G.contacts.end());
    // Every rank has the same message (the decision came from global sums); the step's
    // reduction raises it as a RunError.
    if (!unconverged.empty() && !results_.failure.empty())
        results_.failure[0] = unconverged;
    if (!error.empty())
        throw std::runtime_error(error);
}

template class ProjectionScheme<2>;
template class ProjectionScheme<3>;

} // namespace sluice
