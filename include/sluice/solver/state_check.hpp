#pragma once
// Blow-up detection: is the new state of a fluid particle healthy? Bounds come from the case
// ([domain], [limits]); no formula of the method lives here.
#include "sluice/core/types.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>

namespace sluice {

template <int D>
struct StateBounds {
    Vec<D> lo, hi;                         // the box a particle may occupy (periodic axes excepted)
    std::array<bool, D> periodic{};        // axes without bounds
    Real max_speed = 0;                    // [m/s]
    Real min_density = 0, max_density = 0; // [kg/m^3]
    // domain.particle_exit = "remove": a particle outside the box is healthy; the step counts
    // it (outside_domain) and the next rebuild removes it.
    bool remove_outside = false;
};

// Whether x lies outside the box along a non-periodic axis.
template <int D>
[[nodiscard]] inline bool outside_domain(const StateBounds<D>& b, const Vec<D>& x) {
    for (int d = 0; d < D; ++d)
        if (!b.periodic[static_cast<std::size_t>(d)] && (x[d] < b.lo[d] || x[d] > b.hi[d]))
            return true;
    return false;
}

// Whether the state passes every test of state_fault below (the hot path of a step's drift:
// only an unhealthy particle pays for the message).
template <int D>
[[nodiscard]] inline bool state_healthy(const StateBounds<D>& b, const Vec<D>& x, const Vec<D>& v,
                                        Real rho) {
    if (!x.allFinite() || !v.allFinite() || !std::isfinite(rho))
        return false;
    if (!b.remove_outside && outside_domain(b, x))
        return false;
    return rho > 0 && rho >= b.min_density && rho <= b.max_density && !(v.norm() > b.max_speed);
}

// Empty when the state is healthy; otherwise the quantity that went wrong, in words, e.g.
// "a speed of 52.1 m/s (limits.max_speed = 40 m/s)".
template <int D>
std::string state_fault(const StateBounds<D>& b, const Vec<D>& x, const Vec<D>& v, Real rho) {
    if (!x.allFinite())
        return "a non-finite position";
    if (!v.allFinite())
        return "a non-finite velocity";
    if (!std::isfinite(rho))
        return "a non-finite density";
    if (!b.remove_outside && outside_domain(b, x))
        return "a position outside the domain (domain.particle_exit = \"remove\" drops such "
               "particles)";
    if (rho <= 0)
        return fmt::format("a non-positive density {:.6g} kg/m^3", rho);
    if (rho < b.min_density || rho > b.max_density)
        return fmt::format("a density of {:.6g} kg/m^3 (limits.min_density = {:.6g}, "
                           "limits.max_density = {:.6g})",
                           rho, b.min_density, b.max_density);
    const Real speed = v.norm();
    if (speed > b.max_speed)
        return fmt::format("a speed of {:.6g} m/s (limits.max_speed = {:.6g} m/s)", speed,
                           b.max_speed);
    return {};
}

} // namespace sluice
