// Leap-frog and equation-of-state identities.
#include "sluice/physics/eos.hpp"
#include "sluice/physics/integrator.hpp"
#include "sluice/physics/timestep.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>

using namespace sluice;

TEST_CASE("Leap-frog is exact for constant acceleration, with a varying step") {
    Vec<2> x(0.1, 2.0), vh(1.0, 0.0), a(0.0, -9.81);
    Real v0y = 0, t = 0, dt_prev = 0;
    Vec<2> v;
    const Real steps[] = {1e-3, 2e-3, 0.5e-3, 1.5e-3, 1e-3};
    for (Real dt : steps) {
        vh = kick<2>(vh, a, dt_prev, dt);
        x = drift<2>(x, vh, dt);
        v = velocity_estimate<2>(vh, a, dt);
        t += dt;
        dt_prev = dt;
    }
    CHECK(x[0] == doctest::Approx(0.1 + 1.0 * t).epsilon(1e-14));
    CHECK(x[1] == doctest::Approx(2.0 + v0y * t - 0.5 * 9.81 * t * t).epsilon(1e-14));
    CHECK(v[1] == doctest::Approx(-9.81 * t).epsilon(1e-14));
}

TEST_CASE("Leap-frog keeps a harmonic oscillator's energy bounded (symplectic)") {
    // x'' = -x, exact energy 0.5; the leap-frog error stays bounded, it does not drift.
    Vec<1> x(1.0), vh(0.0);
    const Real dt = 0.05;
    Real dt_prev = 0, max_err = 0;
    for (int n = 0; n < 20000; ++n) {
        const Vec<1> a = -x;
        // Energy with the synchronised velocity v^n = v^{n-1/2} + dt/2 a^n.
        const Real vn = (vh + 0.5 * dt_prev * a)[0];
        max_err = std::max(max_err, std::abs(0.5 * (x[0] * x[0] + vn * vn) - 0.5));
        vh = kick<1>(vh, a, dt_prev, dt);
        x = drift<1>(x, vh, dt);
        dt_prev = dt;
    }
    CHECK(max_err < 1e-3);
}

TEST_CASE("EOS: linear and Tait are inverted exactly and give p = p_b at rho0") {
    for (EosType type : {EosType::linear, EosType::tait}) {
        Eos eos{type, 1000.0, 35.0, 7.0, 250.0};
        CHECK(eos.pressure(1000.0) == doctest::Approx(250.0));
        for (Real rho : {980.0, 1000.0, 1003.0, 1020.0})
            CHECK(eos.density(eos.pressure(rho)) == doctest::Approx(rho).epsilon(1e-12));
    }
    Eos lin{EosType::linear, 1000.0, 350.0, 7.0, 0.0};
    CHECK(lin.pressure(1001.0) == doctest::Approx(350.0 * 350.0));
}

TEST_CASE("Time-step limits: the Tak (2024) 3-D case at c = 350 m/s needs about 7 microseconds") {
    TimeStepParams prm{0.01, 0.001 / 1000, 0.25, 0.125, 0.25};
    const auto l = particle_time_step(prm, 350.0, 0.0, 9.81);
    CHECK(l.acoustic == doctest::Approx(7.14e-6).epsilon(1e-2));
    CHECK(l.min() == l.acoustic);
    CHECK(l.min() < 1e-3); // Tak's (2024) own dt = 1 ms is far above it
}

TEST_CASE("Time-step limits from the extremes equal the min over the particles, bit for bit") {
    // The drift stage keeps the largest c + |v| and |a|^2 and divides once (TimeStepExtremes);
    // it must give exactly what the per-particle limits' minimum gave.
    const TimeStepParams prm{0.0141, 1e-6, 0.2, 0.125, 0.25};
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> c(40.0, 120.0), u(0.0, 9.0), a(0.0, 400.0);
    for (int trial = 0; trial < 50; ++trial) {
        TimeStepLimits direct;
        TimeStepExtremes ext;
        const int n = 1 + trial * 7;
        for (int k = 0; k < n; ++k) {
            const Vec<2> acc(a(rng) - 200.0, a(rng) - 200.0);
            const double ci = c(rng), ui = u(rng);
            direct = min(direct, particle_time_step(prm, ci, ui, acc.norm()));
            ext.add(ci, ui, acc.squaredNorm());
        }
        const TimeStepLimits l = ext.limits(prm);
        CHECK(l.acoustic == direct.acoustic);
        CHECK(l.viscous == direct.viscous);
        CHECK(l.force == direct.force);
    }
    // No particle: no limit, as the per-particle minimum over nothing.
    CHECK(TimeStepExtremes{}.limits(prm).min() == std::numeric_limits<double>::infinity());
    // At rest without acceleration the force limit stays open.
    TimeStepExtremes rest;
    rest.add(50.0, 0.0, 0.0);
    CHECK(rest.limits(prm).force == std::numeric_limits<double>::infinity());
    CHECK(rest.limits(prm).acoustic == prm.cfl * prm.h / 50.0);
}
