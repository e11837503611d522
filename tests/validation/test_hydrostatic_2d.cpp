// Still water (cases/hydrostatic_2d.toml, Park et al.'s (2014) 0.4 m x 0.4 m tank): from 1 s to 5 s
// the bottom-centre probe stays within 2 % of rho0 g (H - y_probe), the density of every
// particle stays within 1 % of its hydrostatic value, and no fluid particle crosses a wall.
#include "sluice/physics/probes.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("Hydrostatic tank: bottom pressure, density and walls over 5 s") {
    const CaseConfig cfg = read_case(case_path("hydrostatic_2d.toml"));
    Simulation<2> sim(cfg);
    const auto& probe = cfg.probes.at(0);
    const Vec<2> point(probe.position[0], probe.position[1]);
    const double g = std::abs(cfg.gravity[1]);
    const double H = cfg.blocks.at(0).hi[1];
    const double p_ref = cfg.rho0 * g * (H - point[1]);
    const double mass0 = sim.particles().total_mass();

    double worst_p = 0, worst_rho = 0, p_sum = 0, p_sum2 = 0;
    int samples = 0;
    bool crossed = false;
    double next = 0.05;
    while (sim.time() < cfg.end_time) {
        sim.step();
        const auto& P = sim.particles();
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid &&
                (P.x[i][0] < cfg.tank_lo[0] || P.x[i][0] > cfg.tank_hi[0] || P.x[i][1] < 0))
                crossed = true;
        if (sim.time() < next)
            continue;
        next += 0.05;
        const double p = pressure_probe(P, sim.kernel(), point);
        if (sim.time() >= 1.0) {
            worst_p = std::max(worst_p, std::abs(p - p_ref) / p_ref);
            p_sum += p;
            p_sum2 += p * p;
            ++samples;
            for (std::size_t i = 0; i < P.size(); ++i) {
                if (P.kind[i] != Kind::fluid)
                    continue;
                const double rho_hyd = sim.eos().density(cfg.rho0 * g * (H - P.x[i][1]));
                worst_rho = std::max(worst_rho, std::abs(P.rho[i] - rho_hyd) / cfg.rho0);
            }
        }
    }
    const double mean = p_sum / samples;
    const double noise = std::sqrt(std::max(0.0, p_sum2 / samples - mean * mean));
    std::printf("hydrostatic: p_ref = %.1f Pa, mean %.1f Pa, worst deviation %.2f %%, noise "
                "(std after 1 s) %.1f Pa, worst density deviation %.3f %%\n",
                p_ref, mean, 100 * worst_p, noise, 100 * worst_rho);
    CHECK(samples >= 70);
    CHECK(worst_p < 0.02);
    CHECK(worst_rho < 0.01);
    CHECK_FALSE(crossed);
    CHECK(sim.particles().total_mass() == mass0);
}
