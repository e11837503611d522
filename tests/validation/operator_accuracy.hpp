#pragma once
// Accuracy of the particle operators (WMLS, MPS, SPH) on seed 004's benchmark (Park et al.
// 2014, section 3.1): a square lattice on [lo, hi]^2 of spacing l0, every coordinate displaced
// by randomness * l0 * U(-1, 1) (randomness 0.5: up to half a spacing), neighbours within
// re = 3.1 l0, test field f = sin(x) cos(y). Shared by tests/validation/test_wmls_benchmark.cpp
// and perf/wmls/operator_accuracy.cpp.
//
// Relative error (seed eq. 23 is missing from the text; this is the usual discrete L2 form):
//   E = sqrt(sum_i |q_i - q_exact(x_i)|^2) / sqrt(sum_i |q_exact(x_i)|^2)
// over the particles evaluated, q = grad f (vector norm) or lap f.
#include "sluice/physics/particle_operators.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace sluice::testing {

struct OperatorBenchmark {
    Real lo = 0.8, hi = 4.1; // domain of seed 004, Fig. 3
    Real l0 = 0.1;
    Real re_over_l0 = 3.1;
    Real randomness = 0.5;
    std::uint64_t seed = 2014;
    Real re() const { return re_over_l0 * l0; }
};

// f = sin(x) cos(y): grad f = (cos x cos y, -sin x sin y), lap f = -2 f.
struct TestField {
    static Real value(const Vec<2>& x) { return std::sin(x[0]) * std::cos(x[1]); }
    static Vec<2> gradient(const Vec<2>& x) {
        return {std::cos(x[0]) * std::cos(x[1]), -std::sin(x[0]) * std::sin(x[1])};
    }
    static Real laplacian(const Vec<2>& x) { return -2 * value(x); }
};

inline std::vector<Vec<2>> perturbed_lattice(const OperatorBenchmark& b) {
    const int n = static_cast<int>(std::lround((b.hi - b.lo) / b.l0)) + 1;
    std::mt19937_64 rng(b.seed);
    std::uniform_real_distribution<Real> u(-1, 1);
    std::vector<Vec<2>> x;
    x.reserve(static_cast<std::size_t>(n * n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Real px = b.lo + i * b.l0 + b.randomness * b.l0 * u(rng);
            const Real py = b.lo + j * b.l0 + b.randomness * b.l0 * u(rng);
            x.emplace_back(px, py);
        }
    return x;
}

// Neighbours within `radius` (self excluded), by bucketing into cells of edge `radius`.
inline std::vector<std::vector<std::uint32_t>> neighbour_lists(const std::vector<Vec<2>>& x,
                                                               Real radius) {
    Vec<2> lo = x.front(), hi = x.front();
    for (const auto& p : x) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const int nx = static_cast<int>((hi[0] - lo[0]) / radius) + 1;
    const int ny = static_cast<int>((hi[1] - lo[1]) / radius) + 1;
    const auto cell = [&](const Vec<2>& p, int a) {
        return std::min(static_cast<int>((p[a] - lo[a]) / radius), a == 0 ? nx - 1 : ny - 1);
    };
    std::vector<std::vector<std::uint32_t>> bucket(static_cast<std::size_t>(nx * ny));
    for (std::uint32_t i = 0; i < x.size(); ++i)
        bucket[static_cast<std::size_t>(cell(x[i], 1) * nx + cell(x[i], 0))].push_back(i);
    std::vector<std::vector<std::uint32_t>> nbrs(x.size());
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        const int cx = cell(x[i], 0), cy = cell(x[i], 1);
        for (int by = std::max(cy - 1, 0); by <= std::min(cy + 1, ny - 1); ++by)
            for (int bx = std::max(cx - 1, 0); bx <= std::min(cx + 1, nx - 1); ++bx)
                for (std::uint32_t j : bucket[static_cast<std::size_t>(by * nx + bx)])
                    if (j != i && (x[j] - x[i]).squaredNorm() < radius * radius)
                        nbrs[i].push_back(j);
    }
    return nbrs;
}

struct OperatorErrors {
    Real gradient = 0, laplacian = 0; // relative errors E (see top of file)
    int particles = 0;                // particles evaluated
    int not_ok = 0;                   // of which the operator flagged ok = false
};

// Errors of one operator over the particles at least `margin` inside the lattice's bounding
// box [lo, hi]^2 (margin 0: every particle).
inline OperatorErrors operator_errors(const physics::OperatorSettings<2>& op,
                                      const OperatorBenchmark& b, const std::vector<Vec<2>>& x,
                                      const std::vector<std::vector<std::uint32_t>>& nbrs,
                                      Real margin) {
    Real eg = 0, ng = 0, el = 0, nl = 0;
    OperatorErrors out;
    std::vector<Vec<2>> offsets;
    std::vector<Real> diffs;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if ((x[i].array() < b.lo + margin).any() || (x[i].array() > b.hi - margin).any())
            continue;
        offsets.clear();
        diffs.clear();
        const Real fi = TestField::value(x[i]);
        for (std::uint32_t j : nbrs[i]) {
            offsets.push_back(x[j] - x[i]);
            diffs.push_back(TestField::value(x[j]) - fi);
        }
        const auto r = physics::particle_derivatives<2>(op, offsets, diffs);
        const Vec<2> g = TestField::gradient(x[i]);
        const Real l = TestField::laplacian(x[i]);
        eg += (r.gradient - g).squaredNorm();
        ng += g.squaredNorm();
        el += (r.laplacian - l) * (r.laplacian - l);
        nl += l * l;
        ++out.particles;
        out.not_ok += !r.ok;
    }
    out.gradient = std::sqrt(eg / ng);
    out.laplacian = std::sqrt(el / nl);
    return out;
}

// Least-squares slope of log(error) against log(l0).
inline Real fitted_slope(const std::vector<Real>& l0, const std::vector<Real>& err) {
    Real sx = 0, sy = 0, sxx = 0, sxy = 0;
    const auto n = static_cast<Real>(l0.size());
    for (std::size_t k = 0; k < l0.size(); ++k) {
        const Real lx = std::log(l0[k]), ly = std::log(err[k]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace sluice::testing
