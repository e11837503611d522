#pragma once
// Equations of state for weakly compressible SPH.
//   linear (Tak 2024, eq. 8, written about the reference density): p = c0^2 (rho - rho0) + p_b
//   Tait (Monaghan 1994, gamma = 7):  p = rho0 c0^2 / gamma ((rho/rho0)^gamma - 1) + p_b
#include "sluice/core/types.hpp"
#include "sluice/physics/options.hpp"

#include <cmath>

namespace sluice {

// x^e, by repeated squaring when e is a small whole number (Tait's usual gamma = 7, and the
// sound speed's (gamma - 1)/2 = 3): pow() per particle was 6 % of a 2-D dam-break step.
inline Real power(Real x, Real e) {
    if (e == std::floor(e) && e >= 0 && e <= 16) {
        auto n = static_cast<unsigned>(e);
        Real result = 1, base = x;
        for (; n != 0; n >>= 1, base *= base)
            if (n & 1U)
                result *= base;
        return result;
    }
    return std::pow(x, e);
}

struct Eos {
    EosType type = EosType::linear;
    Real rho0 = 1000, c0 = 10, gamma = 7, p_background = 0;

    [[nodiscard]] Real pressure(Real rho) const {
        if (type == EosType::linear)
            return c0 * c0 * (rho - rho0) + p_background;
        return rho0 * c0 * c0 / gamma * (power(rho / rho0, gamma) - 1) + p_background;
    }
    // Inverse: density that gives pressure p.
    [[nodiscard]] Real density(Real p) const {
        const Real dp = p - p_background;
        if (type == EosType::linear)
            return rho0 + dp / (c0 * c0);
        const Real base = 1 + gamma * dp / (rho0 * c0 * c0);
        return base > 0 ? rho0 * std::pow(base, 1 / gamma) : Real(0.5) * rho0;
    }
    // Speed of sound at density rho (for time-step control).
    [[nodiscard]] Real sound_speed(Real rho) const {
        if (type == EosType::linear)
            return c0;
        return c0 * power(rho / rho0, (gamma - 1) / 2);
    }
};

} // namespace sluice
