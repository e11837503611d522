#pragma once
// Wall models. (Reflective walls, the other model, are physics/reflection.hpp.)
// Dummy particles (Adami, Hu & Adams 2012, eqs. 22-28), fixed or moving with their wall: each wall
// particle takes
//   the pressure extrapolated from the fluid around it,
//     p_w = [sum_f p_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf] / sum_f W_wf,
//   the density that pressure gives through the EOS, and for no-slip the velocity
//     v_bc = 2 v_w - sum_f v_f W_wf / sum_f W_wf.
//   A wall particle stands for a fixed volume V_w = dx^D of wall, like a fluid particle for
//   its cell, so its mass is m_w = rho_w V_w. In Adami's volume-based momentum equation
//   the wall volume is geometric and rho_w only enters the pressure; in the mass-based
//   Monaghan form used here, the same requires m_w = rho_w V_w. A fixed m_w = rho0 V_w
//   would give the wall particles next to pressurised fluid a volume m_w/rho_w smaller
//   than their spacing, so the kernel sums across the wall are incomplete
//   (sum_j V_j grad W_ij != 0 in a uniform arrangement): at the bottom of a still 0.4 m
//   tank at c0 = 20 m/s the first fluid row is then short of ~3 m/s^2 of support, and
//   the floor pressure creeps up by ~2 % as the column settles onto the weak wall.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"

namespace sluice {

// Adami's extrapolation for one wall particle w: the kernel-weighted sums over the fluid
// particles f around it (dx = x_w - x_f), and the pressure and boundary velocity they give.
// One definition for the step (dummy_wall_state) and for the measurements that need the
// walls' state outside a step (physics/wall_loads.cpp).
template <int D>
struct AdamiSums {
    Real w = 0, pw = 0;
    Vec<D> rho_r = Vec<D>::Zero();
    Vec<D> v = Vec<D>::Zero();

    void add(Real W, Real p_f, Real rho_f, const Vec<D>& dx, const Vec<D>& v_f) {
        w += W;
        pw += p_f * W;
        rho_r += rho_f * W * dx;
        v += W * v_f;
    }
    // p_w = [sum_f p_f W + (g - a_w) . sum_f rho_f (x_w - x_f) W] / sum_f W (a fixed wall
    // passes g: a_w = 0); the background pressure where no fluid is near.
    [[nodiscard]] Real pressure(const Vec<D>& gravity_less_wall_accel, Real p_background) const {
        return w > 0 ? (pw + gravity_less_wall_accel.dot(rho_r)) / w : p_background;
    }
    // v_bc = 2 v_w - <v> for no-slip, <v> for free slip (fixed walls: v_w = 0). A moving
    // free-slip wall keeps the mean fluid velocity too: its normal motion enters through the
    // continuity equation's relative velocity and the pressure's a_w.
    [[nodiscard]] Vec<D> boundary_velocity(bool no_slip,
                                           const Vec<D>& v_wall = Vec<D>::Zero()) const {
        if (w <= 0)
            return no_slip ? v_wall : Vec<D>::Zero();
        return no_slip ? Vec<D>(2 * v_wall - v / w) : Vec<D>(v / w);
    }
};

// The velocity and acceleration of a wall particle: none for fixed walls.
template <int D>
struct FixedWalls {
    static constexpr bool moving = false;
    void operator()(std::uint32_t, Vec<D>& v_w, Vec<D>& a_w) const {
        v_w.setZero();
        a_w.setZero();
    }
};

// Adami pressure, density, mass (rho_w V_w) and boundary velocity of the wall particles of
// cell c; `wall(w, v_w, a_w)` gives wall particle w's velocity and acceleration (FixedWalls:
// zero; a prescribed motion's otherwise).
template <int D, class K, class WallKinematics = FixedWalls<D>>
SLUICE_FLATTEN void dummy_wall_state(const Neighbourhood<D>& nb, const K& kernel, const Eos& eos,
                                     const Vec<D>& gravity, bool no_slip, Real wall_volume,
                                     CellIndex c, Particles<D>& P,
                                     const WallKinematics& wall = {}) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t w = nb.begin(c), stop = nb.end(c); w < stop; ++w) {
        if (P.kind[w] != Kind::wall)
            continue;
        AdamiSums<D> sums;
        nb.for_each_neighbour(adj, w, [&](std::uint32_t f, const Vec<D>& dx, Real r2) {
            if (P.kind[f] != Kind::fluid)
                return;
            sums.add(kernel.W(std::sqrt(r2)), P.p[f], P.rho[f], dx, P.v[f]);
        });
        if constexpr (WallKinematics::moving) {
            Vec<D> v_w, a_w;
            wall(w, v_w, a_w);
            P.p[w] = sums.pressure(gravity - a_w, eos.p_background);
            P.v_bc[w] = sums.boundary_velocity(no_slip, v_w);
        } else {
            P.p[w] = sums.pressure(gravity, eos.p_background);
            P.v_bc[w] = sums.boundary_velocity(no_slip);
        }
        P.rho[w] = eos.density(P.p[w]);
        P.mass[w] = P.rho[w] * wall_volume;
    }
}

} // namespace sluice
