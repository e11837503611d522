#pragma once
// Formulas of the incompressible projection step (Park et al. 2014, section 2.3,
// after the PNU-MPS algorithm of Lee et al. 2011; docs/PROJECTION.md derives each one).
// The paper's equations (12)-(16) are missing from its text; the numbers P1-P8 below are those
// of docs/PROJECTION.md.
//
//   P1 predictor        u*_i = u^n_i + dt (nu lap u_i + g)
//   P2 PPE              lap p_i = b_i
//   P3 source           b_i = rho0/dt div u*_i + gamma rho0/dt^2 (n0 - n_i)/n0
//   P4 scaled row       p_i - sum_j a_ij p_j = bhat_i,  a_ij = L_ij / S_i,  bhat_i = -b_i / S_i,
//                       S_i = sum_j L_ij  (L: WMLS Laplacian coefficients, lap f_i =
//                       sum_j L_ij (f_j - f_i))
//   P5 surface row      p_i = 0
//   P6 wall row         p_w - sum_f c_wf p_f = sum_f c_wf rho0 g.(x_w - x_f),
//                       c_wf = w_wf / sum_f w_wf  (Adami et al. 2012 with a_w = 0)
//   P7 correction       u^{n+1}_i = u*_i - dt/rho0 grad p_i
//   P8 position         x^{n+1}_i = x^n_i + dt u^{n+1}_i, after the wall collision check
// Every row of the scaled system has the form y_i - sum_j a_ij y_j, so one matrix-free
// product serves fluid, surface and wall rows alike.
#include "sluice/core/types.hpp"

#include <algorithm>
#include <limits>

namespace sluice {

// P1.
template <int D>
Vec<D> predicted_velocity(const Vec<D>& u, const Vec<D>& laplacian_u, Real nu,
                          const Vec<D>& gravity, Real dt) {
    return u + dt * (nu * laplacian_u + gravity);
}

// P3. div_u_star: WMLS divergence of u*; n: particle number density sum_{j != i} w(r_ij);
// n0: its value on the full lattice.
inline Real ppe_source(Real rho0, Real dt, Real gamma, Real div_u_star, Real n, Real n0) {
    return rho0 / dt * div_u_star + gamma * rho0 / (dt * dt) * (n0 - n) / n0;
}

// A fluid row whose Laplacian coefficients sum to S <= this fraction of the lattice value is
// treated as a surface row (P5): with S near zero the scaled row P4 would be singular. A
// full stencil has S of order 2 D (2 + D) / re^2 (docs/PROJECTION.md).
inline constexpr Real ppe_min_diagonal_fraction = Real(1e-3);

// P6: the constant of a wall row from one fluid neighbour, before division by sum_f w_wf.
template <int D>
Real wall_row_term(Real rho0, const Vec<D>& gravity, const Vec<D>& x_w_minus_x_f) {
    return rho0 * gravity.dot(x_w_minus_x_f);
}

// P7 uses the stabilised gradient (docs/PROJECTION.md, "Stabilised gradient"):
//   grad p_i ~ sum_j c_ij (p'_j - phat_i),  p' = max(p, 0),
//   phat_i = min(p'_i, min {p'_j : p'_j > 0}),
// Koshizuka & Oka's (1996) minimum-pressure reference applied to the WMLS coefficients c_ij.
// It equals the WMLS gradient of p' plus (p'_i - phat_i) sum_j c_ij, a repulsion that
// vanishes on a symmetric stencil; negative pressures (tension) are not applied, as in MPS;
// neighbours at p' = 0 (surface particles, clamped tension) are not taken as the reference,
// so the rows just below the surface are not pushed towards it.
//
// Without a free surface (periodic or closed flows: no Dirichlet row) the pressure is fixed
// only up to a constant, and its level is a choice (docs/PROJECTION.md, "No free surface").
// There is no surface tension to suppress, and clamping at 0 would make the velocity depend
// on that choice, so p' = p and every neighbour is a reference: both are unchanged by
// p -> p + const, and they equal the forms above wherever p > 0.
enum class PressureLevel : std::uint8_t {
    surface, // fixed by the free surface's p = 0 rows (P5)
    free     // no Dirichlet row: fixed by the solver's gauge
};
inline Real gradient_pressure(Real p, PressureLevel level = PressureLevel::surface) {
    return p > 0 || level == PressureLevel::free ? p : 0;
}
// The lowest pressure P7 applies, gradient_pressure's floor: what the probes read below
// (-infinity: every pressure as it is).
inline Real applied_pressure_floor(PressureLevel level) {
    return level == PressureLevel::free ? -std::numeric_limits<Real>::infinity() : Real(0);
}
inline Real gradient_reference(Real current, Real p_neighbour,
                               PressureLevel level = PressureLevel::surface) {
    return p_neighbour > 0 || level == PressureLevel::free ? std::min(current, p_neighbour)
                                                           : current;
}

// P7 with the hydrostatic reference (projection.correction_reference = "hydrostatic";
// docs/PROJECTION.md, P7): each positive neighbour offers q_j = p_j - rho0 g.(x_j - x_i), its
// pressure less the hydrostatic difference between x_j and x_i, so that in a hydrostatic field
// every q_j equals p_i, the reference is p_i and the gradient is the WMLS gradient of p, exact
// on one-sided stencils too; the repulsion then acts on the departure from hydrostatics only.
// rho0_g_dot_offset: rho0 g.(x_j - x_i).
inline Real hydrostatic_gradient_reference(Real current, Real p_neighbour, Real rho0_g_dot_offset,
                                           PressureLevel level = PressureLevel::surface) {
    return p_neighbour > 0 || level == PressureLevel::free
               ? std::min(current, p_neighbour - rho0_g_dot_offset)
               : current;
}
// The reference stays in [0, p'_i] under a free surface, as the minimum's does: a neighbour
// below i at less than hydrostatic pressure would otherwise give a negative reference, and a
// surface particle (p'_i = 0) would be pushed off its neighbours below.
inline Real clamp_gradient_reference(Real reference, PressureLevel level = PressureLevel::surface) {
    return level == PressureLevel::free ? reference : std::max(reference, Real(0));
}

// P7 with the hydrostatic reference: a wall particle's pressure as fluid particle i's correction
// reads it. Adami's extrapolation (P6) continues the hydrostatic field into the wall particles
// above the free surface, where it is negative; clamped at 0 there, it kinks the field beside a
// wall, the fitted gradient of a surface particle falls short of rho0 g, and the particle sinks
// (the still tank's corner particles sank by ~1 dx in 0.25 s, and the surface agitation spread
// from them; docs/PROJECTION.md, P7). The wall's pressure is floored at the hydrostatic
// continuation of i's own (clamped) pressure instead, and never above 0: a negative wall
// pressure extrapolated from tension in the fluid stays clamped (unclamped, it drew the dam
// break's surge front into the floor at 0.26 s). rho0_g_dot_offset: rho0 g.(x_wall - x_i).
inline Real wall_gradient_pressure(Real p_wall, Real p_i_clamped, Real rho0_g_dot_offset) {
    return std::max(p_wall, std::min(Real(0), p_i_clamped + rho0_g_dot_offset));
}

// P7.
template <int D>
Vec<D> corrected_velocity(const Vec<D>& u_star, const Vec<D>& grad_p, Real rho0, Real dt) {
    return u_star - dt / rho0 * grad_p;
}

// Wall collision (after Koshizuka et al. 1998's collision model, in PNU-MPS's spirit: Park et al.
// (2014) note its splashing particles need one). The walls act through the pressure only where
// their rows see fluid pressure; above the free surface their extrapolated pressure is
// negative and is not applied (P7), so nothing else keeps a splashing particle out of a wall.
// A fluid particle closer than `distance` to a wall particle and moving towards it loses the
// approaching component of its velocity (restitution 0). offset: x_wall - x_fluid.
// With a varying time step the test is on the distance the step would leave (docs/PROJECTION.md,
// "Collisions and the time step"): the pair collides when r - dt (v.e) < distance, i.e. when it
// is already closer than `distance` or the step of length dt would bring it there; dt = 0 is
// the test on the present distance alone.
inline constexpr Real wall_collision_distance_over_dx = Real(0.8);

// Whether a pair r apart that approaches at `approach` (> 0: closing) collides in a step dt.
inline bool collides(Real r, Real approach, Real distance, Real dt) {
    return r > 0 && approach > 0 && r - dt * approach < distance;
}

// Whether a fluid particle moving at v collides with the wall particle `offset` away.
template <int D>
bool wall_collides(const Vec<D>& v, const Vec<D>& offset, Real distance, Real dt = 0) {
    const Real r = offset.norm();
    if (r >= distance + dt * v.norm() || r == 0)
        return false;
    return collides(r, v.dot(offset / r), distance, dt);
}

template <int D>
Vec<D> wall_collision(const Vec<D>& v, const Vec<D>& offset, Real distance, Real dt = 0) {
    if (!wall_collides(v, offset, distance, dt))
        return v;
    const Vec<D> e = offset / offset.norm();
    return v - v.dot(e) * e;
}

// The wall collision along the wall's normal (projection.wall_collision = "wall_normal", the
// default since 2026-11-28; docs/PROJECTION.md, "Wall collision"). wall_collision acts along
// the line of centres to one wall particle: a particle that slides along a floor and dips
// towards the wall particle ahead of it loses forward speed as well, a friction no wall
// exerts (on the Zhou dam break it took 24 N s per metre from the surge over 0.5-0.8 s, 8 % of
// the push the reservoir wall gives it; WCSPH's floor took 2). When wall_collision would act on
// a particle, the particle instead loses the part of its velocity that enters the wall along
// the wall's normal n (pointing out of the wall) and keeps the rest:
//   v' = v - min(0, v.n) n,
// with n from its wall neighbours (wall_normal_at). At a corner n is the bisector, which
// stops a particle running into the corner along either wall only in part; the line of
// centres then backs it up for wall particles already within the distance (the scheme's
// collide_with_walls).
template <int D>
Vec<D> wall_normal_collision(const Vec<D>& v, const Vec<D>& normal) {
    const Real vn = v.dot(normal);
    return vn < 0 ? Vec<D>(v - vn * normal) : v;
}
// The wall's normal at a fluid particle, out of the wall: from the weighted centre of its wall
// neighbours towards it, weighted_sum = sum_w w(r_iw) (x_i - x_w) (on a flat wall the
// neighbours' offsets along the wall cancel, so n is the wall's normal wherever the particle
// sits on the lattice). Zero when the sum vanishes.
template <int D>
Vec<D> wall_normal_at(const Vec<D>& weighted_sum) {
    const Real len = weighted_sum.norm();
    return len > 0 ? Vec<D>(weighted_sum / len) : Vec<D>(Vec<D>::Zero());
}

// Fluid-fluid collision (Koshizuka et al. 1998's collision model, as used in MPS codes for
// particles that the pressure fails to keep apart, e.g. at a splashing jet's tip where the
// surface rows carry p = 0). A pair closer than `distance` that approaches exchanges the
// momentum of its approach along the line of centres, with restitution e, for equal masses:
//   dv_i = -(1 + e)/2 max(0, (v_i - v_j).e_ij) e_ij,   e_ij = (x_j - x_i)/r_ij,
// and dv_j = -dv_i, so the pair's momentum is conserved. Summed over the neighbours of i with
// the velocities before any collision (a Jacobi update: independent of particle order, hence
// of threads and ranks). offset: x_j - x_i.
inline constexpr Real fluid_collision_restitution = Real(0.2);

template <int D>
Vec<D> collision_velocity_change(const Vec<D>& v_i, const Vec<D>& v_j, const Vec<D>& offset,
                                 Real distance, Real restitution, Real dt = 0) {
    const Real r = offset.norm();
    if (r >= distance + dt * (v_i - v_j).norm() || r == 0)
        return Vec<D>::Zero();
    const Vec<D> e = offset / r;
    const Real approach = (v_i - v_j).dot(e);
    return collides(r, approach, distance, dt) ? Vec<D>(-(1 + restitution) / 2 * approach * e)
                                               : Vec<D>::Zero();
}

// Number-density surface criterion (Koshizuka & Oka 1996, MPS): a particle whose number
// density n_i = sum_j w(r_ij) is below beta n0 is a free-surface particle (p = 0), in addition
// to the arc test. beta = 0 turns it off. On a lattice with the paper's re = 3.1 l0 and the
// PNU-MPS weight the first row below a flat surface has n = 0.634 n0, the second 0.908 n0,
// the third 0.998 n0 (docs/PROJECTION.md, P5).
inline bool below_surface_density(Real n, Real n0, Real beta) {
    return n < beta * n0;
}

// Residual of one row of the scaled system: bhat_i - (y_i - sum_j a_ij y_j).
inline Real row_residual(Real bhat, Real y_i, Real sum_a_y) {
    return bhat - (y_i - sum_a_y);
}

} // namespace sluice
