// Tak's (2024) 3-D case (cases/debris_box_3d.toml: 0.25 m fluid cube dropped from 0.05 m in a
// 1 m tank, c = 350 m/s, h = 0.01 m) for 0.025 s (about 3,500 steps) with the time step the
// solver computes: no NaN or escaped particle (the solver throws RunError), mass conserved
// exactly, every particle inside the reflective tank, and the block in free fall as a whole.
// 0.025 s, not longer, to keep CI short: every property here holds from the first step, and the
// full case runs in perf/stability.
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("Tak (2024) debris box: 0.025 s in 3-D without NaN, mass exact") {
    const CaseConfig cfg = read_case(case_path("debris_box_3d.toml"), {"time.end_time=0.025"});
    Simulation<3> sim(cfg);
    const auto& P = sim.particles();
    REQUIRE(P.count(Kind::fluid) == 19 * 19 * 19);
    CHECK(sim.dt() < 1e-5); // c = 350 m/s, h = 0.01 m: Tak's (2024) 1 ms is far too large
    const double mass0 = P.total_mass();
    double z0 = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
        z0 += P.x[i][2];
    z0 /= static_cast<double>(P.size());
    while (sim.time() < cfg.end_time)
        sim.step();
    double z1 = 0;
    bool inside = true;
    for (std::size_t i = 0; i < P.size(); ++i) {
        z1 += P.x[i][2];
        for (int d = 0; d < 3; ++d)
            inside = inside && P.x[i][d] >= cfg.tank_lo[d] && P.x[i][d] <= cfg.tank_hi[d];
    }
    z1 /= static_cast<double>(P.size());
    const double t = sim.time();
    std::printf("debris box: %ld steps, dt = %.3g s, centre of mass fell %.5f m (free fall "
                "%.5f m)\n",
                sim.steps(), sim.dt(), z0 - z1, 0.5 * 9.81 * t * t);
    CHECK(P.total_mass() == mass0);
    CHECK(inside);
    // Before it touches the floor (it needs ~0.1 s), the block falls freely.
    CHECK(z0 - z1 == doctest::Approx(0.5 * 9.81 * t * t).epsilon(0.01));
}
