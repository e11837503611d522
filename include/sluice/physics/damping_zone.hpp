#pragma once
// A damping zone (sponge layer) that absorbs waves at the end of a flume: inside it a fluid
// particle's velocity relaxes towards rest,
//     dv/dt = -sigma(s) v,   sigma(s) = sigma_max f(s)^2,   f = clamp((s - s0) / L, 0, 1),
// with s the distance along the zone's direction from its start and L its length, so the
// damping grows smoothly from nothing at the start (a sudden one would reflect the waves it is
// meant to absorb) to sigma_max at the end and beyond. Integrated exactly over a step,
// v <- v exp(-sigma dt), so that no step overshoots. The quadratic ramp is that of
// DualSPHysics's damping zones (Altomare et al. 2017, "Long-crested wave generation and
// absorption for SPH-based DualSPHysics model", Coastal Engineering 127, section 3.2).
#include "sluice/core/types.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

template <int D>
struct DampingZone {
    Vec<D> start = Vec<D>::Zero();     // where the damping begins
    Vec<D> direction = Vec<D>::Zero(); // unit, into the zone
    Real length = 1;                   // over which it ramps up to sigma_max [m]
    Real sigma_max = 0;                // [1/s]

    // The factor a velocity at x is multiplied by over a step dt (1 outside the zone).
    [[nodiscard]] Real factor(const Vec<D>& x, Real dt) const {
        const Real s = (x - start).dot(direction) / length;
        if (s <= 0)
            return 1;
        const Real f = std::min(s, Real(1));
        return std::exp(-sigma_max * f * f * dt);
    }
};

} // namespace sluice
