// The four-lane acceleration (physics/momentum_lanes.hpp) against the scalar one
// (physics/momentum.hpp) on a jittered, disordered block of fluid over a dummy wall: the same
// terms, so the two agree to rounding (the lanes add the pairs in another order), for every
// switch (laminar and artificial viscosity on or off, on wall pairs or not, a periodic axis).
// And the lanes' sums depend only on the list: the same for any cell order of the calls.
#include "sluice/core/lanes.hpp"
#include "sluice/physics/momentum_lanes.hpp"

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
    std::vector<Vec<2>> scalar(const MomentumParams<2>& prm) const {
        Neighbourhood<2> nb = neighbourhood();
        nb.list = &list;
        std::vector<Vec<2>> a(P.size(), Vec<2>::Zero());
        for (CellIndex c : cells)
            acceleration(nb, kernel, prm, c, P, std::span<Vec<2>>(a));
        return a;
    }
    // in_reverse: the cells in reverse order (as another grouping might visit them).
    std::vector<Vec<2>> lanes(const MomentumParams<2>& prm, bool in_reverse = false) const {
        Neighbourhood<2> nb = neighbourhood();
        nb.list = &list;
        std::vector<MomentumNeighbour<2>> records(P.size());
        for (std::uint32_t j = 0; j < P.size(); ++j)
            write_momentum_neighbour(P, prm.p_floor, j, records[j]);
        std::vector<Vec<2>> a(P.size(), Vec<2>::Zero());
        std::vector<CellIndex> order = cells;
        if (in_reverse)
            std::reverse(order.begin(), order.end());
        for (CellIndex c : order)
            acceleration_lanes(nb, prm, c, P, records.data(), std::span<Vec<2>>(a));
        return a;
    }
};

void check_agreement(bool periodic, const MomentumParams<2>& prm) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        Block B(periodic, seed);
        REQUIRE(B.list.periodic == periodic);
        const std::vector<Vec<2>> s = B.scalar(prm), l = B.lanes(prm);
        double scale = 0, worst = 0;
        int fluid = 0;
        for (std::size_t i = 0; i < B.P.size(); ++i)
            if (B.P.kind[i] == Kind::fluid) {
                scale = std::max(scale, (s[i] - prm.gravity).norm());
                ++fluid;
            }
        REQUIRE(fluid == 360);
        REQUIRE(scale > 100); // the pressures above give accelerations of hundreds of m/s^2
        for (std::size_t i = 0; i < B.P.size(); ++i)
            if (B.P.kind[i] == Kind::fluid)
                worst = std::max(worst, (l[i] - s[i]).norm());
        CAPTURE(seed);
        CHECK(worst <= 1e-12 * scale);
        // Bitwise the same whichever order the cells come in.
        const std::vector<Vec<2>> r = B.lanes(prm, true);
        for (std::size_t i = 0; i < B.P.size(); ++i)
            if (B.P.kind[i] == Kind::fluid)
                REQUIRE((r[i].array() == l[i].array()).all());
    }
}

MomentumParams<2> params(double alpha, bool wall_artificial) {
    MomentumParams<2> prm;
    prm.gravity = Vec<2>(0, -9.81);
    prm.alpha = alpha;
    prm.c0 = 40;
    prm.h = 1.5 * dx;
    prm.wall_artificial = wall_artificial;
    prm.p_floor = 0;
    return prm;
}

} // namespace

TEST_CASE("Four-lane acceleration equals the scalar one to rounding") {
    CHECK(acceleration_uses_lanes<2>());
    for (bool periodic : {false, true}) {
        CAPTURE(periodic);
        check_agreement(periodic, params(0.02, false)); // artificial viscosity, fluid pairs only
        check_agreement(periodic, params(0.02, true));  // and on wall pairs
        check_agreement(periodic, params(0.0, false));  // pressure only
    }
}

TEST_CASE("Four-lane acceleration with laminar viscosity equals the scalar one to rounding") {
    for (bool periodic : {false, true}) {
        CAPTURE(periodic);
        for (bool wall_viscous : {true, false}) {
            MomentumParams<2> prm = params(0.02, false);
            prm.mu = 0.05; // large, so that the laminar term is a sizeable part of the sum
            prm.wall_viscous = wall_viscous;
            check_agreement(periodic, prm);
            prm.alpha = 0; // laminar viscosity alone
            check_agreement(periodic, prm);
        }
    }
    CHECK_FALSE(acceleration_uses_lanes<3>());
}

#else

TEST_CASE("This build has no four-lane acceleration") {
    CHECK_FALSE(lanes_available);
    CHECK_FALSE(acceleration_uses_lanes<2>());
}

#endif
