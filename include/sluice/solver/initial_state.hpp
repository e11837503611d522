#pragma once
// The initial particle set of a case: fluid blocks on a lattice (optionally in hydrostatic
// equilibrium, with a Taylor-Green vortex, a rigid rotation or a straining flow, each with its
// pressure field; a box or the ellipse inscribed in it), and layers of dummy wall particles
// outside the tank faces and inside obstacle boxes. Case set-up, not physics: the formulas it
// uses (wall_layers, settled_height, the profiles' pressures) are in physics/initial_profiles.hpp.
#include "sluice/core/particles.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/initial_profiles.hpp"

#include <cstddef>
#include <functional>

namespace sluice {

// Whether the point x (3 components, the last ignored in 2-D) belongs to block b's shape:
// inside its box, and for an ellipse shape inside the ellipse/ellipsoid inscribed in the box.
bool inside_block_shape(const FluidBlock& b, const Triple& x, int dimension);

// Largest initial speed over block b (uniform velocity plus its profile), for time-step
// estimates before any particle exists.
double block_max_speed(const FluidBlock& b, int dimension);

// One particle as the builders below make it; the derived fields start at zero.
template <int D>
struct InitialParticle {
    ParticleId id;
    Kind kind;
    Vec<D> x, v;
    Real rho, mass;
    // The wall object a wall particle belongs to (wall_object_index); -1 for fluid.
    int object = -1;
};

// Wall objects, numbered in the order their particles are laid: the tank's walls 0, then
// every [[walls.boxes]] entry, then every [[walls.meshes]] entry (what a motion moves).
inline int wall_object_index_of_box(std::size_t box) {
    return 1 + static_cast<int>(box);
}
inline int wall_object_index_of_mesh(const CaseConfig& cfg, std::size_t mesh) {
    return 1 + static_cast<int>(cfg.boxes.size() + mesh);
}
template <int D>
using InitialSink = std::function<void(const InitialParticle<D>&)>;

// The particles add_fluid_blocks / add_wall_particles append, in the same order with the same
// ids (from first_id on) and the same bits, handed to `sink` instead of stored: the distributed
// start (initial_share.hpp) counts them, then keeps only a rank's own. Return the next id.
template <int D>
ParticleId visit_fluid_blocks(const CaseConfig& cfg, const Eos& eos, ParticleId first_id,
                              const InitialSink<D>& sink);
template <int D>
ParticleId visit_wall_particles(const CaseConfig& cfg, int layers, ParticleId first_id,
                                const InitialSink<D>& sink);

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

// Number of particles add_fluid_blocks/add_wall_particles would create (for `sluice info`).
std::size_t count_fluid_particles(const CaseConfig& cfg);
std::size_t count_wall_particles(const CaseConfig& cfg, int layers);

} // namespace sluice
