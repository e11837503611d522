// Rank decomposition along the Morton curve: cut points, peers, halo cells (periodic wrap
// included), imbalance, and the interval arithmetic behind the overlap figures.
#include "sluice/tasks/profile.hpp"
#include "sluice/tasks/rank_layout.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <set>

using namespace sluice;
using namespace sluice::tasks;

namespace {

// Occupied cells: every cell of the grid, in key order.
template <int D>
std::vector<CellIndex> all_cells_by_key(const CellGrid<D>& g) {
    std::vector<CellIndex> c(g.cell_count());
    for (CellIndex i = 0; i < c.size(); ++i)
        c[i] = i;
    std::sort(c.begin(), c.end(), [&](CellIndex a, CellIndex b) {
        return g.morton(g.unlinear(a)) < g.morton(g.unlinear(b));
    });
    return c;
}

} // namespace

TEST_CASE("cut_ranks gives contiguous runs of nearly equal cost") {
    std::vector<CurveUnit> units;
    for (int k = 0; k < 100; ++k)
        units.push_back({static_cast<MortonKey>(10 * k), 1.0});
    const RankLayout l = cut_ranks(units, 4);
    REQUIRE(l.ranks() == 4);
    CHECK(l.key_begin == std::vector<MortonKey>{0, 250, 500, 750});
    std::vector<double> cost(4, 0.0);
    for (const auto& u : units)
        cost[static_cast<std::size_t>(l.rank_of(u.key))] += u.cost;
    CHECK(imbalance(cost) == doctest::Approx(1.0));

    // A heavy unit cannot be split: the cut lands on the side closer to the ideal point
    // (costs 12 | 4 rather than 2 | 14).
    std::vector<CurveUnit> skew{{0, 1}, {5, 1}, {9, 10}, {12, 1}, {20, 3}};
    const RankLayout s = cut_ranks(skew, 2);
    CHECK(s.key_begin == std::vector<MortonKey>{0, 12});

    // More ranks than units: the extra ranks own empty ranges, cut points stay increasing.
    const RankLayout e = cut_ranks({{3, 1.0}}, 3);
    REQUIRE(e.ranks() == 3);
    CHECK(std::is_sorted(e.key_begin.begin(), e.key_begin.end()));
    CHECK(e.rank_of(3) == 0);
}

TEST_CASE("imbalance is max over mean") {
    CHECK(imbalance({1, 1, 1}) == doctest::Approx(1.0));
    CHECK(imbalance({3, 1}) == doctest::Approx(1.5));
    CHECK(imbalance({0, 0}) == 1.0);
}

TEST_CASE("peers and halo cells on an open 2-D grid") {
    // 8 x 8 cells of edge 1; two ranks split the key space in half: with Morton order the
    // halves are the lower and upper 8 x 4 blocks (y is the slower axis at the top bit).
    const auto g = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(8, 8), 1.0, {false, false});
    REQUIRE(g.dims[0] == 8);
    const RankLayout l = cut_ranks_by_key(g, 2);
    CHECK(l.rank_of(g.morton({7, 3})) == 0);
    CHECK(l.rank_of(g.morton({0, 4})) == 1);
    const auto peers = peer_ranks(g, l);
    CHECK(peers[0] == std::vector<int>{1});
    CHECK(peers[1] == std::vector<int>{0});

    // Rank 0's halo cells for rank 1 are exactly its top row (y = 3).
    std::vector<CellIndex> mine;
    for (CellIndex c : all_cells_by_key(g))
        if (l.rank_of(g.morton(g.unlinear(c))) == 0)
            mine.push_back(c);
    const auto targets = halo_targets(g, l, 0, peers[0], mine);
    for (std::size_t k = 0; k < mine.size(); ++k) {
        const auto xy = g.unlinear(mine[k]);
        CHECK(targets[k] == (xy[1] == 3 ? std::vector<int>{0} : std::vector<int>{}));
    }
}

TEST_CASE("periodic wrap makes the first and last rank neighbours") {
    // 9 cells along x, periodic; 3 ranks as three vertical slabs of the 1-row grid.
    const auto g = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(9, 1), 1.0, {true, false});
    REQUIRE(g.dims[0] == 9);
    REQUIRE(g.dims[1] == 1);
    // Keys along a single row are increasing in x; cut at x = 3 and x = 6.
    RankLayout l;
    l.key_begin = {0, g.morton({3, 0}), g.morton({6, 0})};
    const auto peers = peer_ranks(g, l);
    CHECK(peers[0] == std::vector<int>{1, 2});
    CHECK(peers[2] == std::vector<int>{0, 1});
    // Rank 0 owns x = 0,1,2: x = 0 is a halo cell of rank 2 (through the seam), x = 2 of rank 1.
    std::vector<CellIndex> mine{g.linear({0, 0}), g.linear({1, 0}), g.linear({2, 0})};
    const auto t = halo_targets(g, l, 0, peers[0], mine);
    CHECK(t[0] == std::vector<int>{1}); // peer index 1 = rank 2
    CHECK(t[1].empty());
    CHECK(t[2] == std::vector<int>{0}); // peer index 0 = rank 1
}

TEST_CASE("ranks two peer steps away and the owners around a cell") {
    // 12 cells along x in one row, four slabs of 3 cells: 0 | 1 | 2 | 3, open ends. Rank 0's
    // peers are {1}; within two steps it also reaches rank 2, not rank 3.
    const auto g = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(12, 1), 1.0, {false, false});
    REQUIRE(g.dims[0] == 12);
    RankLayout l;
    l.key_begin = {0, g.morton({3, 0}), g.morton({6, 0}), g.morton({9, 0})};
    const auto peers = peer_ranks(g, l);
    CHECK(two_step_ranks(peers, 0) == std::vector<int>{1, 2});
    CHECK(two_step_ranks(peers, 1) == std::vector<int>{0, 2, 3});
    CHECK(two_step_ranks(peers, 3) == std::vector<int>{1, 2});
    std::vector<int> owners;
    // x = 3 is rank 1's first cell: it touches rank 0 (x = 2) only.
    adjacent_owners(g, l, g.linear({3, 0}), 1, owners);
    CHECK(owners == std::vector<int>{0});
    // Were x = 5 owned by rank 0 (a migrant's view from outside), it would be a halo cell of
    // ranks 1 and 2.
    adjacent_owners(g, l, g.linear({5, 0}), 0, owners);
    CHECK(owners == std::vector<int>{1, 2});
    adjacent_owners(g, l, g.linear({1, 0}), 0, owners);
    CHECK(owners.empty());
}

TEST_CASE("peer sets are symmetric in 3-D") {
    const auto g = CellGrid<3>::make(Vec<3>(0, 0, 0), Vec<3>(6, 5, 4), 1.0, {true, false, false});
    for (int ranks : {2, 3, 5, 7}) {
        const RankLayout l = cut_ranks_by_key(g, ranks);
        const auto peers = peer_ranks(g, l);
        for (int r = 0; r < ranks; ++r)
            for (int s : peers[static_cast<std::size_t>(r)]) {
                const auto& back = peers[static_cast<std::size_t>(s)];
                CHECK(std::find(back.begin(), back.end(), r) != back.end());
                CHECK(s != r);
            }
    }
}

namespace {

// The peers as a scan of the whole grid finds them (the O(grid) form peers_of replaced).
template <int D>
std::vector<std::vector<int>> peers_by_grid_scan(const CellGrid<D>& g, const RankLayout& l) {
    std::vector<std::set<int>> sets(static_cast<std::size_t>(l.ranks()));
    NeighbourCell<D> nbr[D == 2 ? 9 : 27];
    for (CellIndex c = 0; c < g.cell_count(); ++c) {
        const int own = l.rank_of(g.morton(g.unlinear(c)));
        const int k = adjacent_cells(g, c, nbr);
        for (int m = 0; m < k; ++m) {
            const int o = l.rank_of(g.morton(g.unlinear(nbr[m].cell)));
            if (o != own)
                sets[static_cast<std::size_t>(own)].insert(o);
        }
    }
    std::vector<std::vector<int>> out;
    for (const auto& s : sets)
        out.emplace_back(s.begin(), s.end());
    return out;
}

// Random cut points (sorted, distinct, some past the grid's last key) on a grid whose
// dimensions are not powers of two: a range's ends cut the Morton tree's blocks anywhere.
template <int D>
void check_range_walk(const CellGrid<D>& g, unsigned seed) {
    MortonKey top = 0;
    for (CellIndex c = 0; c < g.cell_count(); ++c)
        top = std::max(top, g.morton(g.unlinear(c)));
    std::uint64_t state = seed;
    const auto next = [&] { // xorshift: reproducible, no <random> distribution differences
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    };
    for (int trial = 0; trial < 20; ++trial) {
        const int ranks = 2 + static_cast<int>(next() % 7);
        std::set<MortonKey> cuts;
        while (static_cast<int>(cuts.size()) < ranks - 1)
            cuts.insert(1 + next() % (top + 3));
        RankLayout l;
        l.key_begin.assign(1, 0);
        l.key_begin.insert(l.key_begin.end(), cuts.begin(), cuts.end());
        // Every cell visited once, by the rank whose range holds its key.
        std::vector<int> seen(g.cell_count(), 0);
        for (int r = 0; r < ranks; ++r)
            for_each_cell_in_keys(g, range_begin(l, r), range_end(l, r), [&](CellIndex c) {
                CHECK(l.rank_of(g.morton(g.unlinear(c))) == r);
                ++seen[c];
            });
        CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
        // The same peers as the scan of the whole grid; two steps from the lists of the rank
        // and its peers only.
        const auto expected = peers_by_grid_scan(g, l);
        CHECK(peer_ranks(g, l) == expected);
        for (int r = 0; r < ranks; ++r) {
            std::vector<std::vector<int>> known(static_cast<std::size_t>(ranks));
            known[static_cast<std::size_t>(r)] = peers_of(g, l, r);
            for (const int p : known[static_cast<std::size_t>(r)])
                known[static_cast<std::size_t>(p)] = peers_of(g, l, p);
            CHECK(two_step_ranks(known, r) == two_step_ranks(expected, r));
        }
    }
}

} // namespace

TEST_CASE("peers from each rank's own cells agree with a scan of the whole grid") {
    // peers_of walks the rank's key range through the Morton tree, not the grid.
    check_range_walk(CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(13, 7), 1.0, {false, false}), 1);
    check_range_walk(CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(29, 3), 1.0, {true, false}), 2);
    check_range_walk(CellGrid<3>::make(Vec<3>(0, 0, 0), Vec<3>(7, 5, 9), 1.0, {false, true, false}),
                     3);
    check_range_walk(CellGrid<3>::make(Vec<3>(0, 0, 0), Vec<3>(11, 3, 4), 1.0, {true, true, true}),
                     4);
    // A range inside one cell's key, an empty range, and one past the grid.
    const auto g = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(5, 5), 1.0, {false, false});
    int visits = 0;
    for_each_cell_in_keys(g, 3, 4, [&](CellIndex c) {
        CHECK(g.morton(g.unlinear(c)) == 3);
        ++visits;
    });
    CHECK(visits == 1);
    for_each_cell_in_keys(g, 7, 7, [&](CellIndex) { ++visits; });
    for_each_cell_in_keys(g, 1000, 2000, [&](CellIndex) { ++visits; });
    CHECK(visits == 1);
}

TEST_CASE("interval arithmetic of the overlap figures") {
    std::vector<Interval> msgs{{0, 4}, {2, 6}, {10, 12}};
    CHECK(union_length(msgs) == doctest::Approx(8.0));
    // Tasks cover [1, 3] and [5, 11]: uncovered message time is [0,1] + [3,5] + [11,12] = 4.
    CHECK(uncovered_length({{0, 4}, {2, 6}, {10, 12}}, {{1, 3}, {5, 11}}) == doctest::Approx(4.0));
    CHECK(uncovered_length({{0, 1}}, {}) == doctest::Approx(1.0));
    CHECK(uncovered_length({{0, 1}}, {{-1, 2}}) == doctest::Approx(0.0));
}
