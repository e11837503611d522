// Cost of convex-hull neighbour selection per particle against the plain radius search
// (perf/convex_hull/README.md, "Cost per particle"). A jittered lattice (20 % random
// displacement of dx) is binned with the solver's own cell grid; per particle we time
//   search  : the radius search over the adjacent cells (Neighbourhood::for_each_neighbour),
//             gathering the offsets within the candidate radius 3.1 dx;
//   radius  : select_neighbours_into with the radius policy on those offsets (support 3.1 dx);
//   hull    : select_neighbours_into with the convex-hull policy (vertices + boundary points):
//             inverse-square map + Lee & Lee's quadrant hull (2-D) or the exact quickhull (3-D),
//             one scratch reused particle after particle as the solver does;
//   andrew  : (2-D) the same images through Andrew's monotone chain, for comparison.
// Each figure is the best of 5 repetitions in processor time (the machine is shared). Usage:
//   bench_hull_selection [particles per axis in 2-D = 100] [per axis in 3-D = 20]
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/convex_hull_2d.hpp"
#include "sluice/physics/mapped_hull.hpp"
#include "sluice/physics/neighbour_selection.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <random>

using namespace sluice;

namespace {

// Processor time of this (single-threaded) process: other programs on a shared machine
// do not count, though they still compete for caches.
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double seconds_best_of_5(const std::function<void()>& f) {
    double best = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
        const double t0 = cpu_seconds();
        f();
        best = std::min(best, cpu_seconds() - t0);
    }
    return best;
}

template <int D>
void run(int per_axis) {
    const Real dx = 0.01;
    const Real rc = 3.1 * dx;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> jitter(-0.2 * dx, 0.2 * dx);
    Particles<D> P;
    std::size_t n = 1;
    for (int d = 0; d < D; ++d)
        n *= static_cast<std::size_t>(per_axis);
    P.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t r = k;
        for (int d = 0; d < D; ++d) {
            P.x[k][d] = (static_cast<Real>(r % static_cast<std::size_t>(per_axis)) + 0.5) * dx +
                        jitter(rng);
            r /= static_cast<std::size_t>(per_axis);
        }
        P.id[k] = k;
    }
    const Vec<D> lo = Vec<D>::Constant(-dx);
    const Vec<D> hi = Vec<D>::Constant((per_axis + 1) * dx);
    std::array<bool, D> periodic{};
    const CellGrid<D> grid = CellGrid<D>::make(lo, hi, rc, periodic);
    CellRanges ranges;
    std::vector<CellOccupancy> occupied;
    rebin(grid, P, ranges, occupied);
    Neighbourhood<D> nb;
    nb.grid = &grid;
    nb.cells = &ranges;
    nb.x = P.x;
    nb.support = rc;

    // Offsets of every particle's candidates (centre excluded), gathered once for the
    // selection timings; the search timing repeats the gathering alone.
    std::vector<std::vector<Vec<D>>> offsets(n);
    const auto gather = [&](std::uint32_t i, std::vector<Vec<D>>& out) {
        out.clear();
        const CellIndex c = grid.linear(grid.coords(P.x[i]));
        nb.for_each_neighbour(nb.adjacent(c), i, [&](std::uint32_t j, const Vec<D>& d, Real) {
            if (j != i)
                out.push_back(-d); // x_j - x_i
        });
    };
    std::vector<Vec<D>> scratch;
    std::size_t sink = 0;
    const double t_search = seconds_best_of_5([&] {
        for (std::uint32_t i = 0; i < n; ++i) {
            gather(i, scratch);
            sink += scratch.size();
        }
    });
    for (std::uint32_t i = 0; i < n; ++i)
        gather(i, offsets[i]);

    // The solver's form (selected_operators.cpp): one scratch, reused particle after particle.
    NeighbourSelectionScratch<D> selection_scratch;
    std::vector<int> picked;
    const auto select = [&](std::size_t i, const NeighbourSelection& s) {
        select_neighbours_into<D>(offsets[i], rc, dx, s, selection_scratch, picked);
        return picked.size();
    };
    NeighbourSelection radius;
    NeighbourSelection hull;
    hull.policy = NeighbourPolicy::convex_hull;
    hull.candidate_radius_over_dx = 3.1;
    std::size_t n_radius = 0, n_hull = 0, n_vertices = 0;
    const double t_radius = seconds_best_of_5([&] {
        n_radius = 0;
        for (std::size_t i = 0; i < n; ++i)
            n_radius += select(i, radius);
    });
    const double t_hull = seconds_best_of_5([&] {
        n_hull = 0;
        for (std::size_t i = 0; i < n; ++i)
            n_hull += select(i, hull);
    });
    hull.hull_boundary = false;
    const double t_vertices = seconds_best_of_5([&] {
        n_vertices = 0;
        for (std::size_t i = 0; i < n; ++i)
            n_vertices += select(i, hull);
    });
    const double per = 1e9 / static_cast<double>(n);
    std::printf("%d-D, %zu particles (jittered lattice, 20 %% of dx), candidates within 3.1 dx\n",
                D, n);
    std::printf("  mean candidates %.1f, radius set %.1f, hull vertices %.1f, hull + boundary "
                "%.1f\n",
                static_cast<double>(sink) / 5 / static_cast<double>(n),
                static_cast<double>(n_radius) / static_cast<double>(n),
                static_cast<double>(n_vertices) / static_cast<double>(n),
                static_cast<double>(n_hull) / static_cast<double>(n));
    std::printf("  radius search (cell scan)        %9.0f ns/particle\n", t_search * per);
    std::printf("  select: radius policy            %9.0f ns/particle\n", t_radius * per);
    std::printf("  select: convex hull (vertices)   %9.0f ns/particle  (%.1fx the search)\n",
                t_vertices * per, t_vertices / t_search);
    std::printf("  select: convex hull (+ boundary) %9.0f ns/particle  (%.1fx the search)\n",
                t_hull * per, t_hull / t_search);
    if constexpr (D == 2) {
        std::size_t n_andrew = 0;
        const double t_andrew = seconds_best_of_5([&] {
            n_andrew = 0;
            std::vector<Vec<2>> images;
            for (std::size_t i = 0; i < n; ++i) {
                images.clear();
                for (const auto& r : offsets[i])
                    images.push_back(inverse_square_map<2>(r));
                n_andrew += monotone_chain_hull_2d(images).size();
            }
        });
        std::printf("  map + Andrew's monotone chain    %9.0f ns/particle  (vertices %.1f)\n",
                    t_andrew * per, static_cast<double>(n_andrew) / static_cast<double>(n));
    }
}

} // namespace

int main(int argc, char** argv) {
    const int n2 = argc > 1 ? std::atoi(argv[1]) : 100;
    const int n3 = argc > 2 ? std::atoi(argv[2]) : 20;
    if (n2 < 4 || n3 < 4) {
        std::fprintf(stderr,
                     "usage: bench_hull_selection [per axis 2-D >= 4] [per axis 3-D >= 4]\n");
        return 2;
    }
    run<2>(n2);
    run<3>(n3);
    return 0;
}
