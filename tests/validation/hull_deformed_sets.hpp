#pragma once
// Operator error and stencil quality of the projection scheme's WMLS operators with radius
// against convex-hull neighbours on particle sets deformed by motion, through the
// function the solver's stencil stage calls (physics/selected_operators.hpp) with the
// solver's settings: re = 3.1 dx, PNU-MPS weight, candidates = the particles within re.
// Shared by tests/unit/test_hull_deformed_guard.cpp and perf/convex_hull/bench_hull_deformed.cpp.
//
// Sets: a square block of N x N particles (spacing dx, every coordinate jittered by 5 % of dx,
// seeded: the noise of a block in motion) carried by a linear flow for a time t, so that each
// particle moves by the flow map F:
//   sheared   u = (gamma y, 0):            F = [[1, gamma t], [0, 1]]   (strain gamma t)
//   stretched u = (eps x, -eps y):         F = diag(e^{eps t}, e^{-eps t}) (aspect e^{2 eps t})
// Scored: the particles farther than 1.2 re from the deformed block's edges (a full stencil).
// Sets taken from a run (the dam break's jet and splash) come from the benchmark.
//
// Field f = sin(x/L) cos(y/L), L = 10 dx: grad f and lap f = -2 f / L^2 exact. Errors, relative
// L2 over the scored particles (Park et al.'s (2014) form): E = sqrt(sum |q - q_exact|^2 / sum |q_exact|^2).
// Stencil quality (the pressure rows P4 are built from L_ij): `not ok` counts fits not exact
// for quadratics (those rows become surface rows in the solver); `|L|/L` is
// sum_j |L_ij| / sum_j L_ij, 1 when every Laplacian coefficient is positive (an M-matrix row)
// and larger the more the row amplifies noise through negative coefficients (mean and max).
#include "sluice/physics/selected_operators.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace sluice::testing {

struct DeformedSet {
    std::string name;
    Real dx = 0;
    std::vector<Vec<2>> x;    // every particle (neighbours)
    std::vector<char> scored; // particles whose errors count
};

inline DeformedSet deformed_block(const std::string& name, const Mat<2>& F, int n, Real dx,
                                  std::uint64_t seed) {
    DeformedSet s;
    s.name = name;
    s.dx = dx;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<Real> u(-0.05 * dx, 0.05 * dx);
    const Real side = n * dx;
    // The deformed block is the parallelogram F [0, side]^2; inward unit normals of its edges.
    const Vec<2> e1 = F.col(0) * side, e2 = F.col(1) * side;
    const auto dist_to_edges = [&](const Vec<2>& p) {
        const Vec<2> n1 = Vec<2>(-e1.y(), e1.x()).normalized(); // edge along e1 through 0
        const Vec<2> n2 = Vec<2>(e2.y(), -e2.x()).normalized(); // edge along e2 through 0
        const Real s1 = n1.dot(e2) > 0 ? 1 : -1, s2 = n2.dot(e1) > 0 ? 1 : -1;
        const Real a = s1 * n1.dot(p), b = s1 * n1.dot(e2 - p);
        const Real c = s2 * n2.dot(p), d = s2 * n2.dot(e1 - p);
        return std::min({a, b, c, d});
    };
    const Real re = 3.1 * dx;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Vec<2> X((i + 0.5) * dx + u(rng), (j + 0.5) * dx + u(rng));
            const Vec<2> p = F * X;
            s.x.push_back(p);
            s.scored.push_back(dist_to_edges(p) > 1.2 * re ? 1 : 0);
        }
    return s;
}

inline Mat<2> shear_map(Real strain) {
    Mat<2> F = Mat<2>::Identity();
    F(0, 1) = strain;
    return F;
}

inline Mat<2> stretch_map(Real aspect) {
    Mat<2> F = Mat<2>::Zero();
    F(0, 0) = std::sqrt(aspect);
    F(1, 1) = 1 / std::sqrt(aspect);
    return F;
}

enum class DeformedSelection { radius, hull, hull_union };

inline const char* deformed_selection_name(DeformedSelection s) {
    switch (s) {
    case DeformedSelection::radius:
        return "radius";
    case DeformedSelection::hull:
        return "convex hull";
    case DeformedSelection::hull_union:
        return "hull + radius";
    }
    return "?";
}

inline NeighbourSelection deformed_policy(DeformedSelection s) {
    NeighbourSelection p;
    if (s != DeformedSelection::radius) {
        p.policy = NeighbourPolicy::convex_hull;
        p.union_with_radius = s == DeformedSelection::hull_union;
    }
    return p;
}

struct DeformedErrors {
    Real gradient = 0, laplacian = 0;
    int scored = 0, not_ok = 0;
    Real mean_neighbours = 0;                   // of the Laplacian, per scored particle
    Real mean_abs_ratio = 0, max_abs_ratio = 0; // |L|/L over the ok rows
};

// `which` restricts the scored particles further (e.g. interior / surface of a snapshot).
template <class Which>
DeformedErrors deformed_errors(const DeformedSet& s, DeformedSelection selection, Which which) {
    const Real dx = s.dx, re = 3.1 * dx, L = 10 * dx;
    const auto f = [&](const Vec<2>& p) { return std::sin(p.x() / L) * std::cos(p.y() / L); };
    OperatorSelections sel;
    sel.gradient = sel.laplacian = sel.free_surface = deformed_policy(selection);
    SelectedOperatorScratch<2> scratch;
    DeformedErrors out;
    Real eg = 0, ng = 0, el = 0, nl = 0, count = 0, ratio_sum = 0;
    int ratio_rows = 0;
    std::vector<Vec<2>> offsets, grad;
    std::vector<Real> diffs, lap;
    // Cell binning of the particles (edge re) for the candidate search.
    Vec<2> lo = s.x.front(), hi = s.x.front();
    for (const auto& p : s.x) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const int nx = static_cast<int>((hi.x() - lo.x()) / re) + 1;
    const int ny = static_cast<int>((hi.y() - lo.y()) / re) + 1;
    std::vector<std::vector<std::size_t>> cell(static_cast<std::size_t>(nx) * ny);
    const auto cell_of = [&](const Vec<2>& p, int& cx, int& cy) {
        cx = std::min(nx - 1, static_cast<int>((p.x() - lo.x()) / re));
        cy = std::min(ny - 1, static_cast<int>((p.y() - lo.y()) / re));
    };
    for (std::size_t k = 0; k < s.x.size(); ++k) {
        int cx = 0, cy = 0;
        cell_of(s.x[k], cx, cy);
        cell[static_cast<std::size_t>(cy) * nx + cx].push_back(k);
    }
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (s.scored[i] == 0 || !which(i))
            continue;
        offsets.clear();
        diffs.clear();
        int cx = 0, cy = 0;
        cell_of(s.x[i], cx, cy);
        for (int dy = -1; dy <= 1; ++dy)
            for (int dxc = -1; dxc <= 1; ++dxc) {
                const int x = cx + dxc, y = cy + dy;
                if (x < 0 || y < 0 || x >= nx || y >= ny)
                    continue;
                for (std::size_t j : cell[static_cast<std::size_t>(y) * nx + x]) {
                    const Vec<2> o = s.x[j] - s.x[i];
                    if (j != i && o.squaredNorm() < re * re) {
                        offsets.push_back(o);
                        diffs.push_back(f(s.x[j]) - f(s.x[i]));
                    }
                }
            }
        grad.assign(offsets.size(), Vec<2>::Zero());
        lap.assign(offsets.size(), 0);
        const auto ops = selected_operators<2>(offsets, sel, re, dx, LsWeight::pnu_mps, 2.1 * dx,
                                               std::span<Vec<2>>(grad), std::span<Real>(lap),
                                               std::span<Vec<2>>(), scratch);
        Vec<2> g = Vec<2>::Zero();
        Real l = 0, abs_sum = 0, sum = 0;
        int used = 0;
        for (std::size_t m = 0; m < offsets.size(); ++m) {
            g += grad[m] * diffs[m];
            l += lap[m] * diffs[m];
            abs_sum += std::abs(lap[m]);
            sum += lap[m];
            used += lap[m] != 0 ? 1 : 0;
        }
        const Vec<2>& p = s.x[i];
        const Vec<2> g_exact(std::cos(p.x() / L) * std::cos(p.y() / L) / L,
                             -std::sin(p.x() / L) * std::sin(p.y() / L) / L);
        const Real l_exact = -2 * f(p) / (L * L);
        eg += (g - g_exact).squaredNorm();
        ng += g_exact.squaredNorm();
        el += (l - l_exact) * (l - l_exact);
        nl += l_exact * l_exact;
        count += used;
        ++out.scored;
        if (!ops.ok) {
            ++out.not_ok;
        } else if (sum > 0) {
            ratio_sum += abs_sum / sum;
            out.max_abs_ratio = std::max(out.max_abs_ratio, abs_sum / sum);
            ++ratio_rows;
        }
    }
    if (out.scored > 0) {
        out.gradient = std::sqrt(eg / ng);
        out.laplacian = std::sqrt(el / nl);
        out.mean_neighbours = count / out.scored;
    }
    out.mean_abs_ratio = ratio_rows > 0 ? ratio_sum / ratio_rows : 0;
    return out;
}

inline DeformedErrors deformed_errors(const DeformedSet& s, DeformedSelection selection) {
    return deformed_errors(s, selection, [](std::size_t) { return true; });
}

} // namespace sluice::testing
