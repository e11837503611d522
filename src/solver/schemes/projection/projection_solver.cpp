// The projection scheme's pressure solvers (docs/PROJECTION.md, "Solvers"): matrix-free
// BiCGSTAB and SOR as repeated runs of a small solver graph, the iterate exchanged between
// ranks, and the global reductions of their dot products.
#include "projection_scheme.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/physics/projection.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

namespace sluice {

// One node of the solver graph: stage 0 prepares the vector y that stage 1 multiplies by the
// scaled operator (docs/PROJECTION.md, "Solvers"). Partial dot products are summed per group
// in particle order.
template <int D>
void ProjectionScheme<D>::solver_stage(int stage, int group) {
    ProjectionData<D>& d = *proj_;
    const auto gi = static_cast<std::size_t>(group);
    ProjectionGroup<D>& G = d.groups[gi];
    if (stage == 0)
        G.partial.fill(0);
    if (d.failed)
        return;
    const NeighbourList<D>& list = neighbours_.lists[gi];
    const std::uint32_t lo = list.first;
    const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
    std::vector<Real>& x = P_.p;
    auto& q = G.partial;
    const bool bicg = d.phase == SolverPhase::bicg_dir || d.phase == SolverPhase::bicg_half;
    if (stage == 0 && bicg) {
        // Right-preconditioned BiCGSTAB: y = M^{-1} p or M^{-1} s; x advances by the previous
        // y of this group's rows (M^{-1} s of the last half step, M^{-1} p of this direction),
        // which no other group changes. Without a block (Jacobi: the scaling is in the
        // operator) M is the identity and y is p or s itself.
        const bool solve = d.preconditioned && G.block.ready();
        G.work.resize(static_cast<Eigen::Index>(solve ? G.block.size() : 0));
        // Two-level (docs/PROJECTION.md, "Two-level"): the coarse correction first, then the
        // row scaling alone (no block is factorised for "two_level"; a block, were it ready,
        // would act on the rest): y = P e + M_g^{-1} (z - A P e), e = A_c^{-1} R z (computed
        // by the main thread).
        const CoarseLevel& cl = d.coarse;
        const auto coarse_of = [&](std::uint32_t i) {
            const std::int32_t c = cl.of[i];
            return c >= 0 ? Real(cl.e[static_cast<std::size_t>(c)]) : Real(0);
        };
        for (std::uint32_t i = lo; i < hi; ++i) {
            Real z;
            if (d.phase == SolverPhase::bicg_dir) {
                if (d.first_direction) {
                    d.dir[i] = d.r[i];
                } else {
                    x[i] += Real(d.omega) * d.y[i];
                    d.r[i] = d.s[i] - Real(d.omega) * d.t[i];
                    q[0] += d.r[i] * d.r[i];
                    d.dir[i] = d.r[i] + Real(d.beta) * (d.dir[i] - Real(d.omega) * d.v[i]);
                }
                z = d.dir[i];
            } else {
                d.s[i] = d.r[i] - Real(d.alpha) * d.v[i];
                x[i] += Real(d.alpha) * d.y[i];
                z = d.s[i];
            }
            if (cl.active) {
                const std::uint32_t k = i - lo;
                double ape = 0;
                for (int at = G.ap_outer[k]; at < G.ap_outer[k + 1]; ++at) {
                    const auto c = static_cast<std::size_t>(at);
                    ape += G.ap_val[c] * cl.e[static_cast<std::size_t>(G.ap_col[c])];
                }
                z -= Real(ape);
                d.y[i] = z + coarse_of(i);
            } else {
                d.y[i] = z; // identity rows outside the factorised block
            }
            if (const std::int32_t b = solve ? G.block_index[i - lo] : -1; b >= 0)
                G.work[b] = double(z);
        }
        if (solve) {
            G.block.solve(G.work);
            for (std::uint32_t i = lo; i < hi; ++i)
                if (const std::int32_t b = G.block_index[i - lo]; b >= 0)
                    d.y[i] = cl.active ? Real(G.work[b]) + coarse_of(i) : Real(G.work[b]);
        }
        return;
    }
    if (stage == 0) {
        for (std::uint32_t i = lo; i < hi; ++i)
            switch (d.phase) {
            case SolverPhase::residual:
                // A Dirichlet row (P5) is solved by p = 0 exactly. Starting it there keeps it
                // there (its residual, direction and updates are 0 in every phase and with
                // either preconditioner), instead of converging towards 0 from the last step's
                // pressure and stopping at a rounding-size value whose sign depends on the
                // layout: P7's reference pressure takes a neighbour only when its p > 0, so
                // such a sign flip moved particles by 3e-5 m between 1 and 3 ranks
                // (docs/PROJECTION.md, "Dirichlet rows start at 0").
                if (d.row[i] == PpeRow::surface)
                    x[i] = 0;
                d.y[i] = x[i];
                break;
            case SolverPhase::sor_sweep:
                d.y[i] = x[i];
                break;
            case SolverPhase::set_zero:
                x[i] = 0;
                d.y[i] = 0;
                break;
            case SolverPhase::sor_save:
                d.s[i] = x[i];
                break;
            case SolverPhase::sor_restore:
                x[i] = d.s[i];
                d.y[i] = x[i];
                break;
            case SolverPhase::coarse_mark:
                d.y[i] = d.row[i] == PpeRow::surface ? Real(0) : Real(1);
                break;
            default: // bicg_dir, bicg_half: above
                break;
            }
        return;
    }
    if (d.phase == SolverPhase::set_zero || d.phase == SolverPhase::sor_save ||
        d.phase == SolverPhase::sor_restore || d.phase == SolverPhase::coarse_mark)
        return;
    const bool sor = d.phase == SolverPhase::sor_sweep;
    const Real omega = Real(d.relaxation);
    // The bordered system's column e (lambda on the fluid rows) and row m (their sum).
    const auto lambda = Real(d.extra.y);
    const std::size_t sum_slot = d.phase == SolverPhase::bicg_half ? 5 : 2;
    for (std::uint32_t i = lo; i < hi; ++i) {
        const std::uint32_t k = i - lo;
        Real sum = 0;
        if (sor) {
            // Gauss-Seidel order inside the group (x already updated for j < i), the previous
            // sweep's values (y) across group and rank boundaries: results do not depend on
            // the order in which groups run.
            for (std::uint32_t p = list.offset[k]; p < list.offset[k + 1]; ++p) {
                const std::uint32_t j = list.j[p];
                sum += G.a[p] * (j >= lo && j < hi ? x[j] : d.y[j]);
            }
            const Real res = row_residual(d.bhat[i], x[i], sum);
            x[i] += omega * res;
            q[0] += res * res;
            continue;
        }
        for (std::uint32_t p = list.offset[k]; p < list.offset[k + 1]; ++p)
            sum += G.a[p] * d.y[list.j[p]];
        Real ay = d.y[i] - sum;
        const bool fluid_row = d.row[i] == PpeRow::fluid;
        if (fluid_row && d.free_level)
            ay += lambda;
        if (fluid_row && (d.free_level || d.phase == SolverPhase::residual))
            q[sum_slot] += d.y[i];
        switch (d.phase) {
        case SolverPhase::residual:
            d.r[i] = d.bhat[i] - ay;
            d.rhat[i] = d.r[i];
            q[0] += d.r[i] * d.r[i];
            q[1] += d.bhat[i] * d.bhat[i];
            // What decides whether the level is free, counted on every solve.
            if (fluid_row)
                q[3] += 1;
            else if (P_.kind[i] == Kind::fluid)
                q[4] += 1;
            break;
        case SolverPhase::bicg_dir:
            d.v[i] = ay;
            q[1] += d.rhat[i] * ay;
            break;
        case SolverPhase::bicg_half:
            d.t[i] = ay;
            q[0] += ay * d.s[i];
            q[1] += ay * ay;
            q[2] += d.rhat[i] * d.s[i];
            q[3] += d.rhat[i] * ay;
            q[4] += d.s[i] * d.s[i];
            break;
        default:
            break;
        }
    }
}

template <int D>
std::array<double, 7> ProjectionScheme<D>::reduce_partials(int count, bool failed_here,
                                                           std::vector<double>* coarse) {
    // Per group in group order, then across ranks in rank order: every rank gets the same
    // numbers, so every rank takes the same decisions (iterate, stop, fail).
    std::array<double, 7> sum{};
    for (const auto& G : proj_->groups)
        for (int k = 0; k < count; ++k)
            sum[static_cast<std::size_t>(k)] += G.partial[static_cast<std::size_t>(k)];
    sum[6] = failed_here ? 1.0 : 0.0;
    if (!rank_.comm.parallel())
        return sum;
    const double t0 = tasks::clock_seconds();
    const std::size_t extra = coarse != nullptr ? coarse->size() : 0;
    std::vector<double> mine(sum.begin(), sum.end());
    if (extra > 0)
        mine.insert(mine.end(), coarse->begin(), coarse->end());
    const auto all = rank_.comm.all_gather(std::span<const std::byte>(
        reinterpret_cast<const std::byte*>(mine.data()), mine.size() * sizeof(double)));
    rank_.between.push_back(
        {"solver reduce", -1, true, mine.size() * sizeof(double), t0, tasks::clock_seconds()});
    std::array<double, 7> global{};
    if (extra > 0)
        std::fill(coarse->begin(), coarse->end(), 0.0);
    std::vector<double> part(mine.size());
    for (const auto& b : all) {
        std::memcpy(part.data(), b.data(), part.size() * sizeof(double));
        for (std::size_t k = 0; k < 6; ++k)
            global[k] += part[k];
        global[6] = std::max(global[6], part[6]);
        for (std::size_t k = 0; k < extra; ++k)
            (*coarse)[k] += part[7 + k];
    }
    return global;
}

template <int D>
std::string ProjectionScheme<D>::solve_pressure(std::string& error) {
    ProjectionData<D>& d = *proj_;
    const ProjectionSettings& ps = case_.cfg.projection;
    const auto t0 = std::chrono::steady_clock::now();
    bool failed = false;
    CoarseLevel& cl = d.coarse;
    cl.active = false;
    const auto run = [&](SolverPhase phase, int count) {
        d.phase = phase;
        try {
            d.solver_graph->run();
        } catch (const std::exception& e) {
            if (error.empty())
                error = e.what();
            d.failed = true;
        }
        // Two-level: R v or R t, summed with the partials (BiCGSTAB's recurrences then give
        // R of the next vector to precondition without another run).
        const bool product = phase == SolverPhase::bicg_dir || phase == SolverPhase::bicg_half;
        if (cl.active && product)
            restrict_owned(phase == SolverPhase::bicg_dir ? d.v : d.t, cl.restricted);
        const auto g =
            reduce_partials(count, !error.empty(), cl.active && product ? &cl.restricted : nullptr);
        if (cl.active && product)
            std::swap(phase == SolverPhase::bicg_dir ? cl.v : cl.t, cl.restricted);
        if (g[6] > 0) {
            d.failed = true;
            failed = true;
        }
        return g;
    };
    PressureSolveRecord rec;
    // The bordered system's extra component (ProjectionData::free_level): e.x = lambda.
    auto& e = d.extra;
    e = {};
    d.free_level = false;
    d.preconditioned = ps.solver == PressureSolver::bicgstab &&
                       ps.preconditioner != PressurePreconditioner::jacobi;
    auto g = run(SolverPhase::residual, 5);
    // No fluid particle on a Dirichlet row: the level is free; the counts are exact sums.
    if (!failed && g[4] == 0 && g[3] > 0) {
        d.free_level = true;
        d.gauge = case_.cfg.background_pressure;
        d.fluid_rows = g[3];
    }
    // The residual's and the right-hand side's components along lambda (e.x = 0 here).
    const auto border_residual = [&](std::array<double, 7>& sums) {
        if (!d.free_level)
            return;
        e.r = d.gauge - sums[2] / d.fluid_rows;
        e.rhat = e.r;
        sums[0] += e.r * e.r;
        sums[1] += d.gauge * d.gauge;
    };
    border_residual(g);
    const double bnorm = std::sqrt(g[1]);
    double rnorm = std::sqrt(g[0]);
    // Without a free surface the source can vanish to rounding (a divergence-free field on a
    // lattice) while the starting iterate is far from the solution: the residual is then
    // measured against the larger of |bhat| and the initial residual.
    const double scale = d.free_level ? std::max(bnorm, rnorm) : bnorm;
    const double tol = ps.tolerance * scale;
    bool converged = rnorm <= tol;
    std::string breakdown;
    if (!failed && bnorm == 0) {
        run(SolverPhase::set_zero, 0);
        converged = true;
    }
    if (!failed && !converged && d.free_level && ps.solver == PressureSolver::sor)
        return "the pressure Poisson system has no free-surface row (a periodic or closed "
               "flow): its pressure level is free, which projection.solver = \"sor\" does not "
               "handle; use projection.solver = \"bicgstab\"";
    // The coarse level of the two-level preconditioner, for this solve: not with a free level
    // (A_c would be singular as A is) nor where A_c cannot be factorised (then the solve goes on
    // with the row scaling alone; the decision is the same on every rank, which all factorise
    // the same A_c).
    if (!failed && !converged && bnorm > 0 && !d.free_level &&
        ps.solver == PressureSolver::bicgstab &&
        ps.preconditioner == PressurePreconditioner::two_level) {
        run(SolverPhase::coarse_mark, 0);
        if (!failed && setup_coarse()) {
            restrict_owned(d.r, cl.r);
            reduce_partials(0, false, &cl.r);
            cl.active = true;
        }
    }
    // e = A_c^{-1} R z for the vector z the next run preconditions.
    const auto coarse_solve = [&](const std::vector<double>& rz) {
        cl.e = rz;
        cl.system.solve(cl.e);
    };
    int it = 0;
    if (!failed && !converged && ps.solver == PressureSolver::bicgstab) {
        // BiCGSTAB (van der Vorst 1992) on the row-scaled system, i.e. with the Jacobi
        // preconditioner applied from the left. (rhat, r_new) follows from the identity
        // (rhat, s - omega t) = (rhat, s) - omega (rhat, t); the true |r| is summed when r is
        // formed, at the start of the next direction update.
        double rho = g[0];
        d.first_direction = true;
        while (true) {
            if (d.free_level) { // the vector updates of bicg_dir's prepare stage, for lambda
                if (!d.first_direction) {
                    e.x += d.omega * e.s;
                    e.r = e.s - d.omega * e.t;
                    e.dir = e.r + d.beta * (e.dir - d.omega * e.v);
                } else {
                    e.dir = e.r;
                }
                e.y = e.dir;
            }
            if (cl.active) { // the same recurrences on the restricted vectors
                if (d.first_direction) {
                    cl.p = cl.r;
                } else {
                    for (std::size_t k = 0; k < cl.p.size(); ++k) {
                        cl.r[k] = cl.s[k] - d.omega * cl.t[k];
                        cl.p[k] = cl.r[k] + d.beta * (cl.p[k] - d.omega * cl.v[k]);
                    }
                }
                coarse_solve(cl.p);
            }
            g = run(SolverPhase::bicg_dir, d.free_level ? 3 : 2);
            if (failed)
                break;
            if (d.free_level) {
                e.v = g[2] / d.fluid_rows;
                g[1] += e.rhat * e.v;
                if (!d.first_direction)
                    g[0] += e.r * e.r;
            }
            if (!d.first_direction) {
                rnorm = std::sqrt(g[0]);
                if (rnorm <= tol) {
                    converged = true;
                    break;
                }
            }
            if (it >= ps.max_iterations)
                break;
            d.first_direction = false;
            if (g[1] == 0 || !std::isfinite(g[1])) {
                breakdown = "(rhat, v) = 0";
                break;
            }
            d.alpha = rho / g[1];
            if (d.free_level) {
                e.s = e.r - d.alpha * e.v;
                e.x += d.alpha * e.dir;
                e.y = e.s;
            }
            if (cl.active) {
                for (std::size_t k = 0; k < cl.s.size(); ++k)
                    cl.s[k] = cl.r[k] - d.alpha * cl.v[k];
                coarse_solve(cl.s);
            }
            g = run(SolverPhase::bicg_half, d.free_level ? 6 : 5);
            if (failed)
                break;
            if (d.free_level) {
                e.t = g[5] / d.fluid_rows;
                g[0] += e.t * e.s;
                g[1] += e.t * e.t;
                g[2] += e.rhat * e.s;
                g[3] += e.rhat * e.t;
                g[4] += e.s * e.s;
            }
            ++it;
            const double snorm = std::sqrt(std::max(0.0, g[4]));
            if (snorm <= tol) { // x already holds x + alpha p
                rnorm = snorm;
                converged = true;
                break;
            }
            if (!(g[1] > 0) || g[0] == 0) {
                breakdown = "omega = 0";
                break;
            }
            d.omega = g[0] / g[1];
            const double rho_new = g[2] - d.omega * g[3];
            d.beta = (rho_new / rho) * (d.alpha / d.omega);
            rho = rho_new;
        }
    }
    if (!failed && !converged && ps.solver == PressureSolver::sor) {
        d.relaxation = ps.relaxation;
        const double r0 = rnorm;
        if (d.relaxation > 1)
            run(SolverPhase::sor_save, 0);
        while (it < ps.max_iterations) {
            g = run(SolverPhase::sor_sweep, 1);
            if (failed)
                break;
            ++it;
            rnorm = std::sqrt(g[0]);
            // The hybrid sweep is Jacobi across cell groups and ranks, where over-relaxation
            // diverges (docs/PROJECTION.md, "SOR"): once the residual has grown tenfold over
            // the starting one, the solve starts again from its starting iterate without
            // over-relaxation (the sweeps so far count). Decided on global sums: every rank
            // does the same.
            if (d.relaxation > 1 && (!std::isfinite(rnorm) || rnorm > 10 * r0)) {
                run(SolverPhase::sor_restore, 0);
                d.relaxation = 1;
                rec.relaxation_dropped = true;
                continue;
            }
            // Hybrid SOR is not guaranteed to converge for a non-symmetric system; stop early
            // when it clearly diverges.
            if (!std::isfinite(rnorm) || rnorm > 1e6 * bnorm) {
                breakdown = "the sweep diverges; try a smaller projection.relaxation";
                break;
            }
            if (rnorm <= tol) {
                converged = true;
                break;
            }
        }
    }
    if (!failed) {
        // The reported residual is recomputed from the final iterate, not the recursion's.
        e.y = e.x;
        g = run(SolverPhase::residual, 5);
        border_residual(g);
        rec.source_shift = e.x;
        rec.residual = scale > 0 ? std::sqrt(g[0]) / scale : std::sqrt(g[0]);
        rec.free_level = d.free_level;
    }
    rec.iterations = it;
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    d.last = rec;
    if (!failed && !converged) {
        const char* name = ps.solver == PressureSolver::sor ? "SOR" : "BiCGSTAB";
        return fmt::format(
            "the pressure Poisson solve ({}) did not converge at step {}, t = {:.6g} s: "
            "relative residual {:.3e} after {} iterations, tolerance {:.3e}{}; raise "
            "projection.max_iterations, loosen projection.tolerance or reduce the time step",
            name, clock_.steps + 1, clock_.time + clock_.dt, rec.residual, it, ps.tolerance,
            breakdown.empty() ? std::string() : fmt::format(" (breakdown: {})", breakdown));
    }
    if (!failed)
        d.totals.add(rec);
    return {};
}

#define SLUICE_PROJECTION_SOLVER_MEMBERS(D)                                                        \
    template void ProjectionScheme<D>::solver_stage(int, int);                                     \
    template std::string ProjectionScheme<D>::solve_pressure(std::string&);                        \
    template std::array<double, 7> ProjectionScheme<D>::reduce_partials(int, bool,                 \
                                                                        std::vector<double>*);
SLUICE_PROJECTION_SOLVER_MEMBERS(2)
SLUICE_PROJECTION_SOLVER_MEMBERS(3)
#undef SLUICE_PROJECTION_SOLVER_MEMBERS

} // namespace sluice
