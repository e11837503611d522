#pragma once
// Free-surface particles by circle (2-D) or sphere (3-D) coverage; docs/WMLS.md, "Free surface".
//
// 2-D, Dilts' arc method (Dilts 2000; Park et al. 2014, section 2.4): every
// particle carries a circle of diameter `diameter` (Park et al. 2014: 2.1 l0). A neighbour at distance
// d < diameter covers the open arc of the particle's circle inside its own circle: the arc of
// half-angle arccos(d / diameter) centred on the direction to the neighbour. The particle is
// on the free surface when the union of these arcs leaves any part of its circle uncovered.
//
// 3-D counterpart, exact sphere coverage: a neighbour covers the open spherical cap of
// half-angle arccos(d / diameter) around its direction. The union of open caps covers the
// sphere iff there is at least one cap and the boundary circle of every cap is covered by the
// other caps (an uncovered region is bounded by cap circles, and its boundary points are
// uncovered), so the 3-D test is the 2-D arc test run on each cap's boundary circle.
//
// Arcs that only touch (gaps below 1e-9 rad) count as covering; coincident neighbours (d = 0)
// cover nothing.
#include "sluice/core/types.hpp"

#include <span>
#include <utility>
#include <vector>

namespace sluice {

// Open arc (centre - half, centre + half) on a circle parametrised by angle.
struct SurfaceArc {
    Real centre, half;
};

// Cap of the unit sphere of directions: {n : n . axis > cos_half}.
struct SurfaceCap {
    Vec<3> axis;
    Real cos_half, sin_half;
};

// Buffers of the test reused from particle to particle (one per task: nothing is shared).
template <int D>
struct FreeSurfaceScratch {
    std::vector<SurfaceArc> arcs;
    std::vector<std::pair<Real, Real>> intervals;
    std::vector<SurfaceCap> caps;
};

// offsets: x_j - x_i of the neighbours (any list containing all within `diameter`).
template <int D>
bool is_free_surface(std::span<const Vec<D>> offsets, Real diameter,
                     FreeSurfaceScratch<D>& scratch);

template <int D>
bool is_free_surface(std::span<const Vec<D>> offsets, Real diameter) {
    FreeSurfaceScratch<D> scratch;
    return is_free_surface<D>(offsets, diameter, scratch);
}

extern template bool is_free_surface<2>(std::span<const Vec<2>>, Real, FreeSurfaceScratch<2>&);
extern template bool is_free_surface<3>(std::span<const Vec<3>>, Real, FreeSurfaceScratch<3>&);

} // namespace sluice
