// SurfaceIndex (surface_index.hpp): CGAL's AABB tree over the triangles (3-D) or the segments
// in the plane z = 0 (2-D); the inside test of closed shapes by CGAL's Side_of_triangle_mesh
// (3-D) or the bounded side of each closed loop (2-D, parity over loops, so holes work).
#include "sluice/geometry/surface_index.hpp"

#include "point_math.hpp"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <boost/variant/get.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace sluice {

using detail::dot;
using detail::minus;
using detail::norm;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;
using Triangles = std::vector<K::Triangle_3>;
using Segments = std::vector<K::Segment_3>;
using TriTree = CGAL::AABB_tree<
    CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>>>;
using SegTree = CGAL::AABB_tree<
    CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Segments::const_iterator>>>;
using Mesh = CGAL::Surface_mesh<P3>;
using MeshSide = CGAL::Side_of_triangle_mesh<Mesh, K>;

P3 point(const Point3& p) {
    return {p[0], p[1], p[2]};
}
Point3 triple(const P3& p) {
    return {p.x(), p.y(), p.z()};
}

// Directed edges (3-D) or segments (2-D) each matched by exactly one reverse, and no directed
// edge used twice: a closed, consistently oriented surface.
bool is_closed(const SurfaceGeometry& g) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    if (g.dimension == 3) {
        edges.reserve(3 * g.triangles.size());
        for (const auto& t : g.triangles)
            for (int k = 0; k < 3; ++k)
                edges.emplace_back(t[static_cast<std::size_t>(k)],
                                   t[static_cast<std::size_t>((k + 1) % 3)]);
    } else {
        // In 2-D every vertex needs one segment arriving and one leaving.
        std::vector<int> out(g.vertices.size(), 0), in(g.vertices.size(), 0);
        for (const auto& s : g.segments) {
            ++out[s[0]];
            ++in[s[1]];
        }
        for (std::size_t v = 0; v < g.vertices.size(); ++v)
            if ((out[v] != 0 || in[v] != 0) && (out[v] != 1 || in[v] != 1))
                return false;
        return !g.segments.empty();
    }
    std::sort(edges.begin(), edges.end());
    if (std::adjacent_find(edges.begin(), edges.end()) != edges.end())
        return false;
    for (const auto& [a, b] : edges)
        if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a)))
            return false;
    return !edges.empty();
}

// Signed enclosed volume (3-D, divergence theorem) or area (2-D, shoelace) of a closed shape.
double signed_content(const SurfaceGeometry& g) {
    double sum = 0;
    if (g.dimension == 3) {
        for (const auto& t : g.triangles) {
            const Point3 &a = g.vertices[t[0]], &b = g.vertices[t[1]], &c = g.vertices[t[2]];
            sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
        return sum / 6;
    }
    // Normals are (dy, -dx): outward for a counter-clockwise loop, whose shoelace sum is > 0.
    for (const auto& s : g.segments) {
        const Point3 &a = g.vertices[s[0]], &b = g.vertices[s[1]];
        sum += a[0] * b[1] - b[0] * a[1];
    }
    return sum / 2;
}

// The closed loops of a closed 2-D shape, each as its vertices in order.
std::vector<std::vector<K::Point_2>> loops_of(const SurfaceGeometry& g) {
    std::vector<std::uint32_t> next(g.vertices.size(), std::numeric_limits<std::uint32_t>::max());
    for (const auto& s : g.segments)
        next[s[0]] = s[1];
    std::vector<bool> seen(g.vertices.size(), false);
    std::vector<std::vector<K::Point_2>> loops;
    for (const auto& s : g.segments) {
        if (seen[s[0]])
            continue;
        std::vector<K::Point_2> loop;
        for (std::uint32_t v = s[0]; !seen[v]; v = next[v]) {
            seen[v] = true;
            loop.emplace_back(g.vertices[v][0], g.vertices[v][1]);
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

// Pseudo-normals (Baerentzen & Aanaes 2005): the sign of (x - p) . n tells the side of x only
// where p lies inside an element; where the closest point p is an edge or a vertex, n must be
// that feature's pseudo-normal, the sum of its elements' normals (angle-weighted at a 3-D
// vertex). With the element's own normal, a point behind a convex corner can read as in front
// of the face whose end it is nearest. Per vertex here; per edge on demand (two normals).
std::vector<Point3> vertex_pseudo_normals(const SurfaceGeometry& g,
                                          const std::vector<Point3>& normals) {
    std::vector<Point3> n(g.vertices.size(), Point3{});
    const auto add = [&](std::uint32_t v, const Point3& m, double w) {
        for (std::size_t a = 0; a < 3; ++a)
            n[v][a] += w * m[a];
    };
    if (g.dimension == 3) {
        for (std::size_t e = 0; e < g.triangles.size(); ++e) {
            const auto& t = g.triangles[e];
            for (std::size_t k = 0; k < 3; ++k) {
                const Point3 u = minus(g.vertices[t[(k + 1) % 3]], g.vertices[t[k]]);
                const Point3 w = minus(g.vertices[t[(k + 2) % 3]], g.vertices[t[k]]);
                const double nu = norm(u), nw = norm(w);
                const double angle =
                    nu > 0 && nw > 0 ? std::acos(std::clamp(dot(u, w) / (nu * nw), -1.0, 1.0)) : 0;
                add(t[k], normals[e], angle);
            }
        }
    } else {
        for (std::size_t e = 0; e < g.segments.size(); ++e) {
            add(g.segments[e][0], normals[e], 1);
            add(g.segments[e][1], normals[e], 1);
        }
    }
    return n;
}

// Each triangle's neighbour across its edge k (from vertex k to k + 1), or none.
constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();
std::vector<std::array<std::uint32_t, 3>> edge_neighbours(const SurfaceGeometry& g) {
    std::vector<std::array<std::uint32_t, 3>> nb(g.triangles.size(),
                                                 {kNoTriangle, kNoTriangle, kNoTriangle});
    // (low vertex, high vertex, triangle, edge) sorted: the two uses of an edge side by side.
    std::vector<std::array<std::uint32_t, 4>> uses;
    uses.reserve(3 * g.triangles.size());
    for (std::size_t e = 0; e < g.triangles.size(); ++e)
        for (std::uint32_t k = 0; k < 3; ++k) {
            const std::uint32_t a = g.triangles[e][k], b = g.triangles[e][(k + 1) % 3];
            uses.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(e), k});
        }
    std::sort(uses.begin(), uses.end());
    for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
        const auto &u = uses[i], &w = uses[i + 1];
        if (u[0] != w[0] || u[1] != w[1])
            continue;
        // Exactly two uses: a manifold edge (a third use leaves the edge to its own normals).
        if ((i + 2 < uses.size() && uses[i + 2][0] == u[0] && uses[i + 2][1] == u[1]) ||
            (i > 0 && uses[i - 1][0] == u[0] && uses[i - 1][1] == u[1]))
            continue;
        nb[u[2]][u[3]] = w[2];
        nb[w[2]][w[3]] = u[2];
    }
    return nb;
}

} // namespace

struct SurfaceIndex::Impl {
    SurfaceGeometry g;
    std::vector<Point3> normals;
    bool closed = false;
    double content = 0, size = 0;
    Point3 lo{}, hi{};
    Triangles triangles;
    Segments segments;
    std::unique_ptr<TriTree> tri_tree;
    std::unique_ptr<SegTree> seg_tree;
    Mesh mesh;                                            // closed 3-D shapes: for the inside test
    std::unique_ptr<MeshSide> side;                       // ...
    std::vector<std::vector<K::Point_2>> loops;           // closed 2-D shapes
    std::vector<Point3> vertex_normals;                   // pseudo-normals (unnormalised)
    std::vector<std::array<std::uint32_t, 3>> neighbours; // 3-D: across each edge
    // Elements of no size (collinear or repeated vertices, up to round-off against the shape's
    // size): no normal, and CGAL's segment-triangle intersection asserts on them. Skipped by
    // the crossing queries.
    std::vector<bool> degenerate;

    // The pseudo-normal of the feature of element e that p (its closest point to some x)
    // lies on: the element's normal inside it, an edge's or a vertex's at its boundary.
    Point3 feature_normal(std::size_t e, const Point3& p) const {
        const double tol2 = 1e-18 * std::max(1.0, dot(p, p));
        if (g.dimension == 2) {
            for (std::uint32_t v : g.segments[e]) {
                const Point3 r = minus(p, g.vertices[v]);
                if (dot(r, r) <= tol2)
                    return vertex_normals[v];
            }
            return normals[e];
        }
        const auto& t = g.triangles[e];
        for (std::uint32_t v : t) {
            const Point3 r = minus(p, g.vertices[v]);
            if (dot(r, r) <= tol2)
                return vertex_normals[v];
        }
        for (std::size_t k = 0; k < 3; ++k) {
            const Point3& a = g.vertices[t[k]];
            const Point3 ab = minus(g.vertices[t[(k + 1) % 3]], a), ap = minus(p, a);
            const double len2 = dot(ab, ab);
            if (len2 == 0)
                continue;
            const double f = dot(ap, ab) / len2;
            const Point3 off{ap[0] - f * ab[0], ap[1] - f * ab[1], ap[2] - f * ab[2]};
            if (dot(off, off) > tol2)
                continue;
            Point3 n = normals[e];
            if (const std::uint32_t o = neighbours[e][k]; o != kNoTriangle)
                for (std::size_t a2 = 0; a2 < 3; ++a2)
                    n[a2] += normals[o][a2];
            return n;
        }
        return normals[e];
    }

    std::size_t element_of(Triangles::const_iterator it) const {
        return static_cast<std::size_t>(it - triangles.begin());
    }
    std::size_t element_of(Segments::const_iterator it) const {
        return static_cast<std::size_t>(it - segments.begin());
    }
    Point3 anchor(std::size_t e) const {
        return g.vertices[g.dimension == 3 ? g.triangles[e][0] : g.segments[e][0]];
    }
};

SurfaceIndex::SurfaceIndex(SurfaceGeometry geometry) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.g = std::move(geometry);
    const SurfaceGeometry& g = m.g;
    if (g.elements() == 0)
        throw GeometryError("the shape has no triangles or segments");
    m.lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    m.hi = {-m.lo[0], -m.lo[1], -m.lo[2]};
    const auto grow = [&](const Point3& p) {
        for (std::size_t a = 0; a < 3; ++a) {
            m.lo[a] = std::min(m.lo[a], p[a]);
            m.hi[a] = std::max(m.hi[a], p[a]);
        }
    };
    m.normals.reserve(g.elements());
    std::vector<double> sizes(g.elements());
    for (std::size_t e = 0; e < g.elements(); ++e) {
        m.normals.push_back(element_normal(g, e));
        sizes[e] = element_size(g, e);
        m.size += sizes[e];
    }
    if (g.dimension == 3) {
        m.triangles.reserve(g.triangles.size());
        for (const auto& t : g.triangles) {
            for (auto v : t)
                grow(g.vertices[v]);
            m.triangles.emplace_back(point(g.vertices[t[0]]), point(g.vertices[t[1]]),
                                     point(g.vertices[t[2]]));
        }
        m.tri_tree = std::make_unique<TriTree>(m.triangles.begin(), m.triangles.end());
        // Built now, not lazily at the first query: the step queries from many threads.
        m.tri_tree->build();
        m.tri_tree->accelerate_distance_queries();
    } else {
        m.segments.reserve(g.segments.size());
        for (const auto& s : g.segments) {
            grow(g.vertices[s[0]]);
            grow(g.vertices[s[1]]);
            m.segments.emplace_back(point(g.vertices[s[0]]), point(g.vertices[s[1]]));
        }
        m.seg_tree = std::make_unique<SegTree>(m.segments.begin(), m.segments.end());
        m.seg_tree->build();
        m.seg_tree->accelerate_distance_queries();
    }
    double diagonal2 = 0;
    for (std::size_t a = 0; a < 3; ++a)
        diagonal2 += (m.hi[a] - m.lo[a]) * (m.hi[a] - m.lo[a]);
    const double tiny = 1e-24 * (g.dimension == 3 ? diagonal2 : std::sqrt(diagonal2));
    m.degenerate.resize(g.elements());
    for (std::size_t e = 0; e < g.elements(); ++e)
        m.degenerate[e] = !(sizes[e] > tiny);
    m.vertex_normals = vertex_pseudo_normals(g, m.normals);
    if (g.dimension == 3)
        m.neighbours = edge_neighbours(g);
    m.closed = is_closed(g);
    if (!m.closed)
        return;
    m.content = signed_content(g);
    if (g.dimension == 2) {
        m.loops = loops_of(g);
        return;
    }
    std::vector<P3> points;
    points.reserve(g.vertices.size());
    for (const auto& v : g.vertices)
        points.push_back(point(v));
    std::vector<std::vector<std::size_t>> faces;
    faces.reserve(g.triangles.size());
    for (const auto& t : g.triangles)
        faces.push_back({t[0], t[1], t[2]});
    if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces)) {
        m.closed = false; // edges pair up, but a vertex is non-manifold
        return;
    }
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, m.mesh);
    m.side = std::make_unique<MeshSide>(m.mesh);
}

SurfaceIndex::~SurfaceIndex() = default;
SurfaceIndex::SurfaceIndex(SurfaceIndex&&) noexcept = default;
SurfaceIndex& SurfaceIndex::operator=(SurfaceIndex&&) noexcept = default;

const SurfaceGeometry& SurfaceIndex::geometry() const {
    return impl_->g;
}
int SurfaceIndex::dimension() const {
    return impl_->g.dimension;
}
bool SurfaceIndex::closed() const {
    return impl_->closed;
}
bool SurfaceIndex::outward() const {
    return impl_->closed && impl_->content > 0;
}
double SurfaceIndex::enclosed_volume() const {
    return impl_->content;
}
double SurfaceIndex::surface_size() const {
    return impl_->size;
}
Point3 SurfaceIndex::lo() const {
    return impl_->lo;
}
Point3 SurfaceIndex::hi() const {
    return impl_->hi;
}

ClosestPoint SurfaceIndex::closest(const Point3& x) const {
    const Impl& m = *impl_;
    ClosestPoint c;
    if (m.tri_tree) {
        const auto [p, it] = m.tri_tree->closest_point_and_primitive(point(x));
        c.point = triple(p);
        c.element = m.element_of(it);
    } else {
        const auto [p, it] = m.seg_tree->closest_point_and_primitive(point({x[0], x[1], 0}));
        c.point = triple(p);
        c.element = m.element_of(it);
    }
    c.normal = m.normals[c.element];
    const Point3 r = minus(x, c.point);
    c.distance = std::sqrt(dot(r, r));
    // The side by the pseudo-normal of the feature the closest point lies on; its sign only
    // (an edge's or a vertex's is not unit): -1 or +1 off an element's interior.
    const Point3 n = m.feature_normal(c.element, c.point);
    const double nn = std::sqrt(dot(n, n));
    c.side = c.distance > 0 && nn > 0 ? dot(r, n) / (c.distance * nn) : 0;
    return c;
}

double SurfaceIndex::squared_distance(const Point3& x) const {
    const Impl& m = *impl_;
    if (m.tri_tree)
        return CGAL::to_double(m.tri_tree->squared_distance(point(x)));
    return CGAL::to_double(m.seg_tree->squared_distance(point({x[0], x[1], 0})));
}

bool SurfaceIndex::within(const Point3& x, double r) const {
    const Impl& m = *impl_;
    if (m.tri_tree)
        return m.tri_tree->do_intersect(K::Sphere_3(point(x), r * r));
    return m.seg_tree->do_intersect(K::Sphere_3(point({x[0], x[1], 0}), r * r));
}

bool SurfaceIndex::inside(const Point3& x) const {
    const Impl& m = *impl_;
    if (!m.closed)
        throw GeometryError("an open shape has no inside");
    if (m.side)
        return (*m.side)(point(x)) != CGAL::ON_UNBOUNDED_SIDE;
    bool in = false;
    const K::Point_2 q(x[0], x[1]);
    for (const auto& loop : m.loops) {
        const auto s = CGAL::bounded_side_2(loop.begin(), loop.end(), q, K());
        if (s == CGAL::ON_BOUNDARY)
            return true;
        in = in != (s == CGAL::ON_BOUNDED_SIDE);
    }
    return in;
}

std::optional<Crossing> SurfaceIndex::first_crossing(const Point3& a, const Point3& b,
                                                     CrossingSense sense) const {
    const Impl& m = *impl_;
    const Point3 d = minus(b, a);
    const double len2 = dot(d, d);
    if (len2 == 0)
        return std::nullopt;
    std::optional<Crossing> best;
    const auto consider = [&](const P3& p, std::size_t e) {
        if (sense == CrossingSense::entering_front && !(dot(d, m.normals[e]) < 0))
            return;
        const double f = std::clamp(dot(minus(triple(p), a), d) / len2, 0.0, 1.0);
        if (!best || f < best->fraction || (f == best->fraction && e < best->element))
            best = Crossing{triple(p), m.normals[e], m.anchor(e), f, e};
    };
    if (m.tri_tree) {
        const K::Segment_3 q(point(a), point(b));
        if (!m.tri_tree->do_intersect(q)) // most moves: no list to build
            return best;
        std::vector<TriTree::Primitive_id> hits;
        m.tri_tree->all_intersected_primitives(q, std::back_inserter(hits));
        for (const auto it : hits) {
            if (m.degenerate[m.element_of(it)])
                continue;
            const auto r = CGAL::intersection(q, *it);
            if (!r)
                continue;
            if (const P3* p = boost::get<P3>(&*r))
                consider(*p, m.element_of(it));
            else if (const auto* s = boost::get<K::Segment_3>(&*r)) // moving within the plane
                consider(s->source(), m.element_of(it));
        }
        return best;
    }
    // 2-D: the move and the segments in the plane z = 0.
    const K::Segment_3 q(point({a[0], a[1], 0}), point({b[0], b[1], 0}));
    if (!m.seg_tree->do_intersect(q))
        return best;
    std::vector<SegTree::Primitive_id> hits;
    m.seg_tree->all_intersected_primitives(q, std::back_inserter(hits));
    const K::Segment_2 q2({a[0], a[1]}, {b[0], b[1]});
    for (const auto it : hits) {
        if (m.degenerate[m.element_of(it)])
            continue;
        const K::Segment_2 s2({it->source().x(), it->source().y()},
                              {it->target().x(), it->target().y()});
        const auto r = CGAL::intersection(q2, s2);
        if (!r)
            continue;
        if (const auto* p = boost::get<K::Point_2>(&*r))
            consider(P3(p->x(), p->y(), 0), m.element_of(it));
        else if (const auto* s = boost::get<K::Segment_2>(&*r))
            consider(P3(s->source().x(), s->source().y(), 0), m.element_of(it));
    }
    return best;
}

} // namespace sluice
