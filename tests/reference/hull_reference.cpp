// The convex-hull neighbour selection as it was at commit 0f22f9e, before its rewrite (Qhull in
// 3-D, allocating 2-D hull): the reference the new selection must reproduce exactly
// (tests/unit/test_hull_selection_reference.cpp, test_quickhull_3d.cpp). Frozen: the code below
// is the old sources with their public names prefixed old_; do not change it.
#include "tests/reference/hull_reference.hpp"

#include "sluice/physics/exact_orientation.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

extern "C" {
#include <libqhull_r/libqhull_r.h>
}

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <utility>

namespace sluice::hull_reference {
// ---- src/physics/convex_hull_2d.cpp at 0f22f9e ----

namespace {

// Indices of the distinct points, sorted by (x, y); of equal points the lowest index stays.
void distinct_sorted_into(std::span<const Vec<2>> p, std::vector<int>& idx) {
    idx.resize(p.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::sort(idx.begin(), idx.end(), [&](int a, int b) {
        const auto& pa = p[static_cast<std::size_t>(a)];
        const auto& pb = p[static_cast<std::size_t>(b)];
        if (pa.x() != pb.x())
            return pa.x() < pb.x();
        if (pa.y() != pb.y())
            return pa.y() < pb.y();
        return a < b;
    });
    const auto same = [&](int a, int b) {
        return p[static_cast<std::size_t>(a)] == p[static_cast<std::size_t>(b)];
    };
    idx.erase(std::unique(idx.begin(), idx.end(), same), idx.end());
}

std::vector<int> distinct_sorted(std::span<const Vec<2>> p) {
    std::vector<int> idx;
    distinct_sorted_into(p, idx);
    return idx;
}

// A point seen in a frame rotated by k quarter turns counter-clockwise: exact in floating
// point (negation and swap), and orientation is unchanged.
Vec<2> rotated(const Vec<2>& q, int k) {
    switch (k & 3) {
    case 0:
        return q;
    case 1:
        return {-q.y(), q.x()};
    case 2:
        return {-q.x(), -q.y()};
    default:
        return {q.y(), -q.x()};
    }
}

// Lee & Lee's extreme point that starts region k (k = 0: A, 1: B, 2: C, 3: D), found in the
// frame rotated by k quarter turns as "the highest point, the leftmost of them". In the
// original frame this is P1 = leftmost of the highest, P2 = highest of the rightmost,
// P3 = rightmost of the lowest, P4 = lowest of the leftmost: the tie-breaking under which
// their strict/non-strict region bounds cover every hull vertex exactly once.
int extreme_point(std::span<const Vec<2>> p, const std::vector<int>& idx, int k) {
    int best = idx.front();
    Vec<2> b = rotated(p[static_cast<std::size_t>(best)], k);
    for (int i : idx) {
        const Vec<2> q = rotated(p[static_cast<std::size_t>(i)], k);
        if (q.y() > b.y() || (q.y() == b.y() && q.x() < b.x())) {
            best = i;
            b = q;
        }
    }
    return best;
}

// The polygon chain of region k: the start point, then the points of the region ordered by
// falling Y (rising X among equal Y) in the rotated frame, keeping each one whose X exceeds
// that of the last kept point ("the next smaller Y AND the next larger X", section 2.나.1.가).
// The region of A is X1 <= X < Xmax, Y2 < Y <= Ymax; B-D are the same rule rotated.
//
// One addition to the text: a point enters the region only if it lies strictly beyond the
// chord from the start to the end point (Akl & Toussaint's 1978 elimination of the points
// inside the quadrilateral P1 P2 P3 P4, which cannot be hull vertices). Lee & Lee's boxes
// overlap when X1 <= X3 and Y2 < Y4 (regions A and C) or X3 < X1 and Y4 <= Y2 (B and D), which
// coincident extreme points make certain: with P1 = P2 = (2, 2) and P3 = P4 = (-2, -1), the
// point (1, 0) lies in the boxes of both B and D, enters the polygon twice, and the scan then
// deletes real vertices. Beyond its own chord, a point lies in one region only.
void append_region_chain(std::span<const Vec<2>> p, const std::vector<int>& idx, int start, int end,
                         int k, std::vector<int>& polygon) {
    const Vec<2>& s0 = p[static_cast<std::size_t>(start)];
    const Vec<2>& e0 = p[static_cast<std::size_t>(end)];
    const Vec<2> s = rotated(s0, k);
    const Vec<2> e = rotated(e0, k);
    // Reused between calls (the hull runs once per particle and step).
    thread_local std::vector<std::pair<Vec<2>, int>> region;
    region.clear();
    for (int i : idx) {
        const Vec<2> q = rotated(p[static_cast<std::size_t>(i)], k);
        if (i != start && q.x() >= s.x() && q.x() < e.x() && q.y() > e.y() && q.y() <= s.y() &&
            orientation_sign(s0, e0, p[static_cast<std::size_t>(i)]) > 0)
            region.emplace_back(q, i);
    }
    std::sort(region.begin(), region.end(), [](const auto& a, const auto& b) {
        if (a.first.y() != b.first.y())
            return a.first.y() > b.first.y();
        return a.first.x() < b.first.x();
    });
    // Coincident extreme points (start == end, e.g. P1 == P2): the region's range is empty
    // and contradicts itself. Lee & Lee's repair keeps the start point as the region's only
    // polygon point and lets the next region start again from it; the doubled point is merged
    // before the scan (merge_repeats).
    polygon.push_back(start);
    Real last_x = s.x();
    for (const auto& [q, i] : region) {
        if (q.x() > last_x) {
            polygon.push_back(i);
            last_x = q.x();
        }
    }
}

// "The doubled P1 appears as one P1 in the end": consecutive repeats (cyclically) go.
void merge_repeats(std::vector<int>& polygon) {
    polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
    while (polygon.size() > 1 && polygon.back() == polygon.front())
        polygon.pop_back();
}

// Sklansky's cross-product scan over the closed polygon (traversed clockwise), section 2.나.2:
// P = (X_{j+1} - X_j)(Y_{j+2} - Y_{j+1}) - (Y_{j+1} - Y_j)(X_{j+2} - X_{j+1});
// P < 0 (a clockwise, convex turn): advance; otherwise j+1 is deleted. After a deletion the
// scan steps back one point (j-1, j, j+2) before going on: read literally ("j stays fixed"),
// a deletion can leave j itself concave, e.g. at (1, 9.5) in the set
// (0, 10), (1, 9.5), (2, 8.5), (10, 8), (11, 0) (tests/unit/test_convex_hull_2d.cpp). The
// first point, P1, is a hull vertex and closes the scan ("one point more than the polygon").
// Collinear turns (P == 0) are deleted: only corners remain.
std::vector<int> sklansky_scan(std::span<const Vec<2>> p, const std::vector<int>& polygon) {
    std::vector<int> hull;
    hull.reserve(polygon.size() + 1);
    const auto at = [&](int i) -> const Vec<2>& { return p[static_cast<std::size_t>(i)]; };
    for (std::size_t n = 0; n <= polygon.size(); ++n) {
        const int q = polygon[n % polygon.size()];
        while (hull.size() >= 2 &&
               orientation_sign(at(hull[hull.size() - 2]), at(hull.back()), at(q)) >= 0)
            hull.pop_back();
        hull.push_back(q);
    }
    hull.pop_back(); // P1 again
    return hull;
}

// True when q lies on the closed segment [a, b] (exact).
bool on_segment(const Vec<2>& a, const Vec<2>& b, const Vec<2>& q) {
    return orientation_sign(a, b, q) == 0 && std::min(a.x(), b.x()) <= q.x() &&
           q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
           q.y() <= std::max(a.y(), b.y());
}

// Corners -> corners plus the points on their edges, in the order of the corners.
std::vector<int> add_edge_points(std::span<const Vec<2>> p, const std::vector<int>& distinct,
                                 const std::vector<int>& corners) {
    if (corners.size() < 2)
        return corners;
    const auto at = [&](int i) -> const Vec<2>& { return p[static_cast<std::size_t>(i)]; };
    std::vector<char> is_corner(p.size(), 0);
    for (int c : corners)
        is_corner[static_cast<std::size_t>(c)] = 1;
    // A 2-corner hull is a segment: walk it once, not there and back.
    const std::size_t edges = corners.size() == 2 ? 1 : corners.size();
    std::vector<int> out;
    for (std::size_t k = 0; k < edges; ++k) {
        const int a = corners[k];
        const int b = corners[(k + 1) % corners.size()];
        out.push_back(a);
        std::vector<int> on_edge;
        for (int i : distinct)
            if (is_corner[static_cast<std::size_t>(i)] == 0 && on_segment(at(a), at(b), at(i)))
                on_edge.push_back(i);
        // Order along a -> b by the coordinate that changes most (exact comparisons).
        const bool by_x = std::abs(at(b).x() - at(a).x()) >= std::abs(at(b).y() - at(a).y());
        const Real sign =
            by_x ? (at(b).x() > at(a).x() ? 1 : -1) : (at(b).y() > at(a).y() ? 1 : -1);
        std::sort(on_edge.begin(), on_edge.end(), [&](int u, int v) {
            return by_x ? sign * at(u).x() < sign * at(v).x() : sign * at(u).y() < sign * at(v).y();
        });
        out.insert(out.end(), on_edge.begin(), on_edge.end());
    }
    if (corners.size() == 2)
        out.push_back(corners[1]);
    return out;
}

} // namespace

std::vector<int> old_quadrant_hull_2d(std::span<const Vec<2>> points, HullPoints which) {
    thread_local std::vector<int> idx;
    distinct_sorted_into(points, idx);
    if (idx.empty())
        return {};
    std::array<int, 4> extreme{};
    for (int k = 0; k < 4; ++k)
        extreme[static_cast<std::size_t>(k)] = extreme_point(points, idx, k);
    thread_local std::vector<int> polygon;
    polygon.clear();
    for (int k = 0; k < 4; ++k)
        append_region_chain(points, idx, extreme[static_cast<std::size_t>(k)],
                            extreme[static_cast<std::size_t>((k + 1) & 3)], k, polygon);
    merge_repeats(polygon);
    std::vector<int> corners = polygon.size() <= 2 ? polygon : sklansky_scan(points, polygon);
    return which == HullPoints::vertices ? corners : add_edge_points(points, idx, corners);
}

std::vector<int> old_monotone_chain_hull_2d(std::span<const Vec<2>> points, HullPoints which) {
    const std::vector<int> idx = distinct_sorted(points);
    if (idx.size() <= 2)
        return idx;
    const auto at = [&](int i) -> const Vec<2>& { return points[static_cast<std::size_t>(i)]; };
    // Pop on a clockwise turn, and on a straight one unless edge points are kept.
    const int pop_below = which == HullPoints::boundary ? 0 : 1;
    const auto chain = [&](auto first, auto last) {
        std::vector<int> c;
        for (auto it = first; it != last; ++it) {
            while (c.size() >= 2 &&
                   orientation_sign(at(c[c.size() - 2]), at(c.back()), at(*it)) < pop_below)
                c.pop_back();
            c.push_back(*it);
        }
        c.pop_back(); // the first point of the other chain
        return c;
    };
    std::vector<int> hull = chain(idx.begin(), idx.end());
    const std::vector<int> upper = chain(idx.rbegin(), idx.rend());
    hull.insert(hull.end(), upper.begin(), upper.end());
    // A collinear set with its edge points kept comes back twice (there and back): once only.
    std::vector<char> seen(points.size(), 0);
    std::erase_if(hull,
                  [&](int i) { return std::exchange(seen[static_cast<std::size_t>(i)], 1) != 0; });
    return hull;
}

std::vector<Eigen::Matrix<Real, 3, 1>>
old_hull_edges_2d(std::span<const Vec<2>> points, const std::vector<int>& clockwise_corners) {
    std::vector<Eigen::Matrix<Real, 3, 1>> edges;
    const std::size_t n = clockwise_corners.size();
    if (n < 3)
        return edges;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec<2>& a = points[static_cast<std::size_t>(clockwise_corners[k])];
        const Vec<2>& b = points[static_cast<std::size_t>(clockwise_corners[(k + 1) % n])];
        const Vec<2> t = (b - a).normalized();
        const Vec<2> normal(-t.y(), t.x()); // left of a -> b: outside for a clockwise hull
        edges.emplace_back(normal.x(), normal.y(), -normal.dot(a));
    }
    return edges;
}

// ---- src/physics/old_convex_hull_3d.cpp at 0f22f9e ----

namespace {

constexpr Real kRankTolerance = Real(1e-10);    // singular value / largest one below this: flat
constexpr Real kBoundaryTolerance = Real(1e-9); // distance to a facet / set size: on the facet

std::vector<int> distinct_points(std::span<const Vec<3>> p) {
    std::vector<int> idx(p.size());
    std::iota(idx.begin(), idx.end(), 0);
    const auto key = [&](int i) {
        const auto& q = p[static_cast<std::size_t>(i)];
        return std::array<Real, 3>{q.x(), q.y(), q.z()};
    };
    std::sort(idx.begin(), idx.end(),
              [&](int a, int b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
    idx.erase(std::unique(idx.begin(), idx.end(), [&](int a, int b) { return key(a) == key(b); }),
              idx.end());
    return idx;
}

// Qhull's messages on precision trouble go nowhere: the caller gets the exit code.
std::FILE* quiet_stream() {
    static std::FILE* f = std::fopen("/dev/null", "w");
    return f;
}

// One Qhull instance per thread, reused from call to call: qh_freeqhull(!qh_ALL)
// keeps Qhull's short-memory pools, so a call after the first skips their set-up and most of
// its allocations. Calls in different threads never share it.
class QhullInstance {
public:
    QhullInstance() { qh_zero(&qh_, quiet_stream()); }
    ~QhullInstance() { release(); }
    // After a refused input Qhull's state is not trusted again: everything goes, a fresh one
    // starts.
    void reset() {
        release();
        qh_zero(&qh_, quiet_stream());
    }
    QhullInstance(const QhullInstance&) = delete;
    QhullInstance& operator=(const QhullInstance&) = delete;
    qhT* get() { return &qh_; }

private:
    void release() {
        qh_freeqhull(&qh_, qh_ALL);
        int still_long = 0;
        int total_long = 0;
        qh_memfreeshort(&qh_, &still_long, &total_long);
    }
    qhT qh_{};
};

// Runs Qhull on the distinct points; false when it refuses them.
bool run_qhull(std::span<const Vec<3>> p, const std::vector<int>& idx, const char* options,
               ConvexHull3d& out) {
    thread_local std::vector<coordT> coords;
    coords.clear();
    for (int i : idx)
        for (int a = 0; a < 3; ++a)
            coords.push_back(p[static_cast<std::size_t>(i)][a]);
    thread_local QhullInstance instance;
    qhT* qh = instance.get();
    std::array<char, 64> command{};
    std::snprintf(command.data(), command.size(), "qhull %s", options);
    const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(idx.size()), coords.data(), False,
                                       command.data(), nullptr, quiet_stream());
    if (exit_code == 0) {
        vertexT* vertex = nullptr;
        FORALLvertices {
            out.points.push_back(idx[static_cast<std::size_t>(qh_pointid(qh, vertex->point))]);
        }
        facetT* facet = nullptr;
        FORALLfacets {
            out.facets.emplace_back(facet->normal[0], facet->normal[1], facet->normal[2],
                                    facet->offset);
        }
    }
    // The hull's memory goes back to the pools, which stay for the next call.
    qh_freeqhull(qh, !qh_ALL);
    if (exit_code != 0)
        instance.reset();
    return exit_code == 0;
}

} // namespace

ConvexHull3d old_convex_hull_3d(std::span<const Vec<3>> points, HullPoints which) {
    ConvexHull3d hull;
    const std::vector<int> idx = distinct_points(points);
    if (idx.empty())
        return hull;
    const auto at = [&](int i) -> const Vec<3>& { return points[static_cast<std::size_t>(i)]; };

    Vec<3> centre = Vec<3>::Zero();
    for (int i : idx)
        centre += at(i);
    centre /= static_cast<Real>(idx.size());
    // At least 3 rows (zero rows change nothing) so that there are 3 singular values.
    Eigen::Matrix<Real, Eigen::Dynamic, 3> centred =
        Eigen::Matrix<Real, Eigen::Dynamic, 3>::Zero(std::max<Eigen::Index>(3, std::ssize(idx)), 3);
    for (std::size_t k = 0; k < idx.size(); ++k)
        centred.row(static_cast<Eigen::Index>(k)) = (at(idx[k]) - centre).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix<Real, Eigen::Dynamic, 3>> svd(centred,
                                                                       Eigen::ComputeFullV);
    const Vec<3> sigma = svd.singularValues();
    hull.dimension = 0;
    for (int a = 0; a < 3; ++a)
        if (sigma[a] > kRankTolerance * sigma[0])
            hull.dimension = a + 1;

    if (hull.dimension <= 1) {
        // A point or a segment: its end points along the principal direction, or all points.
        const Vec<3> u = svd.matrixV().col(0);
        const auto along = [&](int i) { return u.dot(at(i)); };
        if (which == HullPoints::boundary || hull.dimension == 0) {
            hull.points = idx;
        } else {
            const auto [lo, hi] = std::minmax_element(
                idx.begin(), idx.end(), [&](int a, int b) { return along(a) < along(b); });
            hull.points = {*lo, *hi};
        }
    } else if (hull.dimension == 2) {
        // A flat set has no interior: every point is on its boundary. Its corners: drop the
        // coordinate along which the plane's normal points most, an exact affine projection,
        // so the 2-D hull of the images is the hull of the plane's points.
        if (which == HullPoints::boundary) {
            hull.points = idx;
        } else {
            const Vec<3> normal = svd.matrixV().col(2);
            int drop = 0;
            normal.cwiseAbs().maxCoeff(&drop);
            const int u = (drop + 1) % 3;
            const int v = (drop + 2) % 3;
            std::vector<Vec<2>> flat;
            flat.reserve(idx.size());
            for (int i : idx)
                flat.emplace_back(at(i)[u], at(i)[v]);
            for (int k : old_monotone_chain_hull_2d(flat, HullPoints::vertices))
                hull.points.push_back(idx[static_cast<std::size_t>(k)]);
        }
    } else {
        if (!run_qhull(points, idx, "", hull)) {
            // Nearly flat sets can still trouble Qhull's precision checks: joggle the input
            // (deterministic seed) rather than fail.
            hull.points.clear();
            hull.facets.clear();
            run_qhull(points, idx, "QJ", hull);
        }
        if (which == HullPoints::boundary) {
            Real size = 0;
            for (int i : idx)
                size = std::max(size, (at(i) - centre).norm());
            const Real tol = kBoundaryTolerance * size;
            std::vector<char> in(points.size(), 0);
            for (int i : hull.points)
                in[static_cast<std::size_t>(i)] = 1;
            for (int i : idx) {
                if (in[static_cast<std::size_t>(i)] != 0)
                    continue;
                for (const auto& f : hull.facets)
                    if (f.head<3>().dot(at(i)) + f[3] > -tol) {
                        hull.points.push_back(i);
                        break;
                    }
            }
        }
    }
    std::sort(hull.points.begin(), hull.points.end());
    return hull;
}

// ---- src/physics/old_mapped_hull.cpp at 0f22f9e ----

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
Real old_inscribed_ball_radius(std::span<const Vec<D>> images) {
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
void old_mapped_hull_into(std::span<const Vec<D>> offsets, HullPrefilter prefilter,
                          MappedHull<D>& h) {
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
    thread_local std::vector<Vec<D>> kept_images;
    thread_local std::vector<int> kept;
    thread_local std::vector<char> dropped;
    kept_images.clear();
    kept.clear();
    dropped.assign(h.images.size(), 0);
    std::span<const Vec<D>> hull_input(h.images);
    if (prefilter == HullPrefilter::inscribed_ball) {
        const Real rho = old_inscribed_ball_radius<D>(h.images);
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
        std::vector<int> corners = old_quadrant_hull_2d(hull_input, HullPoints::vertices);
        h.facets = old_hull_edges_2d(hull_input, corners);
        original(corners);
        h.vertices = corners;
        std::sort(h.vertices.begin(), h.vertices.end());
        if (h.facets.empty()) {
            // Fewer than 3 corners: a point or a segment; its edge points come exactly.
            h.boundary = old_quadrant_hull_2d(hull_input, HullPoints::boundary);
            original(h.boundary);
            std::sort(h.boundary.begin(), h.boundary.end());
            return;
        }
    } else {
        ConvexHull3d v = old_convex_hull_3d(hull_input, HullPoints::vertices);
        original(v.points);
        h.vertices = v.points;
        h.facets = v.facets;
        if (h.facets.empty()) {
            std::vector<int> b = old_convex_hull_3d(hull_input, HullPoints::boundary).points;
            original(b);
            h.boundary = b;
            return;
        }
    }
    // Points within the tolerance of a facet join the corners. Duplicates of a corner (same
    // image) are on the boundary too.
    for (std::size_t i = 0; i < h.images.size(); ++i) {
        if (dropped[i] != 0)
            continue;
        for (const auto& f : h.facets)
            if (f.template head<D>().dot(h.images[i]) + f[D] > -tol) {
                h.boundary.push_back(static_cast<int>(i));
                break;
            }
    }
}

template <int D>
MappedHull<D> old_mapped_hull(std::span<const Vec<D>> offsets, HullPrefilter prefilter) {
    MappedHull<D> h;
    old_mapped_hull_into<D>(offsets, prefilter, h);
    return h;
}

template <int D>
bool old_hull_surrounds_origin(const MappedHull<D>& hull) {
    if (hull.facets.empty())
        return false;
    const Real tol = kMappedHullTolerance * hull.size;
    return std::all_of(hull.facets.begin(), hull.facets.end(),
                       [&](const auto& f) { return f[D] < -tol; });
}

template MappedHull<2> old_mapped_hull<2>(std::span<const Vec<2>>, HullPrefilter);
template MappedHull<3> old_mapped_hull<3>(std::span<const Vec<3>>, HullPrefilter);
template void old_mapped_hull_into<2>(std::span<const Vec<2>>, HullPrefilter, MappedHull<2>&);
template void old_mapped_hull_into<3>(std::span<const Vec<3>>, HullPrefilter, MappedHull<3>&);
template Real old_inscribed_ball_radius<2>(std::span<const Vec<2>>);
template Real old_inscribed_ball_radius<3>(std::span<const Vec<3>>);
template bool old_hull_surrounds_origin<2>(const MappedHull<2>&);
template bool old_hull_surrounds_origin<3>(const MappedHull<3>&);

// ---- src/physics/neighbour_selection.cpp at 0f22f9e ----

template <int D>
std::vector<int> old_select_neighbours(std::span<const Vec<D>> offsets, Real support, Real dx,
                                       const NeighbourSelection& selection) {
    std::vector<int> out;
    const auto add_radius_set = [&] {
        const Real s2 = support * support;
        for (std::size_t j = 0; j < offsets.size(); ++j)
            if (offsets[j].squaredNorm() < s2)
                out.push_back(static_cast<int>(j));
    };
    if (selection.policy == NeighbourPolicy::radius) {
        add_radius_set();
        return out;
    }
    const Real rc = Real(selection.candidate_radius_over_dx) * dx;
    // Reused between calls (once per particle and step).
    thread_local std::vector<int> candidate;
    thread_local std::vector<Vec<D>> r;
    candidate.clear();
    r.clear();
    for (std::size_t j = 0; j < offsets.size(); ++j) {
        const Real r2 = offsets[j].squaredNorm();
        if (r2 > 0 && r2 <= rc * rc) {
            candidate.push_back(static_cast<int>(j));
            r.push_back(offsets[j]);
        }
    }
    thread_local MappedHull<D> hull; // buffers reused between calls
    old_mapped_hull_into<D>(r, HullPrefilter::inscribed_ball, hull);
    for (int k : selection.hull_boundary ? hull.boundary : hull.vertices)
        out.push_back(candidate[static_cast<std::size_t>(k)]);
    if (selection.union_with_radius)
        add_radius_set();
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

template std::vector<int> old_select_neighbours<2>(std::span<const Vec<2>>, Real, Real,
                                                   const NeighbourSelection&);
template std::vector<int> old_select_neighbours<3>(std::span<const Vec<3>>, Real, Real,
                                                   const NeighbourSelection&);

} // namespace sluice::hull_reference
