// Fluid-wall pairs of the momentum equation (physics/momentum.hpp): a layer of fluid sliding
// along a dummy wall at rest, with no pressure and no laminar viscosity, so that only the
// artificial viscosity can act between fluid and wall.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/momentum.hpp"

#include <doctest/doctest.h>

using namespace sluice;

namespace {

// Three rows of fluid moving at (u, 0) over three rows of no-slip wall (v_bc = (-u, 0), the
// mirror of the fluid velocity), periodic along x.
struct SlidingLayer {
    Particles<2> P;
    CellGrid<2> grid;
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    WendlandC2Kernel<2> kernel{0.015};
    static constexpr double dx = 0.01, u = 2.0;

    SlidingLayer() {
        const int n = 40;
        ParticleId id = 0;
        for (int row = 0; row < 3; ++row)
            for (int i = 0; i < n; ++i)
                P.push_back(id++, Kind::fluid, Vec<2>((i + 0.5) * dx, (row + 0.5) * dx),
                            Vec<2>(u, 0), 1000, 1000 * dx * dx);
        for (int row = 1; row <= 3; ++row)
            for (int i = 0; i < n; ++i) {
                P.push_back(id++, Kind::wall, Vec<2>((i + 0.5) * dx, (0.5 - row) * dx),
                            Vec<2>::Zero(), 1000, 1000 * dx * dx);
                P.v_bc.back() = Vec<2>(-u, 0);
            }
        for (std::size_t i = 0; i < P.size(); ++i) {
            P.p[i] = 0;
            P.p_over_rho2[i] = 0;
            P.volume[i] = P.mass[i] / P.rho[i];
        }
        grid = CellGrid<2>::make(Vec<2>(0, -0.04), Vec<2>(n * dx, 0.04), kernel.support(),
                                 {true, false});
        rebin(grid, P, ranges, occ);
    }
    // x-acceleration of the fluid row next to the wall (mean over the row).
    double drag(const MomentumParams<2>& prm) {
        const Neighbourhood<2> nb{&grid, &ranges, std::span<const Vec<2>>(P.x), kernel.support()};
        for (const auto& c : occ)
            acceleration(nb, kernel, prm, c.cell, P, std::span<Vec<2>>(P.a));
        double sum = 0;
        int count = 0;
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid && P.x[i][1] < dx) {
                sum += P.a[i][0];
                ++count;
            }
        return sum / count;
    }
};

} // namespace

TEST_CASE("Artificial viscosity brakes flow along a no-slip wall only when asked") {
    SlidingLayer L;
    MomentumParams<2> prm;
    prm.alpha = 0.02;
    prm.c0 = 50;
    prm.h = 0.015;
    prm.wall_viscous = true; // no-slip, but mu = 0: no laminar term
    prm.wall_artificial = false;
    // The fluid moves as a rigid body and the wall takes no part in the artificial viscosity:
    // nothing acts along x at all.
    CHECK(L.drag(prm) == 0.0);
    // With the term on wall pairs, each wall particle ahead of a fluid particle "approaches" it
    // at 2u (the mirrored no-slip velocity), so the lowest row is braked although nothing
    // moves into the wall: here by more than gravity (measured: 21 m/s^2). Bound: |Pi_ij| r <=
    // alpha c0 h 2u / rho, so |a| <= alpha c0 h 2u sum_j V_j |F_ij| <= alpha c0 h 2u pi W(0)
    // over the half-plane of wall, with pi W(0) = 7/(4 h^2) for the 2-D Wendland C2 kernel.
    prm.wall_artificial = true;
    const double a = L.drag(prm);
    const double bound = prm.alpha * prm.c0 * prm.h * 2 * SlidingLayer::u * 7 / (4 * prm.h * prm.h);
    CHECK(a < -9.81);
    CHECK(a > -bound);
}
