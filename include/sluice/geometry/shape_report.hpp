#pragma once
// What a shape is, for `sluice info` and `check` and the case reader's refusals: its size,
// whether it encloses a volume and which way its normals point, degenerate elements, and the
// thinnest part of a closed shape (against the wall layers a solid needs).
#include "sluice/geometry/surface_index.hpp"

#include <cstddef>

namespace sluice {

struct ShapeReport {
    std::size_t elements = 0; // triangles (3-D) or segments (2-D)
    std::size_t vertices = 0;
    bool closed = false;
    bool outward = false; // closed, normals out of the enclosed volume
    Point3 lo{}, hi{};
    double size = 0;   // area (3-D) or length (2-D) [m^2 or m]
    double volume = 0; // enclosed volume (area in 2-D) when closed [m^3 or m^2]
    // Elements smaller than `degenerate_below` (area or length): they have no normal.
    std::size_t degenerate = 0;
    // Closed shapes: the shortest distance, through the inside, from an element's centre
    // straight in (along minus its normal) to the far side; infinity for open shapes.
    double thinnest = 0;
};

// The report of a shape; elements below `degenerate_below` (area in 3-D, length in 2-D) count
// as degenerate. The thinnest part costs a ray through the shape per element (seconds for
// 100,000 triangles): without `thickness` it is left at infinity.
ShapeReport report_shape(const SurfaceIndex& shape, double degenerate_below, bool thickness = true);

} // namespace sluice
