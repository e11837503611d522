// Inverse-square images of candidate neighbours and their convex hull; see mapped_hull.hpp.
#include "sluice/physics/mapped_hull.hpp"

#include "sluice/physics/convex_hull_2d.hpp"
#include "sluice/physics/convex_hull_3d.hpp"

#include <algorithm>

namespace sluice {

template <int D>
MappedHull<D> mapped_hull(std::span<const Vec<D>> offsets) {
    MappedHull<D> h;
    h.images.reserve(offsets.size());
    for (const auto& r : offsets) {
        h.images.push_back(inverse_square_map<D>(r));
        h.size = std::max(h.size, h.images.back().norm());
    }
    if constexpr (D == 2) {
        const std::vector<int> corners = quadrant_hull_2d(h.images, HullPoints::vertices);
        h.facets = hull_edges_2d(h.images, corners);
        h.vertices = corners;
        std::sort(h.vertices.begin(), h.vertices.end());
        if (h.facets.empty()) {
            // Fewer than 3 corners: a point or a segment; its edge points come exactly.
            h.boundary = quadrant_hull_2d(h.images, HullPoints::boundary);
            std::sort(h.boundary.begin(), h.boundary.end());
            return h;
        }
    } else {
        const ConvexHull3d v = convex_hull_3d(h.images, HullPoints::vertices);
        h.vertices = v.points;
        h.facets = v.facets;
        if (h.facets.empty()) {
            h.boundary = convex_hull_3d(h.images, HullPoints::boundary).points;
            return h;
        }
    }
    // Points within the tolerance of a facet join the corners. Duplicates of a corner (same
    // image) are on the boundary too.
    const Real tol = kMappedHullTolerance * h.size;
    for (std::size_t i = 0; i < h.images.size(); ++i)
        for (const auto& f : h.facets)
            if (f.template head<D>().dot(h.images[i]) + f[D] > -tol) {
                h.boundary.push_back(static_cast<int>(i));
                break;
            }
    return h;
}

template <int D>
bool hull_surrounds_origin(const MappedHull<D>& hull) {
    if (hull.facets.empty())
        return false;
    const Real tol = kMappedHullTolerance * hull.size;
    return std::all_of(hull.facets.begin(), hull.facets.end(),
                       [&](const auto& f) { return f[D] < -tol; });
}

template MappedHull<2> mapped_hull<2>(std::span<const Vec<2>>);
template MappedHull<3> mapped_hull<3>(std::span<const Vec<3>>);
template bool hull_surrounds_origin<2>(const MappedHull<2>&);
template bool hull_surrounds_origin<3>(const MappedHull<3>&);

} // namespace sluice
