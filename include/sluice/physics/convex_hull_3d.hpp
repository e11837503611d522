#pragma once
// Convex hull of a small 3-D point set (the inverse-square images of a particle's candidate
// neighbours in 3-D), computed with Qhull's reentrant library (libqhull_r, Barber, Dobkin &
// Huhdanpaa 1996), one qhT per thread, reused from call to call (its memory pools stay set up),
// so that calls in different threads are safe.
//
// Degenerate sets never reach Qhull (which stops on them): points with identical coordinates
// count once (lowest index), and the affine dimension of the set is found first (singular
// values of the centred points, relative tolerance 1e-10). The vertices of a set of dimension
// 0 or 1 are its end points; those of a flat set (dimension 2) the corners of its 2-D hull,
// found by projecting along the axis closest to its normal (exact coordinates, same hull) and
// the exact 2-D hull. A set of dimension < 3 has no interior: all its points are boundary.
#include "sluice/core/types.hpp"
#include "sluice/physics/convex_hull_2d.hpp"

#include <span>
#include <vector>

namespace sluice {

struct ConvexHull3d {
    std::vector<int> points; // hull vertices (or boundary points), ascending input index
    // Facets as (n, d) with unit outward normal n: n.x + d <= 0 inside. Empty unless the
    // set spans 3-D.
    std::vector<Eigen::Matrix<Real, 4, 1>> facets;
    int dimension = -1; // affine dimension of the set: -1 (empty) to 3
};

// `boundary` adds the points lying on a facet (within 1e-9 of the set's size) to the vertices.
[[nodiscard]] ConvexHull3d convex_hull_3d(std::span<const Vec<3>> points,
                                          HullPoints which = HullPoints::vertices);

} // namespace sluice
