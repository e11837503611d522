// The acoustic damper (physics/acoustic_damper.hpp) on a periodic lattice: the SPH divergence
// against analytic fields, no change to the pressure of a divergence-free flow, and the
// pressure correction -rho nu_a div u with its p/rho^2.
#include "periodic_lattice.hpp"

#include "sluice/physics/acoustic_damper.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace sluice;
using sluice::testing::Lattice;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// (div u)_i of every particle.
std::vector<double> divergences(const Lattice& L) {
    std::vector<double> div(L.P.size());
    const auto nb = L.nb();
    for (const auto& c : L.occ) {
        const AdjacentCells<2> adj = nb.adjacent(c.cell);
        for (std::uint32_t i = nb.begin(c.cell), stop = nb.end(c.cell); i < stop; ++i)
            div[i] = velocity_divergence(nb, L.kernel, adj, i, L.P);
    }
    return div;
}

} // namespace

TEST_CASE("acoustic damper: the divergence of u = (sin 2 pi x, cos 2 pi y)") {
    Lattice L(50, 1.5);
    for (std::size_t i = 0; i < L.P.size(); ++i)
        L.P.v[i] = Vec<2>(std::sin(kTwoPi * L.P.x[i][0]), std::cos(kTwoPi * L.P.x[i][1]));
    const auto div = divergences(L);
    double err = 0;
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        const double exact =
            kTwoPi * (std::cos(kTwoPi * L.P.x[i][0]) - std::sin(kTwoPi * L.P.x[i][1]));
        err = std::max(err, std::abs(div[i] - exact));
    }
    INFO("max error " << err << " of " << 2 * kTwoPi);
    CHECK(err < 0.02 * 2 * kTwoPi);
}

TEST_CASE("acoustic damper: a divergence-free flow keeps its pressure") {
    // A Taylor-Green field (div u = 0) and a uniform translation: the damper adds nothing
    // beyond round-off, so it cannot disturb incompressible motion or a tank at rest.
    Lattice L(40, 1.5);
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        const double x = L.P.x[i][0], y = L.P.x[i][1];
        L.P.v[i] = Vec<2>(std::sin(kTwoPi * x) * std::cos(kTwoPi * y) + 0.3,
                          -std::cos(kTwoPi * x) * std::sin(kTwoPi * y) - 0.7);
        L.P.p[i] = 500 + 10 * std::sin(kTwoPi * y);
    }
    L.derive_factors();
    const std::vector<Real> p_before = L.P.p;
    const Real nu_a = acoustic_damper_viscosity(0.5, 1.5 / 40, 50);
    for (const auto& c : L.occ)
        apply_acoustic_damper(L.nb(), L.kernel, nu_a, c.cell, L.P, std::span<Real>(L.P.p),
                              std::span<Real>(L.P.p_over_rho2));
    double change = 0;
    for (std::size_t i = 0; i < L.P.size(); ++i)
        change = std::max(change, std::abs(L.P.p[i] - p_before[i]));
    // On the lattice the two halves of a Taylor-Green divergence cancel by symmetry and a
    // translation cancels in the difference form: only round-off is left, against
    // rho nu_a k = 1000 * 0.94 * 6.3 = 5.9 kPa for a compression of the same size.
    INFO("largest change " << change << " Pa");
    CHECK(change < 1e-6 * 1000 * nu_a * kTwoPi);
}

TEST_CASE("acoustic damper: a compression raises the pressure by -rho nu_a div u") {
    // u = (-sin(2 pi x) / 2 pi, 0) has div u = -cos 2 pi x: the columns near x = 0 are
    // compressed at unit rate and gain rho nu_a, those near x = 1/2 lose it; p/rho^2 follows.
    Lattice L(40, 1.5);
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        L.P.v[i] = Vec<2>(-std::sin(kTwoPi * L.P.x[i][0]) / kTwoPi, 0);
        L.P.p[i] = 0;
        L.P.rho[i] = 1002;
    }
    L.derive_factors();
    const Real nu_a = acoustic_damper_viscosity(0.1, 1.5 / 40, 40);
    CHECK(nu_a == doctest::Approx(0.15));
    for (const auto& c : L.occ)
        apply_acoustic_damper(L.nb(), L.kernel, nu_a, c.cell, L.P, std::span<Real>(L.P.p),
                              std::span<Real>(L.P.p_over_rho2));
    double err = 0;
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        const double exact = 1002 * nu_a * std::cos(kTwoPi * L.P.x[i][0]);
        err = std::max(err, std::abs(L.P.p[i] - exact));
        CHECK(L.P.p_over_rho2[i] == doctest::Approx(L.P.p[i] / (1002.0 * 1002.0)));
    }
    INFO("max error " << err << " Pa of " << 1002 * nu_a);
    CHECK(err < 0.02 * 1002 * nu_a);
}
