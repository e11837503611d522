// Seed 004's operator benchmark as a table (WMLS vs MPS vs SPH), orders of convergence on
// random particles, conditioning of the WMLS fit and the cost per particle. Shares the set-up
// and the error norm with tests/validation/test_wmls_benchmark.cpp (operator_accuracy.hpp).
// Usage: bench_wmls_accuracy [--seeds N]     (perf/wmls/README.md)
#include "operator_accuracy.hpp"
#include "sluice/physics/free_surface.hpp"

#include <Eigen/SVD>
#include <fmt/core.h>

#include <cstring>
#include <ctime>
#include <string>

using namespace sluice;
using namespace sluice::physics;
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

OperatorErrors run(const Variant& v, const OperatorBenchmark& b, const std::vector<Vec<2>>& x,
                   const std::vector<std::vector<std::uint32_t>>& nbrs, Real margin) {
    return operator_errors(operator_settings<2>(v.op, b.l0, b.re(), v.weight, v.kernel), b, x, nbrs,
                           margin);
}

// Processor time of this (single-threaded) program: less disturbed by other load than wall time.
double cpu_seconds_since(std::clock_t t0) {
    return static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
}

} // namespace

int main(int argc, char** argv) {
    int seeds = 10;
    for (int a = 1; a + 1 < argc; ++a)
        if (std::strcmp(argv[a], "--seeds") == 0)
            seeds = std::stoi(argv[a + 1]);

    const OperatorBenchmark base;
    fmt::print("Seed 004 benchmark: [{}, {}]^2, l0 = {}, re = {} l0, displacement up to {} l0 "
               "per coordinate, f = sin x cos y\n",
               base.lo, base.hi, base.l0, base.re_over_l0, base.randomness);
    fmt::print("relative L2 errors E (operator_accuracy.hpp); seed {} and [min, max] over {} "
               "seeds\n\n",
               base.seed, seeds);
    for (const Real margin : {0.0, base.re()}) {
        fmt::print("{} particles\n", margin > 0 ? "interior (>= re from the edge)" : "all");
        fmt::print("  {:<34} {:>9} {:>21} {:>10} {:>21} {:>7}\n", "operator", "E(grad)", "range",
                   "E(lap)", "range", "not ok");
        for (const auto& v : variants) {
            OperatorErrors first;
            Real gmin = 1e300, gmax = 0, lmin = 1e300, lmax = 0;
            for (int s = 0; s < seeds; ++s) {
                OperatorBenchmark b = base;
                b.seed = base.seed + static_cast<std::uint64_t>(s);
                const auto x = perturbed_lattice(b);
                const auto e = run(v, b, x, neighbour_lists(x, b.re()), margin);
                if (s == 0)
                    first = e;
                gmin = std::min(gmin, e.gradient);
                gmax = std::max(gmax, e.gradient);
                lmin = std::min(lmin, e.laplacian);
                lmax = std::max(lmax, e.laplacian);
            }
            fmt::print("  {:<34} {:>8.2f}% [{:>7.2f}%, {:>7.2f}%] {:>9.2f}% [{:>7.2f}%, "
                       "{:>7.2f}%] {:>7}\n",
                       v.name, 100 * first.gradient, 100 * gmin, 100 * gmax, 100 * first.laplacian,
                       100 * lmin, 100 * lmax, first.not_ok);
        }
        fmt::print("  seed 004 (its own error norm): WMLS 6.5% / 3.2%, PNU-MPS 68.5% / 60.4%\n\n");
    }

    // Orders of convergence in a fixed interior window [1.5, 3.4]^2.
    const std::vector<Real> l0s{0.2, 0.1, 0.05, 0.025, 0.0125};
    fmt::print("Convergence on random particles (interior window, errors in %)\n");
    fmt::print("  {:<34}", "operator");
    for (const Real l0 : l0s)
        fmt::print(" {:>9}", fmt::format("l0={}", l0));
    fmt::print(" {:>12} {:>12}\n", "slope (fit)", "slope (last)");
    for (const auto& v : variants) {
        for (const bool lap : {false, true}) {
            std::vector<Real> err;
            for (const Real l0 : l0s) {
                OperatorBenchmark b = base;
                b.l0 = l0;
                const auto x = perturbed_lattice(b);
                const auto e = run(v, b, x, neighbour_lists(x, b.re()), 0.7);
                err.push_back(lap ? e.laplacian : e.gradient);
            }
            fmt::print("  {:<34}", v.name + (lap ? " lap" : " grad"));
            for (const Real e : err)
                fmt::print(" {:>9.4f}", 100 * e);
            const std::vector<Real> tail_l0(l0s.end() - 2, l0s.end());
            const std::vector<Real> tail_e(err.end() - 2, err.end());
            fmt::print(" {:>12.2f} {:>12.2f}\n", fitted_slope(l0s, err),
                       fitted_slope(tail_l0, tail_e));
        }
    }

    // Conditioning of the scaled weighted design matrix, and cost per particle.
    const auto x = perturbed_lattice(base);
    const auto nbrs = neighbour_lists(x, base.re());
    Real worst = 1, sum_n = 0;
    std::vector<std::vector<Vec<2>>> offsets(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        for (std::uint32_t j : nbrs[i])
            offsets[i].push_back(x[j] - x[i]);
        sum_n += static_cast<Real>(offsets[i].size());
        const auto B = wmls_design_matrix<2>(offsets[i], base.re(), LsWeight::pnu_mps);
        const auto sv = Eigen::JacobiSVD<Eigen::MatrixXd>(B).singularValues();
        worst = std::min(worst, sv[sv.size() - 1] / sv[0]);
    }
    fmt::print("\nWMLS conditioning on the benchmark (all {} particles, {:.1f} neighbours on "
               "average): smallest sigma_min/sigma_max = {:.3g} (rank tolerance {:.0e})\n",
               x.size(), sum_n / static_cast<Real>(x.size()), worst, wmls_rank_tolerance);

    const int reps = 50;
    std::vector<Real> df(200, 0.5);
    auto t0 = std::clock();
    Real sink = 0;
    for (int r = 0; r < reps; ++r)
        for (const auto& o : offsets)
            sink += wmls_stencil<2>(o, base.re(), LsWeight::pnu_mps).laplacian.sum();
    const double t_stencil = cpu_seconds_since(t0) / (reps * static_cast<double>(x.size()));
    const auto mps = operator_settings<2>(Operator::mps, base.l0, base.re());
    t0 = std::clock();
    for (int r = 0; r < reps; ++r)
        for (const auto& o : offsets)
            sink += particle_derivatives<2>(mps, o, std::span<const Real>(df.data(), o.size()))
                        .laplacian;
    const double t_mps = cpu_seconds_since(t0) / (reps * static_cast<double>(x.size()));
    t0 = std::clock();
    int surface = 0;
    for (int r = 0; r < reps; ++r)
        for (const auto& o : offsets)
            surface += is_free_surface<2>(o, 2.1 * base.l0);
    const double t_fs = cpu_seconds_since(t0) / (reps * static_cast<double>(x.size()));
    fmt::print("CPU time per particle (this run): WMLS stencil {:.2f} us, MPS gradient+Laplacian "
               "{:.3f} us, arc free-surface test {:.2f} us ({} surface particles of {}) "
               "[checksum {:.3g}]\n",
               1e6 * t_stencil, 1e6 * t_mps, 1e6 * t_fs, surface / reps, x.size(), sink);
    return 0;
}
