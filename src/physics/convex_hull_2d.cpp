// 2-D convex hulls: Lee & Lee's quadrant + Sklansky algorithm and Andrew's monotone chain.
// See include/sluice/physics/convex_hull_2d.hpp.
#include "sluice/physics/convex_hull_2d.hpp"

#include "sluice/physics/exact_orientation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <utility>

namespace sluice {
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

// Indices of the distinct points in ascending order; of equal points the lowest index stays.
// The quadrant hull's decisions do not depend on the order of its input (the extreme points'
// ties are broken by coordinates, the regions sorted by them), so small sets skip the sort.
void distinct_into(std::span<const Vec<2>> p, std::vector<int>& idx) {
    if (p.size() > 32) {
        distinct_sorted_into(p, idx);
        return;
    }
    idx.clear();
    for (std::size_t i = 0; i < p.size(); ++i) {
        bool repeat = false;
        for (std::size_t j = 0; j < i && !repeat; ++j)
            repeat = p[j] == p[i];
        if (!repeat)
            idx.push_back(static_cast<int>(i));
    }
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
                         int k, std::vector<std::pair<Vec<2>, int>>& region,
                         std::vector<int>& polygon) {
    const Vec<2>& s0 = p[static_cast<std::size_t>(start)];
    const Vec<2>& e0 = p[static_cast<std::size_t>(end)];
    const Vec<2> s = rotated(s0, k);
    const Vec<2> e = rotated(e0, k);
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
void sklansky_scan(std::span<const Vec<2>> p, const std::vector<int>& polygon,
                   std::vector<int>& hull) {
    hull.clear();
    const auto at = [&](int i) -> const Vec<2>& { return p[static_cast<std::size_t>(i)]; };
    for (std::size_t n = 0; n <= polygon.size(); ++n) {
        const int q = polygon[n % polygon.size()];
        while (hull.size() >= 2 &&
               orientation_sign(at(hull[hull.size() - 2]), at(hull.back()), at(q)) >= 0)
            hull.pop_back();
        hull.push_back(q);
    }
    hull.pop_back(); // P1 again
}

// True when q lies on the closed segment [a, b] (exact).
bool on_segment(const Vec<2>& a, const Vec<2>& b, const Vec<2>& q) {
    return orientation_sign(a, b, q) == 0 && std::min(a.x(), b.x()) <= q.x() &&
           q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
           q.y() <= std::max(a.y(), b.y());
}

// Corners -> corners plus the points on their edges, in the order of the corners, into out.
void add_edge_points(std::span<const Vec<2>> p, const std::vector<int>& distinct,
                     const std::vector<int>& corners, QuadrantHullWork& work,
                     std::vector<int>& out) {
    out.clear();
    if (corners.size() < 2) {
        out.assign(corners.begin(), corners.end());
        return;
    }
    const auto at = [&](int i) -> const Vec<2>& { return p[static_cast<std::size_t>(i)]; };
    std::vector<char>& is_corner = work.is_corner;
    is_corner.assign(p.size(), 0);
    for (int c : corners)
        is_corner[static_cast<std::size_t>(c)] = 1;
    // A 2-corner hull is a segment: walk it once, not there and back.
    const std::size_t edges = corners.size() == 2 ? 1 : corners.size();
    std::vector<int>& on_edge = work.on_edge;
    for (std::size_t k = 0; k < edges; ++k) {
        const int a = corners[k];
        const int b = corners[(k + 1) % corners.size()];
        out.push_back(a);
        on_edge.clear();
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
}

} // namespace

void quadrant_hull_2d_into(std::span<const Vec<2>> points, HullPoints which, QuadrantHullWork& work,
                           std::vector<int>& out) {
    out.clear();
    std::vector<int>& idx = work.distinct;
    distinct_into(points, idx);
    if (idx.empty())
        return;
    std::array<int, 4> extreme{};
    for (int k = 0; k < 4; ++k)
        extreme[static_cast<std::size_t>(k)] = extreme_point(points, idx, k);
    std::vector<int>& polygon = work.polygon;
    polygon.clear();
    for (int k = 0; k < 4; ++k)
        append_region_chain(points, idx, extreme[static_cast<std::size_t>(k)],
                            extreme[static_cast<std::size_t>((k + 1) & 3)], k, work.region,
                            polygon);
    merge_repeats(polygon);
    std::vector<int>& corners = which == HullPoints::vertices ? out : work.corners;
    if (polygon.size() <= 2)
        corners.assign(polygon.begin(), polygon.end());
    else
        sklansky_scan(points, polygon, corners);
    if (which == HullPoints::boundary)
        add_edge_points(points, idx, corners, work, out);
}

std::vector<int> quadrant_hull_2d(std::span<const Vec<2>> points, HullPoints which) {
    QuadrantHullWork work;
    std::vector<int> out;
    quadrant_hull_2d_into(points, which, work, out);
    return out;
}

std::vector<int> monotone_chain_hull_2d(std::span<const Vec<2>> points, HullPoints which) {
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

void hull_edges_2d_into(std::span<const Vec<2>> points, const std::vector<int>& clockwise_corners,
                        std::vector<Eigen::Matrix<Real, 3, 1>>& edges) {
    edges.clear();
    const std::size_t n = clockwise_corners.size();
    if (n < 3)
        return;
    for (std::size_t k = 0; k < n; ++k) {
        const Vec<2>& a = points[static_cast<std::size_t>(clockwise_corners[k])];
        const Vec<2>& b = points[static_cast<std::size_t>(clockwise_corners[(k + 1) % n])];
        const Vec<2> t = (b - a).normalized();
        const Vec<2> normal(-t.y(), t.x()); // left of a -> b: outside for a clockwise hull
        edges.emplace_back(normal.x(), normal.y(), -normal.dot(a));
    }
}

std::vector<Eigen::Matrix<Real, 3, 1>> hull_edges_2d(std::span<const Vec<2>> points,
                                                     const std::vector<int>& clockwise_corners) {
    std::vector<Eigen::Matrix<Real, 3, 1>> edges;
    hull_edges_2d_into(points, clockwise_corners, edges);
    return edges;
}

} // namespace sluice
