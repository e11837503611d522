// A block of water hitting a wall (tests/data/wall_loads/block_impact_2d.toml: 0.1 m x 0.1 m
// at dx = 0.005, 1 m/s, zero gravity, a free-slip dummy wall on the x+ face only): the
// impulse of the force probe on that wall, sampled every step through the whole pipeline
// (case reader, run loop, probe CSV), equals minus the change of the fluid's x-momentum
// within 5 % (measured: 0.012 % over 0.3 s, 3555 steps, the x-momentum going from +10 to
// -0.38 kg m/s per m as the block rebounds). Nothing else acts on the fluid in x (its internal pair
// forces cancel), so the two agree up to the probe's timing: it samples the state after a step,
// with the wall pressures the step extrapolated, where the next step's force uses re-extrapolated
// ones. The impulse is the sum the leap-frog applies (integrator.hpp): the force of step k (sampled
// at t_k) acts for (dt_{k-1} + dt_k)/2, and the last one dt/2 more for the velocity estimate the
// particles carry.
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/run.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h> // getpid: a folder of its own when suites run side by side

using namespace sluice;
using namespace sluice::testing;

namespace {

// Total x-momentum of the fluid particles (per metre of width), from their velocity.
double fluid_momentum_x(const Particles<2>& P) {
    double px = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
        if (P.kind[i] == Kind::fluid)
            px += double(P.mass[i]) * double(P.v[i][0]);
    return px;
}

} // namespace

TEST_CASE("Block hitting a wall: the force's impulse equals the momentum change") {
    const CaseConfig cfg = read_case(data_path("wall_loads/block_impact_2d.toml"));
    const std::string out = (std::filesystem::temp_directory_path() /
                             ("sluice_test_wall_loads_block_impact_" + std::to_string(::getpid())))
                                .string();
    std::filesystem::remove_all(out);
    RunOptions opts;
    opts.out_dir = out;
    opts.threads = 1;
    opts.quiet = true;
    const RunResult result = run_case(cfg, opts);
    const auto rows = read_csv(out + "/probes/wall.csv");

    // The same run through the Simulation API, for the particles' momentum before and after
    // and the time steps (the run is deterministic: the same steps as run_case's).
    SimulationOptions so;
    so.threads = 1;
    Simulation<2> sim(cfg, so);
    const double p0 = fluid_momentum_x(sim.particles());
    std::vector<double> dts;
    while (sim.time() < cfg.end_time * (1 - 1e-12)) {
        const double t = sim.time();
        sim.step();
        dts.push_back(sim.time() - t);
    }
    const double p1 = fluid_momentum_x(sim.particles());
    REQUIRE(static_cast<long>(dts.size()) == result.steps);
    REQUIRE(rows.size() == dts.size() + 1); // the start and every step

    double leapfrog = 0, trapezoid = 0, f_max = 0, t_prev = 0;
    const std::size_t n = dts.size();
    for (std::size_t k = 0; k <= n; ++k) {
        const double t = std::stod(rows[k].at(0)), fx = std::stod(rows[k].at(1));
        CHECK(std::abs(t - t_prev - (k > 0 ? dts[k - 1] : 0.0)) < 1e-6);
        t_prev = t;
        f_max = std::max(f_max, std::abs(fx));
        if (k < n)
            leapfrog += fx * ((k > 0 ? dts[k - 1] : 0.0) + dts[k]) / 2;
        if (k == n - 1)
            leapfrog += fx * dts[k] / 2;
        if (k > 0)
            trapezoid += (fx + std::stod(rows[k - 1].at(1))) * dts[k - 1] / 2;
    }
    const double dp = p1 - p0;
    const double err = std::abs(leapfrog + dp) / std::abs(dp);
    const double err_trapezoid = std::abs(trapezoid + dp) / std::abs(dp);
    MESSAGE("block impact: fluid x-momentum "
            << p0 << " -> " << p1 << " kg m/s per m, wall "
            << "impulse " << leapfrog << " N s/m (trapezoid " << trapezoid << "), peak force "
            << f_max << " N/m, " << n << " steps; impulse error " << 100 * err << " % (trapezoid "
            << 100 * err_trapezoid << " %)");
    CHECK(p0 > 0);
    CHECK(p1 < 0); // it rebounded
    CHECK(err < 0.05);
    std::filesystem::remove_all(out);
}
