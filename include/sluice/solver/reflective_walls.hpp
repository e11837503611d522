#pragma once
// The reflective walls of a case (walls.model = "reflective"; physics/reflection.hpp): the
// tank's faces and [[walls.planes]] as planes, and each [[walls.meshes]] shape as a surface
// whose triangles (segments in 2-D) reflect, found through the shape's AABB tree.
#include "sluice/io/case_config.hpp"
#include "sluice/physics/reflection.hpp"

namespace sluice {

template <int D>
Reflector<D> reflective_walls(const CaseConfig& cfg);

} // namespace sluice
