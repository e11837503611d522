// Adami et al. (2012) dummy-wall state (physics/walls.hpp, dummy_wall_state) on hand-computed
// cases: two fluid particles over one wall particle, the exact reproduction of a hydrostatic
// field for any particle positions, a dry wall particle, and the derived density and mass.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/walls.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sluice;

namespace {

constexpr Real kDx = 0.01, kH = 0.015, kRho = 1000, kG = 9.81;

// Runs dummy_wall_state over every occupied cell of P (rebinned: look particles up by id).
void walls_stage(Particles<2>& P, const Eos& eos, bool no_slip) {
    const WendlandC2Kernel<2> kernel(kH);
    const auto grid =
        CellGrid<2>::make(Vec<2>(-0.1, -0.1), Vec<2>(0.1, 0.1), kernel.support(), {false, false});
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    rebin(grid, P, ranges, occ);
    const Neighbourhood<2> nb{&grid, &ranges, std::span<const Vec<2>>(P.x), kernel.support()};
    for (const auto& c : occ)
        dummy_wall_state(nb, kernel, eos, Vec<2>(0, -kG), no_slip, kDx * kDx, c.cell, P);
}

std::size_t index_of(const Particles<2>& P, ParticleId id) {
    for (std::size_t i = 0; i < P.size(); ++i)
        if (P.id[i] == id)
            return i;
    FAIL("no particle with id " << id);
    return 0;
}

} // namespace

TEST_CASE("Adami wall state: two fluid particles over one wall particle") {
    // Wall particle 0 at the origin; fluid 1 at (0, dx) with p = 100 Pa, v = (1, 0); fluid 2 at
    // (dx, dx) with p = 300 Pa, v = (0, 2); densities 1000 and 1010.
    Particles<2> P;
    P.push_back(0, Kind::wall, Vec<2>(0, 0), Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    P.push_back(1, Kind::fluid, Vec<2>(0, kDx), Vec<2>(1, 0), 1000, kRho * kDx * kDx);
    P.push_back(2, Kind::fluid, Vec<2>(kDx, kDx), Vec<2>(0, 2), 1010, kRho * kDx * kDx);
    P.p[1] = 100;
    P.p[2] = 300;
    Eos eos;
    eos.rho0 = kRho;
    eos.c0 = 20;
    walls_stage(P, eos, true);

    const WendlandC2Kernel<2> kernel(kH);
    const Real W1 = kernel.W(kDx), W2 = kernel.W(std::sqrt(Real(2)) * kDx);
    // p_w = [sum p_f W + g . sum rho_f (x_w - x_f) W] / sum W; g = (0, -g), x_w - x_f has
    // y-component -dx for both, so g . (x_w - x_f) = +g dx.
    const Real expected = (100 * W1 + 300 * W2 + kG * kDx * (1000 * W1 + 1010 * W2)) / (W1 + W2);
    const std::size_t w = index_of(P, 0);
    CHECK(P.p[w] == doctest::Approx(expected).epsilon(1e-12));
    // No-slip: the mirror of the kernel-mean fluid velocity.
    CHECK(P.v_bc[w][0] == doctest::Approx(-W1 / (W1 + W2)).epsilon(1e-12));
    CHECK(P.v_bc[w][1] == doctest::Approx(-2 * W2 / (W1 + W2)).epsilon(1e-12));
    // Density from the equation of state (linear: rho0 + p/c0^2), mass rho_w V_w.
    CHECK(P.rho[w] == doctest::Approx(kRho + expected / (20 * 20)).epsilon(1e-12));
    CHECK(P.mass[w] == doctest::Approx(P.rho[w] * kDx * kDx).epsilon(1e-12));

    // Free slip: the mean velocity itself.
    walls_stage(P, eos, false);
    CHECK(P.v_bc[index_of(P, 0)][0] == doctest::Approx(W1 / (W1 + W2)).epsilon(1e-12));
}

TEST_CASE("Adami wall state reproduces a hydrostatic field exactly, for any positions") {
    // Fluid with p = rho g (H - y) at irregular positions above three layers of wall: the
    // extrapolation gives every wetted wall particle rho g (H - y_w) (the sum is exact for a
    // uniform density, however uneven the weights).
    const Real H = 0.05;
    Particles<2> P;
    ParticleId id = 0;
    for (int layer = 1; layer <= 3; ++layer)
        for (int i = -4; i <= 4; ++i)
            P.push_back(id++, Kind::wall, Vec<2>(i * kDx, (0.5 - layer) * kDx), Vec<2>::Zero(),
                        kRho, kRho * kDx * kDx);
    const ParticleId walls = id;
    for (int row = 0; row < 5; ++row)
        for (int i = -6; i <= 6; ++i) {
            // A fixed, uneven offset per particle (no randomness: the test is reproducible).
            const Real ox = Real(0.3) * std::sin(Real(7 * i + 3 * row)) * kDx;
            const Real oy = Real(0.3) * std::cos(Real(5 * i + 11 * row)) * kDx;
            const Vec<2> x((i + Real(0.5)) * kDx + ox, (row + Real(0.5)) * kDx + oy);
            P.push_back(id++, Kind::fluid, x, Vec<2>::Zero(), kRho, kRho * kDx * kDx);
            P.p.back() = kRho * kG * (H - x[1]);
        }
    Eos eos;
    eos.rho0 = kRho;
    walls_stage(P, eos, true);
    const Real support = WendlandC2Kernel<2>(kH).support();
    int wet = 0, dry = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        if (P.id[i] >= walls)
            continue;
        bool reached = false; // any fluid particle within the support
        for (std::size_t f = 0; f < P.size(); ++f)
            reached = reached || (P.kind[f] == Kind::fluid && (P.x[f] - P.x[i]).norm() < support);
        if (reached) {
            CHECK(P.p[i] == doctest::Approx(kRho * kG * (H - P.x[i][1])).epsilon(1e-12));
            ++wet;
        } else {
            CHECK(P.p[i] == eos.p_background);
            ++dry;
        }
    }
    CHECK(wet >= 21); // the deepest layer's ends are out of the fluid's reach
    CHECK(wet + dry == 27);
}

TEST_CASE("Adami wall state: a wall particle with no fluid in reach") {
    Particles<2> P;
    P.push_back(0, Kind::wall, Vec<2>(0, 0), Vec<2>::Zero(), 999, 1);
    P.push_back(1, Kind::fluid, Vec<2>(0.05, 0.05), Vec<2>(1, 1), kRho, kRho * kDx * kDx);
    P.p[1] = 1e4;
    Eos eos;
    eos.rho0 = kRho;
    eos.p_background = 250;
    walls_stage(P, eos, true);
    const std::size_t w = index_of(P, 0);
    CHECK(P.p[w] == 250); // the background pressure
    CHECK(P.v_bc[w] == Vec<2>::Zero());
    CHECK(P.rho[w] == doctest::Approx(kRho).epsilon(1e-12)); // rho(p_background) = rho0
}
