#pragma once
// The convex-hull neighbour selection as it was at commit 0f22f9e, before the exact quickhull
// replaced Qhull and the 2-D hull came to reuse its buffers: the reference the new code
// must reproduce exactly. Test-only (links Qhull); frozen copy of the old sources, public
// names prefixed old_.
#include "sluice/core/types.hpp"
#include "sluice/physics/convex_hull_2d.hpp"
#include "sluice/physics/convex_hull_3d.hpp"
#include "sluice/physics/mapped_hull.hpp"
#include "sluice/physics/options.hpp"

#include <span>
#include <vector>

namespace sluice::hull_reference {

[[nodiscard]] std::vector<int> old_quadrant_hull_2d(std::span<const Vec<2>> points,
                                                    HullPoints which = HullPoints::vertices);

// Qhull (libqhull_r, default options) on the distinct points of a solid set.
[[nodiscard]] ConvexHull3d old_convex_hull_3d(std::span<const Vec<3>> points,
                                              HullPoints which = HullPoints::vertices);

template <int D>
[[nodiscard]] MappedHull<D>
old_mapped_hull(std::span<const Vec<D>> offsets,
                HullPrefilter prefilter = HullPrefilter::inscribed_ball);

template <int D>
[[nodiscard]] bool old_hull_surrounds_origin(const MappedHull<D>& hull);

template <int D>
[[nodiscard]] std::vector<int> old_select_neighbours(std::span<const Vec<D>> offsets, Real support,
                                                     Real dx, const NeighbourSelection& selection);

} // namespace sluice::hull_reference
