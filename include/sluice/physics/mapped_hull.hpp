#pragma once
// The inverse-square mapping of Randles & Libersky (2000), as used by Lee & Lee (2011, seed
// 003, Fig. 1): a candidate neighbour at offset r = x_j - x_i from the centre particle maps to
//
//     r' = r / |r|^2,
//
// which keeps its direction and inverts its distance, so the nearest particle in each
// direction lands farthest out and becomes a vertex of the convex hull of the images.
// MappedHull is that hull in D = 2 (Lee & Lee's quadrant + Sklansky algorithm) or D = 3
// (Qhull), with its facets for inside/outside tests.
#include "sluice/core/types.hpp"

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

// Hull of the images of `offsets` (none may be zero: the mapping is singular there).
template <int D>
[[nodiscard]] MappedHull<D> mapped_hull(std::span<const Vec<D>> offsets);

// True when the images surround the origin: it lies inside the hull by more than the
// tolerance, so the offsets point into every half-space (they positively span R^D).
template <int D>
[[nodiscard]] bool hull_surrounds_origin(const MappedHull<D>& hull);

} // namespace sluice
