// The task graph computes the same neighbour sums as a brute-force O(N^2) loop, on random
// particles in 2-D and 3-D with open and periodic axes, and the result is bitwise identical
// for any thread count. A two-stage graph checks that a stage reading its neighbours'
// previous-stage results only ever sees finished values.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/density.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/tasks/decomposition.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <random>

using namespace sluice;

namespace {

template <int D>
struct Fixture {
    Particles<D> P;
    CellGrid<D> grid;
    CellRanges ranges;
    std::vector<CellOccupancy> occupied;
    tasks::GroupTopology topo;
    QuinticKernel<D> kernel{0.05};
    // Stage 2 output: s_i = sum_j m_j rho_j W_ij (needs every neighbour's stage-1 rho).
    std::vector<Real> second;

    Fixture(std::size_t n, std::array<bool, D> periodic, int groups, unsigned seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (std::size_t i = 0; i < n; ++i) {
            Vec<D> x;
            for (int d = 0; d < D; ++d)
                x[d] = u(rng);
            // Ids deliberately not in position order.
            P.push_back(static_cast<ParticleId>((i * 7919) % n), Kind::fluid, x, Vec<D>::Zero(),
                        1000, 0.5 + u(rng));
        }
        grid = CellGrid<D>::make(Vec<D>::Zero(), Vec<D>::Ones(), kernel.support(), periodic);
        rebin(grid, P, ranges, occupied);
        std::vector<tasks::OccupiedCell> occ;
        for (const auto& c : occupied)
            occ.push_back({c.key, c.cell, double(c.count)});
        topo.key_begin = tasks::cut_by_cost(occ, groups);
        tasks::assign_cells(occ, topo);
        topo.neighbours = tasks::group_adjacency(grid, occ, topo);
        second.assign(P.size(), 0);
    }

    void run_graph() {
        const Neighbourhood<D> nb{&grid, &ranges, std::span<const Vec<D>>(P.x), kernel.support()};
        std::fill(P.rho.begin(), P.rho.end(), -1.0); // poison: a premature read shows up
        tasks::StepGraph graph(
            {{"density", tasks::Reach::neighbourhood}, {"second", tasks::Reach::neighbourhood}},
            topo.neighbours, [&](int stage, int g) {
                for (CellIndex c : topo.cells[static_cast<std::size_t>(g)]) {
                    if (stage == 0) {
                        summation_density(nb, kernel, c, P, std::span<Real>(P.rho));
                        continue;
                    }
                    const auto adj = nb.adjacent(c);
                    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
                        Real s = 0;
                        nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>&, Real r2) {
                            s += P.mass[j] * P.rho[j] * kernel.W(std::sqrt(r2));
                        });
                        second[i] = s;
                    }
                }
            });
        graph.run();
    }

    void check_against_brute_force() const {
        const std::size_t n = P.size();
        std::vector<Real> rho(n, 0), s(n, 0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                rho[i] += P.mass[j] * kernel.W(grid.displacement(P.x[i], P.x[j]).norm());
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j)
                s[i] += P.mass[j] * rho[j] * kernel.W(grid.displacement(P.x[i], P.x[j]).norm());
        for (std::size_t i = 0; i < n; ++i) {
            REQUIRE(P.rho[i] == doctest::Approx(rho[i]).epsilon(1e-12));
            REQUIRE(second[i] == doctest::Approx(s[i]).epsilon(1e-12));
        }
    }
};

template <int D>
void check_case(std::size_t n, std::array<bool, D> periodic) {
    Fixture<D> f(n, periodic, 23, 42);
    REQUIRE(f.topo.group_count() == 23);
    std::vector<Real> rho1, s1;
    {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        f.run_graph();
        rho1 = f.P.rho;
        s1 = f.second;
    }
    f.check_against_brute_force();
    {
        tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
        for (int rep = 0; rep < 5; ++rep) {
            f.run_graph();
            CHECK(f.P.rho == rho1); // bitwise
            CHECK(f.second == s1);
        }
    }
}

} // namespace

TEST_CASE("2-D random particles, open box: graph sums equal brute force") {
    check_case<2>(3000, {false, false});
}
TEST_CASE("2-D random particles, periodic in x and y") {
    check_case<2>(3000, {true, true});
}
TEST_CASE("3-D random particles, open box") {
    check_case<3>(4000, {false, false, false});
}
TEST_CASE("3-D random particles, periodic in x and z") {
    check_case<3>(4000, {true, false, true});
}

TEST_CASE("Rebin sorts by (Morton key, id) and cell ranges cover every particle once") {
    Fixture<2> f(2000, {false, true}, 8, 7);
    std::size_t covered = 0;
    for (const auto& c : f.occupied) {
        covered += c.count;
        for (auto i = f.ranges.begin(c.cell) + 1; i < f.ranges.end(c.cell); ++i)
            CHECK(f.P.id[i - 1] < f.P.id[i]);
    }
    CHECK(covered == f.P.size());
    for (std::size_t k = 1; k < f.occupied.size(); ++k)
        CHECK(f.occupied[k - 1].key < f.occupied[k].key);
}

TEST_CASE("The graph's recorded predecessors are its edges, each ended before its dependent") {
    // Groups in a row, 0 - 1 - 2 - 3; stages: first, a neighbourhood stage, a self stage.
    const std::vector<std::vector<int>> adjacent{{1}, {0, 2}, {1, 3}, {2}};
    tasks::StepGraph graph({{"first", tasks::Reach::neighbourhood},
                            {"neighbourhood", tasks::Reach::neighbourhood},
                            {"self", tasks::Reach::self}},
                           adjacent, [](int, int) {
                               // Long enough for the clock to tell a task's start from its end.
                               const double t0 = tasks::clock_seconds();
                               while (tasks::clock_seconds() - t0 < 20e-6) {
                               }
                           });
    graph.run();
    const auto& preds = graph.task_predecessors();
    const auto& rec = graph.task_records();
    REQUIRE(preds.size() == rec.size());
    REQUIRE(rec.size() == 12);
    auto sorted = [](std::vector<int> v) {
        std::sort(v.begin(), v.end());
        return v;
    };
    for (int g = 0; g < 4; ++g) {
        CHECK(preds[static_cast<std::size_t>(g)].empty()); // the first stage waits for the start
        std::vector<int> around{g};
        for (int nb : adjacent[static_cast<std::size_t>(g)])
            around.push_back(nb);
        CHECK(sorted(preds[static_cast<std::size_t>(4 + g)]) == sorted(around));
        CHECK(preds[static_cast<std::size_t>(8 + g)] == std::vector<int>{4 + g});
    }
    for (std::size_t slot = 0; slot < rec.size(); ++slot)
        for (int q : preds[slot])
            CHECK(rec[static_cast<std::size_t>(q)].end <= rec[slot].start);
}
