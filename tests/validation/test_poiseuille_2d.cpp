// Start-up of plane Poiseuille flow (cases/poiseuille_2d.toml) against the analytic series of
// Morris, Fox & Zhu (1997, eq. 21):
//   u(y,t) = F/(2 nu) y (L - y) - sum_n 4 F L^2/(nu pi^3 (2n+1)^3) sin((2n+1) pi y / L)
//            exp(-(2n+1)^2 pi^2 nu t / L^2).
// L2 relative error of the fluid velocity profile below 2 % at steady state (t = 1 s).
#include "analytic_flows.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

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
        err_final = poiseuille_profile_error(sim.particles(), sim.time(), F, nu, L);
        std::printf("poiseuille: t = %.3f s, L2 relative error %.3f %%\n", sim.time(),
                    100 * err_final);
        CHECK(err_final < 0.05); // start-up transient too
    }
    CHECK(err_final < 0.02);
}
