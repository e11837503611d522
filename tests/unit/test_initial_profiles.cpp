// Initial fields of fluid blocks: the rotating patch's pressure (against Colagrossi's double
// sine series, its Poisson equation and its zero edge), the elliptical-drop pressure, the
// velocities and pressures the particles actually receive, and the particle count of an
// ellipse-shaped block.
#include "sluice/physics/initial_profiles.hpp"
#include "sluice/solver/initial_state.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace sluice;

namespace {

// Colagrossi (2005) / Le Touze et al. (2013): p = -rho sum_{m,n odd} 32 omega^2 /
// (m n pi^2 ((m pi/Lx)^2 + (n pi/Ly)^2)) sin(m pi x/Lx) sin(n pi y/Ly). Converges like 1/M^2.
double double_series(double rho, double omega, double Lx, double Ly, double x, double y) {
    const double pi = std::numbers::pi;
    double p = 0;
    for (int m = 1; m < 3000; m += 2)
        for (int n = 1; n < 3000; n += 2) {
            const double k2 = std::pow(m * pi / Lx, 2) + std::pow(n * pi / Ly, 2);
            p -= 32 * omega * omega / (m * n * pi * pi * k2) * std::sin(m * pi * x / Lx) *
                 std::sin(n * pi * y / Ly);
        }
    return rho * p;
}

// Five-point Laplacian of f at (x, y).
template <class F>
double laplacian(F f, double x, double y, double e) {
    return (f(x + e, y) + f(x - e, y) + f(x, y + e) + f(x, y - e) - 4 * f(x, y)) / (e * e);
}

CaseConfig drop_case(double dx) {
    CaseConfig c;
    c.dimension = 2;
    c.rho0 = 1000;
    c.sound_speed = 50;
    c.gravity = {0, 0, 0};
    c.dx = dx;
    FluidBlock b;
    b.lo = {-1, -1, 0};
    b.hi = {1, 1, 0};
    b.shape = BlockShape::ellipse;
    b.profile = VelocityProfile::strain;
    b.strain_rate = 100;
    b.hydrostatic = false;
    c.blocks.push_back(b);
    return c;
}

} // namespace

TEST_CASE("rotating patch pressure equals Colagrossi's double series") {
    const double rho = 1000, omega = 1.5;
    for (const auto& [Lx, Ly] : {std::pair{1.0, 1.0}, std::pair{2.0, 0.5}})
        for (const auto& [fx, fy] :
             {std::pair{0.5, 0.5}, std::pair{0.1, 0.3}, std::pair{0.8, 0.9}}) {
            const double x = fx * Lx, y = fy * Ly;
            const double p = rotating_rectangle_pressure(rho, omega, Lx, Ly, x, y);
            CHECK(p < 0); // suction everywhere inside
            CHECK(p == doctest::Approx(double_series(rho, omega, Lx, Ly, x, y)).epsilon(1e-5));
        }
    // Centre of the unit square: -2 x 0.0736713 rho omega^2 L^2 (0.0736713 L^2 is the centre
    // value of the solution of lap u = -1 on a square, u = 0 on its edges).
    CHECK(rotating_rectangle_pressure(1, 1, 1, 1, 0.5, 0.5) ==
          doctest::Approx(-2 * 0.0736713).epsilon(1e-5));
}

TEST_CASE("rotating patch pressure solves lap p = 2 rho omega^2 with p = 0 on the edges") {
    const double rho = 1000, omega = 2, Lx = 1.2, Ly = 0.7;
    const auto p = [&](double x, double y) {
        return rotating_rectangle_pressure(rho, omega, Lx, Ly, x, y);
    };
    for (const auto& [x, y] : {std::pair{0.6, 0.35}, std::pair{0.1, 0.1}, std::pair{1.0, 0.6}})
        CHECK(laplacian(p, x, y, 1e-3) == doctest::Approx(2 * rho * omega * omega).epsilon(1e-4));
    const double scale = rho * omega * omega * Lx * Ly;
    for (double s : {0.0, 0.13, 0.5, 0.91, 1.0}) {
        CHECK(std::abs(p(s * Lx, 0)) < 1e-6 * scale);
        CHECK(std::abs(p(s * Lx, Ly)) < 1e-6 * scale);
        CHECK(std::abs(p(0, s * Ly)) < 1e-6 * scale);
        CHECK(std::abs(p(Lx, s * Ly)) < 1e-6 * scale);
    }
}

TEST_CASE("ellipse pressure solves lap p = -rho tr(G^2) with p = 0 on the edge") {
    const double rho = 1000, a = 1.5, b = 0.6, tr = 2 * 100.0 * 100.0;
    const auto p = [&](double x, double y) { return ellipse_pressure(rho, tr, a, b, x, y); };
    CHECK(laplacian(p, 0.3, -0.2, 1e-3) == doctest::Approx(-rho * tr).epsilon(1e-6));
    for (double th : {0.0, 0.7, 2.0, 4.0})
        CHECK(std::abs(p(a * std::cos(th), b * std::sin(th))) < 1e-9 * p(0, 0));
    // Monaghan's circular drop: p(0) = rho A0^2 R^2 / 2.
    CHECK(ellipse_pressure(rho, tr, 1, 1, 0, 0) == doctest::Approx(0.5 * rho * 100 * 100));
}

TEST_CASE("a rotating square block: v = omega x (x - c) and the patch pressure") {
    CaseConfig c = drop_case(0.1);
    FluidBlock& b = c.blocks[0];
    b.shape = BlockShape::box;
    b.profile = VelocityProfile::rotating;
    b.angular_velocity = 2;
    b.lo = {1, 2, 0}; // centre (1.5, 2.5), side 1
    b.hi = {2, 3, 0};
    const Eos eos{EosType::linear, c.rho0, c.sound_speed, 7, 0};
    Particles<2> P;
    add_fluid_blocks<2>(c, eos, P);
    REQUIRE(P.size() == 100);
    REQUIRE(count_fluid_particles(c) == 100);
    for (std::size_t i = 0; i < P.size(); i += 7) {
        const double xi = P.x[i][0] - 1.5, eta = P.x[i][1] - 2.5;
        CHECK(P.v[i][0] == doctest::Approx(-2 * eta));
        CHECK(P.v[i][1] == doctest::Approx(2 * xi));
        const double p = rotating_rectangle_pressure(1000, 2, 1, 1, P.x[i][0] - 1, P.x[i][1] - 2);
        CHECK(eos.pressure(P.rho[i]) == doctest::Approx(p).epsilon(1e-9));
        CHECK(P.mass[i] == doctest::Approx(1000 * 0.01)); // continuity: reference mass
    }
    CHECK(block_max_speed(b, 2) == doctest::Approx(2 * std::sqrt(0.5)));
}

TEST_CASE("particles.jitter: bounded, spread, reproducible displacements of the lattice") {
    CaseConfig c = drop_case(0.1);
    c.blocks[0].shape = BlockShape::box;
    const Eos eos{EosType::linear, c.rho0, c.sound_speed, 7, 0};
    Particles<2> lattice, moved, again;
    add_fluid_blocks<2>(c, eos, lattice);
    c.jitter = 0.01;
    add_fluid_blocks<2>(c, eos, moved);
    add_fluid_blocks<2>(c, eos, again);
    REQUIRE(lattice.size() == 400);
    REQUIRE(moved.size() == lattice.size());
    double largest = 0, mean = 0;
    for (std::size_t i = 0; i < moved.size(); ++i)
        for (int d = 0; d < 2; ++d) {
            const double off = (moved.x[i][d] - lattice.x[i][d]) / c.dx;
            CHECK(std::abs(off) <= 0.005 + 1e-12);
            largest = std::max(largest, std::abs(off));
            mean += off / 800;
            CHECK(again.x[i][d] == moved.x[i][d]); // a function of the particle id alone
        }
    CHECK(largest > 0.0049);           // the offsets fill [-jitter/2, jitter/2]
    CHECK(std::abs(mean) < 0.0005);    // 800 uniform offsets: sigma of the mean 1e-4
    CHECK(moved.v[7] == lattice.v[7]); // the fields (here the strain flow) of the lattice site
    CHECK(moved.rho[7] == lattice.rho[7]);
}

TEST_CASE("an ellipse block holds the lattice sites inside the inscribed circle") {
    const double dx = 0.1; // R = 10 dx
    const CaseConfig c = drop_case(dx);
    const Eos eos{EosType::linear, c.rho0, c.sound_speed, 7, 0};
    Particles<2> P;
    add_fluid_blocks<2>(c, eos, P);
    // Sites (i + 1/2, j + 1/2) dx with i, j in [-10, 9]: in row j, |i + 1/2| <= sqrt(100 - y^2).
    std::size_t expected = 0;
    for (int j = -10; j < 10; ++j) {
        const double half_width = std::sqrt(100 - (j + 0.5) * (j + 0.5));
        expected += 2 * static_cast<std::size_t>(std::floor(half_width + 0.5));
    }
    CHECK(P.size() == expected);
    CHECK(count_fluid_particles(c) == expected);
    CHECK(static_cast<double>(expected) == doctest::Approx(std::numbers::pi * 100).epsilon(0.02));
    double r_max = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        r_max = std::max(r_max, P.x[i].norm());
        // Monaghan's drop: v = (-A0 x, A0 y), p = rho A0^2 (R^2 - r^2)/2.
        CHECK(P.v[i][0] == doctest::Approx(-100 * P.x[i][0]));
        CHECK(P.v[i][1] == doctest::Approx(100 * P.x[i][1]));
        CHECK(eos.pressure(P.rho[i]) ==
              doctest::Approx(0.5 * 1000 * 100 * 100 * (1 - P.x[i].squaredNorm())).epsilon(1e-9));
    }
    CHECK(r_max <= 1.0);
    CHECK(r_max > 1.0 - dx);
}
