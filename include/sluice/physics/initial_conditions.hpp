#pragma once
// Initial particle sets: fluid blocks on a lattice (optionally in hydrostatic equilibrium or
// with a Taylor-Green vortex), and layers of dummy wall particles outside the tank faces.
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
