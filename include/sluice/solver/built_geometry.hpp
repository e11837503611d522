#pragma once
// The geometry a case's particles take when built (solver/initial_state.hpp), from the
// configuration alone, without making the particles.
#include "sluice/geometry/shape_report.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/solver/mesh_walls.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace sluice {

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
struct BuiltMesh {
    ShapeReport shape; // the mesh as placed
    // Dummy walls: the layers laid (reflective walls lay none).
    MeshWallCensus walls;
    // Innermost-layer sites x dx^(D-1) over the surface's area: about 1 for a flat face;
    // below 1 where the surface curves on the scale of dx or sites were left out.
    double coverage = 0;
};
struct BuiltGeometry {
    std::vector<BuiltFace> faces; // walled tank faces (dummy walls only)
    std::vector<BuiltBox> boxes;
    std::vector<BuiltBlock> blocks;
    std::vector<BuiltMesh> meshes;
};
BuiltGeometry built_geometry(const CaseConfig& cfg, int layers);

} // namespace sluice
