// The free body's integrator (motion/rigid_body.hpp) and the order-independent sum its load is
// reduced with (core/exact_sum.hpp), without fluid:
// - free fall under gravity follows x0 + v0 t + g t^2/2 to round-off, with a varying time step
//   (the leap-frog is exact for a constant force), held until its start;
// - a torque-free 2-D spin turns at its initial rate; a constant torque gives T t^2 / (2 I);
// - a 3-D torque-free spin about a principal axis stays about it and keeps |L| and the energy;
//   the rotation stays orthonormal;
// - a hinged pendulum (a box on a hinge above it) swings at the period of a compound pendulum,
//   2 pi sqrt(I_hinge / (M g d)) for small angles, within 0.5 %;
// - a planar 3-D body keeps out of the plane's normal whatever load it takes;
// - box mass properties against the formulas; a law's own mass, centre and inertia win;
// - ExactSum gives the same bits in any order of its terms, and refuses a term that does not fit.
#include "sluice/core/exact_sum.hpp"
#include "sluice/motion/rigid_body.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace sluice;

namespace {

MotionLaw body_law(BodyConstraint c = BodyConstraint::free) {
    MotionLaw law;
    law.kind = MotionKind::free_body;
    law.body.density = 500;
    law.body.constraint = c;
    return law;
}

MassProperties unit_box(int dim) {
    const MassProperties shape = box_mass_properties({0, 0, 0}, {0.2, 0.1, 0.3}, dim);
    return body_mass_properties(body_law().body, shape);
}

} // namespace

TEST_CASE("Box mass properties; a law's own values replace the shape's") {
    const MassProperties m2 = box_mass_properties({0, 0, 0}, {0.2, 0.1, 0}, 2);
    CHECK(m2.mass == doctest::Approx(0.02));
    CHECK(m2.centre.isApprox(Eigen::Vector3d(0.1, 0.05, 0)));
    CHECK(m2.inertia(2, 2) == doctest::Approx(0.02 * (0.04 + 0.01) / 12));
    const MassProperties m3 = box_mass_properties({0, 0, 0}, {0.2, 0.1, 0.3}, 3);
    CHECK(m3.mass == doctest::Approx(0.006));
    CHECK(m3.inertia(0, 0) == doctest::Approx(0.006 * (0.01 + 0.09) / 12));
    CHECK(m3.inertia(1, 1) == doctest::Approx(0.006 * (0.04 + 0.09) / 12));
    BodyLaw law = body_law().body;
    CHECK(body_mass_properties(law, m3).mass == doctest::Approx(3.0));
    CHECK(body_mass_properties(law, m3).inertia(2, 2) == doctest::Approx(3.0 * 0.05 / 12));
    law.density = 0;
    law.mass = 7;
    law.centre_of_mass = std::array<double, 3>{1, 2, 3};
    law.inertia = std::array<double, 9>{1, 0, 0, 0, 2, 0, 0, 0, 3};
    const MassProperties given = body_mass_properties(law, std::nullopt);
    CHECK(given.mass == 7);
    CHECK(given.centre == Eigen::Vector3d(1, 2, 3));
    CHECK(given.inertia(1, 1) == 2);
    law.inertia.reset();
    CHECK_THROWS(body_mass_properties(law, std::nullopt));
}

TEST_CASE("Free fall: x0 + v0 (t - start) + g (t - start)^2 / 2 to round-off, held before start") {
    MotionLaw law = body_law();
    law.velocity = {0.3, 0.5, -0.2};
    law.start = 0.01;
    const Eigen::Vector3d g(0, 0, -9.81), v0(0.3, 0.5, -0.2);
    const MassProperties mp = unit_box(3);
    RigidBody body(law, mp, g, 3);
    double t = 0, dt_prev = 0;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pick(0.5e-4, 1.5e-4);
    double worst = 0;
    while (t < 0.5) {
        const double dt = pick(rng);
        const BodyStep s = body.step(t, dt_prev, dt, {});
        t += dt;
        dt_prev = dt;
        const double since = std::max(0.0, t - law.start);
        const Eigen::Vector3d x = s.end.centre + s.end.d;
        if (!body.released())
            CHECK(x == mp.centre);
        // Released at the first step that starts at or after `start`.
        static double t_release = -1;
        if (body.released() && t_release < 0)
            t_release = t - dt;
        if (t_release >= 0) {
            const double tau = t - t_release;
            const Eigen::Vector3d exact = mp.centre + v0 * tau + 0.5 * g * tau * tau;
            worst = std::max(worst, (x - exact).norm());
        }
        (void)since;
    }
    CHECK(worst < 1e-13);
    CHECK(body.orientation() == Eigen::Matrix3d::Identity());
}

TEST_CASE("2-D spin: torque-free at its initial rate; a constant torque gives T t^2 / (2 I)") {
    MotionLaw law = body_law();
    law.body.angular_velocity = {0, 0, 2.0};
    const MassProperties mp = unit_box(2);
    RigidBody spin(law, mp, Eigen::Vector3d::Zero(), 2);
    law.body.angular_velocity = {0, 0, 0};
    RigidBody pushed(law, mp, Eigen::Vector3d::Zero(), 2);
    BodyLoad torque;
    torque.moment = {0, 0, 0.004};
    const double dt = 1e-4;
    double t = 0, dt_prev = 0;
    for (int n = 0; n < 5000; ++n) {
        spin.step(t, dt_prev, dt, {});
        pushed.step(t, dt_prev, dt, torque);
        t += dt;
        dt_prev = dt;
    }
    const double angle = std::remainder(2.0 * t, 2 * std::numbers::pi);
    CHECK(spin.pose().angle == doctest::Approx(angle).epsilon(1e-10));
    CHECK(spin.pose().d.norm() < 1e-15);
    const double I = mp.inertia(2, 2);
    CHECK(pushed.pose().angle == doctest::Approx(0.004 * t * t / (2 * I)).epsilon(1e-10));
}

TEST_CASE("3-D torque-free spin about a principal axis: stays, |L| and energy kept") {
    MotionLaw law = body_law();
    law.body.angular_velocity = {0, 3.0, 0};
    const MassProperties mp = unit_box(3);
    RigidBody body(law, mp, Eigen::Vector3d::Zero(), 3);
    double t = 0, dt_prev = 0;
    for (int n = 0; n < 20000; ++n) {
        body.step(t, dt_prev, 1e-4, {});
        t += 1e-4;
        dt_prev = 1e-4;
    }
    const Eigen::Vector3d w = body.angular_velocity();
    CHECK(w.y() == doctest::Approx(3.0).epsilon(1e-12));
    CHECK(std::hypot(w.x(), w.z()) < 1e-12);
    const Eigen::Matrix3d R = body.orientation();
    CHECK((R * R.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    CHECK(body.pose().angle ==
          doctest::Approx(std::abs(std::remainder(3.0 * t, 2 * std::numbers::pi))).epsilon(1e-9));
}

TEST_CASE("Hinged box: a compound pendulum's small-angle period within 0.5 %") {
    // A 0.2 x 0.1 box hanging from a hinge 0.25 m above its centre, released at 3 degrees.
    MotionLaw law = body_law(BodyConstraint::hinge);
    law.centre = {0.1, 0.3, 0};
    const MassProperties shape = box_mass_properties({0, 0, 0}, {0.2, 0.1, 0}, 2);
    const MassProperties mp = body_mass_properties(law.body, shape);
    const double d = 0.25, g = 9.81;
    const double I_hinge = mp.inertia(2, 2) + mp.mass * d * d;
    const double period = 2 * std::numbers::pi * std::sqrt(I_hinge / (mp.mass * g * d));
    // Start at 3 degrees: the centre of mass swung about the hinge.
    const double a0 = 3 * std::numbers::pi / 180;
    MassProperties tilted = mp;
    const Eigen::Vector3d hinge(0.1, 0.3, 0);
    tilted.centre = hinge + Eigen::AngleAxisd(a0, Eigen::Vector3d::UnitZ()) * (mp.centre - hinge);
    RigidBody body(law, tilted, Eigen::Vector3d(0, -g, 0), 2);
    double t = 0, dt_prev = 0, last_up = -1, first_up = -1, prev_angle = 0;
    int crossings = 0;
    const double dt = 1e-4;
    while (t < 3.5 * period) {
        body.step(t, dt_prev, dt, {});
        t += dt;
        dt_prev = dt;
        const double angle = body.pose().angle; // relative to the start: 0 at +3 degrees
        const double from_vertical = a0 + angle;
        const double prev = a0 + prev_angle;
        if (prev < 0 && from_vertical >= 0) { // upward crossings of the vertical
            const double tc = t - dt * from_vertical / (from_vertical - prev);
            if (first_up < 0)
                first_up = tc;
            last_up = tc;
            ++crossings;
        }
        prev_angle = angle;
    }
    REQUIRE(crossings >= 3);
    const double measured = (last_up - first_up) / (crossings - 1);
    // The small-angle period, corrected for the 3-degree amplitude (1 + a0^2/16).
    CHECK(measured == doctest::Approx(period * (1 + a0 * a0 / 16)).epsilon(0.005));
    // The hinge point stays where it is.
    CHECK(body.pose().position(hinge).isApprox(hinge, 1e-12));
}

TEST_CASE("A planar 3-D body moves in its plane only") {
    MotionLaw law = body_law(BodyConstraint::plane);
    law.axis = {0, 0, 1};
    const MassProperties mp = unit_box(3);
    RigidBody body(law, mp, Eigen::Vector3d(0, 0, -9.81), 3);
    BodyLoad load;
    load.force = {1, 2, 3};
    load.moment = {0.01, -0.02, 0.003};
    double t = 0, dt_prev = 0;
    for (int n = 0; n < 1000; ++n) {
        body.step(t, dt_prev, 1e-3, load);
        t += 1e-3;
        dt_prev = 1e-3;
    }
    CHECK(body.pose().d.z() == 0);
    CHECK(body.pose().d.x() > 0);
    const Eigen::Vector3d w = body.angular_velocity();
    CHECK(w.x() == 0);
    CHECK(w.y() == 0);
    CHECK(w.z() > 0);
}

TEST_CASE("ExactSum: the same bits in any order; a term too large is refused") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> mag(-3, 3);
    std::vector<double> terms;
    for (int k = 0; k < 2000; ++k)
        terms.push_back(std::pow(10.0, mag(rng) * 3) * (k % 3 == 0 ? -1 : 1));
    ExactSum a;
    for (double x : terms)
        CHECK(a.add(x));
    std::shuffle(terms.begin(), terms.end(), rng);
    ExactSum b, c, d;
    for (std::size_t k = 0; k < terms.size(); ++k)
        (k % 2 ? c : d).add(terms[k]);
    b.add(c);
    b.add(d);
    CHECK(a == b);
    CHECK(a.value() == b.value());
    long double plain = 0;
    for (double x : terms)
        plain += x;
    CHECK(a.value() == doctest::Approx(double(plain)).epsilon(1e-14));
    ExactSum e;
    CHECK_FALSE(e.add(1e30));
    CHECK_FALSE(e.add(std::nan("")));
    CHECK(e.value() == 0);
}
