// The neighbour census (core/neighbour_census.hpp) on hand-built sets: pair counts by kind, and
// the fluid's spacing (crowded particles, the closest fluid pair, particles alone), with
// counts that add up over any partition of the cells, and each fluid particle's nearest fluid
// neighbour.
#include "sluice/core/neighbour_census.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace sluice;

namespace {

constexpr Real kDx = 0.01, kSupport = 0.03, kRho = 1000;

CellGrid<2> grid() {
    return CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(0.5, 0.5), kSupport, {false, false});
}

// A 10 x 10 fluid lattice of spacing dx at (0.1, 0.1) on a row of wall particles below it.
Particles<2> lattice() {
    Particles<2> P;
    ParticleId id = 0;
    for (int i = 0; i < 10; ++i)
        P.push_back(id++, Kind::wall, Vec<2>(0.1 + i * kDx, 0.1 - kDx), Vec<2>::Zero(), kRho,
                    kRho * kDx * kDx);
    for (int j = 0; j < 10; ++j)
        for (int i = 0; i < 10; ++i)
            P.push_back(id++, Kind::fluid, Vec<2>(0.1 + i * kDx, 0.1 + j * kDx), Vec<2>::Zero(),
                        kRho, kRho * kDx * kDx);
    return P;
}

} // namespace

TEST_CASE("a regular lattice has no crowded and no lone fluid particle") {
    const Particles<2> P = lattice();
    const NeighbourCensus n = count_neighbours<2>(grid(), P, kSupport, kDx / 2);
    CHECK(n.fluid == 100);
    CHECK(n.wall == 10);
    CHECK(n.fluid_crowded == 0);
    CHECK(n.fluid_isolated == 0);
    CHECK(n.closest_fluid_pair == doctest::Approx(kDx).epsilon(1e-12));
    // The wall particles are closer to nothing than dx, but they are not fluid: a wall
    // particle does not make a fluid particle crowded.
    CHECK(n.fluid_wall > 0);
}

TEST_CASE("two fluid particles closer than dx/2 are both crowded; a droplet is alone") {
    Particles<2> P = lattice();
    // Particle (3, 4) of the lattice moves to 0.3 dx from (4, 4) (and 0.7 dx from (3, 4)'s
    // site: only its new neighbour is closer than dx/2).
    const std::size_t moved = 10 + 4 * 10 + 3;
    P.x[moved] = Vec<2>(0.1 + 4 * kDx - 0.3 * kDx, 0.1 + 4 * kDx);
    // A droplet 10 cm away from everything.
    P.push_back(1000, Kind::fluid, Vec<2>(0.4, 0.4), Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    const NeighbourCensus n = count_neighbours<2>(grid(), P, kSupport, kDx / 2);
    CHECK(n.fluid == 101);
    CHECK(n.fluid_crowded == 2);
    CHECK(n.fluid_isolated == 1);
    CHECK(n.closest_fluid_pair == doctest::Approx(0.3 * kDx).epsilon(1e-9));
    // With a threshold below their distance nobody is crowded; the closest pair stays.
    const NeighbourCensus loose = count_neighbours<2>(grid(), P, kSupport, 0.25 * kDx);
    CHECK(loose.fluid_crowded == 0);
    CHECK(loose.closest_fluid_pair == n.closest_fluid_pair);
}

TEST_CASE("the spacing counts add up over a partition of the cells") {
    Particles<2> P = lattice();
    P.x[10 + 55] += Vec<2>(0.45 * kDx, 0.2 * kDx); // 0.58 dx from (6, 5): not crowded
    P.x[10 + 22] += Vec<2>(0.6 * kDx, 0);          // and (2, 2) onto (3, 2)
    const CellGrid<2> g = grid();
    const auto whole =
        count_neighbours<2>(g, std::span<const Vec<2>>(P.x), std::span<const Kind>(P.kind),
                            kSupport, kDx / 2, [](MortonKey) { return true; });
    const auto part = [&](bool even) {
        return count_neighbours<2>(g, std::span<const Vec<2>>(P.x), std::span<const Kind>(P.kind),
                                   kSupport, kDx / 2,
                                   [even](MortonKey k) { return (k % 2 == 0) == even; });
    };
    const NeighbourCensus a = part(true), b = part(false);
    CHECK(whole.fluid_crowded == 2); // (2, 2) and (3, 2) at 0.4 dx; (5, 5) is 0.58 dx off (6, 5)
    CHECK(a.fluid_crowded + b.fluid_crowded == whole.fluid_crowded);
    CHECK(a.fluid_isolated + b.fluid_isolated == whole.fluid_isolated);
    CHECK(a.fluid_fluid + b.fluid_fluid == whole.fluid_fluid);
    CHECK(std::min(a.closest_fluid_pair, b.closest_fluid_pair) == whole.closest_fluid_pair);
    CHECK(whole.closest_fluid_pair == doctest::Approx(0.4 * kDx).epsilon(1e-9));
}

TEST_CASE("no fluid at all: nothing crowded, no closest pair") {
    Particles<2> P;
    P.push_back(0, Kind::wall, Vec<2>(0.1, 0.1), Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    P.push_back(1, Kind::fluid, Vec<2>(0.3, 0.3), Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    const NeighbourCensus n = count_neighbours<2>(grid(), P, kSupport, kDx / 2);
    CHECK(n.fluid_isolated == 1);
    CHECK(n.fluid_crowded == 0);
    CHECK(n.closest_fluid_pair == std::numeric_limits<Real>::infinity());
}

TEST_CASE("each fluid particle's nearest fluid neighbour, in the order given") {
    Particles<2> P = lattice();
    const std::size_t moved = 10 + 4 * 10 + 3; // to 0.3 dx from (4, 4), as above
    P.x[moved] = Vec<2>(0.1 + 4 * kDx - 0.3 * kDx, 0.1 + 4 * kDx);
    P.push_back(1000, Kind::fluid, Vec<2>(0.4, 0.4), Vec<2>::Zero(), kRho, kRho * kDx * kDx);
    const CellGrid<2> g = grid();
    const Real untouched = -1;
    std::vector<Real> nearest(P.size(), untouched);
    count_neighbours<2>(
        g, std::span<const Vec<2>>(P.x), std::span<const Kind>(P.kind), kSupport, kDx / 2,
        [](MortonKey) { return true; }, std::span<Real>(nearest));
    for (std::size_t i = 0; i < 10; ++i) // walls: not fluid, left alone
        CHECK(nearest[i] == untouched);
    CHECK(nearest[moved] == doctest::Approx(0.3 * kDx).epsilon(1e-9));
    CHECK(nearest[moved + 1] == doctest::Approx(0.3 * kDx).epsilon(1e-9)); // (4, 4)
    CHECK(nearest[10] == doctest::Approx(kDx).epsilon(1e-12));             // the corner (0, 0)
    // (2, 4): its right neighbour moved 0.7 dx away (to 1.7 dx); (2, 3) and (2, 5) stay at dx.
    CHECK(nearest[moved - 1] == doctest::Approx(kDx).epsilon(1e-12));
    CHECK(nearest.back() == std::numeric_limits<Real>::infinity()); // the droplet
    // Over a partition of the cells each part sets the entries of the particles it counts,
    // to the same values.
    std::vector<Real> parts(P.size(), untouched);
    for (const bool even : {true, false})
        count_neighbours<2>(
            g, std::span<const Vec<2>>(P.x), std::span<const Kind>(P.kind), kSupport, kDx / 2,
            [even](MortonKey k) { return (k % 2 == 0) == even; }, std::span<Real>(parts));
    CHECK(parts == nearest);
    // The output must have an entry per particle.
    std::vector<Real> short_out(3);
    CHECK_THROWS_AS(count_neighbours<2>(
                        g, std::span<const Vec<2>>(P.x), std::span<const Kind>(P.kind), kSupport,
                        kDx / 2, [](MortonKey) { return true; }, std::span<Real>(short_out)),
                    std::invalid_argument);
}
