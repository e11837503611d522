#pragma once
// Equations of state for weakly compressible SPH.
//   linear (seed 000 eq. 8, written about the reference density): p = c0^2 (rho - rho0) + p_b
//   Tait (Monaghan 1994, gamma = 7):  p = rho0 c0^2 / gamma ((rho/rho0)^gamma - 1) + p_b
#include "sluice/core/types.hpp"
#include "sluice/io/case_config.hpp"

#include <cmath>

namespace sluice {

struct Eos {
    EosType type = EosType::linear;
    Real rho0 = 1000, c0 = 10, gamma = 7, p_background = 0;

    [[nodiscard]] Real pressure(Real rho) const {
        if (type == EosType::linear)
            return c0 * c0 * (rho - rho0) + p_background;
        return rho0 * c0 * c0 / gamma * (std::pow(rho / rho0, gamma) - 1) + p_background;
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
        return c0 * std::pow(rho / rho0, (gamma - 1) / 2);
    }
};

} // namespace sluice
