// The SPH momentum operators against analytic fields on a periodic lattice: pressure gradient
// -grad p / rho and Morris viscous term nu lap u, for smooth sinusoidal fields resolved by 50
// particles per wavelength.
#include "periodic_lattice.hpp"

#include "sluice/physics/momentum.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace sluice;
using sluice::testing::Lattice;

TEST_CASE("Pressure term gives -grad p / rho for p = p0 cos(2 pi x)") {
    Lattice L(50, 1.5);
    const double k = 2 * std::numbers::pi, p0 = 100;
    for (std::size_t i = 0; i < L.P.size(); ++i)
        L.P.p[i] = 5000 + p0 * std::cos(k * L.P.x[i][0]);
    MomentumParams<2> prm;
    prm.h = L.kernel.h;
    L.accelerate(prm);
    double err = 0, ref = 0;
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        const double exact = p0 * k * std::sin(k * L.P.x[i][0]) / 1000;
        err = std::max(err, std::abs(L.P.a[i][0] - exact));
        ref = std::max(ref, std::abs(exact));
        CHECK(std::abs(L.P.a[i][1]) < 1e-9);
    }
    INFO("max error " << err << " of " << ref);
    CHECK(err < 0.02 * ref);
}

TEST_CASE("Morris viscous term gives nu lap u for u = (sin 2 pi y, 0)") {
    Lattice L(50, 1.5);
    const double k = 2 * std::numbers::pi, mu = 1.0;
    for (std::size_t i = 0; i < L.P.size(); ++i)
        L.P.v[i] = Vec<2>(std::sin(k * L.P.x[i][1]), 0);
    MomentumParams<2> prm;
    prm.h = L.kernel.h;
    prm.mu = mu;
    L.accelerate(prm);
    double err = 0, ref = 0;
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        const double exact = -(mu / 1000) * k * k * std::sin(k * L.P.x[i][1]);
        err = std::max(err, std::abs(L.P.a[i][0] - exact));
        ref = std::max(ref, std::abs(exact));
    }
    INFO("max error " << err << " of " << ref);
    CHECK(err < 0.02 * ref);
}
