// The Riemann-solver WCSPH terms (physics/riemann.hpp; Zhang, Hu & Adams 2017): the pair
// pressure, the continuity rate against -rho div u, and the density diffusion vanishing on a
// hydrostatic profile.
#include "periodic_lattice.hpp"

#include "sluice/physics/density.hpp"
#include "sluice/physics/riemann.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

using namespace sluice;
using sluice::testing::Lattice;

TEST_CASE("Riemann pair pressure: density-weighted mean, plus limited dissipation when closing") {
    // rho_L = 1000, rho_R = 1000, p_L = 100, p_R = 300, c0 = 50, eta = 3 (Zhang et al. 2017).
    CHECK(riemann_pressure(1000, 1000, 100, 300, -1, 50, 3) == doctest::Approx(200));
    // dU = 1 m/s: beta = 3 * 1 / 50 = 0.06; beta rho_L rho_R / (rho_L + rho_R) c0 dU = 1500.
    CHECK(riemann_pressure(1000, 1000, 100, 300, 1, 50, 3) == doctest::Approx(1700));
    // dU = 20 m/s: beta = min(1.2, 1) = 1: the full acoustic impedance, 500 * 50 * 20.
    CHECK(riemann_pressure(1000, 1000, 100, 300, 20, 50, 3) == doctest::Approx(500200));
    // Unequal densities weight the other side's pressure: (1000 * 300 + 1100 * 100) / 2100.
    CHECK(riemann_pressure(1000, 1100, 100, 300, 0, 50, 3) == doctest::Approx(410000.0 / 2100));
}

TEST_CASE("Riemann continuity rate gives -rho div u for u = (sin 2 pi x, 0) at uniform pressure") {
    Lattice L(50, 1.5);
    L.set_sine_velocity();
    L.derive_factors();
    RiemannParams<2> prm;
    prm.c0 = 20;
    for (const auto& c : L.occ)
        riemann_continuity_rate(L.nb(), L.kernel, prm, c.cell, L.P, std::span<const Vec<2>>(L.P.v),
                                std::span<Real>(L.P.drho));
    const auto [err, ref] = L.sine_continuity_error();
    INFO("max error " << err << " of " << ref);
    CHECK(err < 0.02 * ref);
}

TEST_CASE("Riemann density diffusion vanishes on a hydrostatic pressure profile") {
    // Still water under gravity -g e_y: p = rho0 g (1 - y). The solver's diffusion acts on the
    // pressure jump less its hydrostatic part, so it must vanish (round-off); with gravity left
    // out of the correction it does not.
    Lattice L(50, 1.5);
    const double g = 9.81, c0 = 20;
    const Eos eos{EosType::linear, 1000, c0, 7, 0};
    for (std::size_t i = 0; i < L.P.size(); ++i) {
        L.P.p[i] = 1000 * g * (1 - L.P.x[i][1]);
        L.P.rho[i] = eos.density(L.P.p[i]); // so that the volumes m/rho vary as in still water
    }
    L.derive_factors();
    const auto worst_rate = [&](const Vec<2>& gravity) {
        RiemannParams<2> prm;
        prm.c0 = c0;
        prm.gravity = gravity;
        for (const auto& c : L.occ)
            riemann_continuity_rate(L.nb(), L.kernel, prm, c.cell, L.P,
                                    std::span<const Vec<2>>(L.P.v), std::span<Real>(L.P.drho));
        double worst = 0; // away from the periodic seam in y, where the profile jumps
        for (std::size_t i = 0; i < L.P.size(); ++i)
            if (L.P.x[i][1] > 0.2 && L.P.x[i][1] < 0.8)
                worst = std::max(worst, std::abs(L.P.drho[i]));
        return worst;
    };
    const double corrected = worst_rate(Vec<2>(0, -g));
    const double uncorrected = worst_rate(Vec<2>(0, g)); // the hydrostatic part doubled
    MESSAGE("max |drho|: corrected " << corrected << ", sign-flipped " << uncorrected);
    CHECK(corrected < 1e-6);
    CHECK(uncorrected > 1e-3);
}
