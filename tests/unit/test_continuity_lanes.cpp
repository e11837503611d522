// The four-lane continuity rate (physics/continuity_lanes.hpp) against the scalar one
// (physics/density.hpp) on a jittered, disordered block of fluid over a dummy wall: the same
// terms, so the two agree to rounding (the lanes add the pairs in another order), with no
// density diffusion, Antuono's and Fourtakas's, and a periodic axis. Wall particles carry a
// velocity and a density gradient that the rate must ignore (a fixed wall, diffusion over fluid
// pairs only). And the lanes' sums depend only on the list: the same for any cell order.
#include "sluice/core/lanes.hpp"
#include "sluice/physics/continuity_lanes.hpp"

#include "lane_block.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <span>
#include <vector>

using namespace sluice;

#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)

namespace {

using test::dx;

// The shared block (lane_block.hpp) with this test's two ways of computing on it.
struct Block : test::LaneBlock {
    using LaneBlock::LaneBlock;
    std::vector<Real> scalar(const DensityDiffusionParams<2>& diff) const {
        Neighbourhood<2> nb = neighbourhood();
        nb.list = &list;
        std::vector<Real> drho(P.size(), 0);
        for (CellIndex c : cells)
            continuity_rate(nb, kernel, diff, c, P, std::span<const Vec<2>>(P.v_half),
                            std::span<Real>(drho));
        return drho;
    }
    // in_reverse: the cells in reverse order (as another grouping might visit them).
    std::vector<Real> lanes(const DensityDiffusionParams<2>& diff, bool in_reverse = false) const {
        Neighbourhood<2> nb = neighbourhood();
        nb.list = &list;
        std::vector<MomentumNeighbour<2>> records(P.size());
        for (std::uint32_t j = 0; j < P.size(); ++j)
            write_momentum_neighbour(P, Real(0), j, records[j]);
        std::vector<Real> drho(P.size(), 0);
        std::vector<CellIndex> order = cells;
        if (in_reverse)
            std::reverse(order.begin(), order.end());
        for (CellIndex c : order)
            continuity_rate_lanes(nb, diff, c, P, records.data(), std::span<const Vec<2>>(P.v_half),
                                  std::span<Real>(drho));
        return drho;
    }
};

void check_agreement(bool periodic, const DensityDiffusionParams<2>& diff) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        Block B(periodic, seed);
        REQUIRE(B.list.periodic == periodic);
        const std::vector<Real> s = B.scalar(diff), l = B.lanes(diff);
        double scale = 0, worst = 0;
        int fluid = 0;
        for (std::size_t i = 0; i < B.P.size(); ++i)
            if (B.P.kind[i] == Kind::fluid) {
                scale = std::max(scale, std::abs(s[i]));
                worst = std::max(worst, std::abs(l[i] - s[i]));
                ++fluid;
            }
        REQUIRE(fluid == 360);
        REQUIRE(scale > 1e4); // velocities of 1 m/s over 1 cm give rates of order 1e5 kg/m^3/s
        CAPTURE(seed);
        CHECK(worst <= 1e-12 * scale);
        // Bitwise the same whichever order the cells come in.
        const std::vector<Real> r = B.lanes(diff, true);
        for (std::size_t i = 0; i < B.P.size(); ++i)
            if (B.P.kind[i] == Kind::fluid)
                REQUIRE(r[i] == l[i]);
    }
}

} // namespace

TEST_CASE("Four-lane continuity rate equals the scalar one to rounding") {
    CHECK(continuity_uses_lanes<2>());
    CHECK_FALSE(continuity_uses_lanes<3>());
    const Vec<2> hydrostatic(0, -1000 * 9.81 / (40.0 * 40.0));
    for (bool periodic : {false, true}) {
        CAPTURE(periodic);
        check_agreement(periodic, {0, DensityDiffusion::antuono, Vec<2>::Zero()}); // none
        // delta h c0 large enough that the diffusion is a sizeable part of the rate
        check_agreement(
            periodic, {Real(0.1 * 1.5 * dx * 40 * 100), DensityDiffusion::antuono, Vec<2>::Zero()});
        check_agreement(
            periodic, {Real(0.1 * 1.5 * dx * 40 * 100), DensityDiffusion::fourtakas, hydrostatic});
    }
}

#else

TEST_CASE("This build has no four-lane continuity rate") {
    CHECK_FALSE(continuity_uses_lanes<2>());
}

#endif
