#pragma once
// Accuracy of the particle operators (WMLS, MPS, SPH) on Park et al.'s (2014) benchmark (
// section 3.1): a square lattice on [lo, hi]^2 of spacing l0, every coordinate displaced
// by randomness * l0 * U(-1, 1) (randomness 0.5: up to half a spacing), neighbours within
// re = 3.1 l0, test field f = sin(x) cos(y); the same in 3-D on a cube with f = sin x cos y cos z.
// Shared by tests/validation/test_wmls_benchmark.cpp and perf/wmls/operator_accuracy.cpp.
//
// Relative error (paper eq. 23 is missing from the text; this is the usual discrete L2 form):
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
    Real lo = 0.8, hi = 4.1; // domain of Park et al. (2014), Fig. 3
    Real l0 = 0.1;
    Real re_over_l0 = 3.1;
    Real randomness = 0.5;
    std::uint64_t seed = 2014;
    Real re() const { return re_over_l0 * l0; }
};

// 2-D: f = sin x cos y: grad f = (cos x cos y, -sin x sin y), lap f = -2 f.
// 3-D: f = sin x cos y cos z, lap f = -3 f.
template <int D>
struct TestField {
    static Real value(const Vec<D>& x) {
        Real f = std::sin(x[0]);
        for (int a = 1; a < D; ++a)
            f *= std::cos(x[a]);
        return f;
    }
    static Vec<D> gradient(const Vec<D>& x) {
        Vec<D> g;
        for (int a = 0; a < D; ++a) {
            g[a] = a == 0 ? std::cos(x[0]) : -std::sin(x[0]);
            for (int b = 1; b < D; ++b)
                g[a] *= b == a ? std::sin(x[b]) : std::cos(x[b]);
        }
        return g;
    }
    static Real laplacian(const Vec<D>& x) { return -Real(D) * value(x); }
};

template <int D>
std::vector<Vec<D>> perturbed_lattice(const OperatorBenchmark& b) {
    const int n = static_cast<int>(std::lround((b.hi - b.lo) / b.l0)) + 1;
    std::mt19937_64 rng(b.seed);
    std::uniform_real_distribution<Real> u(-1, 1);
    std::vector<Vec<D>> x;
    const int total = D == 2 ? n * n : n * n * n;
    x.reserve(static_cast<std::size_t>(total));
    for (int c = 0; c < total; ++c) {
        Vec<D> p;
        int rest = c;
        for (int a = 0; a < D; ++a) {
            p[a] = b.lo + (rest % n) * b.l0 + b.randomness * b.l0 * u(rng);
            rest /= n;
        }
        x.push_back(p);
    }
    return x;
}

// Neighbours within `radius` (self excluded), by bucketing into cells of edge `radius`.
template <int D>
std::vector<std::vector<std::uint32_t>> neighbour_lists(const std::vector<Vec<D>>& x, Real radius) {
    Vec<D> lo = x.front(), hi = x.front();
    for (const auto& p : x) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    Eigen::Matrix<int, D, 1> n;
    for (int a = 0; a < D; ++a)
        n[a] = static_cast<int>((hi[a] - lo[a]) / radius) + 1;
    const auto cell = [&](const Vec<D>& p) {
        Eigen::Matrix<int, D, 1> c;
        for (int a = 0; a < D; ++a)
            c[a] = std::min(static_cast<int>((p[a] - lo[a]) / radius), n[a] - 1);
        return c;
    };
    const auto index = [&](const Eigen::Matrix<int, D, 1>& c) {
        std::size_t k = 0;
        for (int a = D - 1; a >= 0; --a)
            k = k * static_cast<std::size_t>(n[a]) + static_cast<std::size_t>(c[a]);
        return k;
    };
    std::vector<std::vector<std::uint32_t>> bucket(static_cast<std::size_t>(n.prod()));
    for (std::uint32_t i = 0; i < x.size(); ++i)
        bucket[index(cell(x[i]))].push_back(i);
    std::vector<std::vector<std::uint32_t>> nbrs(x.size());
    const int adjacent = D == 2 ? 9 : 27;
    for (std::uint32_t i = 0; i < x.size(); ++i) {
        const auto ci = cell(x[i]);
        for (int k = 0; k < adjacent; ++k) {
            Eigen::Matrix<int, D, 1> c;
            bool inside = true;
            for (int a = 0, rest = k; a < D; ++a, rest /= 3) {
                c[a] = ci[a] + rest % 3 - 1;
                inside = inside && c[a] >= 0 && c[a] < n[a];
            }
            if (!inside)
                continue;
            for (std::uint32_t j : bucket[index(c)])
                if (j != i && (x[j] - x[i]).squaredNorm() < radius * radius)
                    nbrs[i].push_back(j);
        }
    }
    return nbrs;
}

struct OperatorErrors {
    Real gradient = 0, laplacian = 0; // relative errors E (see top of file)
    int particles = 0;                // particles evaluated
    int not_ok = 0;                   // of which the operator flagged ok = false
};

// Errors of one operator over the particles at least `margin` inside the lattice's bounding
// box [lo, hi]^D (margin 0: every particle).
template <int D>
OperatorErrors operator_errors(const OperatorSettings<D>& op, const OperatorBenchmark& b,
                               const std::vector<Vec<D>>& x,
                               const std::vector<std::vector<std::uint32_t>>& nbrs, Real margin) {
    Real eg = 0, ng = 0, el = 0, nl = 0;
    OperatorErrors out;
    std::vector<Vec<D>> offsets;
    std::vector<Real> diffs;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if ((x[i].array() < b.lo + margin).any() || (x[i].array() > b.hi - margin).any())
            continue;
        offsets.clear();
        diffs.clear();
        const Real fi = TestField<D>::value(x[i]);
        for (std::uint32_t j : nbrs[i]) {
            offsets.push_back(x[j] - x[i]);
            diffs.push_back(TestField<D>::value(x[j]) - fi);
        }
        const auto r = particle_derivatives<D>(op, offsets, diffs);
        const Vec<D> g = TestField<D>::gradient(x[i]);
        const Real l = TestField<D>::laplacian(x[i]);
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
