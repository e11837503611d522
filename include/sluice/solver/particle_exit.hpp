#pragma once
// domain.particle_exit = "remove": the fluid particles that a step left outside the domain are
// taken out of the rank's set at the rebuild after it (Simulation::rebuild). Spray thrown over
// an open top or a wall then no longer stops the run; the run counts what it removed.
#include "sluice/core/particles.hpp"
#include "sluice/solver/state_check.hpp"

#include <cstddef>
#include <vector>

namespace sluice {

// Removes the fluid particles outside the box (the rank's owned particles, no halo); keeps the
// order of the others. Returns how many it removed.
template <int D>
std::size_t remove_outside_domain(Particles<D>& P, const StateBounds<D>& b) {
    std::vector<std::size_t> keep;
    keep.reserve(P.size());
    for (std::size_t i = 0; i < P.size(); ++i)
        if (P.kind[i] != Kind::fluid || !outside_domain(b, P.x[i]))
            keep.push_back(i);
    const std::size_t removed = P.size() - keep.size();
    if (removed > 0) {
        P.permute(keep);
        P.resize(keep.size());
    }
    return removed;
}

} // namespace sluice
