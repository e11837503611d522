// Free-surface test through the mapped hull; see include/sluice/physics/hull_free_surface.hpp.
#include "sluice/physics/hull_free_surface.hpp"

#include "sluice/physics/mapped_hull.hpp"

#include <vector>

namespace sluice {

template <int D>
bool is_surface_particle_by_hull(std::span<const Vec<D>> offsets) {
    std::vector<Vec<D>> r;
    r.reserve(offsets.size());
    for (const auto& o : offsets)
        if (o.squaredNorm() > 0)
            r.push_back(o);
    return !hull_surrounds_origin(mapped_hull<D>(r));
}

template bool is_surface_particle_by_hull<2>(std::span<const Vec<2>>);
template bool is_surface_particle_by_hull<3>(std::span<const Vec<3>>);

} // namespace sluice
