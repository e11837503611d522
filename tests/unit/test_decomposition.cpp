// Cell groups: cost-balanced cuts along the Morton curve and group adjacency (periodic wrap).
#include "sluice/tasks/decomposition.hpp"

#include <doctest/doctest.h>

using namespace sluice;
using namespace sluice::tasks;

TEST_CASE("cut_by_cost gives groups of nearly equal cost") {
    std::vector<OccupiedCell> occ;
    for (std::uint32_t k = 0; k < 1000; ++k)
        occ.push_back({MortonKey(3 * k), k, double(1 + k % 5)});
    GroupTopology topo;
    topo.key_begin = cut_by_cost(occ, 10);
    REQUIRE(topo.group_count() == 10);
    assign_cells(occ, topo);
    double total = 0;
    for (const auto& c : occ)
        total += c.cost;
    for (int g = 0; g < 10; ++g) {
        double cost = 0;
        for (CellIndex c : topo.cells[g])
            cost += occ[c].cost;
        CHECK(cost == doctest::Approx(total / 10).epsilon(0.02));
    }
    CHECK(topo.group_of(0) == 0);
    CHECK(topo.group_of(topo.key_begin[3]) == 3);
    CHECK(topo.group_of(topo.key_begin[3] - 1) == 2);
}

TEST_CASE("target_group_count: the size target, or 8 groups per thread for small ranks") {
    using sluice::tasks::target_group_count;
    // The 232k strong-scaling case: the size target (2,000 particles) decides.
    CHECK(target_group_count(232128, 2000, 1) == 117);
    CHECK(target_group_count(232128, 2000, 2) == 117);
    // Tak's (2024) box (6,859 particles): 4 groups by size; 8 per thread on 2 threads; one thread
    // keeps the old floor of 4.
    CHECK(target_group_count(6859, 2000, 1) == 4);
    CHECK(target_group_count(6859, 2000, 2) == 16);
    CHECK(target_group_count(3430, 2000, 2) == 14); // a rank of it at 2 ranks x 2 threads
    // No group below 250 particles for the 8-per-thread floor, but never under 4 per thread.
    CHECK(target_group_count(1000, 2000, 2) == 8);
    CHECK(target_group_count(3000, 2000, 4) == 16);
    CHECK(target_group_count(100000, 2000, 16) == 128);
    CHECK(target_group_count(0, 2000, 1) == 4);
}

TEST_CASE("Group adjacency follows cell adjacency, including the periodic wrap") {
    // A 6x1-cell strip, periodic in x: cells 0 and 5 touch through the boundary.
    auto grid = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(6, 1), 1.0, {true, false});
    REQUIRE(grid.dims[0] == 6);
    std::vector<OccupiedCell> occ;
    for (int i = 0; i < 6; ++i)
        occ.push_back({grid.morton({i, 0}), grid.linear({i, 0}), 1.0});
    std::sort(occ.begin(), occ.end(), [](auto& a, auto& b) { return a.key < b.key; });
    GroupTopology topo;
    topo.key_begin = cut_by_cost(occ, 6);
    assign_cells(occ, topo);
    const auto adj = group_adjacency(grid, occ, topo);
    auto group_of_x = [&](int x) { return topo.group_of(grid.morton({x, 0})); };
    const int g0 = group_of_x(0), g5 = group_of_x(5), g2 = group_of_x(2);
    CHECK(std::binary_search(adj[g0].begin(), adj[g0].end(), g5));
    CHECK(adj[g2].size() == 2);
    // Without the wrap, the ends do not touch.
    auto open = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(6, 1), 1.0, {false, false});
    const auto adj_open = group_adjacency(open, occ, topo);
    CHECK(!std::binary_search(adj_open[g0].begin(), adj_open[g0].end(), g5));
    CHECK(adjacency_covers(adj, adj_open));
    CHECK(!adjacency_covers(adj_open, adj));
}

TEST_CASE("A periodic axis needs at least three cells") {
    CHECK_THROWS_AS(CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(2.5, 1), 1.0, {true, false}),
                    std::invalid_argument);
}
