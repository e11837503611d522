#pragma once
// Convex hulls of small 2-D point sets (the inverse-square images of a particle's candidate
// neighbours). Two independent algorithms with the same answer:
//
//  * quadrant_hull_2d: the algorithm of Lee & Lee (2011, section 2.나, after
//    Randles & Libersky 2000 and Ye 1995): four extreme points P1 (Ymax), P2 (Xmax),
//    P3 (Ymin), P4 (Xmin) cut the set into the quadrant regions A-D; in each region the
//    staircase of points that advance in X AND Y from the region's start point forms a
//    polygon; Sklansky's cross-product scan (their steps 1-4) then deletes the concave
//    vertices. Includes their repair for coincident extreme points (P1 == P2 etc.), and two
//    additions without which the text's algorithm fails on some sets (both shown by tests):
//    a region keeps only points beyond its chord (Akl & Toussaint 1978), and the scan steps
//    back after a deletion.
//  * monotone_chain_hull_2d: Andrew's (1979) monotone chain, the reference.
//
// Both decide every turn with the exact predicate of exact_orientation.hpp, so collinear and
// nearly collinear inputs are handled exactly and the two agree point for point (checked on
// random and adversarial sets in tests/unit/test_convex_hull_2d.cpp).
//
// Results are indices into the input. Points with identical coordinates count once, by their
// lowest index. Sets of one or two distinct points are their own hull; a collinear set has
// its two end points as vertices.
#include "sluice/core/types.hpp"

#include <span>
#include <utility>
#include <vector>

namespace sluice {

// Which points of the hull boundary to report.
enum class HullPoints {
    vertices, // corners only (points where the boundary turns)
    boundary  // corners and every point lying on an edge between two corners
};

// Lee & Lee's quadrant + Sklansky hull. Returned clockwise, starting at P1 (the leftmost of
// the highest points), as their algorithm traverses it.
[[nodiscard]] std::vector<int> quadrant_hull_2d(std::span<const Vec<2>> points,
                                                HullPoints which = HullPoints::vertices);

// Buffers of quadrant_hull_2d_into, reused from call to call (one per task or thread).
struct QuadrantHullWork {
    std::vector<int> distinct, polygon, corners, on_edge;
    std::vector<std::pair<Vec<2>, int>> region;
    std::vector<char> is_corner;
};

// The same into `out` (a caller that hulls once per particle: no allocation once the buffers
// have grown).
void quadrant_hull_2d_into(std::span<const Vec<2>> points, HullPoints which, QuadrantHullWork& work,
                           std::vector<int>& out);

// Andrew's monotone chain. Returned counter-clockwise, starting at the lowest of the
// leftmost points.
[[nodiscard]] std::vector<int> monotone_chain_hull_2d(std::span<const Vec<2>> points,
                                                      HullPoints which = HullPoints::vertices);

// The edges of a hull given clockwise (as quadrant_hull_2d returns its corners) as (n, d) with
// unit outward normal n: n.x + d <= 0 inside. Empty for fewer than 3 corners.
[[nodiscard]] std::vector<Eigen::Matrix<Real, 3, 1>>
hull_edges_2d(std::span<const Vec<2>> points, const std::vector<int>& clockwise_corners);

// The same into `edges`.
void hull_edges_2d_into(std::span<const Vec<2>> points, const std::vector<int>& clockwise_corners,
                        std::vector<Eigen::Matrix<Real, 3, 1>>& edges);

} // namespace sluice
