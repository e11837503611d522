// Contact through Bullet (contact/contact_world.hpp), without fluid: the bodies take Bullet's
// velocities and placement each step, as WallMotion does after the bodies' kicks.
// - a box resting on the floor under gravity stays where it is (no drift beyond 1e-9 m in 1 s);
// - a box sliding on the floor decelerates at mu g (friction 0.4) within 2 %;
// - two equal boxes meeting head-on in zero gravity with restitution 1 exchange velocities
//   (within 2 %), and momentum is kept to round-off whatever the restitution;
// - the same inputs give the same bits (a fresh world each step: nothing carried over).
#include "sluice/contact/contact_world.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace sluice;

namespace {

ContactBody box_body(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double friction,
                     double restitution) {
    ContactBody b;
    b.box = {lo, hi};
    b.mass = 1.0;
    b.centre = 0.5 * (lo + hi);
    const Eigen::Vector3d e = hi - lo;
    b.inertia = Eigen::Vector3d(e.y() * e.y() + e.z() * e.z(), e.x() * e.x() + e.z() * e.z(),
                                e.x() * e.x() + e.y() * e.y()) /
                12;
    b.friction = friction;
    b.restitution = restitution;
    b.planar = true; // 2-D
    return b;
}

ContactPlane floor_plane() {
    return {Eigen::Vector3d::UnitY(), 0.0};
}

// Steps the bodies under gravity g (kicked by g dt each step, as the bodies' own kick does);
// a body Bullet did not take (far from everything) drifts on its own, as RigidBody does.
std::vector<ContactState> run(ContactWorld& world, std::vector<ContactState> s, double g, double dt,
                              int steps) {
    for (int n = 0; n < steps; ++n) {
        for (auto& b : s)
            b.v.y() -= g * dt;
        s = world.step(s, dt);
        for (auto& b : s)
            if (!b.resolved)
                b.x += dt * b.v;
    }
    return s;
}

} // namespace

TEST_CASE("A box resting on the floor stays") {
    ContactWorld world(2, {floor_plane()}, {}, {box_body({0.4, 0, 0}, {0.6, 0.1, 0}, 0.5, 0)});
    ContactState s;
    s.x = {0.5, 0.05, 0};
    const auto end = run(world, {s}, 9.81, 2e-4, 5000);
    CHECK((end[0].x - s.x).norm() < 1e-9);
    CHECK(std::abs(end[0].R(0, 1)) < 1e-9);
    CHECK(world.last_contacts() >= 2);
}

TEST_CASE("A box sliding on the floor decelerates at mu g") {
    const double mu = 0.4, g = 9.81, dt = 2e-4;
    ContactWorld world(2, {floor_plane()}, {}, {box_body({0.4, 0, 0}, {0.6, 0.1, 0}, mu, 0)});
    ContactState s;
    s.x = {0.5, 0.05, 0};
    s.v = {1.0, 0, 0};
    const auto end = run(world, {s}, g, dt, 1000); // 0.2 s: 1 - 0.4 g 0.2 = 0.215 m/s left
    const double expected = 1.0 - mu * g * 0.2;
    CHECK(end[0].v.x() == doctest::Approx(expected).epsilon(0.02));
}

TEST_CASE("Equal boxes meeting head-on: restitution 1 exchanges velocities; momentum kept") {
    for (double e : {1.0, 0.0}) {
        ContactWorld world(2, {}, {},
                           {box_body({0.0, 0, 0}, {0.1, 0.1, 0}, 0, e),
                            box_body({0.3, 0, 0}, {0.4, 0.1, 0}, 0, e)});
        ContactState a, b;
        a.x = {0.05, 0.05, 0};
        a.v = {1.0, 0, 0};
        b.x = {0.35, 0.05, 0};
        b.v = {-0.5, 0, 0};
        const auto end = run(world, {a, b}, 0, 1e-4, 4000);
        CHECK(end[0].v.x() + end[1].v.x() == doctest::Approx(0.5).epsilon(1e-12));
        if (e == 1.0) {
            CHECK(end[0].v.x() == doctest::Approx(-0.5).epsilon(0.02));
            CHECK(end[1].v.x() == doctest::Approx(1.0).epsilon(0.02));
        } else {
            CHECK(end[0].v.x() == doctest::Approx(0.25).epsilon(0.02));
        }
        // Nothing carried from step to step: the same inputs, the same bits.
        ContactWorld again(2, {}, {},
                           {box_body({0.0, 0, 0}, {0.1, 0.1, 0}, 0, e),
                            box_body({0.3, 0, 0}, {0.4, 0.1, 0}, 0, e)});
        const auto twice = run(again, {a, b}, 0, 1e-4, 4000);
        CHECK(twice[0].x == end[0].x);
        CHECK(twice[1].v == end[1].v);
    }
}
