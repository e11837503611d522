// Park et al.'s (2014) 2-D dam break with the projection scheme
// (cases/projection_dam_break_2d.toml) at a coarse resolution (dx = 0.02 m, 800 fluid particles, dt
// = 0.4 ms: the case's dt scaled with dx; the case's 0.01 m run to 1 s and the comparison with
// WCSPH are perf/projection/dam_break_compare.py). The run goes to 0.8 s, past the 0.66 s at which
// the 0.01 m case used to fail (a splash particle left the domain) and past the first impact on the
// right wall (about 0.4 s). Checks: every step succeeds (a failed step throws); the surge front Z =
// x/a against T = t sqrt(2g/a) follows Martin & Moyce (1952, n^2 = 2) within the 15 % RMS guard (T
// <= 3); the closest pair of fluid particles stays more than 0.3 dx apart (the fluid-fluid
// collision's job: without it pairs closed to 0.004 dx, nearly coincident, in the 0.02 s snapshots
// of this run; with it the test measures 0.65 dx, sampled every 5 ms); no fluid particle passes the
// first wall layer (dx/2 behind a tank face); every pressure solve reaches the tolerance; mass is
// kept exactly.
#include "sluice/physics/probes.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("Projection scheme, dam break: runs past the old failure, front follows Martin & Moyce") {
    const CaseConfig cfg =
        read_case(case_path("projection_dam_break_2d.toml"),
                  {"particles.dx=0.02", "numerics.dt=4e-4", "time.end_time=0.8"});
    Simulation<2> sim(cfg);
    const double a = cfg.blocks.at(0).hi[0] - cfg.blocks.at(0).lo[0];
    const double g = 9.81, T_scale = std::sqrt(2 * g / a);
    const double mass0 = sim.particles().total_mass();
    const double x_hi = cfg.tank_hi[0];

    std::vector<double> Ts{0.0}, Zs{1.0};
    double next_sample = 0.005, penetration = 0, closest = 1e9;
    while (sim.time() < cfg.end_time - 1e-9) {
        sim.step();
        const auto& P = sim.particles();
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid)
                penetration = std::max({penetration, -P.x[i][0], P.x[i][0] - x_hi, -P.x[i][1]});
        if (sim.time() >= next_sample) {
            for (std::size_t i = 0; i < P.size(); ++i)
                for (std::size_t j = i + 1; j < P.size(); ++j)
                    if (P.kind[i] == Kind::fluid && P.kind[j] == Kind::fluid)
                        closest = std::min(closest, (P.x[i] - P.x[j]).norm());
            Ts.push_back(sim.time() * T_scale);
            Zs.push_back(surge_front(P, cfg.dx) / a);
            next_sample += 0.005;
        }
    }
    CHECK(sim.time() >= cfg.end_time - 1e-9);
    CHECK(sim.particles().total_mass() == mass0);

    const FrontDeviation front =
        front_deviation(Ts, Zs, data_path("martin_moyce_1952_n2_2.csv"), -1.0, 3.0);
    const int n = front.points;
    REQUIRE(n >= 8);
    const double rms = front.rms;
    const PressureSolveTotals& solves = *sim.pressure_solve_totals();
    std::printf("projection dam break (dx = %.3f m, to %.2f s): front RMS deviation from Martin & "
                "Moyce (T <= 3, %d points) %.2f %% (guard 15 %%); %ld steps, %.1f iterations per "
                "solve (max %d), largest residual %.2e; closest fluid pair %.3f dx; deepest fluid "
                "particle %.2f mm behind a wall face\n",
                cfg.dx, cfg.end_time, n, 100 * rms, sim.steps(),
                static_cast<double>(solves.iterations) / static_cast<double>(solves.solves),
                solves.max_iterations, solves.max_residual, closest / cfg.dx, 1e3 * penetration);
    CHECK(rms < 0.15);
    CHECK(closest > 0.3 * cfg.dx);
    CHECK(penetration < 0.5 * cfg.dx);
    CHECK(solves.max_residual < 2 * cfg.projection.tolerance);
}
