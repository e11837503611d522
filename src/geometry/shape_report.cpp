// ShapeReport (shape_report.hpp).
#include "sluice/geometry/shape_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sluice {

ShapeReport report_shape(const SurfaceIndex& shape, double degenerate_below, bool thickness) {
    const SurfaceGeometry& g = shape.geometry();
    ShapeReport r;
    r.elements = g.elements();
    r.vertices = g.vertices.size();
    r.closed = shape.closed();
    r.outward = shape.outward();
    r.lo = shape.lo();
    r.hi = shape.hi();
    r.size = shape.surface_size();
    r.volume = shape.enclosed_volume();
    r.thinnest = std::numeric_limits<double>::infinity();
    double diagonal = 0;
    for (std::size_t a = 0; a < 3; ++a)
        diagonal += (r.hi[a] - r.lo[a]) * (r.hi[a] - r.lo[a]);
    diagonal = std::sqrt(diagonal);
    for (std::size_t e = 0; e < g.elements(); ++e) {
        if (element_size(g, e) < degenerate_below) {
            ++r.degenerate;
            continue;
        }
        if (!r.closed || !thickness)
            continue;
        // From just inside the element's centre straight through the shape.
        Point3 c{};
        const std::size_t corners = g.dimension == 3 ? 3 : 2;
        for (std::size_t k = 0; k < corners; ++k) {
            const Point3& v = g.vertices[g.dimension == 3 ? g.triangles[e][k] : g.segments[e][k]];
            for (std::size_t a = 0; a < 3; ++a)
                c[a] += v[a] / double(corners);
        }
        const Point3 n = element_normal(g, e);
        const double sign = r.outward ? -1.0 : 1.0; // into the enclosed volume
        const double start = 1e-9 * diagonal;
        Point3 a{}, b{};
        for (std::size_t k = 0; k < 3; ++k) {
            a[k] = c[k] + sign * start * n[k];
            b[k] = c[k] + sign * 2 * diagonal * n[k];
        }
        if (const auto hit = shape.first_crossing(a, b))
            r.thinnest = std::min(r.thinnest, start + hit->fraction * 2 * diagonal);
    }
    return r;
}

} // namespace sluice
