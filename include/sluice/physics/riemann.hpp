#pragma once
// Weakly compressible SPH with a low-dissipation Riemann solver between particle pairs
// (Zhang, Hu & Adams 2017, J. Comput. Phys. 335:605-620; case key numerics.dissipation =
// "riemann"). Each pair (i, j) is a one-dimensional Riemann problem along e_ij = (x_j - x_i)/r
// with left state i and right state j; its linearised (acoustic) solution gives the pair's
// interface pressure and velocity:
//   U_L = v_i . e_ij, U_R = v_j . e_ij, dU = U_L - U_R (> 0: the pair approaches)
//   P* = (rho_L p_R + rho_R p_L)/(rho_L + rho_R) + beta rho_L rho_R/(rho_L + rho_R) c0 dU   (eq.
//   15) U* = (U_L + U_R)/2 + dp/(c0 (rho_L + rho_R))                                           (eq.
//   15)
// with the low-dissipation limiter beta = min(eta max(dU, 0)/c0, 1), eta = 3 (eq. 21): the
// momentum dissipation is ~ rho dU^2, a quadratic viscosity that acts only where a pair
// closes fast (an impact) and does not grow with c0. Then (eqs. 9-10, v* = U* e_ij + the
// tangential part of the mean velocity):
//   dv_i/dt   = -2 sum_j m_j P*/(rho_i rho_j) grad_i W_ij + viscous + g
//   drho_i/dt =  2 rho_i sum_j V_j (v_i - v*) . grad_i W_ij
//             =  rho_i sum_j V_j F_ij [ (v_i - v_j) . dx + r dp/(rho_bar c0) ]        (fluid j)
// (grad_i W_ij = F_ij dx, dx = x_i - x_j). The second term of the density rate is the
// solver's density diffusion: no delta-SPH is needed. Its pressure jump dp is taken without
// the hydrostatic part, dp = p_i - p_j - rho0 g . dx (as Fourtakas et al. 2019 do for
// delta-SPH), so that water at rest stays at rest; Zhang et al. use p_i - p_j.
//
// Fixed dummy walls (Zhang et al. 2017, section 3.3): the right state of a fluid-wall pair
// has the wall's extrapolated pressure and density (Adami, Hu & Adams 2012,
// dummy_wall_state) and the mirrored velocity U_R = -U_L (a wall at rest), so v* has no
// part along e_ij beyond U* = dp/(2 rho_bar c0):
//   drho_i/dt += 2 rho_i V_w F_iw [ v_i . dx + r dp/(2 rho_bar c0) ]
// Unlike Zhang et al., the momentum equation takes no dissipation from fluid-wall pairs (see
// riemann_acceleration): P* there is the density-weighted mean pressure.
// Moving dummy walls: the wall particle carries its wall's velocity v_w, and the right state
// is the mirror in the wall's frame, U_R = 2 U_w - U_L (as Adami et al. 2012's no-slip
// velocity 2 v_w - <v>), so U* - U_w = dp/(2 rho_bar c0) and the wall term takes the
// relative velocity:
//   drho_i/dt += 2 rho_i V_w F_iw [ (v_i - v_w) . dx + r dp/(2 rho_bar c0) ]
// and the momentum equation's wall pairs see the moving wall through its pressure
// (extrapolated with g - a_w) and the no-slip v_bc.
// The wall pressure is clipped below at the background pressure in the momentum equation,
// as in momentum.hpp (a wall pushes, never pulls).
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/kernels.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

template <int D>
struct RiemannParams {
    Vec<D> gravity = Vec<D>::Zero();
    Real rho0 = 1000;
    Real c0 = 0;              // reference speed of sound (linearised solver)
    Real limiter = 3;         // eta of the low-dissipation limiter
    Real mu = 0;              // laminar viscosity (Morris), as in MomentumParams
    Real h = 0;               // smoothing length (the viscous term's eta^2 = 0.01 h^2)
    bool wall_viscous = true; // no-slip walls: the viscous term acts against wall particles
    Real p_floor = 0;         // lowest pressure a fluid-wall pair pushes with
};

// The pair's interface pressure P* (eq. 15 with the limiter of eq. 21).
inline Real riemann_pressure(Real rho_l, Real rho_r, Real p_l, Real p_r, Real du, Real c0,
                             Real limiter) {
    const Real sum = rho_l + rho_r;
    const Real beta = std::min(limiter * std::max(du, Real(0)) / c0, Real(1));
    return (rho_l * p_r + rho_r * p_l) / sum + beta * rho_l * rho_r / sum * c0 * du;
}

// Acceleration of the fluid particles of cell c.
template <int D, class K>
SLUICE_FLATTEN void riemann_acceleration(const Neighbourhood<D>& nb, const K& kernel,
                                         const RiemannParams<D>& prm, CellIndex c,
                                         const Particles<D>& P, std::span<Vec<D>> a_out) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    const Real eta2 = Real(0.01) * prm.h * prm.h;
    const Real two_mu = 2 * prm.mu;
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const Real rho_i = P.rho[i];
        const Vec<D> v_i = P.v[i];
        const Vec<D> acc = nb.sum_over_pairs(
            adj, i, F, Vec<D>(Vec<D>::Zero()),
            [&](std::uint32_t j, const Vec<D>& dx, Real r2, Real dWr) -> Vec<D> {
                if (r2 <= 0)
                    return Vec<D>::Zero();
                const Real r = std::sqrt(r2);
                const Real rho_j = P.rho[j];
                const bool wall = P.kind[j] == Kind::wall;
                // dU = (v_i - v_j) . e_ij with e_ij = -dx / r. No dissipation in fluid-wall
                // pairs: mirrored along e_ij (U_R = -U_L), every wall particle ahead of a
                // particle sliding along the wall would count as approaching, and the term
                // would brake flow along the wall (the same defect as artificial viscosity on
                // wall pairs, momentum.hpp).
                const Real du = wall ? Real(0) : -(v_i - P.v[j]).dot(dx) / r;
                const Real p_i = wall ? std::max(P.p[i], prm.p_floor) : P.p[i];
                const Real p_j = wall ? std::max(P.p[j], prm.p_floor) : P.p[j];
                const Real p_star =
                    riemann_pressure(rho_i, rho_j, p_i, p_j, du, prm.c0, prm.limiter);
                Vec<D> pair = -2 * P.mass[j] * p_star / (rho_i * rho_j) * dWr * dx;
                if (two_mu > 0 && (!wall || prm.wall_viscous)) {
                    const Vec<D> v_ij = v_i - (wall ? P.v_bc[j] : P.v[j]);
                    pair += P.mass[j] * two_mu / (rho_i * rho_j) * (dWr * r2 / (r2 + eta2)) * v_ij;
                }
                return pair;
            });
        a_out[i] = acc + prm.gravity;
    }
}

// Density rate of the fluid particles of cell c, with `vel` the velocity the leap-frog
// advances densities with (v^{n+1/2}; see continuity_rate); with `moving_walls` the wall
// particles' too (their prescribed velocity at mid-step), and wall pairs take v_i - v_w.
template <int D, class K>
SLUICE_FLATTEN void riemann_continuity_rate(const Neighbourhood<D>& nb, const K& kernel,
                                            const RiemannParams<D>& prm, CellIndex c,
                                            const Particles<D>& P, std::span<const Vec<D>> vel,
                                            std::span<Real> drho_out, bool moving_walls = false) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const Real rho_i = P.rho[i];
        const Real p_i = P.p[i];
        const Vec<D> v_i = vel[i];
        const Real rate = nb.sum_over_pairs(
            adj, i, F, Real(0), [&](std::uint32_t j, const Vec<D>& dx, Real r2, Real Fij) -> Real {
                if (r2 <= 0)
                    return 0;
                const Real r = std::sqrt(r2);
                const Real rho_j = P.rho[j];
                const Real V_j = P.mass[j] / rho_j;
                // Hydrostatic part of p_i - p_j: rho0 g . (x_i - x_j) (grad p = rho0 g).
                const Real dp = p_i - P.p[j] - prm.rho0 * prm.gravity.dot(dx);
                const Real rho_bar = Real(0.5) * (rho_i + rho_j);
                if (P.kind[j] == Kind::wall) {
                    // Fixed walls keep v_i alone (v_w = 0): the same arithmetic as before.
                    const Real approach = moving_walls ? (v_i - vel[j]).dot(dx) : v_i.dot(dx);
                    return 2 * V_j * Fij * (approach + r * dp / (2 * rho_bar * prm.c0));
                }
                return V_j * Fij * ((v_i - vel[j]).dot(dx) + r * dp / (rho_bar * prm.c0));
            });
        drho_out[i] = rho_i * rate;
    }
}

} // namespace sluice
