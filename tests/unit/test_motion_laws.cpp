// The motion layer below the wave-makers: the smooth ramp's ends and derivatives, the formula
// signals against their closed forms and finite differences, a rigid pose's velocity and
// acceleration against finite differences of its positions (rotation about an off-origin
// centre plus translation), body_point as the inverse of position, the time-series signal
// (through its rows, relative to the first, clamped after the last) and make_motion for each
// kind (the flap's top leans to +x first).
#include "sluice/motion/motion_law.hpp"
#include "sluice/motion/motion_series.hpp"
#include "sluice/motion/rigid_motion.hpp"
#include "sluice/motion/signal.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

using namespace sluice;

namespace {

constexpr double pi = std::numbers::pi;

void check_derivatives(const Signal& s, double t, double scale) {
    const double e = 1e-5;
    const SignalValue v = s(t), a = s(t - e), b = s(t + e);
    CHECK(v.rate == doctest::Approx((b.value - a.value) / (2 * e)).scale(scale).epsilon(1e-7));
    CHECK(v.accel == doctest::Approx((b.rate - a.rate) / (2 * e)).scale(scale).epsilon(1e-7));
}

} // namespace

TEST_CASE("Smooth ramp: 0 before, 1 after, zero first and second derivatives at both ends") {
    const double start = 0.5, d = 2.0;
    CHECK(smooth_ramp(0.4, start, d).value == 0);
    CHECK(smooth_ramp(2.6, start, d).value == 1);
    for (double t : {start + 1e-9, start + d - 1e-9}) {
        const SignalValue r = smooth_ramp(t, start, d);
        CHECK(std::abs(r.rate) < 1e-12);
        CHECK(std::abs(r.accel) < 1e-6);
    }
    CHECK(smooth_ramp(start + d / 2, start, d).value == doctest::Approx(0.5));
    CHECK(smooth_ramp(start + d / 2, start, d).rate == doctest::Approx(15.0 / 8 / d));
    check_derivatives([&](double t) { return smooth_ramp(t, start, d); }, 1.1, 1);
}

TEST_CASE("Formula signals: closed forms after the ramp, derivatives everywhere") {
    const double start = 0.2, ramp = 0.5;
    const Signal s = sinusoid(0.1, 2.0, pi / 6, start, ramp);
    CHECK(s(0.1).value == 0);
    const double t = 1.7;
    CHECK(s(t).value == doctest::Approx(0.1 * std::sin(pi * (t - start) + pi / 6)));
    for (double u : {0.3, 0.45, 1.7})
        check_derivatives(s, u, 1);

    const Signal v = constant_rate(0.3, start, ramp);
    // After the ramp: u (t - start - ramp / 2), its rate u, no acceleration.
    CHECK(v(2.0).value == doctest::Approx(0.3 * (2.0 - start - ramp / 2)));
    CHECK(v(2.0).rate == doctest::Approx(0.3));
    CHECK(v(2.0).accel == 0);
    for (double u : {0.3, 0.6, 2.0})
        check_derivatives(v, u, 1);

    const Signal a = constant_acceleration(1.5, start, 0);
    CHECK(a(1.2).value == doctest::Approx(0.75 * 1.0));
    CHECK(a(1.2).rate == doctest::Approx(1.5));
    CHECK(a(1.2).accel == doctest::Approx(1.5));
    const Signal ar = constant_acceleration(1.5, start, ramp);
    for (double u : {0.3, 0.6, 2.0})
        check_derivatives(ar, u, 1);
    // The ramped value continues the ramp's end state: value' = rate holds across it.
    check_derivatives(ar, start + ramp, 1);
}

TEST_CASE("Rigid pose: velocity and acceleration are derivatives of position") {
    RigidMotion m;
    m.centre = {0.3, -0.2, 0.1};
    m.axis = Eigen::Vector3d(1, 2, 2).normalized();
    m.angle = sinusoid(0.4, 1.3, 0.2, 0, 0);
    m.translation[0] = sinusoid(0.05, 0.7, 0, 0, 0);
    m.translation[2] = constant_acceleration(0.8, 0, 0);
    const Eigen::Vector3d x0(1.0, 0.5, -0.4);
    const double t = 0.9, e = 1e-5;
    const Pose p = m.pose(t), a = m.pose(t - e), b = m.pose(t + e);
    const Eigen::Vector3d v_fd = (b.position(x0) - a.position(x0)) / (2 * e);
    const Eigen::Vector3d a_fd = (b.velocity(x0) - a.velocity(x0)) / (2 * e);
    CHECK((p.velocity(x0) - v_fd).norm() < 1e-7);
    CHECK((p.acceleration(x0) - a_fd).norm() < 1e-6);
    // A rigid motion keeps distances, and body_point undoes position.
    const Eigen::Vector3d y0(-0.2, 0.9, 0.3);
    CHECK((p.position(x0) - p.position(y0)).norm() == doctest::Approx((x0 - y0).norm()));
    CHECK((p.body_point(p.position(x0)) - x0).norm() < 1e-14);
    // The centre moves with the translation only.
    CHECK((p.position(m.centre) - (m.centre + p.d)).norm() < 1e-15);
}

TEST_CASE("Time-series signal: through its rows relative to the first, held after the last") {
    const std::vector<double> t{0, 0.5, 1.0, 1.5, 2.0, 2.5};
    const std::vector<double> x{0.2, 0.3, 0.5, 0.4, 0.4, 0.4};
    const Signal s = series_signal(t, x);
    for (std::size_t i = 0; i < t.size(); ++i)
        CHECK(s(t[i]).value == doctest::Approx(x[i] - x[0]).epsilon(1e-12));
    CHECK(s(-1).value == 0);
    CHECK(s(3).value == doctest::Approx(0.2));
    // Makima: flat where the data are flat over two intervals (x = 0.4 from 1.5 to 2.5).
    for (double u = 1.5; u <= 2.5; u += 0.05)
        CHECK(s(u).value == doctest::Approx(0.2).epsilon(1e-12));
    const double e = 1e-6;
    CHECK(s(0.7).rate == doctest::Approx((s(0.7 + e).value - s(0.7 - e).value) / (2 * e)));
    // Two rows: a straight line.
    const Signal line = series_signal({0, 2}, {1, 2});
    CHECK(line(1).value == doctest::Approx(0.5));
    CHECK(line(1).rate == doctest::Approx(0.5));
    CHECK_THROWS(series_signal({0}, {1}));
}

TEST_CASE("make_motion: each kind's pose") {
    MotionLaw law;
    SUBCASE("sway along a vector") {
        law.kind = MotionKind::sway;
        law.amplitude = {0.03, 0.04, 0};
        law.period = 2;
        const Pose p = make_motion(law).pose(0.5);
        CHECK(p.d[0] == doctest::Approx(0.03));
        CHECK(p.d[1] == doctest::Approx(0.04));
        CHECK(p.angle == 0);
    }
    SUBCASE("roll about a centre") {
        law.kind = MotionKind::roll;
        law.angle = 5;
        law.period = 4;
        law.centre = {1, 0.5, 0};
        const Pose p = make_motion(law).pose(1.0);
        CHECK(p.angle == doctest::Approx(5 * pi / 180));
        CHECK(p.angle_rate == doctest::Approx(0).scale(1));
        CHECK((p.position({1, 0.5, 0}) - Eigen::Vector3d(1, 0.5, 0)).norm() < 1e-15);
    }
    SUBCASE("constant velocity and acceleration from start") {
        law.kind = MotionKind::constant_velocity;
        law.velocity = {0.2, 0, 0};
        law.start = 1;
        CHECK(make_motion(law).pose(0.5).d[0] == 0);
        CHECK(make_motion(law).pose(2.0).d[0] == doctest::Approx(0.2));
        law.kind = MotionKind::constant_acceleration;
        law.acceleration = {0, 0, -2};
        CHECK(make_motion(law).pose(2.0).d[2] == doctest::Approx(-1));
    }
    SUBCASE("file: translation and angle, shifted by start") {
        law.kind = MotionKind::file;
        law.start = 0.5;
        law.series_t = {0, 1, 2};
        law.series_d = {{1, 0, 0}, {1.5, 0, 0}, {2, 0, 0}};
        law.series_angle = {0, 10, 20};
        const Pose p = make_motion(law).pose(1.5);
        CHECK(p.d[0] == doctest::Approx(0.5));
        CHECK(p.d[1] == 0);
        CHECK(p.angle == doctest::Approx(10 * pi / 180));
    }
    SUBCASE("piston along its direction, flap leaning to +x") {
        law.kind = MotionKind::piston;
        law.wave_height = 0.04;
        law.wave_period = 1.2;
        law.depth = 0.4;
        law.direction = {0, 0, 2};
        const RigidMotion piston = make_motion(law);
        // Quarter of a period: the stroke's crest, along z only.
        const Pose p = piston.pose(0.3);
        CHECK(p.d[0] == 0);
        CHECK(p.d[2] > 0);
        law.kind = MotionKind::flap;
        law.centre = {0, 0, 0};
        const Pose f = make_motion(law).pose(0.3);
        const Eigen::Vector3d top = f.position({0, 0.4, 0});
        CHECK(top[0] > 0);
        CHECK(top.norm() == doctest::Approx(0.4));
    }
}

TEST_CASE("moved_bounds: the box around a turned and shifted square") {
    RigidMotion m;
    m.angle = [](double) { return SignalValue{pi / 4, 0, 0}; };
    m.translation[0] = [](double) { return SignalValue{1, 0, 0}; };
    const Bounds b = moved_bounds({{-1, -1, 5}, {1, 1, 6}}, m.pose(0), 2);
    const double r = std::sqrt(2.0);
    CHECK(b.lo[0] == doctest::Approx(1 - r));
    CHECK(b.hi[0] == doctest::Approx(1 + r));
    CHECK(b.lo[1] == doctest::Approx(-r));
    CHECK(b.hi[1] == doctest::Approx(r));
    CHECK(b.lo[2] == 5); // axes past the dimension kept
    CHECK(b.hi[2] == 6);
}
