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

// A fluid lattice site x (before settling and jitter) that a mesh takes: inside a solid,
// behind a surface, or closer than dx/2 to either (where the innermost wall layer is dx/2
// behind the surface, a fluid particle keeps at least dx from it). A block that reaches into a
// bed or an obstacle is so cut to the shape.
bool fluid_site_taken_by_mesh(const CaseConfig& cfg, const Triple& x);

} // namespace sluice
