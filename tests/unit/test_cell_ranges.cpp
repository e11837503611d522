// The cell storage: a rank stores the particle ranges of the cells it holds particles in, not
// of the whole grid, and cell indices are 64-bit (grids beyond 2^32 cells).
#include "sluice/core/cell_ranges.hpp"
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"

#include <doctest/doctest.h>

#include <random>
#include <thread>

namespace sluice {
namespace {

TEST_CASE("cells never set read as empty, a set cell reads its range, a reset clears it") {
    CellRanges r;
    CHECK(r.range(12345).end == 0); // before any reset
    r.reset(3);
    const CellIndex far = (CellIndex{1} << 40) + 7; // beyond 32 bits
    r.set(far, 10, 20);
    r.set(5, 0, 10);
    r.set(far, 11, 21); // replaces
    CHECK(r.begin(far) == 11);
    CHECK(r.end(far) == 21);
    CHECK(r.end(5) == 10);
    CHECK(r.end(far - (CellIndex{1} << 32)) == 0); // same low 32 bits, another cell
    CHECK(r.end(6) == 0);
    CHECK(r.stored() == 2);
    r.reset(3);
    CHECK(r.end(far) == 0);
    CHECK(r.stored() == 0);
}

TEST_CASE("the table holds twice the cells in a power of two of slots, 16 bytes each") {
    CHECK(CellRanges::kBytesPerSlot == 16);
    CHECK(CellRanges::bytes_for(0) == 16 * 16);
    CHECK(CellRanges::bytes_for(1000) == 2048 * 16);
    CHECK(CellRanges::bytes_for(1024) == 2048 * 16);
    CHECK(CellRanges::bytes_for(1025) == 4096 * 16);
    CellRanges r;
    r.reset(1000);
    CHECK(r.bytes() == CellRanges::bytes_for(1000));
}

TEST_CASE("reserve keeps the stored ranges; concurrent sets of distinct cells all land") {
    CellRanges r;
    r.reset(10);
    for (CellIndex c = 0; c < 10; ++c)
        r.set(c * 1000003, static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(c + 1));
    constexpr int threads = 4, each = 5000;
    r.reserve(threads * each);
    CHECK(r.slots() >= 2 * (10 + threads * each));
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&r, t] {
            for (int k = 0; k < each; ++k) {
                const auto c = static_cast<CellIndex>(t * each + k) * 7 + 3;
                r.set(c, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k + t + 1));
            }
        });
    for (auto& th : pool)
        th.join();
    CHECK(r.stored() == 10 + threads * each);
    for (CellIndex c = 0; c < 10; ++c)
        CHECK(r.end(c * 1000003) == c + 1);
    int wrong = 0;
    for (int t = 0; t < threads; ++t)
        for (int k = 0; k < each; ++k) {
            const auto c = static_cast<CellIndex>(t * each + k) * 7 + 3;
            wrong += r.begin(c) == static_cast<std::uint32_t>(k) &&
                             r.end(c) == static_cast<std::uint32_t>(k + t + 1)
                         ? 0
                         : 1;
        }
    CHECK(wrong == 0);
}

// A 3-D grid of 3000^3 = 2.7e10 cells (beyond 2^32) with 3,000 particles in a corner whose
// cell indices exceed 2^32: the rebin stores only the occupied cells, and every particle's
// neighbours found through the ranges are exactly the brute-force ones.
TEST_CASE("a rebin on a grid beyond 2^32 cells stores the occupied cells only") {
    const Real edge = Real(1) / 3000;
    const auto grid = CellGrid<3>::make(Vec<3>::Zero(), Vec<3>::Ones(), edge, {});
    REQUIRE(grid.cell_count() > (std::size_t{1} << 32));
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> corner(Real(0.99), Real(0.99) + 12 * edge);
    Particles<3> P;
    for (int k = 0; k < 3000; ++k)
        P.push_back(static_cast<ParticleId>(k), Kind::fluid,
                    Vec<3>(corner(rng), corner(rng), corner(rng)), Vec<3>::Zero(), 1000, 1);
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    rebin(grid, P, ranges, occ);
    CHECK(ranges.stored() == occ.size());
    CHECK(occ.size() <= 13 * 13 * 13);
    CHECK(ranges.bytes() <= CellRanges::bytes_for(occ.size()));
    CHECK(occ.front().cell > (CellIndex{1} << 32));
    std::size_t covered = 0;
    for (std::size_t k = 0; k < occ.size(); ++k) {
        if (k > 0)
            CHECK(occ[k - 1].key < occ[k].key);
        CHECK(ranges.end(occ[k].cell) - ranges.begin(occ[k].cell) == occ[k].count);
        for (std::uint32_t i = ranges.begin(occ[k].cell); i < ranges.end(occ[k].cell); ++i)
            CHECK(grid.linear(grid.coords(P.x[i])) == occ[k].cell);
        covered += occ[k].count;
    }
    CHECK(covered == P.size());
    const Real support = edge;
    const Neighbourhood<3> nb{&grid, &ranges, std::span<const Vec<3>>(P.x), support};
    std::size_t found = 0, brute = 0;
    for (const auto& c : occ) {
        const AdjacentCells<3> adj = nb.adjacent(c.cell);
        for (std::uint32_t i = nb.begin(c.cell), stop = nb.end(c.cell); i < stop; ++i)
            nb.for_each_neighbour(adj, i, [&](std::uint32_t, const Vec<3>&, Real) { ++found; });
    }
    for (std::size_t i = 0; i < P.size(); ++i)
        for (std::size_t j = 0; j < P.size(); ++j)
            brute += (P.x[i] - P.x[j]).squaredNorm() < support * support ? 1 : 0;
    CHECK(found == brute);
    CHECK(found > 2 * P.size()); // the test has pairs beyond i == j
}

} // namespace
} // namespace sluice
