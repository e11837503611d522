#pragma once
// Free-surface test through the mapped convex hull (Randles & Libersky 2000): a
// particle is inside the fluid when its neighbours surround it in every direction, i.e. when
// the hull of their inverse-square images (mapped_hull.hpp) encloses the origin; otherwise it
// is a surface particle. The mapping scales each offset by a positive factor, so the test
// asks whether the offsets positively span R^D; the hull makes it one facet loop.
#include "sluice/core/types.hpp"

#include <span>

namespace sluice {

// `offsets` are x_j - x_i of the particles within the chosen radius (centre excluded; zero
// offsets are ignored). No neighbours, or all on one side: surface.
template <int D>
[[nodiscard]] bool is_surface_particle_by_hull(std::span<const Vec<D>> offsets);

} // namespace sluice
