#pragma once
// Density: summation (Tak 2024, eq. 6) or the continuity equation with delta-SPH density
// diffusion in the Antuono et al. (2010) / Marrone et al. (2011) form, whose renormalised
// density gradient removes the hydrostatic part so a still tank stays still.
// Each function handles the particles of one cell; it writes only those particles' fields.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"

#include <Eigen/LU>

namespace sluice {

// rho_i = sum_j m_j W_ij over fluid and wall particles, for the fluid particles of cell c.
template <int D, class K>
SLUICE_FLATTEN void summation_density(const Neighbourhood<D>& nb, const K& kernel, CellIndex c,
                                      const Particles<D>& P, std::span<Real> rho_out) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        Real rho = 0;
        nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>&, Real r2) {
            rho += P.mass[j] * kernel.W(std::sqrt(r2));
        });
        rho_out[i] = rho;
    }
}

// Renormalised density gradient <grad rho>^L_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,
// L_i = [sum_j V_j grad_i W_ij (x_j - x_i)^T]^{-1}, over fluid neighbours (Antuono 2010,
// eq. 9). Where L is singular (too few neighbours) the uncorrected sum is used.
// The pair sums are lane sums in plain components (Neighbourhood::lane_sum_over_pairs), with
// a select for non-fluid partners: summed as an Eigen D x (D+1) matrix per pair, GCC stored
// the pair's matrix with narrow stores and re-read it with wide loads, a store-forwarding
// stall per pair that took 90 % of this function and half of a 3-D step. M = -sum_j V_j F_ij
// dx dx^T is symmetric, so only its upper triangle is summed.
template <int D, class K>
SLUICE_FLATTEN void renormalised_density_gradient(const Neighbourhood<D>& nb, const K& kernel,
                                                  CellIndex c, const Particles<D>& P,
                                                  std::span<Vec<D>> grad_out) {
    static_assert(D == 2 || D == 3);
    constexpr int kUpper = D * (D + 1) / 2; // M_ab, a <= b, row by row; then g
    const AdjacentCells<D> adj = nb.adjacent(c);
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    const Kind* const kind = P.kind.data();
    const Real* const rho = P.rho.data();
    const Real* const mass = P.mass.data();
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (kind[i] != Kind::fluid)
            continue;
        const Real rho_i = rho[i];
        const auto sums = nb.template lane_sum_over_pairs<kUpper + D>(
            adj, i, F,
            [&](std::uint32_t j, const typename Neighbourhood<D>::Dx& dx, Real r2,
                Real Fij) -> std::array<Real, kUpper + D> {
                // grad_i W_ij V_j = w dx and x_j - x_i = -dx; the self pair (r2 = 0) and
                // wall partners add nothing.
                const bool use = kind[j] == Kind::fluid && r2 > 0;
                const Real w = use ? mass[j] / rho[j] * Fij : Real(0);
                const Real wr = (rho[j] - rho_i) * w;
                // Written out per dimension: GCC does not vectorise a pair loop whose body
                // holds two consecutive loops.
                const Real m = -w;
                if constexpr (D == 2)
                    return {m * dx[0] * dx[0], m * dx[0] * dx[1], m * dx[1] * dx[1], wr * dx[0],
                            wr * dx[1]};
                else
                    return {m * dx[0] * dx[0], m * dx[0] * dx[1], m * dx[0] * dx[2],
                            m * dx[1] * dx[1], m * dx[1] * dx[2], m * dx[2] * dx[2],
                            wr * dx[0],        wr * dx[1],        wr * dx[2]};
            });
        Mat<D> M;
        Vec<D> g;
        int k = 0;
        for (int a = 0; a < D; ++a)
            for (int b = a; b < D; ++b, ++k)
                M(a, b) = M(b, a) = sums[k];
        for (int a = 0; a < D; ++a)
            g[a] = sums[kUpper + a];
        // M is the identity for a full, regular support.
        grad_out[i] = std::abs(M.determinant()) > Real(1e-3) ? Vec<D>(M.inverse() * g) : g;
    }
}

// delta-SPH density diffusion: coefficient and form (case key numerics.density_diffusion).
template <int D>
struct DensityDiffusionParams {
    Real delta_h_c0 = 0; // delta h c0; 0 = no diffusion
    DensityDiffusion form = DensityDiffusion::antuono;
    // fourtakas: rho0 g / c0^2, the hydrostatic density gradient (see continuity_rate)
    Vec<D> hydrostatic_gradient = Vec<D>::Zero();
};

// Continuity equation with delta-SPH diffusion:
//   drho_i = sum_j m_j (v_i - v_j) . grad_i W_ij + delta h c0 sum_j psi_ij . grad_i W_ij V_j,
// the diffusion over fluid-fluid pairs only (wall densities are extrapolated, not evolved).
//   antuono   (Antuono et al. 2010, eq. 8):
//             psi_ij = 2 (rho_j - rho_i)(x_j - x_i)/r^2 - (<grad rho>_i + <grad rho>_j)
//   fourtakas (Fourtakas et al. 2019, eqs. 10-12):
//             psi_ij = 2 (rho_j - rho_i - rho^H_ji)(x_j - x_i)/r^2, with rho^H_ji the density
//             difference of the hydrostatic pressure difference rho0 g.(x_j - x_i); no gradient
//             pass is needed. rho^H_ji is taken to first order, rho0 g.(x_j - x_i)/c0^2 (exact
//             for the linear EOS). For Tait the second-order term is smaller by
//             gamma g r / c0^2 ~ 1e-4 over a kernel support, and a pow() per pair costs more
//             than the rest of the pair.
// With grad_i W_ij = F dx (dx = x_i - x_j), (x_j - x_i)/r^2 . grad_i W_ij = -F exactly, so
// neither form divides by r^2 per pair.
// `vel` is the velocity the leap-frog advances densities with: v^{n+1/2}, the same that
// drifts the positions, so density and velocity stay staggered like x and v; with
// `moving_walls` the wall particles' too (their prescribed velocity at mid-step).
template <int D, class K>
SLUICE_FLATTEN void continuity_rate(const Neighbourhood<D>& nb, const K& kernel,
                                    const DensityDiffusionParams<D>& diff, CellIndex c,
                                    const Particles<D>& P, std::span<const Vec<D>> vel,
                                    std::span<Real> drho_out, bool moving_walls = false) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    // One loop per diffusion form (compile-time constants inside), so that no pair computes
    // or gathers what its form does not use.
    const auto run = [&]<bool diffuse, DensityDiffusion form, bool moving>() {
        constexpr bool antuono = diffuse && form == DensityDiffusion::antuono;
        constexpr bool fourtakas = diffuse && form == DensityDiffusion::fourtakas;
        for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
            if (P.kind[i] != Kind::fluid)
                continue;
            const Real rho_i = P.rho[i];
            const Vec<D> v_i = vel[i];
            const Vec<D> g_i = P.grad_rho[i];
            // (velocity divergence part, diffusion part), in plain components and with selects
            // instead of branches so that the pair loop vectorises
            // (Neighbourhood::lane_sum_over_pairs). The self pair adds nothing: its dx is zero
            // and its factor finite.
            const auto sums = nb.template lane_sum_over_pairs<2>(
                adj, i, F,
                [&](std::uint32_t j, const typename Neighbourhood<D>::Dx& dx, Real,
                    Real Fij) -> std::array<Real, 2> {
                    const bool wall = P.kind[j] == Kind::wall;
                    Real dv_dx = 0, g_dx = 0, rho_h = 0;
                    for (int d = 0; d < D; ++d) {
                        // A fixed wall's v_j = 0 (its v_half is not exchanged); a moving wall's
                        // is its velocity at the middle of the step.
                        const Real v_j = wall && !moving ? Real(0) : vel[j][d];
                        dv_dx += (v_i[d] - v_j) * dx[d];
                        if constexpr (antuono)
                            g_dx += (g_i[d] + P.grad_rho[j][d]) * dx[d];
                        if constexpr (fourtakas)
                            rho_h -= diff.hydrostatic_gradient[d] * dx[d]; // dx = x_i - x_j
                    }
                    const Real div = P.mass[j] * Fij * dv_dx;
                    Real diffusion = 0;
                    if constexpr (antuono)
                        diffusion = P.volume[j] * (-2 * (P.rho[j] - rho_i) * Fij - g_dx * Fij);
                    if constexpr (fourtakas)
                        diffusion = P.volume[j] * (-2 * (P.rho[j] - rho_i - rho_h) * Fij);
                    return {div, wall ? Real(0) : diffusion}; // diffusion over fluid pairs only
                });
            drho_out[i] = sums[0] + diff.delta_h_c0 * sums[1];
        }
    };
    // Fixed walls compile to the loop without moving walls' arithmetic.
    const auto walls = [&]<bool diffuse, DensityDiffusion form>() {
        if (moving_walls)
            run.template operator()<diffuse, form, true>();
        else
            run.template operator()<diffuse, form, false>();
    };
    if (diff.delta_h_c0 <= 0)
        walls.template operator()<false, DensityDiffusion::antuono>();
    else if (diff.form == DensityDiffusion::antuono)
        walls.template operator()<true, DensityDiffusion::antuono>();
    else
        walls.template operator()<true, DensityDiffusion::fourtakas>();
}

// Pressure from the equation of state for the fluid particles of cell c, and the two
// per-particle factors the pair loops of the step read of a fluid neighbour j: p_j / rho_j^2
// (momentum) and V_j = m_j / rho_j (continuity). Computed once per particle here instead of
// once per pair there: the same values (the same expressions), without a division per pair.
template <int D>
void equation_of_state(const Neighbourhood<D>& nb, const Eos& eos, CellIndex c,
                       const Particles<D>& P, std::span<Real> p_out,
                       std::span<Real> p_over_rho2_out, std::span<Real> volume_out) {
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i)
        if (P.kind[i] == Kind::fluid) {
            const Real rho = P.rho[i];
            const Real p = eos.pressure(rho);
            p_out[i] = p;
            p_over_rho2_out[i] = p / (rho * rho);
            volume_out[i] = P.mass[i] / rho;
        }
}

} // namespace sluice
