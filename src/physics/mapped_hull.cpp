// Inverse-square images of candidate neighbours and their convex hull; see mapped_hull.hpp.
#include "sluice/physics/mapped_hull.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sluice {

namespace {

// Relative margins of the prefilter: an edge/triangle counts as seen from the origin with the
// right orientation when its orientation determinant exceeds this fraction of the product of
// its corners' lengths; an image is dropped when |r'| < (1 - kDropMargin) rho.
constexpr Real kOrientationMargin = Real(1e-6);
constexpr Real kDropMargin = Real(1e-2);

// Index of the image farthest along +axis (sign = 1) or -axis (sign = -1); -1 if none is
// strictly on that side.
template <int D>
int extreme_image(std::span<const Vec<D>> p, int axis, Real sign) {
    int best = -1;
    Real far = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (sign * p[i][axis] > far) {
            far = sign * p[i][axis];
            best = static_cast<int>(i);
        }
    return best;
}

} // namespace

template <int D>
Real inscribed_ball_radius(std::span<const Vec<D>> images) {
    // e[2 a] along +axis a, e[2 a + 1] along -axis a.
    std::array<Vec<D>, 2 * D> e;
    for (int a = 0; a < D; ++a)
        for (int s = 0; s < 2; ++s) {
            const int k = extreme_image<D>(images, a, s == 0 ? Real(1) : Real(-1));
            if (k < 0)
                return 0;
            e[static_cast<std::size_t>(2 * a + s)] = images[static_cast<std::size_t>(k)];
        }
    Real rho = std::numeric_limits<Real>::max();
    if constexpr (D == 2) {
        // Edges (+x, +y), (+y, -x), (-x, -y), (-y, +x): counter-clockwise about the origin.
        const std::array<std::array<int, 2>, 4> edges{{{0, 2}, {2, 1}, {1, 3}, {3, 0}}};
        for (const auto& [u, v] : edges) {
            const Vec<2>& a = e[static_cast<std::size_t>(u)];
            const Vec<2>& b = e[static_cast<std::size_t>(v)];
            const Real cross = a.x() * b.y() - a.y() * b.x();
            if (!(cross > kOrientationMargin * a.norm() * b.norm()))
                return 0;
            rho = std::min(rho, cross / (b - a).norm());
        }
    } else {
        // Octant (sx, sy, sz): the triangle of the extremes along sx x, sy y, sz z, whose
        // determinant has the sign sx sy sz on the regular octahedron.
        for (int o = 0; o < 8; ++o) {
            const int sx = o & 1, sy = (o >> 1) & 1, sz = (o >> 2) & 1;
            const Vec<3>& a = e[static_cast<std::size_t>(sx)];
            const Vec<3>& b = e[static_cast<std::size_t>(2 + sy)];
            const Vec<3>& c = e[static_cast<std::size_t>(4 + sz)];
            const Real sign = ((sx + sy + sz) & 1) != 0 ? Real(-1) : Real(1);
            const Real det = sign * a.dot(b.cross(c));
            if (!(det > kOrientationMargin * a.norm() * b.norm() * c.norm()))
                return 0;
            rho = std::min(rho, det / (b - a).cross(c - a).norm());
        }
    }
    return rho;
}

template <int D>
void mapped_hull_into(std::span<const Vec<D>> offsets, HullPrefilter prefilter,
                      MappedHullWork<D>& work, MappedHull<D>& h) {
    h.images.clear();
    h.vertices.clear();
    h.boundary.clear();
    h.facets.clear();
    Real size2 = 0; // sqrt is monotone: the largest norm is the root of the largest square
    for (const auto& r : offsets) {
        h.images.push_back(inverse_square_map<D>(r));
        size2 = std::max(size2, h.images.back().squaredNorm());
    }
    h.size = std::sqrt(size2);
    const Real tol = kMappedHullTolerance * h.size;
    // The images the hull is computed on (all, or those the prefilter keeps) and their
    // indices; `dropped` marks the others, which are neither corners nor boundary points.
    std::vector<Vec<D>>& kept_images = work.kept_images;
    std::vector<int>& kept = work.kept;
    std::vector<char>& dropped = work.dropped;
    kept_images.clear();
    kept.clear();
    dropped.assign(h.images.size(), 0);
    std::span<const Vec<D>> hull_input(h.images);
    if (prefilter == HullPrefilter::inscribed_ball) {
        const Real rho = inscribed_ball_radius<D>(h.images);
        const Real drop = (1 - kDropMargin) * rho;
        // The margin left inside every facet must dwarf the boundary tolerance.
        if (rho > 0 && kDropMargin * rho > 1e3 * tol) {
            for (std::size_t i = 0; i < h.images.size(); ++i) {
                if (h.images[i].squaredNorm() < drop * drop) {
                    dropped[i] = 1;
                } else {
                    kept.push_back(static_cast<int>(i));
                    kept_images.push_back(h.images[i]);
                }
            }
            hull_input = kept_images;
        }
    }
    const bool filtered = hull_input.data() != h.images.data();
    const auto original = [&](std::vector<int>& idx) {
        if (filtered)
            for (int& k : idx)
                k = kept[static_cast<std::size_t>(k)];
    };
    if constexpr (D == 2) {
        std::vector<int>& corners = work.corners;
        quadrant_hull_2d_into(hull_input, HullPoints::vertices, work.quadrant, corners);
        hull_edges_2d_into(hull_input, corners, h.facets);
        original(corners);
        h.vertices.assign(corners.begin(), corners.end());
        std::sort(h.vertices.begin(), h.vertices.end());
        if (h.facets.empty()) {
            // Fewer than 3 corners: a point or a segment; its edge points come exactly.
            quadrant_hull_2d_into(hull_input, HullPoints::boundary, work.quadrant, h.boundary);
            original(h.boundary);
            std::sort(h.boundary.begin(), h.boundary.end());
            return;
        }
    } else {
        ConvexHull3d& v = work.hull_3d;
        convex_hull_3d_into(hull_input, HullPoints::vertices, work.quickhull, v);
        original(v.points);
        h.vertices.assign(v.points.begin(), v.points.end());
        h.facets.assign(v.facets.begin(), v.facets.end());
        if (h.facets.empty()) {
            convex_hull_3d_into(hull_input, HullPoints::boundary, work.quickhull, v);
            original(v.points);
            h.boundary.assign(v.points.begin(), v.points.end());
            return;
        }
    }
    // Points within the tolerance of a facet join the corners. Duplicates of a corner (same
    // image) are on the boundary too. An image nearer the origin than every facet's plane by
    // more than the tolerance (|r'| < min(-d) - 2 tol: n.r' + d <= |r'| + d < -tol, with a
    // tolerance's margin for rounding) is on none; the test skips it (issue 22).
    Real inner = std::numeric_limits<Real>::max();
    for (const auto& f : h.facets)
        inner = std::min(inner, -f[D]);
    const Real skip = inner - 2 * tol;
    const Real skip2 = skip > 0 ? skip * skip : Real(-1);
    for (std::size_t i = 0; i < h.images.size(); ++i) {
        if (dropped[i] != 0 || h.images[i].squaredNorm() < skip2)
            continue;
        for (const auto& f : h.facets)
            if (f.template head<D>().dot(h.images[i]) + f[D] > -tol) {
                h.boundary.push_back(static_cast<int>(i));
                break;
            }
    }
}

template <int D>
MappedHull<D> mapped_hull(std::span<const Vec<D>> offsets, HullPrefilter prefilter) {
    MappedHull<D> h;
    MappedHullWork<D> work;
    mapped_hull_into<D>(offsets, prefilter, work, h);
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

template MappedHull<2> mapped_hull<2>(std::span<const Vec<2>>, HullPrefilter);
template MappedHull<3> mapped_hull<3>(std::span<const Vec<3>>, HullPrefilter);
template void mapped_hull_into<2>(std::span<const Vec<2>>, HullPrefilter, MappedHullWork<2>&,
                                  MappedHull<2>&);
template void mapped_hull_into<3>(std::span<const Vec<3>>, HullPrefilter, MappedHullWork<3>&,
                                  MappedHull<3>&);
template Real inscribed_ball_radius<2>(std::span<const Vec<2>>);
template Real inscribed_ball_radius<3>(std::span<const Vec<3>>);
template bool hull_surrounds_origin<2>(const MappedHull<2>&);
template bool hull_surrounds_origin<3>(const MappedHull<3>&);

} // namespace sluice
