#pragma once
// Loads on walls and wall-mounted pressure sensors: what the fluid exerts on a group of dummy
// wall particles (a tank face, an obstacle, a part of either), and the pressure a transducer
// of finite size on a wall surface reads (from those forces, or interpolated). Pure functions over
// all particles, with their own cell hash (O(N) per call): they run only at probe times and leave
// the step's loops alone.
//
// Force. Every fluid-wall pair (i fluid, j wall) of the momentum equation (momentum.hpp,
// riemann.hpp) accelerates i by a_ij; the wall particle j receives -m_i a_ij (Newton's third
// law), so the force on a set of wall particles is
//   F = sum_{j in set} sum_{i fluid} m_i m_j s_ij grad_i W_ij,
//   s_ij = (max(p_i, p_floor) - p_gauge)/rho_i^2 + (max(p_j, p_floor) - p_gauge)/rho_j^2
// (riemann: s_ij = 2 (P*_ij - p_gauge)/(rho_i rho_j)), plus the negated viscous pair terms
// where the scheme puts them on wall pairs (Morris laminar term on no-slip walls, artificial
// viscosity when numerics.wall_artificial_viscosity is on). With p_gauge = 0 the sum of F
// over all wall particles is exactly minus the wall part of sum_i m_i a_i. p_gauge removes
// the background pressure: a uniform p_gauge alone would load a face by p_gauge times its
// area (balanced by the opposite face), which is not a load the fluid's motion causes.
// Dummy-wall pressures, densities and masses are the ones the last step computed (Adami
// extrapolation); the boundary velocity v_bc of the viscous terms is recomputed the same way
// (it is not part of the gathered state) unless `adami_v_bc` is false.
#include "sluice/core/particles.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/momentum.hpp"
#include "sluice/physics/riemann.hpp"

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace sluice {

template <int D>
struct WallLoadParams {
    Real p_floor = 0; // pressures in fluid-wall pairs are clipped below at this (momentum.hpp)
    Real p_gauge = 0; // subtracted from both pressures: loads relative to this pressure
    Real mu = 0;      // laminar viscosity; acts on wall pairs when wall_viscous
    bool wall_viscous = false;
    Real alpha = 0; // artificial viscosity; acts on wall pairs when wall_artificial
    bool wall_artificial = false;
    Real c0 = 0;            // speed of sound (artificial viscosity, Riemann solver)
    Real h = 0;             // smoothing length
    bool riemann = false;   // numerics.dissipation = "riemann": the pair pressure is P*
    bool no_slip = true;    // how v_bc is recomputed: mirrored (no-slip) or copied mean velocity
    bool adami_v_bc = true; // recompute v_bc from the fluid; false: read P.v_bc
};

// The pair terms of the momentum equation (momentum.hpp) the loads mirror: its viscosities,
// sound speed, smoothing length and clipping floor. The caller sets what the momentum
// parameters do not hold (p_gauge, riemann, no_slip, adami_v_bc).
template <int D>
WallLoadParams<D> wall_load_params(const MomentumParams<D>& m) {
    WallLoadParams<D> w;
    w.p_floor = m.p_floor;
    w.mu = m.mu;
    w.wall_viscous = m.wall_viscous;
    w.alpha = m.alpha;
    w.wall_artificial = m.wall_artificial;
    w.c0 = m.c0;
    w.h = m.h;
    return w;
}

// Force [N in 3-D; N/m in 2-D, per metre of width] and moment about a point [N m; 2-D: N m/m,
// only the z component] on a set of wall particles; the sums are in double.
struct WallLoad {
    std::array<double, 3> force{};
    std::array<double, 3> moment{};
    std::size_t wall_particles = 0; // in the set
    std::size_t pairs = 0;          // fluid-wall pairs that contributed
};

// Indices (ascending) of the wall particles inside the closed box [lo, hi].
template <int D>
std::vector<std::size_t> wall_particles_in(const Particles<D>& P, const Vec<D>& lo,
                                           const Vec<D>& hi);

// The load on the wall particles `walls` (indices into P) from every fluid particle within
// the kernel support. `kernel` is an AnyKernel<D> (or any kernel of kernels.hpp).
template <int D>
WallLoad wall_load(const Particles<D>& P, const AnyKernel<D>& kernel, const WallLoadParams<D>& prm,
                   const std::vector<std::size_t>& walls, const Vec<D>& moment_point);

// A pressure sensor's face on a wall surface: a disc (3-D) or segment (2-D) of `diameter`
// centred on `centre`, in the surface whose normal is axis `normal_axis`; the wall lies on the
// side `into_wall` (+1: at larger coordinates along the normal, -1: smaller). Diameter 0: a
// point of the surface.
template <int D>
struct SensorFace {
    Vec<D> centre = Vec<D>::Zero();
    int normal_axis = 0;
    int into_wall = 1;
    Real diameter = 0;
};

// What a flush-mounted transducer reads: the normal force the fluid exerts on the wall under its
// face, per unit area. The face is sampled on a lattice of spacing wall_dx/8 (face_samples);
// each sample point reads the traction of the wall column under it: the force on every wall
// particle at that tangential position (all layers behind the surface), normal component, from
// the pair terms of `wall_load`, divided by the column's share of the surface, wall_dx^(D-1).
// The reading is the mean over the sample points plus prm.p_gauge (an absolute pressure, like
// the fluid's). Because it is the momentum equation's own wall force, a lone spray particle
// at the wall adds only its own small share (m_i m_j ...), and a wall that the scheme never
// lets the fluid pull (pressures clipped at p_floor in wall pairs) never reads suction below
// p_floor. A face smaller than wall_dx reads the column it lies on. NaN when no fluid particle
// is within the kernel support of the face's wall particles (a dry sensor).
template <int D>
Real wall_force_sensor(const Particles<D>& P, const AnyKernel<D>& kernel,
                       const WallLoadParams<D>& prm, const SensorFace<D>& face, Real wall_dx);

// An area sensor on a wall of any orientation (on a mesh): its centre on the surface, the unit
// normal pointing into the wall, its diameter (a disc in 3-D, a segment in 2-D).
template <int D>
struct OrientedSensorFace {
    Vec<D> centre = Vec<D>::Zero();
    Vec<D> into_wall = Vec<D>::Zero();
    Real diameter = 0;
};

// What a flush-mounted transducer on such a wall reads: the normal force the fluid exerts on
// the wall particles under its face (of `candidates`, those behind the surface within a kernel
// support whose position along the surface lies within the face), over the surface they stand
// for: the innermost layer's particles under the face (within wall_dx of the surface) times
// wall_dx^(D-1), one per wall_dx^(D-1) of surface (physics of the mesh layers, shape_particles),
// plus prm.p_gauge. Layers laid along a tilted or curved surface do not line up in columns as a
// tank face's do, so the face is not sampled column by column (wall_force_sensor); the count
// of the innermost layer takes the place of the face's area and follows the sites at its edge.
// NaN when no fluid pair reaches the face's particles.
template <int D>
Real oriented_wall_force_sensor(const Particles<D>& P, const AnyKernel<D>& kernel,
                                const WallLoadParams<D>& prm, const OrientedSensorFace<D>& face,
                                const std::vector<std::size_t>& candidates, Real wall_dx);

// The alternative reading: the fluid's pressure interpolated on the face. The face is sampled
// on a lattice of spacing at most `spacing` (face_samples), and each sample point's pressure
// is the Shepard interpolation over fluid AND wall particles
//   p(y) = sum_j p_j W_j V_j / sum_j W_j V_j,   V_j = m_j / rho_j.
// On the surface the kernel reaches as far into the wall as into the fluid; the dummy wall
// particles carry the fluid pressure extrapolated through the wall with the hydrostatic
// gradient (Adami et al. 2012), so the sum is centred on the surface and has no one-sided
// bias (a fluid-only Shepard sum there would read the mean pressure about one smoothing
// length inside the fluid: rho g h too low on a floor). The reading is the mean of the
// sample points (equal area weights). Shepard normalisation makes a lone droplet at the wall
// read its full pressure, which is why the force reading is the default. Each p_j is read as
// max(p_j, p_min), the pressure the scheme applies (pressure_probe). NaN when no sample point
// has a fluid particle within the support (a dry sensor).
template <int D>
Real wall_pressure_sensor(const Particles<D>& P, const AnyKernel<D>& kernel,
                          const SensorFace<D>& face, Real spacing,
                          Real p_min = -std::numeric_limits<Real>::infinity());

// A rectangle (3-D) or segment (2-D) of a wall's surface: the plane x[normal_axis] = at, the
// wall on the side `into_wall` (as SensorFace), spanning [lo, hi] along the other axes (the
// normal components of lo and hi are not read).
template <int D>
struct WallPatch {
    int normal_axis = 0;
    int into_wall = 1;
    Real at = 0;
    Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Zero();
};

// The load from the fluid's pressure interpolated on wall surfaces, the force reading of a
// scheme that has no fluid-wall pair forces (the projection scheme) and a cross-check of those
// forces under WCSPH:
//   F = sum_s (p(y_s) - p_floor) A_s into_wall e_n,   M = sum_s (y_s - moment_point) x F_s,
// over the cell centres y_s of a lattice of spacing <= `spacing` on each patch, A_s their cells'
// area (length in 2-D), p(y) the Shepard interpolation over fluid and wall particles of
// wall_pressure_sensor with every particle's pressure clipped below at p_floor (the background
// pressure): a wall pushes and never pulls, as in WCSPH's fluid-wall pairs (momentum.hpp) and
// the projection scheme's gradient (negative pressures clamped, projection.hpp). Without the
// clip a spray particle at the wall, whose WCSPH pressure can be -10^5 Pa, would pull on it. A
// sample point with no fluid particle within the support is dry and adds nothing. Pressure
// only: the viscous traction, which the force reading includes, is left out. Returned counts:
// wall_particles = sample points, pairs = wet sample points.
template <int D>
WallLoad interpolated_wall_load(const Particles<D>& P, const AnyKernel<D>& kernel,
                                const std::vector<WallPatch<D>>& patches, Real spacing,
                                Real p_floor, const Vec<D>& moment_point);

// A wall collision of the projection scheme's last step (projection.hpp, wall_collision): fluid
// particle `fluid` came closer than the collision distance to wall particle `wall` (at
// `wall_x`) and lost the velocity it approached with. `force` = m (v_before - v_after) / dt is
// what the wall took [N; 2-D: N/m]: the momentum the pressure did not stop, which a force
// reading from the interpolated pressure alone would leave out.
template <int D>
struct WallContact {
    ParticleId fluid = 0;
    ParticleId wall = 0;
    Vec<D> wall_x = Vec<D>::Zero();
    Vec<D> force = Vec<D>::Zero();
};

// The load of the contacts whose wall particle lies in the closed box [lo, hi]:
// F = sum force, M = sum (wall_x - moment_point) x force, summed in (fluid, wall) id order so
// that it does not depend on the order the contacts were recorded in (threads, ranks).
// Returned counts: wall_particles = 0, pairs = contacts summed.
template <int D>
WallLoad contact_wall_load(const std::vector<WallContact<D>>& contacts, const Vec<D>& lo,
                           const Vec<D>& hi, const Vec<D>& moment_point);

// The traction the contacts give the wall under an area sensor's face, per unit area. Each
// contact's normal force (into the wall) is spread evenly over the part of the surface within
// `spread` of its wall particle tangentially (a strip 2 spread wide in 2-D, a square in 3-D):
// with spread = h, the scale over which the interpolated pressure is smoothed, so that the
// two parts of the reading see the wall alike, and a collision that one column takes in one
// step does not read as the pressure of that column alone. The face is sampled on a lattice of
// spacing wall_dx/8 and the reading is the mean over the sample points; contacts with wall
// particles more than `depth` behind the surface are not counted. What the projection
// scheme's area sensors add to the interpolated pressure (a transducer reads the whole normal
// force); 0 where no contact lies near the face. Summed in (fluid, wall) id order.
template <int D>
Real contact_traction(const std::vector<WallContact<D>>& contacts, const SensorFace<D>& face,
                      Real wall_dx, Real depth, Real spread);

// The Adami state of every dummy wall particle (pressure, density, mass = rho_w wall_volume)
// from the fluid around it, as the step's walls stage computes it (walls.hpp,
// dummy_wall_state). The run calls it on its copy of the initial state, whose wall particles
// have not been through a step yet (their pressure would read as the background's).
template <int D>
void refresh_dummy_walls(Particles<D>& P, const AnyKernel<D>& kernel, const Eos& eos,
                         const Vec<D>& gravity, Real wall_volume);

extern template void refresh_dummy_walls<2>(Particles<2>&, const AnyKernel<2>&, const Eos&,
                                            const Vec<2>&, Real);
extern template void refresh_dummy_walls<3>(Particles<3>&, const AnyKernel<3>&, const Eos&,
                                            const Vec<3>&, Real);
extern template std::vector<std::size_t> wall_particles_in<2>(const Particles<2>&, const Vec<2>&,
                                                              const Vec<2>&);
extern template std::vector<std::size_t> wall_particles_in<3>(const Particles<3>&, const Vec<3>&,
                                                              const Vec<3>&);
extern template WallLoad wall_load<2>(const Particles<2>&, const AnyKernel<2>&,
                                      const WallLoadParams<2>&, const std::vector<std::size_t>&,
                                      const Vec<2>&);
extern template WallLoad wall_load<3>(const Particles<3>&, const AnyKernel<3>&,
                                      const WallLoadParams<3>&, const std::vector<std::size_t>&,
                                      const Vec<3>&);
extern template Real wall_pressure_sensor<2>(const Particles<2>&, const AnyKernel<2>&,
                                             const SensorFace<2>&, Real, Real);
extern template Real wall_pressure_sensor<3>(const Particles<3>&, const AnyKernel<3>&,
                                             const SensorFace<3>&, Real, Real);
extern template WallLoad interpolated_wall_load<2>(const Particles<2>&, const AnyKernel<2>&,
                                                   const std::vector<WallPatch<2>>&, Real, Real,
                                                   const Vec<2>&);
extern template WallLoad interpolated_wall_load<3>(const Particles<3>&, const AnyKernel<3>&,
                                                   const std::vector<WallPatch<3>>&, Real, Real,
                                                   const Vec<3>&);
extern template WallLoad contact_wall_load<2>(const std::vector<WallContact<2>>&, const Vec<2>&,
                                              const Vec<2>&, const Vec<2>&);
extern template WallLoad contact_wall_load<3>(const std::vector<WallContact<3>>&, const Vec<3>&,
                                              const Vec<3>&, const Vec<3>&);
extern template Real contact_traction<2>(const std::vector<WallContact<2>>&, const SensorFace<2>&,
                                         Real, Real, Real);
extern template Real contact_traction<3>(const std::vector<WallContact<3>>&, const SensorFace<3>&,
                                         Real, Real, Real);
extern template Real oriented_wall_force_sensor<2>(const Particles<2>&, const AnyKernel<2>&,
                                                   const WallLoadParams<2>&,
                                                   const OrientedSensorFace<2>&,
                                                   const std::vector<std::size_t>&, Real);
extern template Real oriented_wall_force_sensor<3>(const Particles<3>&, const AnyKernel<3>&,
                                                   const WallLoadParams<3>&,
                                                   const OrientedSensorFace<3>&,
                                                   const std::vector<std::size_t>&, Real);

extern template Real wall_force_sensor<2>(const Particles<2>&, const AnyKernel<2>&,
                                          const WallLoadParams<2>&, const SensorFace<2>&, Real);
extern template Real wall_force_sensor<3>(const Particles<3>&, const AnyKernel<3>&,
                                          const WallLoadParams<3>&, const SensorFace<3>&, Real);

} // namespace sluice
