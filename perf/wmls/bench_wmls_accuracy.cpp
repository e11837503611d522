// Park et al.'s (2014) operator benchmark as a table (WMLS vs MPS vs SPH), orders of
// convergence on random particles, conditioning of the WMLS fit and the cost per particle.
// Shares the set-up and the error norm with tests/validation/test_wmls_benchmark.cpp
// (operator_accuracy.hpp).
// Usage: bench_wmls_accuracy [--seeds N]     (perf/wmls/README.md)
#include "operator_accuracy.hpp"
#include "sluice/physics/free_surface.hpp"

#include <Eigen/SVD>
#include <fmt/core.h>

#include <cstring>
#include <ctime>
#include <string>

using namespace sluice;
using namespace sluice::testing;

namespace {

struct Variant {
    std::string name;
    Operator op;
    LsWeight weight;
    KernelType kernel;
};

const Variant variants[] = {
    {"WMLS, PNU-MPS weight", Operator::wmls, LsWeight::pnu_mps, KernelType::wendland_c2},
    {"WMLS, smooth weight", Operator::wmls, LsWeight::smooth, KernelType::wendland_c2},
    {"MPS (K&O), PNU-MPS weight", Operator::mps, LsWeight::pnu_mps, KernelType::wendland_c2},
    {"SPH, Wendland C2 (2h = re)", Operator::sph, LsWeight::pnu_mps, KernelType::wendland_c2},
    {"SPH, quintic (3h = re)", Operator::sph, LsWeight::pnu_mps, KernelType::quintic},
};

template <int D>
OperatorErrors run(const Variant& v, const OperatorBenchmark& b, const std::vector<Vec<D>>& x,
                   const std::vector<std::vector<std::uint32_t>>& nbrs, Real margin) {
    return operator_errors<D>(operator_settings<D>(v.op, b.l0, b.re(), v.weight, v.kernel), b, x,
                              nbrs, margin);
}

// Processor time of this (single-threaded) program: less disturbed by other load than wall time.
double cpu_seconds_since(std::clock_t t0) {
    return static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
}

// Errors of every variant for `seeds` random lattices: the first seed's and the range.
template <int D>
void benchmark_table(const OperatorBenchmark& base, int seeds) {
    for (const Real margin : {0.0, base.re()}) {
        constexpr std::size_t nv = std::size(variants);
        std::vector<OperatorErrors> first(nv);
        std::vector<Real> gmin(nv, 1e300), gmax(nv, 0), lmin(nv, 1e300), lmax(nv, 0);
        for (int s = 0; s < seeds; ++s) {
            OperatorBenchmark b = base;
            b.seed = base.seed + static_cast<std::uint64_t>(s);
            const auto x = perturbed_lattice<D>(b);
            const auto nbrs = neighbour_lists<D>(x, b.re());
            for (std::size_t k = 0; k < nv; ++k) {
                const auto e = run<D>(variants[k], b, x, nbrs, margin);
                if (s == 0)
                    first[k] = e;
                gmin[k] = std::min(gmin[k], e.gradient);
                gmax[k] = std::max(gmax[k], e.gradient);
                lmin[k] = std::min(lmin[k], e.laplacian);
                lmax[k] = std::max(lmax[k], e.laplacian);
            }
        }
        fmt::print("{} particles ({})\n", margin > 0 ? "interior (>= re from the edge)" : "all",
                   first[0].particles);
        fmt::print("  {:<34} {:>9} {:>21} {:>10} {:>21} {:>7}\n", "operator", "E(grad)", "range",
                   "E(lap)", "range", "not ok");
        for (std::size_t k = 0; k < nv; ++k)
            fmt::print("  {:<34} {:>8.2f}% [{:>7.2f}%, {:>7.2f}%] {:>9.2f}% [{:>7.2f}%, "
                       "{:>7.2f}%] {:>7}\n",
                       variants[k].name, 100 * first[k].gradient, 100 * gmin[k], 100 * gmax[k],
                       100 * first[k].laplacian, 100 * lmin[k], 100 * lmax[k], first[k].not_ok);
        fmt::print("  Park et al. 2014 (2-D, its own error norm): WMLS 6.5% / 3.2%, PNU-MPS "
                   "68.5% / 60.4%\n\n");
    }
}

// Errors against l0 in the window at least `margin` inside the domain, with fitted slopes.
template <int D>
void convergence_table(const OperatorBenchmark& base, const std::vector<Real>& l0s, Real margin) {
    fmt::print("  {:<34}", "operator");
    for (const Real l0 : l0s)
        fmt::print(" {:>9}", fmt::format("l0={}", l0));
    fmt::print(" {:>12} {:>12}\n", "slope (fit)", "slope (last)");
    std::vector<std::vector<OperatorErrors>> e(std::size(variants));
    for (const Real l0 : l0s) {
        OperatorBenchmark b = base;
        b.l0 = l0;
        const auto x = perturbed_lattice<D>(b);
        const auto nbrs = neighbour_lists<D>(x, b.re());
        for (std::size_t k = 0; k < std::size(variants); ++k)
            e[k].push_back(run<D>(variants[k], b, x, nbrs, margin));
    }
    for (std::size_t k = 0; k < std::size(variants); ++k)
        for (const bool lap : {false, true}) {
            std::vector<Real> err;
            for (const auto& ek : e[k])
                err.push_back(lap ? ek.laplacian : ek.gradient);
            fmt::print("  {:<34}", variants[k].name + (lap ? " lap" : " grad"));
            for (const Real v : err)
                fmt::print(" {:>9.4f}", 100 * v);
            const std::vector<Real> tail_l0(l0s.end() - 2, l0s.end());
            const std::vector<Real> tail_e(err.end() - 2, err.end());
            fmt::print(" {:>12.2f} {:>12.2f}\n", fitted_slope(l0s, err),
                       fitted_slope(tail_l0, tail_e));
        }
    fmt::print("\n");
}

// Smallest sigma_min/sigma_max of the WMLS design matrices, and processor time per particle of
// a WMLS stencil, the MPS operators and the free-surface test, on the benchmark lattice.
template <int D>
void conditioning_and_cost(const OperatorBenchmark& base) {
    const auto x = perturbed_lattice<D>(base);
    const auto nbrs = neighbour_lists<D>(x, base.re());
    Real worst = 1, sum_n = 0;
    std::vector<std::vector<Vec<D>>> offsets(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        for (std::uint32_t j : nbrs[i])
            offsets[i].push_back(x[j] - x[i]);
        sum_n += static_cast<Real>(offsets[i].size());
        const auto B = wmls_design_matrix<D>(offsets[i], base.re(), LsWeight::pnu_mps);
        const auto sv = Eigen::JacobiSVD<Eigen::MatrixXd>(B).singularValues();
        worst = std::min(worst, sv[sv.size() - 1] / sv[0]);
    }
    fmt::print("  {}-D, {} particles, {:.1f} neighbours on average: smallest sigma_min/sigma_max "
               "= {:.3g} (rank tolerance {:.0e})\n",
               D, x.size(), sum_n / static_cast<Real>(x.size()), worst, wmls_rank_tolerance);

    const int reps = 50;
    std::vector<Real> df(1000, 0.5);
    auto t0 = std::clock();
    Real sink = 0;
    for (int r = 0; r < reps; ++r)
        for (const auto& o : offsets)
            sink += wmls_stencil<D>(o, base.re(), LsWeight::pnu_mps).laplacian.sum();
    const double t_stencil = cpu_seconds_since(t0) / (reps * static_cast<double>(x.size()));
    const auto mps = operator_settings<D>(Operator::mps, base.l0, base.re());
    t0 = std::clock();
    for (int r = 0; r < reps; ++r)
        for (const auto& o : offsets)
            sink += particle_derivatives<D>(mps, o, std::span<const Real>(df.data(), o.size()))
                        .laplacian;
    const double t_mps = cpu_seconds_since(t0) / (reps * static_cast<double>(x.size()));
    t0 = std::clock();
    int surface = 0;
    for (int r = 0; r < reps; ++r)
        for (const auto& o : offsets)
            surface += is_free_surface<D>(o, 2.1 * base.l0);
    const double t_fs = cpu_seconds_since(t0) / (reps * static_cast<double>(x.size()));
    fmt::print(
        "  {}-D: WMLS stencil {:.2f} us, MPS gradient+Laplacian {:.3f} us, free-surface test "
        "{:.2f} us ({} surface particles of {}) [checksum {:.3g}]\n",
        D, 1e6 * t_stencil, 1e6 * t_mps, 1e6 * t_fs, surface / reps, x.size(), sink);
}

} // namespace

int main(int argc, char** argv) {
    int seeds = 10;
    for (int a = 1; a + 1 < argc; ++a)
        if (std::strcmp(argv[a], "--seeds") == 0)
            seeds = std::stoi(argv[a + 1]);

    const OperatorBenchmark base;
    fmt::print("Park et al. (2014) benchmark: [{}, {}]^2, l0 = {}, re = {} l0, displacement up "
               "to {} l0 per coordinate, f = sin x cos y\n",
               base.lo, base.hi, base.l0, base.re_over_l0, base.randomness);
    fmt::print("relative L2 errors E (operator_accuracy.hpp); seed {} and [min, max] over {} "
               "seeds\n\n",
               base.seed, seeds);
    benchmark_table<2>(base, seeds);
    fmt::print("Convergence on random particles (window [1.5, 3.4]^2, errors in %)\n");
    convergence_table<2>(base, {0.2, 0.1, 0.05, 0.025, 0.0125}, 0.7);

    OperatorBenchmark cube = base;
    cube.hi = 2.0;
    fmt::print("3-D: cube [{}, {}]^3, l0 = {}, f = sin x cos y cos z, otherwise the same\n\n",
               cube.lo, cube.hi, cube.l0);
    benchmark_table<3>(cube, seeds);
    cube.hi = 3.2;
    fmt::print("3-D convergence (cube [0.8, 3.2]^3, window [1.5, 2.5]^3, errors in %)\n");
    convergence_table<3>(cube, {0.2, 0.1, 0.05}, 0.7);

    fmt::print("WMLS conditioning and processor time per particle (this run; neighbour lists of "
               "radius re, the free-surface test uses those within 2.1 l0)\n");
    conditioning_and_cost<2>(base);
    OperatorBenchmark cube_b = base;
    cube_b.hi = 2.0;
    conditioning_and_cost<3>(cube_b);
    return 0;
}
