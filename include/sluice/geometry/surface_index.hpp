#pragma once
// Queries over a SurfaceGeometry, answered by CGAL's AABB tree (closest point, segment
// crossings) and, for closed shapes, its inside test (Side_of_triangle_mesh in 3-D, the
// polygons' bounded side in 2-D). Built once per shape at set-up; const queries only. The
// CGAL types stay in surface_index.cpp.
#include "sluice/geometry/surface_geometry.hpp"

#include <memory>
#include <optional>

namespace sluice {

// The point of the surface closest to a query point x.
struct ClosestPoint {
    Point3 point{};
    Point3 normal{};     // the closest element's unit normal
    double distance = 0; // |x - point|
    // (x - point) . n / distance, n the normal of the closest element, or the pseudo-normal of
    // the edge or vertex the closest point lies on: +1 straight in front, -1 behind.
    double side = 0;
    std::size_t element = 0;
};

// Where a straight move from a to b first meets the surface.
struct Crossing {
    Point3 point{};
    Point3 normal{};     // the element's unit normal
    Point3 anchor{};     // the element's first vertex: a point of its plane, as given
    double fraction = 0; // along a -> b, in [0, 1]
    std::size_t element = 0;
};

enum class CrossingSense { any, entering_front };

class SurfaceIndex {
public:
    explicit SurfaceIndex(SurfaceGeometry geometry);
    ~SurfaceIndex();
    SurfaceIndex(SurfaceIndex&&) noexcept;
    SurfaceIndex& operator=(SurfaceIndex&&) noexcept;
    SurfaceIndex(const SurfaceIndex&) = delete;
    SurfaceIndex& operator=(const SurfaceIndex&) = delete;

    [[nodiscard]] const SurfaceGeometry& geometry() const;
    [[nodiscard]] int dimension() const;
    // Every edge (3-D) or vertex (2-D) shared by exactly two elements, traversed in opposite
    // directions by them: the shape encloses a volume and its orientation is consistent.
    [[nodiscard]] bool closed() const;
    // Closed and its normals point out of the volume it encloses (positive signed volume).
    [[nodiscard]] bool outward() const;
    [[nodiscard]] double enclosed_volume() const; // signed (area in 2-D); 0 when not closed
    [[nodiscard]] double surface_size() const;    // area (3-D) or length (2-D)
    [[nodiscard]] Point3 lo() const;              // bounding box
    [[nodiscard]] Point3 hi() const;

    [[nodiscard]] ClosestPoint closest(const Point3& x) const;
    [[nodiscard]] double squared_distance(const Point3& x) const;
    // Some element within distance r of x (a sphere query: stops at the first one found).
    [[nodiscard]] bool within(const Point3& x, double r) const;
    // Inside the enclosed volume (points on the surface count as inside). Closed shapes only.
    [[nodiscard]] bool inside(const Point3& x) const;
    // The first crossing of the segment a -> b with the surface, if any: with any element, or
    // only with the elements it enters from their front (b - a against the element's normal).
    [[nodiscard]] std::optional<Crossing>
    first_crossing(const Point3& a, const Point3& b,
                   CrossingSense sense = CrossingSense::any) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace sluice
