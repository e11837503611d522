#pragma once
// Initial particle sets: fluid blocks on a lattice (optionally in hydrostatic equilibrium, with
// a Taylor-Green vortex, a rigid rotation or a straining flow, each with its pressure field;
// a box or the ellipse inscribed in it), and layers of dummy wall particles outside the tank
// faces.
#include "sluice/core/particles.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/physics/eos.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

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

// Dummy wall particles (model = dummy): `layers` layers outside each tank face named in
// tank_faces, laid from the face outwards (the first dx/2 behind it, then every dx), filling
// corners between walled faces, then every [[walls.boxes]] obstacle as `layers` layers inside
// each of its faces, laid from the face inwards the same way. Along a face the sites cover it
// on a lattice of spacing dx centred between the faces across it. When dx divides an extent
// (to 1e-9) the sites are exactly the lattice lo + (k + 1/2) dx of earlier versions (see
// axis_sites in the .cpp). Ids continue after the fluid.
template <int D>
void add_wall_particles(const CaseConfig& cfg, int layers, Particles<D>& P);

// Lattice sites of fluid block b along axis a: round(extent/dx), one fewer where that would put
// the last particle centre closer than dx/4 to a walled tank face, or beyond it (the count is
// at most floor((face - lo)/dx + 1/4)). Equal to round(extent/dx) when dx divides the extent.
int block_lattice_count(const CaseConfig& cfg, const FluidBlock& b, int axis);

// The geometry as built, for `sluice info` and the case warnings: where the wall surfaces and
// the fluid end up. The surface of a wall as built is its fluid-side particle layer -/+ dx/2.
struct BuiltFace {
    int axis = 0;
    bool upper = false;
    double requested = 0, built = 0; // surface position [m]
    int layers = 0;
    std::size_t particles = 0; // sites of this face's layers (corners counted on each face)
};
struct BuiltBox {
    Triple lo{}, hi{};                 // surfaces as built [m]
    std::array<int, 3> sites{1, 1, 1}; // sites along each axis
    std::array<bool, 3> thin{};        // axis filled symmetrically (thinner than 2 x layers)
    std::size_t particles = 0;
};
struct BuiltBlock {
    Triple hi{}; // upper lattice edge lo + n dx per axis [m]
    std::array<int, 3> sites{1, 1, 1};
    std::array<bool, 3> capped{}; // fewer sites than round(extent/dx): a walled face is near
    std::size_t particles = 0;
    double volume = 0, requested_volume = 0; // particles dx^D, and the shape's volume [m^D]
};
struct BuiltGeometry {
    std::vector<BuiltFace> faces; // walled tank faces (dummy walls only)
    std::vector<BuiltBox> boxes;
    std::vector<BuiltBlock> blocks;
};
BuiltGeometry built_geometry(const CaseConfig& cfg, int layers);

// Number of particles add_fluid_blocks/add_wall_particles would create (for `sluice info`).
std::size_t count_fluid_particles(const CaseConfig& cfg);
std::size_t count_wall_particles(const CaseConfig& cfg, int layers);

} // namespace sluice
