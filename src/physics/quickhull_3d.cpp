// Quickhull on exact orientation; see include/sluice/physics/quickhull_3d.hpp.
#include "sluice/physics/quickhull_3d.hpp"

#include "sluice/physics/exact_orientation.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sluice {
namespace {

using Facet = QuickhullWork::Facet;

// A triangle whose corners are collinear to within rounding (twice its area below this
// fraction of its longest edge squared: an eye barely above a visible facet, next to one of
// its edges, as near-lattice images give) has no reliable plane: its rounded normal can point
// anywhere. It stays in the exact triangulation but is left out of the facets returned (it
// covers no area: its neighbours' planes pass through it), as Qhull merges it away.
constexpr Real kSliver = Real(1e-10);

struct Hull {
    std::span<const Vec<3>> p;
    QuickhullWork& w;
    Real eps;
    Real size; // max |p|: every coordinate difference below is at most 2 size

    const Vec<3>& at(int i) const { return p[static_cast<std::size_t>(i)]; }
    Facet& f(int k) { return w.facets[static_cast<std::size_t>(k)]; }

    // Exact: q strictly above the plane of facet k. The rounded distance to the facet's
    // plane decides first when it is farther from zero than the facet's guard, a bound on its
    // error (add_facet); only the rest go to the exact predicate, so every answer is the
    // predicate's (the predicate's filter was 15 % of quickhull).
    bool above(int k, int q) {
        const Facet& F = f(k);
        const Real dist = (F.n.dot(at(q)) + F.d) * F.area2;
        if (dist > F.guard)
            return true;
        if (-dist > F.guard)
            return false;
        return orientation_sign(at(F.v[0]), at(F.v[1]), at(F.v[2]), at(q)) > 0;
    }

    int add_facet(int a, int b, int c) {
        Facet F;
        F.v = {a, b, c};
        const Vec<3> e1 = at(b) - at(a);
        const Vec<3> e2 = at(c) - at(a);
        const Vec<3> n = e1.cross(e2);
        F.area2 = n.norm();
        F.n = n / F.area2;
        F.d = -F.n.dot(at(a));
        F.guard = distance_guard(e1.squaredNorm() + e2.squaredNorm(), F.area2);
        w.facets.push_back(F);
        return static_cast<int>(w.facets.size()) - 1;
    }

    // A bound on |(n.q + d) - s| |m~| for every point q of the set, s the exact signed
    // distance of q from the exact plane through a, b, c, m~ the rounded (b - a) x (c - a),
    // u = 2^-53, S = size: e1, e2 carry u of rounding each, the cross product another 2u per
    // product, so |m~ - m| <= 5 sqrt(3) u |e1| |e2|; normalising turns that into
    // 2 |m~ - m| / |m| + 3u of direction, times |q - a| <= 2 S; the dot products and d add under
    // 8 u S more: in all u S (34.8 |e1| |e2| / |m| + 14). Times |m~|, with |e1| |e2| <=
    // (|e1|^2 + |e2|^2) / 2 (no root, no division) and a margin on each constant:
    // u S (24 (|e1|^2 + |e2|^2) + 30 |m~|). Where the rounded distance times |m~| exceeds it, its
    // sign is the exact orientation's. The first step needs |m| close to |m~|, which holds while
    // (|e1|^2 + |e2|^2) / |m~| < 1e8 (|m~ - m| < 1e-7 |m~|); a thinner triangle (and one with |m~|
    // = 0) gets an infinite guard: every test goes to the predicate.
    Real distance_guard(Real edges_squared, Real area2) const {
        constexpr Real u = std::numeric_limits<Real>::epsilon() / 2;
        if (!(edges_squared < Real(1e8) * area2))
            return std::numeric_limits<Real>::infinity();
        return u * size * (24 * edges_squared + 30 * area2);
    }

    bool sliver(const Facet& F) const {
        const Vec<3>& a = at(F.v[0]);
        const Vec<3>& b = at(F.v[1]);
        const Vec<3>& c = at(F.v[2]);
        const Real longest =
            std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
        return !(F.area2 > kSliver * longest);
    }

    // Puts point q in the outside set of the first facet in [first, last) it lies more than
    // eps above; false when there is none (q is inside or coplanar: never a vertex).
    bool assign(int q, int first, int last) {
        for (int k = first; k < last; ++k) {
            Facet& F = f(k);
            const Real dist = F.n.dot(at(q)) + F.d;
            if (dist > eps) {
                w.next[static_cast<std::size_t>(q)] = F.outside;
                F.outside = q;
                // Selects, not a branch: whether q is the farthest so far is random.
                const bool farther =
                    dist > F.furthest_dist || (dist == F.furthest_dist && q < F.furthest);
                F.furthest_dist = farther ? dist : F.furthest_dist;
                F.furthest = farther ? q : F.furthest;
                return true;
            }
        }
        return false;
    }

    // The farthest point of facet k's outside set that is exactly above it (a sliver facet's
    // rounded plane could claim one that is not: it is dropped). -1 when none is left.
    int eye_of(int k) {
        while (f(k).furthest >= 0) {
            const int q = f(k).furthest;
            if (above(k, q))
                return q;
            // Unlink q and find the next farthest.
            Facet& F = f(k);
            int* link = &F.outside;
            while (*link != q)
                link = &w.next[static_cast<std::size_t>(*link)];
            *link = w.next[static_cast<std::size_t>(q)];
            F.furthest = -1;
            F.furthest_dist = 0;
            for (int r = F.outside; r >= 0; r = w.next[static_cast<std::size_t>(r)]) {
                const Real dist = F.n.dot(at(r)) + F.d;
                if (F.furthest < 0 || dist > F.furthest_dist ||
                    (dist == F.furthest_dist && r < F.furthest)) {
                    F.furthest_dist = dist;
                    F.furthest = r;
                }
            }
        }
        return -1;
    }

    // Adds `eye` (above facet k): the facets it sees go, a cone of new facets joins it to
    // their horizon, and their outside points move to the new facets.
    void add_point(int k, int eye, int stamp) {
        w.visible.clear();
        w.stack.clear();
        w.stack.push_back(k);
        f(k).mark = stamp;
        f(k).visible = true;
        while (!w.stack.empty()) {
            const int g = w.stack.back();
            w.stack.pop_back();
            w.visible.push_back(g);
            for (int e = 0; e < 3; ++e) {
                const int h = f(g).nb[static_cast<std::size_t>(e)];
                if (f(h).mark == stamp)
                    continue;
                f(h).mark = stamp;
                f(h).visible = above(h, eye);
                if (f(h).visible)
                    w.stack.push_back(h);
            }
        }
        // The cone: one facet per horizon edge a -> b (as the visible facet runs it), whose
        // other two edges meet the cone facets that start at b and end at a.
        const int first_new = static_cast<int>(w.facets.size());
        for (const int g : w.visible) {
            for (int e = 0; e < 3; ++e) {
                const int h = f(g).nb[static_cast<std::size_t>(e)];
                if (f(h).visible)
                    continue;
                const int a = f(g).v[static_cast<std::size_t>(e)];
                const int b = f(g).v[static_cast<std::size_t>((e + 1) % 3)];
                const int c = add_facet(a, b, eye);
                f(c).nb[0] = h;
                for (int& back : f(h).nb) // without a branch: which edge is random
                    back = back == g ? c : back;
                w.start_of[static_cast<std::size_t>(a)] = c;
            }
        }
        const int last_new = static_cast<int>(w.facets.size());
        for (int c = first_new; c < last_new; ++c) {
            const int a = f(c).v[0];
            const int b = f(c).v[1];
            const int next = w.start_of[static_cast<std::size_t>(b)];
            f(c).nb[1] = next;
            f(next).nb[2] = c;
            w.incident[static_cast<std::size_t>(a)] = c;
        }
        w.incident[static_cast<std::size_t>(eye)] = first_new;
        // Outside points of the visible facets (the eye excepted) go to the new facets.
        // (Written without a branch on q != eye, which is random.)
        // w.pending holds a slot per point (quickhull_3d): no point is in two outside sets.
        std::size_t pending = 0;
        for (const int g : w.visible) {
            f(g).alive = false;
            for (int q = f(g).outside; q >= 0; q = w.next[static_cast<std::size_t>(q)]) {
                w.pending[pending] = q;
                pending += q != eye ? 1 : 0;
            }
        }
        for (std::size_t t = 0; t < pending; ++t)
            assign(w.pending[t], first_new, last_new);
    }

    // Whether vertex v is a corner: the triangles around it turn in 3 or more places (a turn
    // where the next triangle's far corner is more than eps below this triangle's plane).
    bool corner(int v) {
        const int first = w.incident[static_cast<std::size_t>(v)];
        int g = first;
        int turns = 0;
        do {
            const Facet& F = f(g);
            const int k = int(F.v[1] == v) + 2 * int(F.v[2] == v); // no branch: random
            const int h = F.nb[static_cast<std::size_t>(k)];
            const int u = F.v[static_cast<std::size_t>((k + 1) % 3)];
            const Facet& H = f(h);
            // H's corner that is neither v nor u (both are corners of H, distinct): the sum of
            // its three less theirs, without a branch per corner.
            const int apex = H.v[0] + H.v[1] + H.v[2] - v - u;
            if (F.n.dot(at(apex)) + F.d < -eps)
                ++turns;
            g = h;
        } while (g != first && turns < 3);
        return turns >= 3;
    }
};

// Index of the point with the largest key (the lowest index among equal keys).
template <class Key>
int argmax(std::size_t n, Key key) {
    int best = 0;
    Real best_key = key(0);
    for (std::size_t i = 1; i < n; ++i) {
        const Real k = key(static_cast<int>(i));
        if (k > best_key) {
            best_key = k;
            best = static_cast<int>(i);
        }
    }
    return best;
}

// The first hull as before the octahedron (and without it): a tetrahedron of the extremes
// along the widest axis, the point farthest from their line, the point farthest from the
// plane of the three; false when its volume is not above `min_volume`.
bool start_tetrahedron(Hull& H, Real min_volume) {
    const std::span<const Vec<3>> points = H.p;
    QuickhullWork& work = H.w;
    const std::size_t n = points.size();
    const auto at = [&](int i) -> const Vec<3>& { return points[static_cast<std::size_t>(i)]; };
    // (One pass for the six extremes; of equal ones the lowest index, as argmax.)
    int axis = 0;
    std::array<int, 3> lo{}, hi{};
    std::array<Real, 3> lo_key{}, hi_key{};
    for (int a = 0; a < 3; ++a) {
        lo_key[static_cast<std::size_t>(a)] = -at(0)[a];
        hi_key[static_cast<std::size_t>(a)] = at(0)[a];
    }
    for (std::size_t q = 1; q < n; ++q) {
        const Vec<3>& x = points[q];
        for (std::size_t a = 0; a < 3; ++a) {
            if (-x[static_cast<Eigen::Index>(a)] > lo_key[a]) {
                lo_key[a] = -x[static_cast<Eigen::Index>(a)];
                lo[a] = static_cast<int>(q);
            }
            if (x[static_cast<Eigen::Index>(a)] > hi_key[a]) {
                hi_key[a] = x[static_cast<Eigen::Index>(a)];
                hi[a] = static_cast<int>(q);
            }
        }
    }
    Real widest = -1;
    for (int a = 0; a < 3; ++a) {
        const Real width =
            at(hi[static_cast<std::size_t>(a)])[a] - at(lo[static_cast<std::size_t>(a)])[a];
        if (width > widest) {
            widest = width;
            axis = a;
        }
    }
    const int i0 = lo[static_cast<std::size_t>(axis)];
    const int i1 = hi[static_cast<std::size_t>(axis)];
    const Vec<3> line = at(i1) - at(i0);
    const int i2 = argmax(n, [&](int i) { return line.cross(at(i) - at(i0)).squaredNorm(); });
    const Vec<3> normal = line.cross(at(i2) - at(i0));
    const int i3 = argmax(n, [&](int i) { return std::abs(normal.dot(at(i) - at(i0))); });
    const Real volume = std::abs(normal.dot(at(i3) - at(i0))) / 6;
    if (!(volume > min_volume) || orientation_sign(at(i0), at(i1), at(i2), at(i3)) == 0)
        return false;

    work.vertices.assign({i0, i1, i2, i3});
    // Faces of the tetrahedron, each turned so that the fourth corner lies below it.
    const std::array<std::array<int, 4>, 4> faces{
        {{i0, i1, i2, i3}, {i0, i3, i1, i2}, {i1, i3, i2, i0}, {i0, i2, i3, i1}}};
    for (const auto& [a, b, c, opposite] : faces) {
        if (orientation_sign(at(a), at(b), at(c), at(opposite)) > 0)
            H.add_facet(a, c, b);
        else
            H.add_facet(a, b, c);
    }
    for (int g = 0; g < 4; ++g) {
        for (int e = 0; e < 3; ++e) {
            const int a = H.f(g).v[static_cast<std::size_t>(e)];
            const int b = H.f(g).v[static_cast<std::size_t>((e + 1) % 3)];
            for (int h = 0; h < 4; ++h)
                if (h != g && std::find(H.f(h).v.begin(), H.f(h).v.end(), a) != H.f(h).v.end() &&
                    std::find(H.f(h).v.begin(), H.f(h).v.end(), b) != H.f(h).v.end())
                    H.f(g).nb[static_cast<std::size_t>(e)] = h;
            work.incident[static_cast<std::size_t>(a)] = g;
        }
    }
    return true;
}

// The octahedron of the six axis extremes as the first hull (facet o = octant o, as
// mapped_hull's star surface numbers them); false when its volume is not above `min_volume`.
bool start_octahedron(Hull& H, const std::array<int, 6>& e, Real min_volume) {
    const auto at = [&](int i) -> const Vec<3>& { return H.at(i); };
    const auto corner = [&](int o, int axis) {
        return e[static_cast<std::size_t>(2 * axis + ((o >> axis) & 1))];
    };
    // A fan of tetrahedra from the +x extreme over the four facets without it (the -x ones).
    Real volume = 0;
    const Vec<3>& apex = at(e[0]);
    for (int o = 1; o < 8; o += 2)
        volume += std::abs((at(corner(o, 0)) - apex)
                               .dot((at(corner(o, 1)) - apex).cross(at(corner(o, 2)) - apex))) /
                  6;
    if (!(volume > min_volume))
        return false;
    // Octant o's corners along x, y, z; outward counter-clockwise when o has an even number of
    // minus signs, so the odd ones are turned (x, z, y). Edge k joins the corners of two axes;
    // the facet across it is the octant with the third axis flipped.
    for (int o = 0; o < 8; ++o) {
        const bool odd = (((o & 1) + ((o >> 1) & 1) + ((o >> 2) & 1)) & 1) != 0;
        const std::array<int, 3> axes =
            odd ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{0, 1, 2};
        const int g = H.add_facet(corner(o, axes[0]), corner(o, axes[1]), corner(o, axes[2]));
        for (std::size_t k = 0; k < 3; ++k) {
            const int third = 3 - axes[k] - axes[(k + 1) % 3];
            H.f(g).nb[k] = o ^ (1 << third);
            H.w.incident[static_cast<std::size_t>(H.f(g).v[k])] = g;
        }
    }
    H.w.vertices.assign(e.begin(), e.end());
    return true;
}

} // namespace

bool quickhull_3d(std::span<const Vec<3>> points, Real min_volume, QuickhullWork& work,
                  std::vector<int>& corners, std::vector<Eigen::Matrix<Real, 4, 1>>& facets,
                  const std::array<int, 6>* octahedron) {
    corners.clear();
    facets.clear();
    const std::size_t n = points.size();
    if (n < 4)
        return false;
    Real size2 = 0;
    for (const auto& q : points)
        size2 = std::max(size2, q.squaredNorm());
    Hull H{points, work, kQuickhullCoplanar * std::sqrt(size2), std::sqrt(size2)};
    work.facets.clear();
    work.next.assign(n, -1);
    work.start_of.resize(n);
    work.incident.assign(n, -1);
    work.pending.resize(n);
    if (octahedron == nullptr || !start_octahedron(H, *octahedron, min_volume)) {
        work.facets.clear();
        work.incident.assign(n, -1);
        if (!start_tetrahedron(H, min_volume))
            return false;
    }
    // The first hull's corners are the points with an incident facet already.
    const int first = static_cast<int>(work.facets.size());
    for (std::size_t q = 0; q < n; ++q)
        if (work.incident[q] < 0)
            H.assign(static_cast<int>(q), 0, first);

    // New facets are appended, so one pass over the growing list sees every one.
    int stamp = 0;
    for (int k = 0; k < static_cast<int>(work.facets.size()); ++k) {
        if (!H.f(k).alive || H.f(k).outside < 0)
            continue;
        const int eye = H.eye_of(k);
        if (eye < 0)
            continue;
        H.add_point(k, eye, ++stamp);
        work.vertices.push_back(eye);
    }

    // A vertex whose facets all went (seen from a later eye) is inside: its record of an
    // incident facet is dead. Every vertex left on the hull had one renewed (the horizon).
    // Ascending without a sort: flags by index, then a compaction without branches.
    work.is_corner.assign(n, 0);
    for (const int v : work.vertices)
        if (H.f(work.incident[static_cast<std::size_t>(v)]).alive && H.corner(v))
            work.is_corner[static_cast<std::size_t>(v)] = 1;
    corners.resize(n);
    std::size_t count = 0;
    for (std::size_t q = 0; q < n; ++q) {
        corners[count] = static_cast<int>(q);
        count += static_cast<std::size_t>(work.is_corner[q]);
    }
    corners.resize(count);
    work.output.assign(work.facets.size(), -1);
    for (std::size_t k = 0; k < work.facets.size(); ++k) {
        const Facet& F = work.facets[k];
        if (F.alive && !H.sliver(F)) {
            work.output[k] = static_cast<int>(facets.size());
            facets.emplace_back(F.n.x(), F.n.y(), F.n.z(), F.d);
        }
    }
    return true;
}

} // namespace sluice
