#pragma once
// A wall or fluid shape as triangles (3-D) or segments (2-D), in metres, after its placement in
// the case (scale, rotation, translation), with what it takes to read it from a file. Geometry
// only: no particles, no physics. The queries over it (closest point, inside) are in
// surface_index.hpp; what it is as built (area, volume, thinnest part) in mesh_report.hpp.
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sluice {

using Point3 = std::array<double, 3>;

// A shape that cannot be used: the message says what is wrong (the case reader adds the file
// and the key).
struct GeometryError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Triangles (dimension 3) or segments (dimension 2, z = 0). Orientation carries the side: a
// triangle's normal is (b - a) x (c - a) normalised (counter-clockwise seen from the side it
// points to); a segment's normal is its direction (b - a) turned clockwise, (dy, -dx): a
// polygon traced counter-clockwise has outward normals, as a closed mesh with the right-hand
// rule.
struct SurfaceGeometry {
    int dimension = 3;
    std::vector<Point3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles; // dimension 3
    std::vector<std::array<std::uint32_t, 2>> segments;  // dimension 2

    [[nodiscard]] std::size_t elements() const {
        return dimension == 3 ? triangles.size() : segments.size();
    }
};

// The largest shape a case may read, checked before it is held in memory.
struct GeometryLimits {
    std::size_t max_elements = 5'000'000;
    std::uintmax_t max_bytes = std::uintmax_t{1} << 30;
};

// Placement of a shape read from a file: x' = R (scale x) + translation, R = Rz Ry Rx (rotation
// in degrees about the axes through the origin, x first). In 2-D only the rotation about z is
// used.
struct Placement {
    double scale = 1;
    Point3 rotation_deg{};
    Point3 translation{};
    bool flip = false; // reverse every element's orientation (its normal)
};

// A triangle mesh from an STL (ASCII or binary), OBJ, PLY or OFF file, chosen by the file's
// extension (CGAL's polygon soup readers). Faces with more than three vertices are split into
// a fan from their first vertex. Throws GeometryError: unreadable file, unknown extension,
// over the limits, no triangle, a non-finite vertex, a face index out of range.
SurfaceGeometry read_triangle_mesh(const std::string& path, const GeometryLimits& limits);

// A 2-D polyline or polygon from a vertex file: one "x, y" pair per line (commas or blanks),
// lines starting with # and blank lines ignored; consecutive vertices are joined, and a last
// vertex equal to the first closes it. Throws GeometryError as read_triangle_mesh.
SurfaceGeometry read_vertex_file(const std::string& path, const GeometryLimits& limits);

// The section of a triangle mesh by the plane z = z0, as 2-D segments oriented so that each
// segment's normal is the cut triangle's normal projected on the plane (CGAL's
// Polygon_mesh_slicer). Throws GeometryError when the plane cuts nothing.
SurfaceGeometry section_by_plane(const SurfaceGeometry& mesh, double z0);

// The shape placed (see Placement). Throws GeometryError for a non-finite or zero scale.
SurfaceGeometry placed(SurfaceGeometry g, const Placement& placement);

// The element's unit normal and its size (area in 3-D, length in 2-D).
Point3 element_normal(const SurfaceGeometry& g, std::size_t e);
double element_size(const SurfaceGeometry& g, std::size_t e);

} // namespace sluice
