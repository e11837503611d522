#pragma once
// Where a shape's particles go (SPH set-up, no physics): the dummy wall layers behind a
// surface or inside a solid.
//
// Wall layers. The lattice sites origin + (k + 1/2) dx within `layers` dx behind the surface
// (inside a solid; on the side opposite the normals of a surface) are taken, and each site at
// distance d from the surface is moved along the line to its closest surface point to the
// distance (floor(d/dx) + 1/2) dx: the layers then lie at dx/2, 3dx/2, ... behind the surface for
// any dx and any orientation, and a slab of thickness dx holds on average one site per
// dx^(D-1) of surface, as a face of the tank. Where the lattice already sits at those distances
// (an axis-aligned face with the origin on it) nothing moves, so a box given as a mesh is laid
// exactly as the same [[walls.boxes]] box. Behind a convex edge the layers follow the circle of
// that radius about the edge; where a moved site would come nearer another part of the
// surface than its layer's depth (along a concave edge of the wall, where two faces' layers
// meet), it is left out, so every site keeps its depth exactly.
#include "sluice/geometry/surface_index.hpp"

#include <cstddef>
#include <functional>

namespace sluice {

enum class ShapeRole {
    solid,   // a closed shape: wall layers inside it, under its surface
    surface, // open or closed: wall layers on the side its normals point away from
};

struct WallSite {
    Point3 x{};       // position [m]
    Point3 normal{};  // the surface's unit normal at the closest point, out of the wall
    double depth = 0; // distance behind the surface [m]: (layer + 1/2) dx
    int layer = 0;
};

struct LatticeSpec {
    double dx = 0;
    Point3 origin{}; // sites at origin + (k + 1/2) dx
    int dimension = 3;
};

// Calls f for every wall site of the shape, in a fixed order (tiles of the lattice, then the
// sites of a tile, x fastest), the same on every rank and machine.
void visit_wall_sites(const SurfaceIndex& shape, ShapeRole role, const LatticeSpec& lattice,
                      int layers, const std::function<void(const WallSite&)>& f);

} // namespace sluice
