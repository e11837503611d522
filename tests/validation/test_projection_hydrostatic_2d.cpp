// Still water with the projection scheme (cases/projection_hydrostatic_2d.toml, Park et al.'s (2014)
// 0.4 m x 0.4 m tank, 1,600 particles). Shortened to 1.5 s for the test suite (the full 5 s
// run and the comparison with WCSPH are perf/projection/hydrostatic_noise.sh): from 0.5 s on
// the mean of the bottom-centre probe is within 2 % of rho0 g (H - y_probe) and its temporal
// noise (standard deviation, printed with the worst sample) below 2 % of it; no fluid
// particle reaches the first layer of wall particles (dx/2 behind the wall face: the walls
// act only through the pressure, so a particle next to a wall may sit slightly past the
// face); every pressure solve converges (or the step would throw) and mass is kept.
#include "sluice/physics/probes.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("Projection scheme, hydrostatic tank: bottom pressure and noise") {
    CaseConfig cfg = read_case(case_path("projection_hydrostatic_2d.toml"));
    cfg.end_time = 1.5;
    Simulation<2> sim(cfg);
    const auto& probe = cfg.probes.at(0);
    const Vec<2> point(probe.position[0], probe.position[1]);
    const double g = std::abs(cfg.gravity[1]);
    const double H = cfg.blocks.at(0).hi[1];
    const double p_ref = cfg.rho0 * g * (H - point[1]);
    const double mass0 = sim.particles().total_mass();

    double worst_p = 0, p_sum = 0, p_sum2 = 0;
    int samples = 0;
    double penetration = 0;
    double next = 0.05;
    while (sim.time() < cfg.end_time - 1e-9) {
        sim.step();
        const auto& P = sim.particles();
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid) {
                const double depth =
                    std::max({cfg.tank_lo[0] - P.x[i][0], P.x[i][0] - cfg.tank_hi[0],
                              cfg.tank_lo[1] - P.x[i][1]});
                penetration = std::max(penetration, depth);
            }
        if (sim.time() < next - 1e-9)
            continue;
        next += 0.05;
        if (sim.time() < 0.5)
            continue;
        const double p = pressure_probe(P, sim.kernel(), point);
        worst_p = std::max(worst_p, std::abs(p - p_ref) / p_ref);
        p_sum += p;
        p_sum2 += p * p;
        ++samples;
    }
    const double mean = p_sum / samples;
    const double noise = std::sqrt(std::max(0.0, p_sum2 / samples - mean * mean));
    const PressureSolveTotals& solves = *sim.pressure_solve_totals();
    std::printf(
        "projection hydrostatic: p_ref = %.1f Pa, mean %.1f Pa (%+.2f %%), worst "
        "deviation %.2f %%, noise (std after 0.5 s) %.1f Pa; %.1f iterations per step "
        "(max %d), largest final residual %.2e; deepest fluid particle %.2f mm behind a wall "
        "face\n",
        p_ref, mean, 100 * (mean / p_ref - 1), 100 * worst_p, noise,
        static_cast<double>(solves.iterations) / static_cast<double>(solves.solves),
        solves.max_iterations, solves.max_residual, 1e3 * penetration);
    CHECK(samples >= 19);
    CHECK(std::abs(mean - p_ref) < 0.02 * p_ref);
    CHECK(noise < 0.02 * p_ref);
    CHECK(penetration < 0.5 * cfg.dx);
    CHECK(solves.solves == sim.steps());
    CHECK(solves.max_residual < 2 * cfg.projection.tolerance);
    CHECK(sim.particles().total_mass() == mass0);
}
