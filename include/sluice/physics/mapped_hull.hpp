#pragma once
// The inverse-square mapping of Randles & Libersky (2000), as used by Lee & Lee (2011,
// Fig. 1): a candidate neighbour at offset r = x_j - x_i from the centre particle maps to
//
//     r' = r / |r|^2,
//
// which keeps its direction and inverts its distance, so the nearest particle in each
// direction lands farthest out and becomes a vertex of the convex hull of the images.
// MappedHull is that hull in D = 2 (Lee & Lee's quadrant + Sklansky algorithm) or D = 3
// (the exact quickhull of quickhull_3d.hpp), with its facets for inside/outside tests.
#include "sluice/core/types.hpp"
#include "sluice/physics/convex_hull_2d.hpp"
#include "sluice/physics/convex_hull_3d.hpp"

#include <array>
#include <span>
#include <vector>

namespace sluice {

template <int D>
[[nodiscard]] inline Vec<D> inverse_square_map(const Vec<D>& r) {
    return r / r.squaredNorm();
}

template <int D>
struct MappedHull {
    std::vector<Vec<D>> images; // r' of every offset, in input order
    std::vector<int> vertices;  // indices of the offsets whose images are hull corners
    std::vector<int> boundary;  // vertices plus offsets whose images lie on an edge/facet
    // (n, d), unit outward n, n.r' + d <= 0 inside; empty when the images do not span D dims.
    std::vector<Eigen::Matrix<Real, D + 1, 1>> facets;
    Real size = 0; // largest |r'|: the scale of the tolerances below
};

// Relative tolerance (of `size`) for "on a facet" and "strictly inside": a facet distance
// below it is round-off of the offsets (x_j - x_i of lattice positions), not geometry.
inline constexpr Real kMappedHullTolerance = Real(1e-9);

// Whether mapped_hull first drops the images that lie deep inside the hull.
//
// Akl & Toussaint's (1978) elimination, in the form the inverse-square map invites: the
// extreme images along the 2 D coordinate half-axes span a closed polygon (2-D: 4 edges) or
// octahedron-like surface (3-D: 8 triangles, one per octant). When every edge/triangle of it
// is seen from the origin with the orientation of the regular one, the surface is star-shaped
// about the origin, so the ball about the origin of radius rho = the smallest distance from
// the origin to the planes of its edges/triangles lies inside their hull, hence inside the
// images' hull. An image with |r'| < (1 - 1e-2) rho is then farther than 1e-2 rho from every
// facet of the hull: neither a corner nor within the boundary tolerance of a facet, and it
// is dropped before the hull is computed (|r'| = 1 / |r|: the far candidates). When that
// surface is also convex (every extreme off a facet lies below the facet's plane by 1e-2 rho:
// it bounds the convex hull of the extremes, inside the images' hull), an image below every
// facet plane by more than 1e-2 rho is farther than that from every facet of the hull too and
// is dropped as well (the images near the extremes' directions,
// which the ball keeps: 58 -> 21 of 123 on a jittered 3-D lattice). The hull of
// the rest has the same corners and facets, so `vertices` and `boundary` are unchanged.
// The argument holds about any centre inside the extremes' hull and for a surface with a
// facet contracted (one image the extreme of two half-axes): when the surface is not
// star-shaped about the origin with a usable rho (a particle at a face or free surface), the
// extremes' centroid is tried (8 % of the bench's 3-D calls, which
// now keep ~29 of ~65 images instead of all). In 3-D a convex surface with six distinct
// extremes is also quickhull's first hull (quickhull_3d.hpp).
// tests/unit/test_neighbour_selection.cpp compares both forms on lattices and deformed
// sets. `none` computes the hull of every image (the reference for that test).
enum class HullPrefilter { inscribed_ball, none };

// The radius rho above for these images (0 when the surface is not star-shaped about the
// origin or some half-axis has no image).
template <int D>
[[nodiscard]] Real inscribed_ball_radius(std::span<const Vec<D>> images);

// Hull of the images of `offsets` (none may be zero: the mapping is singular there).
template <int D>
[[nodiscard]] MappedHull<D> mapped_hull(std::span<const Vec<D>> offsets,
                                        HullPrefilter prefilter = HullPrefilter::inscribed_ball);

// Buffers of mapped_hull_into, reused from call to call (one per task or thread).
template <int D>
struct MappedHullWork {
    std::vector<Vec<D>> kept_images; // the images the hull is computed on, when prefiltered
    std::vector<int> kept;           // their indices
    std::vector<char> dropped;       // per image: 1 dropped by the prefilter, 2 a corner
    std::vector<int> position;       // per kept image: its index in kept
    std::vector<int> on_facet;       // per corner image: a facet it lies on (-1: unknown)
    std::vector<int> corners;
    // The facets' n and d by component (the boundary test's vector lanes).
    std::array<Eigen::Array<Real, Eigen::Dynamic, 1>, D + 1> facet_components;
    QuadrantHullWork quadrant; // D = 2
    QuickhullWork quickhull;   // D = 3
    ConvexHull3d hull_3d;      // D = 3
};

// The same into `out`, whose buffers are reused (a caller that hulls once per particle).
// `with_boundary` false: `boundary` is left empty (a caller that needs the corners only).
template <int D>
void mapped_hull_into(std::span<const Vec<D>> offsets, HullPrefilter prefilter,
                      MappedHullWork<D>& work, MappedHull<D>& out, bool with_boundary = true);

// The hull of the offsets with 0 < |r|^2 <= radius2 (gathered, mapped and scanned for the
// prefilter's extremes in one pass): `candidate` their indices into `offsets`, ascending;
// out.images, vertices and boundary refer to them (the selection's form).
template <int D>
void mapped_hull_within_into(std::span<const Vec<D>> offsets, Real radius2, HullPrefilter prefilter,
                             MappedHullWork<D>& work, MappedHull<D>& out,
                             std::vector<int>& candidate, bool with_boundary = true);

// True when the images surround the origin: it lies inside the hull by more than the
// tolerance, so the offsets point into every half-space (they positively span R^D).
template <int D>
[[nodiscard]] bool hull_surrounds_origin(const MappedHull<D>& hull);

} // namespace sluice
