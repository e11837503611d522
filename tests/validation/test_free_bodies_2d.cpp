// Free bodies in water (motion kind "free_body", docs/FLOATING_BODIES.md), 2-D at coarse
// resolution:
// - momentum: a fluid block in zero gravity, with no tank, thrown at a free box; the fluid's
//   momentum plus the box's stays what it was, to round-off, once the impulse of the last load
//   (agreed, not yet applied) is counted;
// - Archimedes: a box of density 500 released at its equilibrium draft stays within 0.1 dx of it
//   (2 s); released 0.2 of its height too high, its heave over 1.5-3 s averages that draft
//   (below the risen water level) within 2 % of its height, and it does not turn;
// - free fall in air (no fluid within reach): g t^2/2 to round-off.
#include "validation_support.hpp"

#include "sluice/io/case_reader.hpp"
#include "sluice/solver/simulation.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <string>

using namespace sluice;
using namespace sluice::testing;

namespace {

// A tank `length` x 0.5 m with 0.3 m of water and a 0.2 x 0.1 box of density 500 in its middle,
// its bottom at `bottom`; with `absorb`, damping zones over the outer 0.6 m at both ends take up
// the waves the box radiates.
std::string floating_case(double dx, double length, double bottom, bool absorb, double end_time) {
    std::string zones;
    if (absorb)
        zones = fmt::format("[[damping_zones]]\nstart = [0.6, 0]\nend = [0, 0]\n"
                            "[[damping_zones]]\nstart = [{}, 0]\nend = [{}, 0]\n",
                            length - 0.6, length);
    return fmt::format(
        "[case]\ndimension = 2\n[domain]\nlo = [-0.1, -0.1]\nhi = [{}, 0.6]\n"
        "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 20\ngravity = [0, -9.81]\n"
        "[particles]\ndx = {}\n[[blocks]]\nlo = [0, 0]\nhi = [{}, 0.3]\n"
        "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.02\n"
        "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0]\ntank_hi = [{}, 0.5]\n"
        "[[walls.boxes]]\nlo = [{}, {}]\nhi = [{}, {}]\nmotion = \"box\"\n"
        "[[motions]]\nname = \"box\"\nkind = \"free_body\"\ndensity = 500\n{}"
        "[time]\nend_time = {}\n",
        length + 0.1, dx, length, length, length / 2 - 0.1, bottom, length / 2 + 0.1, bottom + 0.1,
        zones, end_time);
}

struct Heave {
    std::vector<double> t, y, angle;
};

Heave run_heave(const std::string& text) {
    const CaseConfig cfg = read_case_text(text, "floating.toml");
    Simulation<2> sim(cfg);
    Heave h;
    const double y0 = sim.motion().bodies()[0].centre().y();
    while (sim.time() < cfg.end_time) {
        sim.step();
        h.t.push_back(sim.time());
        h.y.push_back(sim.motion().bodies()[0].centre().y() - y0);
        h.angle.push_back(sim.motion().bodies()[0].pose().angle);
    }
    return h;
}

} // namespace

TEST_CASE("Momentum: the fluid loses to a free body what the body gains, to round-off") {
    const std::string text =
        "[case]\ndimension = 2\n[domain]\nlo = [0, 0]\nhi = [1.2, 0.6]\n"
        "[fluid]\nrho0 = 1000\nviscosity = 1e-3\nsound_speed = 20\ngravity = [0, 0]\n"
        "[particles]\ndx = 0.02\n[[blocks]]\nlo = [0.1, 0.2]\nhi = [0.4, 0.4]\n"
        "velocity = [1.5, 0.2]\nhydrostatic = false\n"
        "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.05\n"
        "dt = 2e-4\nwall_artificial_viscosity = true\n"
        "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0]\ntank_hi = [1.2, 0.6]\ntank_faces = []\n"
        "[[walls.boxes]]\nlo = [0.5, 0.25]\nhi = [0.6, 0.35]\nmotion = \"box\"\n"
        "[[motions]]\nname = \"box\"\nkind = \"free_body\"\ndensity = 800\n"
        "angular_velocity = 1.0\n"
        "[time]\nend_time = 0.15\n";
    const CaseConfig cfg = read_case_text(text, "momentum.toml");
    Simulation<2> sim(cfg);
    const auto momentum = [&] {
        const Particles<2>& P = sim.particles();
        long double px = 0, py = 0;
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid) {
                px += (long double)P.mass[i] * P.v_half[i].x();
                py += (long double)P.mass[i] * P.v_half[i].y();
            }
        const RigidBody& b = sim.motion().bodies()[0];
        // The load the last agreement gave is applied by the next step's kick, dt of it.
        const Eigen::Vector3d pending = sim.dt() * sim.motion().loads()[0].force;
        return Eigen::Vector2d(double(px) + b.mass().mass * b.velocity().x() + pending.x(),
                               double(py) + b.mass().mass * b.velocity().y() + pending.y());
    };
    const Eigen::Vector2d p0 = momentum();
    double largest_load = 0;
    while (sim.time() < cfg.end_time) {
        sim.step();
        largest_load = std::max(largest_load, sim.motion().loads()[0].force.norm());
    }
    const Eigen::Vector2d p1 = momentum();
    MESSAGE(fmt::format("momentum before [{:.15g}, {:.15g}], after [{:.15g}, {:.15g}] kg m/s; "
                        "largest load {:.4g} N/m; body velocity [{:.4g}, {:.4g}] m/s",
                        p0.x(), p0.y(), p1.x(), p1.y(), largest_load,
                        sim.motion().bodies()[0].velocity().x(),
                        sim.motion().bodies()[0].velocity().y()));
    REQUIRE(largest_load > 10); // the block hit the box
    CHECK(sim.motion().bodies()[0].velocity().x() > 0.1);
    CHECK((p1 - p0).norm() < 1e-11 * p0.norm());
}

TEST_CASE("Archimedes: a box of density 500 at its draft stays; dropped, it returns to it") {
    // Water 0.3 m deep: the draft of a 0.1 m box of density 500 is 0.05 m.
    const double dx = 0.01, height = 0.1;
    const Heave rest = run_heave(floating_case(dx, 1.0, 0.25, false, 2.0));
    double worst = 0;
    for (double y : rest.y)
        worst = std::max(worst, std::abs(y));
    MESSAGE(fmt::format("at its draft: largest heave {:.3g} m = {:.3g} dx over 2 s", worst,
                        worst / dx));
    CHECK(worst < 0.1 * dx);
    const double length = 2.0;
    const Heave drop = run_heave(floating_case(dx, length, 0.27, true, 3.0));
    double sum = 0, turn = 0;
    int n = 0;
    for (std::size_t i = 0; i < drop.t.size(); ++i) {
        turn = std::max(turn, std::abs(drop.angle[i]));
        if (drop.t[i] >= 1.5) {
            sum += drop.y[i];
            ++n;
        }
    }
    const double mean = sum / n;
    // Sinking 0.02 m deeper, the box displaces 0.2 x 0.02 m^2 more: the water outside it
    // rises by that over the free surface's length, and the box with it.
    const double rise = 0.2 * 0.02 / (length - 0.2);
    const double equilibrium = -0.02 + rise;
    MESSAGE(fmt::format("dropped 0.02 m above its draft: mean heave over 1.5-3 s {:.4g} m "
                        "(equilibrium {:.4g} m; {:.2g} % of its height off), largest angle "
                        "{:.2g} rad",
                        mean, equilibrium, 100 * std::abs(mean - equilibrium) / height, turn));
    CHECK(std::abs(mean - equilibrium) < 0.02 * height);
    CHECK(turn < 1e-3);
}

TEST_CASE("Free fall in air: g t^2/2 to round-off") {
    // The water sits in a corner far from the box, which falls 0.3 s.
    const std::string text =
        "[case]\ndimension = 2\n[domain]\nlo = [-0.1, -0.1]\nhi = [1.1, 1.1]\n"
        "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 20\ngravity = [0, -9.81]\n"
        "[particles]\ndx = 0.02\n[[blocks]]\nlo = [0, 0]\nhi = [0.2, 0.06]\n"
        "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.02\n"
        "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0]\ntank_hi = [1, 1]\n"
        "[[walls.boxes]]\nlo = [0.7, 0.8]\nhi = [0.9, 0.9]\nmotion = \"box\"\n"
        "[[motions]]\nname = \"box\"\nkind = \"free_body\"\ndensity = 500\nvelocity = [0.1, 0]\n"
        "[time]\nend_time = 0.3\n";
    const CaseConfig cfg = read_case_text(text, "fall.toml");
    Simulation<2> sim(cfg);
    sim.step(); // held while no load is known
    const double t0 = sim.time();
    const Eigen::Vector3d x0 = sim.motion().bodies()[0].centre();
    double worst = 0;
    while (sim.time() < cfg.end_time) {
        sim.step();
        const double tau = sim.time() - t0;
        const Eigen::Vector3d x = sim.motion().bodies()[0].centre();
        worst = std::max(worst, std::hypot(x.x() - (x0.x() + 0.1 * tau),
                                           x.y() - (x0.y() - 0.5 * 9.81 * tau * tau)));
        CHECK(sim.motion().loads()[0].force.norm() == 0);
    }
    CHECK(worst < 1e-13);
}

TEST_CASE("Several bodies: each is moved by its own load") {
    // Three boxes of density 500 at their draft, side by side: each one's load is its own
    // buoyancy (its weight, 10 N/m, within 5 % after 0.05 s), not another's.
    std::string text = floating_case(0.01, 1.0, 0.25, false, 0.05);
    const std::string box =
        "[[walls.boxes]]\nlo = [0.4, 0.25]\nhi = [0.6, 0.35]\nmotion = \"box\"\n";
    text.replace(text.find(box), box.size(),
                 "[[walls.boxes]]\nlo = [0.05, 0.25]\nhi = [0.25, 0.35]\nmotion = \"a\"\n" + box +
                     "[[walls.boxes]]\nlo = [0.75, 0.25]\nhi = [0.95, 0.35]\nmotion = \"c\"\n");
    text += "[[motions]]\nname = \"a\"\nkind = \"free_body\"\ndensity = 500\n"
            "[[motions]]\nname = \"c\"\nkind = \"free_body\"\ndensity = 500\n";
    const CaseConfig cfg = read_case_text(text, "three.toml");
    Simulation<2> sim(cfg);
    while (sim.time() < cfg.end_time)
        sim.step();
    REQUIRE(sim.motion().bodies().size() == 3);
    for (std::size_t b = 0; b < 3; ++b) {
        const double weight = sim.motion().bodies()[b].mass().mass * 9.81;
        CHECK(sim.motion().loads()[b].force.y() == doctest::Approx(weight).epsilon(0.05));
        CHECK(std::abs(sim.motion().bodies()[b].centre().y() - 0.3) < 0.002);
    }
}
