#pragma once
// Analytic solutions of the periodic validation flows, shared by the WCSPH and projection
// tests: the decaying Taylor-Green vortex and the start-up of plane Poiseuille flow.
#include "sluice/core/particles.hpp"

#include <cmath>
#include <numbers>

namespace sluice::testing {

// Total kinetic energy of the particles.
inline double kinetic_energy(const Particles<2>& P) {
    double e = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
        e += 0.5 * P.mass[i] * P.v[i].squaredNorm();
    return e;
}

// KE(t) / KE(0) of the Taylor-Green vortex on the periodic square of side L:
// exp(-16 pi^2 nu t / L^2).
inline double taylor_green_energy_ratio(double nu, double t, double L) {
    return std::exp(-16 * std::numbers::pi * std::numbers::pi * nu * t / (L * L));
}

// Start-up of plane Poiseuille flow between plates at y = 0 and y = L driven by the body
// force F (Morris, Fox & Zhu 1997, eq. 21):
//   u(y,t) = F/(2 nu) y (L - y) - sum_n 4 F L^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y / L)
//            exp(-(2n+1)^2 pi^2 nu t / L^2).
inline double poiseuille_startup(double y, double t, double F, double nu, double L) {
    const double pi = std::numbers::pi;
    double u = F / (2 * nu) * y * (L - y);
    for (int n = 0; n < 200; ++n) {
        const double k = 2 * n + 1;
        u -= 4 * F * L * L / (nu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / L) *
             std::exp(-k * k * pi * pi * nu * t / (L * L));
    }
    return u;
}

// L2 relative error of the fluid particles' x velocity against poiseuille_startup.
inline double poiseuille_profile_error(const Particles<2>& P, double t, double F, double nu,
                                       double L) {
    double e2 = 0, r2 = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const double ua = poiseuille_startup(P.x[i][1], t, F, nu, L);
        e2 += (P.v[i][0] - ua) * (P.v[i][0] - ua);
        r2 += ua * ua;
    }
    return std::sqrt(e2 / r2);
}

} // namespace sluice::testing
