// The rebin of one rank at a Verlet-list rebuild (Rebinner: sort by cell key, fill the cell
// ranges), as the rank count grows: does its cost shrink with the rank's share of the
// particles, or stay tied to the size of the grid?
//
// A 3-D block of 1.0 x 2.0 x 0.5 m at dx = 0.01 m (10^6 particles) in a tank of L x 2 x 2 m,
// cut into R runs of the space-filling curve as the balancer cuts it; the middle rank's run is
// rebinned after each of 5 random moves of up to 0.1 dx (some particles change cell, so the
// counting sort runs) and the best time is printed, for R = 1, 4, 16, 64.
//
// Usage: bench_rebin [CELL_EDGE [TANK_LENGTH]]   (defaults 0.04 m and 4 m: 250,000 cells;
//        0.015 and 10 give 11.8 million cells, a fine grid around a small block)
#include "sluice/core/rebin.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <random>
#include <utility>
#include <vector>

using namespace sluice;

namespace {

double best_rebin_ms(const CellGrid<3>& grid, Particles<3> P, std::mt19937& rng, Real dx) {
    std::uniform_real_distribution<Real> jitter(Real(-0.1), Real(0.1));
    Rebinner<3> rebinner;
    CellRanges ranges;
    std::vector<CellOccupancy> occupied;
    rebinner(grid, P, ranges, occupied);
    double best = 1e30;
    for (int round = 0; round < 5; ++round) {
        for (auto& x : P.x)
            x += Vec<3>(jitter(rng), jitter(rng), jitter(rng)) * dx;
        const auto t0 = std::chrono::steady_clock::now();
        rebinner(grid, P, ranges, occupied);
        best = std::min(
            best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                      .count());
    }
    return best;
}

} // namespace

int main(int argc, char** argv) {
    const Real edge = argc > 1 ? Real(std::atof(argv[1])) : Real(0.04);
    const Real length = argc > 2 ? Real(std::atof(argv[2])) : Real(4);
    const Real dx = Real(0.01);
    const auto grid = CellGrid<3>::make(Vec<3>::Zero(), Vec<3>(length, 2, 2), edge, {});
    std::vector<std::pair<MortonKey, Vec<3>>> block;
    for (int i = 0; i < 100; ++i)
        for (int j = 0; j < 200; ++j)
            for (int k = 0; k < 50; ++k) {
                const Vec<3> x((i + Real(0.5)) * dx, (j + Real(0.5)) * dx, (k + Real(0.5)) * dx);
                block.emplace_back(grid.morton(grid.coords(x)), x);
            }
    std::stable_sort(block.begin(), block.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    fmt::print("grid {} cells (edge {} m, tank {} x 2 x 2 m), block {} particles\n",
               grid.cell_count(), edge, length, block.size());
    fmt::print("{:>6} {:>12} {:>16}\n", "ranks", "particles", "best rebin [ms]");
    std::mt19937 rng(1);
    for (const int ranks : {1, 4, 16, 64}) {
        const std::size_t share = block.size() / static_cast<std::size_t>(ranks);
        const std::size_t first = share * static_cast<std::size_t>(ranks / 2);
        Particles<3> P;
        for (std::size_t q = first; q < first + share; ++q)
            P.push_back(static_cast<ParticleId>(q), Kind::fluid, block[q].second, Vec<3>::Zero(),
                        1000, 1);
        fmt::print("{:>6} {:>12} {:>16.3f}\n", ranks, share, best_rebin_ms(grid, P, rng, dx));
    }
}
