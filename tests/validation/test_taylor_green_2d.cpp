// Taylor-Green vortex (cases/taylor_green_2d.toml, Re = 100, 100 x 100 particles, periodic):
// the kinetic energy decays as exp(-16 pi^2 nu t / L^2); the relative error of the decay
// KE(t)/KE(0) at t = 0.5 s (KE down to 45 %) must be below 5 %. The case runs to t = 1 s; the
// test stops at half of that to keep CI short (the error at 0.5 s and at 1 s are both below 1 %
// at this resolution: run the case and see perf/speed_vs_error).
#include "analytic_flows.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("Taylor-Green vortex kinetic energy decay at Re = 100") {
    const CaseConfig cfg = read_case(case_path("taylor_green_2d.toml"), {"time.end_time=0.5"});
    REQUIRE(cfg.blocks.at(0).profile == VelocityProfile::taylor_green);
    Simulation<2> sim(cfg);
    const double nu = cfg.viscosity / cfg.rho0;
    const double L = cfg.domain_hi[0] - cfg.domain_lo[0];
    const double ke0 = kinetic_energy(sim.particles());
    const double mass0 = sim.particles().total_mass();
    double next = 0.25, rel = 1;
    while (sim.time() < cfg.end_time) {
        sim.step();
        if (sim.time() < next && sim.time() < cfg.end_time)
            continue;
        next += 0.25;
        const double decay = kinetic_energy(sim.particles()) / ke0;
        const double exact = taylor_green_energy_ratio(nu, sim.time(), L);
        rel = std::abs(decay - exact) / exact;
        std::printf("taylor-green: t = %.3f s, KE/KE0 = %.5f, exact %.5f, error %.2f %%\n",
                    sim.time(), decay, exact, 100 * rel);
    }
    CHECK(rel < 0.05);
    CHECK(sim.particles().total_mass() == mass0);
}
