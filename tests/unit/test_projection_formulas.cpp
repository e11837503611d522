// The projection scheme's formulas (include/sluice/physics/projection.hpp, docs/PROJECTION.md).
#include "sluice/physics/ls_weight.hpp"
#include "sluice/physics/projection.hpp"
#include "sluice/physics/timestep.hpp"

#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>

using namespace sluice;

TEST_CASE("source term: divergence part and density-deviation part (P3)") {
    const Real rho0 = 1000, dt = 1e-3;
    // A divergence of 1/s needs lap p = rho0/dt.
    CHECK(ppe_source(rho0, dt, 0.0, 1.0, 10.0, 10.0) == doctest::Approx(1e6));
    // Compression (n > n0) gives a negative source: a pressure maximum pushes particles apart.
    CHECK(ppe_source(rho0, dt, 0.5, 0.0, 11.0, 10.0) == doctest::Approx(-0.5 * 1e9 * 0.1));
    // gamma = 0: the density deviation is ignored.
    CHECK(ppe_source(rho0, dt, 0.0, 0.0, 11.0, 10.0) == 0.0);
}

TEST_CASE("wall row term is rho0 g.(x_w - x_f): a wall below the fluid carries more pressure") {
    const Vec<2> g(0, -9.81);
    CHECK(wall_row_term<2>(1000, g, Vec<2>(0, -0.01)) == doctest::Approx(98.1));
    CHECK(wall_row_term<2>(1000, g, Vec<2>(0.01, 0)) == 0.0);
}

TEST_CASE("stabilised gradient: tension clamped, zero pressures are no reference") {
    CHECK(gradient_pressure(-5) == 0.0);
    CHECK(gradient_pressure(7) == 7.0);
    CHECK(gradient_reference(100, 0) == 100.0);  // a surface neighbour is skipped
    CHECK(gradient_reference(100, -3) == 100.0); // so is clamped tension
    CHECK(gradient_reference(100, 40) == 40.0);
}

TEST_CASE("hydrostatic reference: a hydrostatic field is its own reference (P7)") {
    // Still water, g = (0, -9.81), rho0 = 1000, p_i = 500 Pa at y_i; a neighbour dy above has
    // p_i - rho0 g dy, one below p_i + rho0 g dy: each offers p_i, so the reference is p_i and
    // the stabilised gradient is the plain (exact) one.
    const double rho_g = 1000 * 9.81, dy = 0.01;
    const double above = hydrostatic_gradient_reference(500, 500 - rho_g * dy, rho_g * -dy);
    const double below = hydrostatic_gradient_reference(500, 500 + rho_g * dy, rho_g * dy);
    CHECK(above == doctest::Approx(500).epsilon(1e-12));
    CHECK(below == doctest::Approx(500).epsilon(1e-12));
    // A neighbour below at less than hydrostatic pressure is a reference (the repulsion acts on
    // the departure from hydrostatics); surface neighbours and tension are not.
    CHECK(hydrostatic_gradient_reference(500, 550, rho_g * dy) ==
          doctest::Approx(550 - rho_g * dy));
    CHECK(hydrostatic_gradient_reference(500, 0, rho_g * dy) == 500.0);
    CHECK(hydrostatic_gradient_reference(500, -3, -rho_g * dy) == 500.0);
    // Under a free surface the reference stays in [0, p'_i]; with a free level it is not clamped.
    CHECK(clamp_gradient_reference(-20) == 0.0);
    CHECK(clamp_gradient_reference(-20, PressureLevel::free) == -20.0);
}

TEST_CASE("wall pressure in P7: floored at the hydrostatic continuation, never above 0") {
    const double rho_g = 1000 * 9.81, dy = 0.01;
    // A surface particle (p' = 0) beside a dry wall particle dy above it: the wall's
    // extrapolated -rho0 g dy is kept, so the field stays linear across the surface.
    CHECK(wall_gradient_pressure(-rho_g * dy, 0, -rho_g * dy) == doctest::Approx(-rho_g * dy));
    // Tension extrapolated into the floor below a surge front is clamped as before.
    CHECK(wall_gradient_pressure(-5000, 0, rho_g * dy) == 0.0);
    // A deeper particle: the continuation is positive, so the floor is 0.
    CHECK(wall_gradient_pressure(-30, 200, -rho_g * dy) == 0.0);
    // Positive wall pressures pass unchanged.
    CHECK(wall_gradient_pressure(700, 200, rho_g * dy) == 700.0);
}

TEST_CASE("wall collision removes only the approaching velocity within the distance") {
    const Real d = 0.008;
    const Vec<2> wall(0.005, 0); // x_wall - x_fluid
    // Approaching along the offset: normal part removed, tangential kept.
    const Vec<2> v = wall_collision<2>(Vec<2>(2, 1), wall, d);
    CHECK(v[0] == doctest::Approx(0));
    CHECK(v[1] == doctest::Approx(1));
    // Receding: unchanged.
    CHECK(wall_collision<2>(Vec<2>(-2, 1), wall, d) == Vec<2>(-2, 1));
    // Beyond the distance: unchanged.
    CHECK(wall_collision<2>(Vec<2>(2, 1), Vec<2>(0.01, 0), d) == Vec<2>(2, 1));
}

TEST_CASE("predictor and correction (P1, P7) and the scaled row residual") {
    const Vec<2> u =
        predicted_velocity<2>(Vec<2>(1, 0), Vec<2>(2, 0), 1e-6, Vec<2>(0, -9.81), 1e-3);
    CHECK(u[0] == doctest::Approx(1 + 1e-3 * 2e-6));
    CHECK(u[1] == doctest::Approx(-9.81e-3));
    // The hydrostatic gradient rho0 g cancels gravity's step.
    const Vec<2> c = corrected_velocity<2>(Vec<2>(0, -9.81e-3), Vec<2>(0, -9810), 1000, 1e-3);
    CHECK(c.norm() == doctest::Approx(0).epsilon(1e-12));
    CHECK(row_residual(3, 5, 4) == 2.0);
}

TEST_CASE("fluid-fluid collision: approach removed with restitution, momentum conserved") {
    const Real d = 0.008, e = 0.2;
    const Vec<2> off(0.005, 0); // x_j - x_i
    const Vec<2> vi(2, 1), vj(-1, 0.5);
    // Approach speed (vi - vj).e = 3: i loses (1 + e)/2 * 3 = 1.8 along e.
    const Vec<2> dvi = collision_velocity_change<2>(vi, vj, off, d, e);
    CHECK(dvi[0] == doctest::Approx(-1.8));
    CHECK(dvi[1] == 0.0);
    const Vec<2> dvj = collision_velocity_change<2>(vj, vi, Vec<2>(-off), d, e);
    CHECK((dvi + dvj).norm() == doctest::Approx(0).epsilon(1e-15));
    // Relative approach after the collision is -e times the one before.
    CHECK(((vi + dvi) - (vj + dvj)).dot(Vec<2>(1, 0)) == doctest::Approx(-e * 3));
    // Receding or beyond the distance: nothing.
    CHECK(collision_velocity_change<2>(vj, vi, off, d, e) == Vec<2>::Zero());
    CHECK(collision_velocity_change<2>(vi, vj, Vec<2>(0.01, 0), d, e) == Vec<2>::Zero());
}

TEST_CASE("number-density surface criterion") {
    CHECK(below_surface_density(0.95, 1.0, 0.97));
    CHECK_FALSE(below_surface_density(0.98, 1.0, 0.97));
    CHECK_FALSE(below_surface_density(0.1, 1.0, 0.0)); // beta = 0: off
}

TEST_CASE("collisions within the step: the distance the step would leave decides") {
    // A pair 0.010 m apart (distance 0.008 m) closing at 3 m/s: no collision on the present
    // distance (dt = 0), nor in a step of 0.5 ms (it closes 1.5 mm, to 8.5 mm); in a step of
    // 1 ms it would close to 7 mm, so it collides, with the same exchange as at contact.
    const Real d = 0.008, e = 0.2;
    const Vec<2> off(0.010, 0), vi(2, 1), vj(-1, 0.5);
    CHECK(collision_velocity_change<2>(vi, vj, off, d, e) == Vec<2>::Zero());
    CHECK(collision_velocity_change<2>(vi, vj, off, d, e, 0.5e-3) == Vec<2>::Zero());
    const Vec<2> dvi = collision_velocity_change<2>(vi, vj, off, d, e, 1e-3);
    CHECK(dvi[0] == doctest::Approx(-1.8));
    CHECK(dvi[1] == 0.0);
    // Receding pairs never collide, whatever the step.
    CHECK(collision_velocity_change<2>(vj, vi, off, d, e, 1.0) == Vec<2>::Zero());
    // The wall: 10 mm away, approaching at 2 m/s: 4 mm in 2 ms reaches the distance.
    const Vec<2> wall(0.010, 0);
    CHECK(wall_collision<2>(Vec<2>(2, 1), wall, d, 0.5e-3) == Vec<2>(2, 1));
    const Vec<2> v = wall_collision<2>(Vec<2>(2, 1), wall, d, 2e-3);
    CHECK(v[0] == doctest::Approx(0));
    CHECK(v[1] == doctest::Approx(1));
    CHECK(wall_collision<2>(Vec<2>(-2, 1), wall, d, 1.0) == Vec<2>(-2, 1));
}

TEST_CASE("wall collision along the wall's normal keeps the flow along the wall") {
    const Vec<2> up(0, 1); // a floor's normal, out of the wall
    // Sliding forward and dipping towards the floor: only the dip is stopped.
    CHECK(wall_normal_collision<2>(Vec<2>(3, -1), up) == Vec<2>(3, 0));
    // Sliding or rising: untouched (a wall neither brakes nor holds a particle).
    CHECK(wall_normal_collision<2>(Vec<2>(3, 0), up) == Vec<2>(3, 0));
    CHECK(wall_normal_collision<2>(Vec<2>(3, 1), up) == Vec<2>(3, 1));
    // The line of centres to the floor particle ahead and below takes forward speed as well:
    // the friction the normal form removes.
    const Vec<2> ahead(Real(0.006), Real(-0.005)); // x_wall - x_fluid
    const Vec<2> old = wall_collision<2>(Vec<2>(3, -1), ahead, Real(0.008));
    CHECK(old[0] < Real(2));
    // A corner's bisector stops the part of the velocity that enters both walls.
    const Vec<2> corner = Vec<2>(-1, 1).normalized(); // wall at x > 0 and floor at y < 0
    const Vec<2> into = wall_normal_collision<2>(Vec<2>(2, 0), corner);
    CHECK(into[0] == doctest::Approx(1));
    CHECK(into[1] == doctest::Approx(1));
}

TEST_CASE("wall normal from the wall neighbours: the floor's normal anywhere above it") {
    // A floor of three layers (y = -dx/2, -3dx/2, -5dx/2) on a lattice of spacing dx, the
    // smooth weight with re = 3.1 dx; a fluid particle at height y0 and any position along it.
    const Real dx = 0.01, re = Real(3.1) * dx;
    Real worst = 0;
    for (Real y0 : {Real(0.3) * dx, Real(0.5) * dx, Real(1.2) * dx})
        for (int s = 0; s < 10; ++s) {
            const Vec<2> x(Real(s) * dx / 10, y0);
            Vec<2> sum = Vec<2>::Zero();
            for (int i = -10; i <= 10; ++i)
                for (int layer = 0; layer < 3; ++layer) {
                    const Vec<2> w((Real(i) + Real(0.5)) * dx, -(Real(layer) + Real(0.5)) * dx);
                    sum += ls_weight((x - w).norm(), re, LsWeight::smooth) * (x - w);
                }
            const Vec<2> n = wall_normal_at<2>(sum);
            CHECK(n.norm() == doctest::Approx(1));
            CHECK(n[1] > 0);
            worst = std::max(worst, std::abs(n[0]));
        }
    MESSAGE("largest tilt of the floor's normal over sub-lattice positions: " << worst);
    CHECK(worst < Real(0.002));
    CHECK(wall_normal_at<2>(Vec<2>::Zero()) == Vec<2>::Zero());
}

TEST_CASE("time step of the incompressible scheme: flow speed, force and viscosity, no sound") {
    // The projection dam break (dx = 0.01 m, h = 1.0333 dx, nu = 1e-6 m^2/s, c0 = 28 m/s in
    // the case file): the CFL limit sees |v| only, 0.25 h / |v|.
    const double h = 0.010333, nu = 1e-6, g = 9.81, c0 = 28;
    const TimeStepParams prm{h, nu, 0.25, 0.125, 0.25};
    const TimeStepLimits rest = particle_time_step(prm, cfl_sound_speed(true, c0), 0.0, g);
    CHECK(std::isinf(rest.acoustic)); // at rest only gravity and viscosity limit the step
    CHECK(rest.force == doctest::Approx(0.25 * std::sqrt(h / g)));
    CHECK(rest.viscous == doctest::Approx(0.125 * h * h / nu));
    CHECK(rest.min() == rest.force); // 8.1 ms
    const TimeStepLimits flow = particle_time_step(prm, cfl_sound_speed(true, c0), 4.0, g);
    CHECK(flow.acoustic == doctest::Approx(0.25 * h / 4.0)); // 0.65 ms at the surge's 4 m/s
    CHECK(flow.min() == flow.acoustic);
    // WCSPH at the same speed: the sound speed enters, (c0 + |v|) / |v| = 8 times smaller.
    const TimeStepLimits wcsph = particle_time_step(prm, cfl_sound_speed(false, c0), 4.0, g);
    CHECK(flow.acoustic / wcsph.acoustic == doctest::Approx((c0 + 4.0) / 4.0));
}
