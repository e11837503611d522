// Start-up of plane Poiseuille flow (cases/poiseuille_2d.toml) against the analytic series of
// Morris, Fox & Zhu (1997, eq. 21):
//   u(y,t) = F/(2 nu) y (L - y) - sum_n 4 F L^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y / L)
//            exp(-(2n+1)^2 pi^2 nu t / L^2).
// L2 relative error of the fluid velocity profile below 2 % at steady state (t = 1 s).
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace sluice;
using namespace sluice::testing;

namespace {
double poiseuille(double y, double t, double F, double nu, double L) {
    const double pi = std::numbers::pi;
    double u = F / (2 * nu) * y * (L - y);
    for (int n = 0; n < 200; ++n) {
        const double k = 2 * n + 1;
        u -= 4 * F * L * L / (nu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / L) *
             std::exp(-k * k * pi * pi * nu * t / (L * L));
    }
    return u;
}
} // namespace

TEST_CASE("Poiseuille start-up matches the Morris series") {
    const CaseConfig cfg = read_case(case_path("poiseuille_2d.toml"));
    Simulation<2> sim(cfg);
    const double F = cfg.gravity[0], nu = cfg.viscosity / cfg.rho0;
    const double L = cfg.tank_hi[1] - cfg.tank_lo[1];
    double err_final = 1;
    double next = 0.25;
    while (sim.time() < cfg.end_time) {
        sim.step();
        if (sim.time() < next && sim.time() < cfg.end_time)
            continue;
        next += 0.25;
        const auto& P = sim.particles();
        double e2 = 0, r2 = 0;
        for (std::size_t i = 0; i < P.size(); ++i) {
            if (P.kind[i] != Kind::fluid)
                continue;
            const double ua = poiseuille(P.x[i][1], sim.time(), F, nu, L);
            e2 += (P.v[i][0] - ua) * (P.v[i][0] - ua);
            r2 += ua * ua;
        }
        err_final = std::sqrt(e2 / r2);
        std::printf("poiseuille: t = %.3f s, L2 relative error %.3f %%\n", sim.time(),
                    100 * err_final);
        CHECK(err_final < 0.05); // start-up transient too
    }
    CHECK(err_final < 0.02);
}
