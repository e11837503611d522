#pragma once
// Acceleration of fluid particles.
//   pressure:   -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad_i W_ij          (Monaghan 1992)
//   viscosity:  sum_j m_j (mu_i + mu_j)/(rho_i rho_j) (x_ij . grad_i W_ij)/(r^2 + eta^2) v_ij
//               (Morris et al. 1997; Tak (2024) eq. 7)
//   artificial: -sum_j m_j Pi_ij grad_i W_ij, Pi_ij = -alpha c0 h (v_ij.x_ij)/(r^2+eta^2)/rho_ij
//               for approaching pairs (Monaghan 1992)
// Wall (dummy) neighbours enter with their extrapolated pressure/density and, in the laminar
// viscous term, their boundary velocity v_bc (Adami, Hu & Adams 2012). The artificial
// viscosity acts on fluid-wall pairs only when asked (wall_artificial): with the mirrored
// no-slip velocity every wall particle ahead of a particle that slides along the wall counts
// as approaching, so the term brakes flow along a wall, not only flow into it; on a dam-break
// surge it slows the lowest layer, blunts the front and doubles the corner impact pressure
// (docs/IMPACT_LOADS.md). In fluid-wall pairs both
// pressures are clipped from below at the background pressure: a wall may push but never
// pull, otherwise the tension of an expanding free-surface tip (rho < rho0) drags particles
// into the wall.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/kernels.hpp"

#include <algorithm>

namespace sluice {

template <int D>
struct MomentumParams {
    Vec<D> gravity = Vec<D>::Zero();
    Real mu = 0;                  // dynamic viscosity [Pa s]
    Real alpha = 0;               // artificial viscosity coefficient
    Real c0 = 0;                  // reference speed of sound
    Real h = 0;                   // smoothing length
    bool wall_viscous = true;     // no-slip walls: the laminar viscous term acts on wall pairs
    bool wall_artificial = false; // artificial viscosity on fluid-wall pairs too (with v_bc)
    Real p_floor = 0; // lowest pressure a fluid-wall pair acts with (background pressure)
};

// Monaghan's (1992) artificial viscosity as the pair's addition to the coefficient of
// -m_j grad W: alpha c0 h (v_ij . x_ij) / ((r^2 + eta^2) rho_ij) with the mean density rho_ij,
// for an approaching pair (vr = min(v_ij . x_ij, 0)); av = alpha c0 h. One definition for the
// scalar loop below and the four-lane one (momentum_lanes.hpp): T is Real or Real4
// (core/lanes.hpp).
template <class T>
T artificial_viscosity(Real av, const T& vr, const T& r2, Real eta2, Real rho_i, const T& rho_j) {
    return av * vr / ((r2 + eta2) * (Real(0.5) * (rho_i + rho_j)));
}

// The laminar viscous term's factor of v_ij (Morris et al. 1997): m_j 2 mu / (rho_i rho_j)
// F r^2 / (r^2 + eta^2), with F = (dW/dr)/r, so that F r^2/(r^2 + eta^2) is
// (x_ij . grad_i W_ij)/(r^2 + eta^2). T is Real or Real4, as above.
template <class T>
T laminar_viscosity(const T& m_j, Real two_mu, Real rho_i, const T& rho_j, const T& factor,
                    const T& r2, Real eta2) {
    return m_j * two_mu / (rho_i * rho_j) * (factor * r2 / (r2 + eta2));
}

// What the acceleration of a fluid particle reads of one neighbour, packed so that a pair
// loads one cache line instead of a value from each of six arrays (2-D: 64 bytes, which
// momentum_lanes.hpp turns into four pairs' lanes with two transposes). The 2-D continuity
// rate reads its x, rho, m and wall flag too (continuity_lanes.hpp): within a step they are
// the values it needs.
// Aligned to a cache line in 2-D (a record that straddles two lines costs two loads, and two
// threads writing neighbouring records would share a line).
template <int D>
struct alignas(D == 2 ? 64 : 32) MomentumNeighbour {
    Vec<D> x = Vec<D>::Zero(); // position
    Vec<D> v = Vec<D>::Zero(); // velocity; a wall particle's boundary velocity v_bc
    Real rho = 0;              // density
    Real m = 0;                // mass
    Real p_over_rho2 = 0;      // p/rho^2; a wall particle's max(p, p_floor)/rho^2 (see above)
    Real wall = 0;             // 1 for a wall particle, 0 for a fluid one
};

// Writes the record of particle j to n: a fluid particle's once its pressure is known, a
// wall particle's once the wall state is (walls.hpp).
template <int D>
void write_momentum_neighbour(const Particles<D>& P, Real p_floor, std::uint32_t j,
                              MomentumNeighbour<D>& n) {
    const Real rho = P.rho[j];
    n.x = P.x[j];
    n.rho = rho;
    n.m = P.mass[j];
    if (P.kind[j] == Kind::wall) {
        n.v = P.v_bc[j];
        n.p_over_rho2 = std::max(P.p[j], p_floor) / (rho * rho);
        n.wall = 1;
    } else {
        n.v = P.v[j];
        n.p_over_rho2 = P.p_over_rho2[j];
        n.wall = 0;
    }
}

namespace detail {

// The momentum equation's sum over the neighbours of fluid particle i, with the laminar and
// the artificial viscosity switched at compile time (`Viscous`: mu > 0, `Artificial`:
// alpha > 0): the configuration-1 case has no laminar viscosity, and testing both switches in
// every pair cost about a tenth of the loop. The particle arrays are hoisted into locals, so
// the compiler keeps them in registers instead of reloading them each pair through the
// Particles object. Same arithmetic in the same order as before this change.
template <int D, class K, bool Viscous, bool Artificial>
SLUICE_FLATTEN void acceleration_cell(const Neighbourhood<D>& nb, const K& kernel,
                                      const MomentumParams<D>& prm, CellIndex c,
                                      const Particles<D>& P, std::span<Vec<D>> a_out) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    const Real eta2 = Real(0.01) * prm.h * prm.h;
    const Real two_mu = 2 * prm.mu;
    const Real av = prm.alpha * prm.h * prm.c0;
    const bool wall_viscous = prm.wall_viscous, wall_artificial = prm.wall_artificial;
    const Real p_floor = prm.p_floor;
    const Kind* const kind = P.kind.data();
    const Real* const rho = P.rho.data();
    const Real* const mass = P.mass.data();
    const Real* const pres = P.p.data();
    const Real* const por2 = P.p_over_rho2.data();
    const Vec<D>* const vel = P.v.data();
    const Vec<D>* const v_bc = P.v_bc.data();
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (kind[i] != Kind::fluid)
            continue;
        const Real rho_i = rho[i];
        const Real p_over_rho2_i = por2[i];
        const Real p_clipped_over_rho2_i = std::max(pres[i], p_floor) / (rho_i * rho_i);
        const Vec<D> v_i = vel[i];
        const auto pair_term = [&](std::uint32_t j, const Vec<D>& dx, Real r2, Real dWr) -> Vec<D> {
            if (r2 <= 0)
                return Vec<D>::Zero();
            const Vec<D> gradW = dWr * dx;
            const Real rho_j = rho[j];
            const Real m_j = mass[j];
            const bool wall = kind[j] == Kind::wall;
            Real s; // the pair's coefficient of -m_j grad W
            if (wall) {
                const Real pj = std::max(pres[j], p_floor);
                s = p_clipped_over_rho2_i + pj / (rho_j * rho_j);
            } else {
                s = p_over_rho2_i + por2[j];
            }
            Vec<D> pair = Vec<D>::Zero();
            const bool laminar = Viscous && (!wall || wall_viscous);
            const bool artificial = Artificial && (!wall || wall_artificial);
            if (laminar || artificial) {
                const Vec<D> v_ij = v_i - (wall ? v_bc[j] : vel[j]);
                if (laminar)
                    pair = laminar_viscosity(m_j, two_mu, rho_i, rho_j, dWr, r2, eta2) * v_ij;
                if (artificial) {
                    // Only approaching pairs (v_ij . x_ij < 0) feel it. min() instead of an
                    // `if`: about half the pairs approach, so the branch mispredicted often;
                    // for the others the term is an exact zero.
                    const Real vr = std::min(v_ij.dot(dx), Real(0));
                    s -= artificial_viscosity(av, vr, r2, eta2, rho_i, rho_j);
                }
            }
            return pair - m_j * s * gradW;
        };
        const Vec<D> acc = nb.sum_over_pairs(adj, i, F, Vec<D>(Vec<D>::Zero()), pair_term);
        a_out[i] = acc + prm.gravity;
    }
}

} // namespace detail

// Calls f.template operator()<Viscous, Artificial>() with the scene's two viscosity switches
// as compile-time constants (laminar: mu > 0; artificial: alpha h c0 > 0), for the pair loops
// that are compiled once per combination (here and momentum_lanes.hpp).
template <int D, class F>
void with_viscosity_switches(const MomentumParams<D>& prm, F&& f) {
    const bool viscous = prm.mu > 0, artificial = prm.alpha * prm.h * prm.c0 > 0;
    if (viscous && artificial)
        f.template operator()<true, true>();
    else if (viscous)
        f.template operator()<true, false>();
    else if (artificial)
        f.template operator()<false, true>();
    else
        f.template operator()<false, false>();
}

template <int D, class K>
void acceleration(const Neighbourhood<D>& nb, const K& kernel, const MomentumParams<D>& prm,
                  CellIndex c, const Particles<D>& P, std::span<Vec<D>> a_out) {
    with_viscosity_switches(prm, [&]<bool Viscous, bool Artificial>() {
        detail::acceleration_cell<D, K, Viscous, Artificial>(nb, kernel, prm, c, P, a_out);
    });
}

} // namespace sluice
