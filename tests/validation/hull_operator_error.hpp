#pragma once
// WMLS operator error with convex-hull neighbours against radius neighbours on strongly
// anisotropic particle sets (the situations where Lee & Lee (2011) and Randles &
// Libersky 2000 say the radius search picks poor neighbours). Shared by
// tests/validation/test_hull_operator_error.cpp and perf/convex_hull/bench_hull_operator_error.cpp.
//
// Sets, on about [0.8, 4.1]^2 like Park et al.'s (2014) operator benchmark (l0 = 0.1), every coordinate
// displaced by 10 % of the local spacing (seeded) so that nothing is exactly degenerate:
//   stretched : a square lattice stretched 4:1, spacing 4 l0 along x and l0 along y;
//   sheared   : the same lattice sheared, row j shifted by 1.3 l0 j along x;
//   gap       : a square lattice of spacing l0 with 3 columns removed (a gap 4 l0 wide between
//               the particles on either side); only the particles beside the gap are scored.
// Field f = sin(x) cos(y) (grad f = (cos x cos y, -sin x sin y), lap f = -2 f). Error:
// E = sqrt(sum |q - q_exact|^2 / sum |q_exact|^2) over the scored particles (Park et al.'s (2014) form).
//
// Neighbour sets, all fitted by WMLS with the PNU-MPS weight:
//   radius      : every particle within re = 3.1 l0 (Park et al.'s (2014) setting), fit radius re;
//   radius-wide : every particle within 1.1 rc (rc = 5 l0, the hull's candidate radius), fit
//                 radius 1.1 rc: the same reach as the hull variant;
//   hull+radius : convex-hull selection among the candidates within rc (corners and edge
//                 points), united with the radius set, fit radius 1.1 rc.
#include "sluice/physics/neighbour_selection.hpp"
#include "sluice/physics/options.hpp"
#include "sluice/physics/wmls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace sluice::testing {

struct AnisotropicSet {
    std::string name;
    std::vector<Vec<2>> x;
    std::vector<char> scored; // particles whose errors count
};

inline constexpr Real kHullErrorL0 = 0.1;

// Lattice sites a i e1 + j e2 (+ origin) inside [0.8, 4.1]^2 grown by `pad`, displaced by 10 %
// of |e1| and |e2| along x and y; `keep(i, j)` filters sites. Scored: the sites at least
// `margin` inside [0.8, 4.1]^2 for which `score(i, j)` holds.
template <class Keep, class Score>
AnisotropicSet lattice_set(const std::string& name, const Vec<2>& e1, const Vec<2>& e2, Real margin,
                           Keep keep, Score score, std::uint64_t seed) {
    AnisotropicSet s;
    s.name = name;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<Real> u(-0.1, 0.1);
    const Real lo = 0.8, hi = 4.1, pad = 0.6;
    const int reach = 200;
    for (int j = -reach; j <= reach; ++j)
        for (int i = -reach; i <= reach; ++i) {
            const Vec<2> p = Vec<2>(lo, lo) + i * e1 + j * e2;
            if ((p.array() < lo - pad).any() || (p.array() > hi + pad).any() || !keep(i, j))
                continue;
            s.x.push_back(p + Vec<2>(u(rng) * e1.norm(), u(rng) * e2.norm()));
            s.scored.push_back(((p.array() >= lo + margin).all() &&
                                (p.array() <= hi - margin).all() && score(i, j))
                                   ? 1
                                   : 0);
        }
    return s;
}

inline std::vector<AnisotropicSet> anisotropic_sets() {
    const Real l0 = kHullErrorL0;
    const Real margin = 0.6; // beyond 1.1 rc of the padded edge: no particle sees the edge
    const auto all = [](int, int) { return true; };
    std::vector<AnisotropicSet> sets;
    sets.push_back(
        lattice_set("stretched 4:1", Vec<2>(4 * l0, 0), Vec<2>(0, l0), margin, all, all, 1));
    sets.push_back(
        lattice_set("sheared", Vec<2>(4 * l0, 0), Vec<2>(1.3 * l0, l0), margin, all, all, 2));
    // Columns 15, 16, 17 removed; the columns beside them (14 and 18) are scored.
    sets.push_back(lattice_set(
        "gap", Vec<2>(l0, 0), Vec<2>(0, l0), margin, [](int i, int) { return i < 15 || i > 17; },
        [](int i, int) { return i == 14 || i == 18; }, 3));
    return sets;
}

enum class Selection { radius, radius_wide, hull_union, hull_union_adaptive };

inline const char* selection_name(Selection s) {
    switch (s) {
    case Selection::radius:
        return "radius (re = 3.1 l0)";
    case Selection::radius_wide:
        return "radius (re = 5.5 l0)";
    case Selection::hull_union:
        return "hull + radius (rc = 5 l0)";
    case Selection::hull_union_adaptive:
        return "hull + radius, adaptive re";
    }
    return "?";
}

struct SetErrors {
    Real gradient = 0, laplacian = 0;
    int scored = 0;
    int not_ok = 0;           // stencils WMLS flags as not exact for quadratics
    Real mean_neighbours = 0; // per scored particle
};

inline SetErrors set_errors(const AnisotropicSet& s, Selection selection) {
    const Real l0 = kHullErrorL0;
    const Real re = 3.1 * l0, rc = 5 * l0, wide = 1.1 * rc;
    const auto f = [](const Vec<2>& p) { return std::sin(p.x()) * std::cos(p.y()); };
    NeighbourSelection policy; // radius
    Real fit_radius = re, support = re;
    if (selection == Selection::radius_wide) {
        fit_radius = support = wide;
    } else if (selection == Selection::hull_union || selection == Selection::hull_union_adaptive) {
        policy.policy = NeighbourPolicy::convex_hull;
        policy.candidate_radius_over_dx = rc / l0;
        policy.union_with_radius = true;
        fit_radius = wide;
    }
    SetErrors out;
    Real eg = 0, ng = 0, el = 0, nl = 0, count = 0;
    std::vector<Vec<2>> candidates, offsets;
    std::vector<Real> diffs;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (s.scored[i] == 0)
            continue;
        candidates.clear();
        std::vector<std::size_t> index;
        for (std::size_t j = 0; j < s.x.size(); ++j)
            if (j != i && (s.x[j] - s.x[i]).norm() < wide) {
                candidates.push_back(s.x[j] - s.x[i]);
                index.push_back(j);
            }
        offsets.clear();
        diffs.clear();
        for (int k : select_neighbours<2>(candidates, support, l0, policy)) {
            const std::size_t j = index[static_cast<std::size_t>(k)];
            offsets.push_back(s.x[j] - s.x[i]);
            diffs.push_back(f(s.x[j]) - f(s.x[i]));
        }
        count += static_cast<Real>(offsets.size());
        if (selection == Selection::hull_union_adaptive) {
            fit_radius = re;
            for (const auto& o : offsets)
                fit_radius = std::max(fit_radius, 1.1 * o.norm());
        }
        const auto r = wmls_derivatives<2>(offsets, diffs, fit_radius, LsWeight::pnu_mps);
        const Vec<2> g(std::cos(s.x[i].x()) * std::cos(s.x[i].y()),
                       -std::sin(s.x[i].x()) * std::sin(s.x[i].y()));
        const Real lap = -2 * f(s.x[i]);
        eg += (r.gradient - g).squaredNorm();
        ng += g.squaredNorm();
        el += (r.laplacian - lap) * (r.laplacian - lap);
        nl += lap * lap;
        ++out.scored;
        out.not_ok += r.ok ? 0 : 1;
    }
    out.gradient = std::sqrt(eg / ng);
    out.laplacian = std::sqrt(el / nl);
    out.mean_neighbours = count / out.scored;
    return out;
}

} // namespace sluice::testing
