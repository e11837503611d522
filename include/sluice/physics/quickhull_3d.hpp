#pragma once
// Quickhull (Barber, Dobkin & Huhdanpaa 1996) for the small 3-D point sets of the mapped hull
// (the inverse-square images of a particle's ~40-100 candidate neighbours, Lee & Lee 2011),
// written for them: no set-up per call, buffers owned by the caller.
//
// Every facet and horizon decision is the exact orientation predicate of exact_orientation.hpp,
// so the surface built is always a closed, convex triangulation of the inserted points. One
// tolerance decides which points are inserted at all, as Qhull's roundoff does (the reference
// the hull replaces, tests/unit/test_quickhull_3d.cpp): a point at most
//
//     eps = kQuickhullCoplanar * max |p|
//
// above every facet is coplanar, never a vertex. kQuickhullCoplanar sits in the band where
// Qhull (2019.1, default options) turns a point raised above a facet into a vertex (4e-15 to
// 8e-15 of the set's size, measured): rounding of lattice offsets (about 1e-16) stays
// coplanar in both, any real displacement makes a vertex in both.
//
// Corners: the inserted points where the surface turns in three or more directions. A vertex
// whose triangles lie in one plane (inside a face) or two (on an edge), neighbouring triangles
// counting as one plane when the apex of one is within eps of the other's plane, is not a
// corner (Qhull merges such facets and drops the vertex).
#include "sluice/core/types.hpp"

#include <array>
#include <span>
#include <vector>

namespace sluice {

inline constexpr Real kQuickhullCoplanar = Real(6e-15);

// Reused buffers (one per task or thread).
struct QuickhullWork {
    struct Facet {
        std::array<int, 3> v{};    // counter-clockwise seen from outside
        std::array<int, 3> nb{};   // nb[k]: the facet across the edge v[k] -> v[k + 1]
        Vec<3> n = Vec<3>::Zero(); // unit outward normal; n.x + d: distance above the plane
        Real d = 0;
        Real area2 = 0;    // |(v1 - v0) x (v2 - v0)|: twice the area, for the sliver test
        Real guard = 0;    // |n.x + d| above this: its sign is the exact orientation's
        int outside = -1;  // first of the points assigned to this facet (linked by next)
        int furthest = -1; // the one farthest above it
        Real furthest_dist = 0;
        int mark = 0; // visit stamp of the visibility search
        bool visible = false;
        bool alive = true;
    };
    std::vector<Facet> facets;
    std::vector<int> next;       // per point: next point of the same outside set
    std::vector<int> start_of;   // per point: the new facet whose horizon edge starts there
    std::vector<int> incident;   // per point: one live facet it is a vertex of (-1: none)
    std::vector<int> output;     // per facet: its index in quickhull_3d's `facets` (-1: none)
    std::vector<char> is_corner; // per point: 1 when a corner
    std::vector<int> stack, visible, pending, vertices;
};

// The hull of `points`, when its first tetrahedron (extremes along the widest axis, the point
// farthest from their line, the point farthest from that plane) has a volume above
// `min_volume`; false otherwise (too flat: the caller decides). `corners` ascending;
// `facets` (n, d), unit outward n, n.x + d <= 0 inside, one per triangle.
//
// `octahedron` (optional): indices of the extremes along +x, -x, +y, -y, +z, -z, six distinct
// points whose octahedron (facet per octant) the caller has proved convex with a margin far
// beyond rounding (mapped_hull's prefilter: every extreme below every other facet's plane by
// 1e-2 of its inradius). The hull then starts from it instead of the tetrahedron when its
// volume is above `min_volume` (two insertions and three passes over the
// points less). The hull found is the same convex set; where points lie within eps of a facet
// (rounded lattices) the triangulation, and with it which of them are corners, can depend on
// the insertion order, as in Qhull (tests/unit/test_hull_selection_reference.cpp).
bool quickhull_3d(std::span<const Vec<3>> points, Real min_volume, QuickhullWork& work,
                  std::vector<int>& corners, std::vector<Eigen::Matrix<Real, 4, 1>>& facets,
                  const std::array<int, 6>* octahedron = nullptr);

} // namespace sluice
