// Particle shifting (physics/shifting.hpp, particle_shift) on hand-made particle sets: no
// shift in a uniform lattice, a shift away from a crowded neighbour, the cap, no normal
// component at a free surface, and wall particles left alone.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/shifting.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sluice;

namespace {

constexpr Real kDx = 0.01, kH = 0.015, kRho = 1000;
constexpr int kN = 12; // lattice of kN x kN over [0, kN dx)^2

// The shifts of every particle (indexed by id) for a set on a grid, periodic or not.
std::vector<Vec<2>> shifts(Particles<2> P, const ShiftingParams& prm, bool periodic) {
    const WendlandC2Kernel<2> kernel(kH);
    const Real L = kN * kDx;
    const auto grid =
        periodic ? CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(L, L), kernel.support(), {true, true})
                 : CellGrid<2>::make(Vec<2>(-L, -L), Vec<2>(2 * L, 2 * L), kernel.support(),
                                     {false, false});
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    rebin(grid, P, ranges, occ);
    const Neighbourhood<2> nb{&grid, &ranges, std::span<const Vec<2>>(P.x), kernel.support()};
    std::vector<Vec<2>> out(P.size(), Vec<2>::Constant(-1)); // -1: not written
    std::vector<Vec<2>> by_slot(P.size(), Vec<2>::Constant(-1));
    for (const auto& c : occ)
        particle_shift(nb, kernel, prm, c.cell, P, std::span<Vec<2>>(by_slot));
    for (std::size_t i = 0; i < P.size(); ++i)
        out[static_cast<std::size_t>(P.id[i])] = by_slot[i];
    return out;
}

Particles<2> lattice(int rows) {
    Particles<2> P;
    ParticleId id = 0;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < kN; ++i)
            P.push_back(id++, Kind::fluid, Vec<2>((i + Real(0.5)) * kDx, (j + Real(0.5)) * kDx),
                        Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    return P;
}

ShiftingParams params(Real coefficient) {
    return {coefficient, WendlandC2Kernel<2>(kH).W(kDx), Real(0.1) * kDx};
}

} // namespace

TEST_CASE("shifting: none in a uniform periodic lattice") {
    for (const Vec<2>& s : shifts(lattice(kN), params(1e-4), true))
        CHECK(s.norm() < 1e-15);
}

TEST_CASE("shifting moves a particle away from a crowded neighbour, capped at 0.1 dx") {
    // Particle 0 of a periodic lattice moved 0.2 dx towards its right neighbour: its shift
    // points back (-x) and, by symmetry about the row, has no y component; the neighbour is
    // pushed the other way.
    Particles<2> P = lattice(kN);
    const Real moved = (Real(0.5) + Real(0.2)) * kDx;
    P.x[0][0] = moved;
    const Real c = 1e-6; // A U h dt, small enough not to reach the cap
    const auto s = shifts(P, params(c), true);
    CHECK(s[0][0] < 0);
    CHECK(std::abs(s[0][1]) < 1e-18);
    CHECK(s[1][0] > 0);
    CHECK(s[0].norm() < Real(0.1) * kDx);
    // The sum is linear in the coefficient until the cap: ten times the coefficient, ten times
    // the shift.
    const auto s10 = shifts(P, params(10 * c), true);
    CHECK(s10[0][0] == doctest::Approx(10 * s[0][0]).epsilon(1e-12));
    // A coefficient far too large: exactly the cap, in the same direction.
    const auto capped = shifts(P, params(1.0), true);
    CHECK(capped[0].norm() == doctest::Approx(Real(0.1) * kDx).epsilon(1e-12));
    CHECK(capped[0][0] < 0);
}

TEST_CASE("shifting at a flat free surface has no normal component") {
    // A 4-row block, periodic along x, nothing above it. The top row (kernel sum below 0.95)
    // would be pushed up, out of the fluid, by the raw sum; its shift keeps only the part
    // along the surface, which is zero on a flat surface. The row below sees enough of the
    // kernel to be treated as interior and keeps its (vertical) shift.
    Particles<2> P = lattice(4);
    const Real L = kN * kDx;
    const WendlandC2Kernel<2> kernel(kH);
    const auto grid =
        CellGrid<2>::make(Vec<2>(0, -L), Vec<2>(L, 2 * L), kernel.support(), {true, false});
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    rebin(grid, P, ranges, occ);
    const Neighbourhood<2> nb{&grid, &ranges, std::span<const Vec<2>>(P.x), kernel.support()};
    std::vector<Vec<2>> s(P.size(), Vec<2>::Zero());
    for (const auto& c : occ)
        particle_shift(nb, kernel, params(1e-4), c.cell, P, std::span<Vec<2>>(s));
    Real top = 0, below = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        if (P.id[i] >= 3 * kN)
            top = std::max(top, s[i].norm());
        else if (P.id[i] >= 2 * kN)
            below = std::max(below, std::abs(s[i][1]));
    }
    MESSAGE("largest shift: top row " << top << " m, row below (vertical) " << below << " m");
    CHECK(below > 1e-7);
    CHECK(top < 1e-12 * below);
}

TEST_CASE("shifting leaves wall particles untouched") {
    Particles<2> P = lattice(4);
    P.push_back(static_cast<ParticleId>(P.size()), Kind::wall, Vec<2>(0.055, -0.005),
                Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    const auto s = shifts(P, params(1e-4), false);
    CHECK(s.back() == Vec<2>::Constant(-1)); // never written
}

// The projection scheme's pieces (shift_pair_term, fickian_shift; Lind et
// al. 2012, eqs. 21-24) on hand-computed values.
TEST_CASE("Fickian shifting: pair term with the anti-clustering factor") {
    // W_ij = W(dx) / 2: factor 1 + 0.2 (1/2)^4 = 1.0125, times V_j = 1e-4.
    const Vec<2> t = shift_pair_term<2>(Vec<2>(1, -2), Real(0.5), Real(1), Real(1e-4));
    CHECK(t[0] == doctest::Approx(1.0125e-4).epsilon(1e-14));
    CHECK(t[1] == doctest::Approx(-2.025e-4).epsilon(1e-14));
    // At the lattice spacing the factor is 1.2.
    const Vec<2> u = shift_pair_term<2>(Vec<2>(0, 3), Real(7), Real(7), Real(2));
    CHECK(u[0] == 0);
    CHECK(u[1] == doctest::Approx(7.2).epsilon(1e-14));
}

TEST_CASE("Fickian shifting: down the gradient, tangential near the surface, capped") {
    const Vec<2> grad_c(3, 4);
    const Vec<2> up(0, 2); // plain concentration gradient: into the fluid, along +y
    // Interior: -D grad C = (-6, -8), |.| = 10.
    Vec<2> dr = fickian_shift<2>(2, grad_c, false, up, 100);
    CHECK(dr[0] == doctest::Approx(-6));
    CHECK(dr[1] == doctest::Approx(-8));
    // Capped at 5: the same direction, length 5.
    dr = fickian_shift<2>(2, grad_c, false, up, 5);
    CHECK(dr[0] == doctest::Approx(-3));
    CHECK(dr[1] == doctest::Approx(-4));
    // Near the surface the normal (y) part goes: (-6, 0), then the cap.
    dr = fickian_shift<2>(2, grad_c, true, up, 100);
    CHECK(dr[0] == doctest::Approx(-6));
    CHECK(dr[1] == 0);
    dr = fickian_shift<2>(2, grad_c, true, up, 5);
    CHECK(dr[0] == doctest::Approx(-5));
    CHECK(dr[1] == 0);
    // No normal known (zero plain gradient): nothing removed.
    dr = fickian_shift<2>(2, grad_c, true, Vec<2>::Zero(), 100);
    CHECK(dr[1] == doctest::Approx(-8));
}

TEST_CASE("Fickian shifting: a particle moves away from a single close neighbour") {
    // i at the origin, j at (dx, 0): grad_i W_ij = W'(dx) (x_i - x_j) / dx = (-W'(dx), 0) with
    // W' < 0, so grad C points towards j and -D grad C away from it, by D 1.2 V |W'(dx)|.
    const QuinticKernel<2> kernel(Real(1.0333) * kDx);
    const Vec<2> r(-kDx, 0); // x_i - x_j
    const Real w = kernel.W(kDx), dw = kernel.dW(kDx);
    REQUIRE(dw < 0);
    const Vec<2> grad_c = shift_pair_term<2>(grad_W<2>(kernel, r, kDx), w, w, kDx * kDx);
    const Real coefficient = Real(1e-7);
    const Vec<2> dr = fickian_shift<2>(coefficient, grad_c, false, grad_c, kDx);
    CHECK(dr[0] == doctest::Approx(coefficient * Real(1.2) * kDx * kDx * dw).epsilon(1e-12));
    CHECK(dr[0] < 0);
    CHECK(dr[1] == 0);
}
