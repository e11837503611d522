#pragma once
// Convex hull of a small 3-D point set (the inverse-square images of a particle's candidate
// neighbours in 3-D). A solid set goes straight to the exact quickhull of quickhull_3d.hpp
// (it replaced Qhull, whose set-up per call cost about 60 us; Qhull stays the
// reference of tests/unit/test_quickhull_3d.cpp), with its tolerance for coplanar points.
//
// Degenerate sets: points with identical coordinates count once (lowest index), and when the
// first tetrahedron of the quickhull is too flat to prove the set solid, the affine dimension
// of the set is found first (singular values of the centred points, relative tolerance 1e-10).
// The vertices of a set of dimension 0 or 1 are its end points; those of a flat set
// (dimension 2) the corners of its 2-D hull, found by projecting along the axis closest to its
// normal (exact coordinates, same hull) and the exact 2-D hull. A set of dimension < 3 has no
// interior: all its points are boundary.
#include "sluice/core/types.hpp"
#include "sluice/physics/convex_hull_2d.hpp"
#include "sluice/physics/quickhull_3d.hpp"

#include <span>
#include <vector>

namespace sluice {

struct ConvexHull3d {
    std::vector<int> points; // hull vertices (or boundary points), ascending input index
    // Facets (triangles) as (n, d) with unit outward normal n: n.x + d <= 0 inside. Empty
    // unless the set spans 3-D.
    std::vector<Eigen::Matrix<Real, 4, 1>> facets;
    int dimension = -1; // affine dimension of the set: -1 (empty) to 3
};

// `boundary` adds the points lying on a facet (within 1e-9 of the set's size) to the vertices.
[[nodiscard]] ConvexHull3d convex_hull_3d(std::span<const Vec<3>> points,
                                          HullPoints which = HullPoints::vertices);

// The same into `hull`, with the quickhull's buffers in `work` (a caller that hulls once per
// particle); `octahedron`: quickhull_3d's optional first hull.
void convex_hull_3d_into(std::span<const Vec<3>> points, HullPoints which, QuickhullWork& work,
                         ConvexHull3d& hull, const std::array<int, 6>* octahedron = nullptr);

} // namespace sluice
