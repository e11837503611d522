#pragma once
// Wall models.
//  (a) Reflective planes (seed 000, its Step 3 and 5-9): a particle that crossed a plane is
//      mirrored back and its normal velocity reversed (times a restitution coefficient).
//  (b) Fixed dummy particles (Adami, Hu & Adams 2012, eqs. 22-28): each wall particle takes
//      the pressure extrapolated from the fluid around it,
//        p_w = [sum_f p_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf] / sum_f W_wf,
//      the density that pressure gives through the EOS, and for no-slip the velocity
//        v_bc = 2 v_w - sum_f v_f W_wf / sum_f W_wf.
//      A wall particle stands for a fixed volume V_w = dx^D of wall, like a fluid particle for
//      its cell, so its mass is m_w = rho_w V_w. In Adami's volume-based momentum equation
//      the wall volume is geometric and rho_w only enters the pressure; in the mass-based
//      Monaghan form used here, the same requires m_w = rho_w V_w. A fixed m_w = rho0 V_w
//      would give the wall particles next to pressurised fluid a volume m_w/rho_w smaller
//      than their spacing, so the kernel sums across the wall are incomplete
//      (sum_j V_j grad W_ij != 0 in a uniform arrangement): at the bottom of a still 0.4 m
//      tank at c0 = 20 m/s the first fluid row is then short of ~3 m/s^2 of support, and
//      the floor pressure creeps up by ~2 % as the column settles onto the weak wall.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"

namespace sluice {

template <int D>
struct Plane {
    Vec<D> point = Vec<D>::Zero();
    Vec<D> normal = Vec<D>::Zero(); // unit, pointing into the fluid
};

// Keeps a particle on the fluid side of every plane. v_half and v are the two velocities the
// leap-frog carries; both lose their inward normal component.
template <int D>
void reflect(const std::vector<Plane<D>>& planes, Real restitution, Vec<D>& x, Vec<D>& v_half,
             Vec<D>& v) {
    for (const Plane<D>& pl : planes) {
        const Real s = (x - pl.point).dot(pl.normal);
        if (s >= 0)
            continue;
        x -= 2 * s * pl.normal;
        const Real vn_half = v_half.dot(pl.normal);
        if (vn_half < 0)
            v_half -= (1 + restitution) * vn_half * pl.normal;
        const Real vn = v.dot(pl.normal);
        if (vn < 0)
            v -= (1 + restitution) * vn * pl.normal;
    }
}

// Adami pressure, density, mass (rho_w V_w) and boundary velocity of the wall particles of
// cell c (fixed walls: a_w = 0, v_w = 0).
template <int D, class K>
SLUICE_FLATTEN void dummy_wall_state(const Neighbourhood<D>& nb, const K& kernel, const Eos& eos,
                                     const Vec<D>& gravity, bool no_slip, Real wall_volume,
                                     CellIndex c, Particles<D>& P) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t w = nb.begin(c); w < nb.end(c); ++w) {
        if (P.kind[w] != Kind::wall)
            continue;
        Real sum_w = 0, sum_pw = 0;
        Vec<D> sum_rho_r = Vec<D>::Zero();
        Vec<D> sum_v = Vec<D>::Zero();
        nb.for_each_neighbour(adj, w, [&](std::uint32_t f, const Vec<D>& dx, Real r2) {
            if (P.kind[f] != Kind::fluid)
                return;
            const Real W = kernel.W(std::sqrt(r2));
            sum_w += W;
            sum_pw += P.p[f] * W;
            sum_rho_r += P.rho[f] * W * dx; // dx = x_w - x_f
            sum_v += W * P.v[f];
        });
        if (sum_w > 0) {
            P.p[w] = (sum_pw + gravity.dot(sum_rho_r)) / sum_w;
            P.v_bc[w] = no_slip ? Vec<D>(-sum_v / sum_w) : Vec<D>(sum_v / sum_w);
        } else {
            P.p[w] = eos.p_background;
            P.v_bc[w].setZero();
        }
        P.rho[w] = eos.density(P.p[w]);
        P.mass[w] = P.rho[w] * wall_volume;
    }
}

} // namespace sluice
