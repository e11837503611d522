#pragma once
// Initial particle sets: fluid blocks on a lattice (optionally in hydrostatic equilibrium, with
// a Taylor-Green vortex, a rigid rotation or a straining flow, each with its pressure field;
// a box or the ellipse inscribed in it), and layers of dummy wall particles outside the tank
// faces.
#include "sluice/core/particles.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/physics/eos.hpp"

namespace sluice {

// Number of wall layers needed so that a fluid particle on the wall sees a full support.
inline int wall_layers(double support, double dx) {
    return static_cast<int>(std::ceil(support / dx - 1e-9));
}

// Vertical axis: y in 2-D, z in 3-D (gravity is not required to point along it).
template <int D>
constexpr int vertical_axis() {
    return D - 1;
}

// Whether the point x (3 components, the last ignored in 2-D) belongs to block b's shape:
// inside its box, and for an ellipse shape inside the ellipse/ellipsoid inscribed in the box.
bool inside_block_shape(const FluidBlock& b, const Triple& x, int dimension);

// Largest initial speed over block b (uniform velocity plus its profile), for time-step
// estimates before any particle exists.
double block_max_speed(const FluidBlock& b, int dimension);

// Pressure (above the background) of fluid in rigid rotation at angular velocity omega filling
// the rectangle [0, Lx] x [0, Ly] with p = 0 on its edges: the rotating square patch of
// Colagrossi (2005), solution of lap p = 2 rho omega^2 (the divergence of the Euler equation,
// lap p = -rho tr(grad v ^2), for v = omega x (x - c)). Written as the torsion-type single
// series p = -rho omega^2 [x (Lx - x) - sum_{m odd} 8 Lx^2/(m pi)^3 sin(m pi x/Lx)
// cosh(m pi (y - Ly/2)/Lx) / cosh(m pi Ly/(2 Lx))], which equals Colagrossi's double sine
// series and converges like 1/m^3. (x, y) measured from the lower-left corner.
double rotating_rectangle_pressure(double rho0, double omega, double Lx, double Ly, double x,
                                   double y);

// Pressure (above the background) of a uniform velocity gradient G inside the ellipse of
// semi-axes a, b with p = 0 on its edge: lap p = -rho tr(G^2) gives
// p = rho tr(G^2)/2 a^2 b^2/(a^2 + b^2) (1 - xi^2/a^2 - eta^2/b^2), (xi, eta) from the centre.
// Rigid rotation: tr(G^2) = -2 omega^2 (suction inside); Monaghan's (1994) elliptical drop
// v = (-A0 xi, A0 eta): tr(G^2) = 2 A0^2.
double ellipse_pressure(double rho0, double trace_g2, double a, double b, double xi, double eta);

// Fluid particles of every block, ids 0..n-1 in block/lattice order.
template <int D>
void add_fluid_blocks(const CaseConfig& cfg, const Eos& eos, Particles<D>& P);

// Dummy wall particles (model = dummy): `layers` lattice layers outside each tank face named
// in tank_faces, filling corners between walled faces, then every [[walls.boxes]] obstacle
// as the lattice sites of the box (spacing dx, centred like a fluid block's) within `layers`
// sites of its surface. Ids continue after the fluid.
template <int D>
void add_wall_particles(const CaseConfig& cfg, int layers, Particles<D>& P);

// Number of particles add_fluid_blocks/add_wall_particles would create (for `sluice info`).
std::size_t count_fluid_particles(const CaseConfig& cfg);
std::size_t count_wall_particles(const CaseConfig& cfg, int layers);

} // namespace sluice
