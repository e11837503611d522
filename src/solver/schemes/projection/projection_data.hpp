#pragma once
// State of the projection scheme (docs/PROJECTION.md) that lives beside a Simulation<D>: the
// per-pair WMLS coefficients of this step, the per-particle rows of the pressure Poisson
// equation, the Krylov/SOR vectors, the solver's own step graphs and their halo data. Private to
// src/solver.
#include "sluice/core/particles.hpp"
#include "sluice/physics/ls_weight.hpp"
#include "sluice/physics/selected_operators.hpp"
#include "sluice/physics/wall_loads.hpp"
#include "sluice/solver/block_preconditioner.hpp"
#include "sluice/solver/coarse_system.hpp"
#include "sluice/solver/halo_fields.hpp"
#include "sluice/solver/pressure_solve.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace sluice {

// What a row of the scaled pressure system says (docs/PROJECTION.md, P4-P6).
enum class PpeRow : std::uint8_t { fluid, surface, wall };

// Per cell group, aligned with the group's neighbour list (pair p of lists_[g]).
template <int D>
struct ProjectionGroup {
    std::vector<Real> lap;            // WMLS Laplacian coefficient L_ij (fluid rows)
    std::vector<Vec<D>> grad;         // WMLS gradient coefficient (fluid rows): divergence in P3
    std::vector<Vec<D>> grad_correct; // correction P7's coefficient (first-order option only)
    std::vector<Real> a;              // coefficient a_ij of the scaled system (every row)
    std::vector<Vec<D>> scratch_offsets, scratch_linear, scratch_grad;
    std::vector<Real> scratch_lap;
    std::vector<std::uint32_t> scratch_pairs;
    SelectedOperatorScratch<D> scratch_ops;
    std::array<double, 6> partial{}; // reduction partials of the last solver run, this group
    // Block-Jacobi preconditioner (projection.preconditioner = "block_lu"): the factorised
    // diagonal block of this group's rows, assembled after ppe_source; its scratch.
    BlockFactor block;
    std::vector<std::int32_t> block_index; // row of the factorised block per particle, or -1
    BlockRows block_rows;                  // the block as assembled (buffers reused)
    Eigen::VectorXd work;
    // Two-level preconditioner ("two_level"): the rows of A P of this group's particles in
    // compressed form (columns are aggregates), for the coarse correction's residual.
    std::vector<int> ap_outer;
    std::vector<std::int32_t> ap_col;
    std::vector<double> ap_val;
    // The wall collisions of this group's fluid particles in the last correction.
    std::vector<WallContact<D>> contacts;
};

// The coarse level of the two-level preconditioner (docs/PROJECTION.md, "Preconditioner"),
// rebuilt every step; its vectors have one entry per aggregate and the same values on every
// rank.
struct CoarseLevel {
    bool active = false;               // this solve applies the coarse correction
    std::vector<std::int32_t> of;      // per particle (owned and halo): aggregate, or -1
    std::vector<std::uint64_t> keys;   // the aggregates' keys, sorted (all ranks)
    std::vector<CoarseEntry> entries;  // this rank's part of A_c, merged
    CoarseSystem system;               // A_c = R A P, factorised
    std::vector<double> r, p, s, v, t; // R of BiCGSTAB's vectors (by their recurrences)
    std::vector<double> e;             // A_c^{-1} R of the vector preconditioned in this run
    std::vector<double> restricted;    // R of this run's product (v or t), then reduced
};

// What a solver graph run does (set by the main thread before each run).
enum class SolverPhase {
    residual,    // y = x; r = bhat - A y, rhat = r; partials (r,r), (bhat,bhat), and over the
                 // fluid rows sum y, their number, the number of fluid particles on surface rows
    bicg_dir,    // [x += omega s; r = s - omega t; partial (r,r)]; p = r + beta (p - omega v);
                 // y = p; v = A y; partial (rhat, v) [, sum of y over the fluid rows]
    bicg_half,   // s = r - alpha v; x += alpha p; y = s; t = A y;
                 // partials (t,s), (t,t), (rhat,s), (rhat,t), (s,s) [, sum of y, fluid rows]
    sor_sweep,   // y = x; Gauss-Seidel/SOR sweep inside the group, y across groups; partial r^2
    set_zero,    // x = 0 (the right-hand side vanishes)
    sor_save,    // s = x (SOR's starting iterate, kept in case the sweep diverges)
    sor_restore, // x = s, y = x
    coarse_mark  // y = 1 on rows that are not Dirichlet rows, 0 on those (for the halo's rows)
};

template <int D>
struct ProjectionData {
    // Per particle (owned and halo).
    std::vector<Vec<D>> u_star;
    // number_density: n_i of P3's density-deviation term, with deviation_weight.
    std::vector<Real> bhat, number_density, y;
    std::vector<PpeRow> row;
    // Per owned particle: solver vectors (x is Particles::p).
    std::vector<Real> r, rhat, dir, v, s, t;

    std::vector<ProjectionGroup<D>> groups;
    CoarseLevel coarse;
    // The halo data of the three graphs (the step graph's carries the state).
    std::unique_ptr<HaloFields<D>> main_halo, solver_halo, correct_halo;
    std::unique_ptr<tasks::StepGraph> solver_graph, correct_graph;

    SolverPhase phase = SolverPhase::residual;
    bool first_direction = true;
    bool preconditioned = false; // block-Jacobi: "block_ilu0" or "block_lu" with BiCGSTAB
    double alpha = 0, beta = 0, omega = 0;
    double relaxation = 1; // SOR's factor in this solve (projection.relaxation, or 1 after a
                           // divergence of the over-relaxed sweep)

    // No free surface (docs/PROJECTION.md, "No free surface"): no fluid row is a Dirichlet
    // row, so A 1 = 0 and the scaled system is singular. It is then solved bordered,
    //   [A  e] [p     ]   [bhat ]
    //   [m  0] [lambda] = [gauge],
    // e = 1 on fluid rows, m p = the mean of p over the fluid rows, gauge = the background
    // pressure: lambda is the uniform correction of the fluid rows' source that makes the
    // system compatible. Each Krylov vector has one component along lambda, the same number
    // on every rank, kept here by the main thread.
    bool free_level = false;
    double gauge = 0;
    double fluid_rows = 0; // the number of fluid rows (all ranks)
    struct Extra {
        double x = 0, r = 0, rhat = 0, dir = 0, v = 0, s = 0, t = 0, y = 0;
    } extra;
    bool failed = false; // a task of this step threw: later stages do nothing

    Real re = 0;           // WMLS influence radius (the kernel support)
    Real n0 = 0;           // particle number density of the full lattice (weight below)
    Real n0_deviation = 0; // the same with the density-deviation term's weight (P3)
    Real lattice_sum = 0;  // S = sum_j L_ij of the full lattice
    Real surface_diameter = 0;
    Real collision_distance = 0;         // wall and fluid-fluid collisions (docs/PROJECTION.md)
    LsWeight weight = LsWeight::pnu_mps; // the WMLS fits' and n0's
    LsWeight deviation_weight = LsWeight::pnu_mps; // projection.deviation_weight (P3)
    OperatorSelections selections; // [neighbours.<operator>] (all radius by default)

    PressureSolveRecord last; // the last step's solve
    // The last step's wall collisions on this rank (its owned fluid particles'), for the force
    // probes (the groups' lists, gathered after the correction).
    std::vector<WallContact<D>> contacts;
    PressureSolveTotals totals;

    void resize(std::size_t n) {
        u_star.resize(n, Vec<D>::Zero());
        bhat.resize(n, 0);
        number_density.resize(n, 0);
        y.resize(n, 0);
        row.resize(n, PpeRow::surface);
        for (auto* f : {&r, &rhat, &dir, &v, &s, &t})
            f->resize(n, 0);
    }
};

} // namespace sluice
