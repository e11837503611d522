// Where a case's particles may lie (wall_extent.hpp).
#include "sluice/io/wall_extent.hpp"

#include "sluice/geometry/surface_index.hpp"
#include "sluice/physics/initial_profiles.hpp"
#include "sluice/physics/kernels.hpp"

#include <algorithm>

namespace sluice {

AxisExtent wall_extent(const CaseConfig& c, std::size_t axis) {
    AxisExtent e{c.domain_lo[axis], c.domain_hi[axis]};
    const bool dummy = c.walls == WallModel::dummy;
    const double depth =
        dummy ? wall_layers(kernel_support_factor(c.kernel) * c.h_over_dx * c.dx, c.dx) * c.dx
              : 0.0;
    e.lo = std::min(e.lo, c.tank_lo[axis] - depth);
    e.hi = std::max(e.hi, c.tank_hi[axis] + depth);
    for (const WallMesh& m : c.meshes) {
        if (!m.shape)
            continue;
        const double reach = m.role == MeshRole::surface ? depth : 0.0;
        e.lo = std::min(e.lo, m.shape->lo()[axis] - reach);
        e.hi = std::max(e.hi, m.shape->hi()[axis] + reach);
    }
    return e;
}

} // namespace sluice
