#pragma once
// The particles of a case's [[walls.meshes]]: dummy wall layers laid behind each shape
// (geometry/shape_particles.hpp), and the lattice sites the shapes take from the fluid blocks.
// Case set-up only; the step sees wall particles, not meshes.
#include "sluice/io/case_config.hpp"
#include "sluice/solver/initial_state.hpp"

#include <cstddef>

namespace sluice {

// The wall particles of every mesh, in case order, ids from first_id; returns the next id.
template <int D>
ParticleId visit_mesh_wall_particles(const CaseConfig& cfg, int layers, ParticleId first_id,
                                     const InitialSink<D>& sink);

// Wall particles per mesh, in case order.
std::vector<std::size_t> count_mesh_wall_particles(const CaseConfig& cfg, int layers);

// A mesh's wall layers as laid, for `sluice info` and the case warnings.
struct MeshWallCensus {
    std::size_t particles = 0;   // every layer
    std::size_t first_layer = 0; // the innermost layer's (dx/2 behind the surface)
    // The largest |distance to the mesh - (layer + 1/2) dx| of any site [m]: how far the wall
    // surface the layers stand for (dx/2 beyond the innermost) lies from the mesh.
    double surface_deviation = 0;
};
MeshWallCensus mesh_wall_census(const CaseConfig& cfg, std::size_t mesh, int layers);

// Whether a wall particle at x is one of the mesh's own: inside a solid (within dx/100 of
// it), or behind a surface within its `layers` layers. A force probe on the mesh reads these
// only, not the other walls its region holds (a tank floor under an obstacle, a side wall).
bool wall_particle_of_mesh(const CaseConfig& cfg, std::size_t mesh, int layers, const Triple& x);

// A fluid lattice site x (before settling and jitter) that a mesh takes: inside a solid,
// behind a surface, or closer than dx/2 to either (where the innermost wall layer is dx/2
// behind the surface, a fluid particle keeps at least dx from it). A block that reaches into a
// bed or an obstacle is so cut to the shape.
bool fluid_site_taken_by_mesh(const CaseConfig& cfg, const Triple& x);

} // namespace sluice
