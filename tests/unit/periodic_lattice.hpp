#pragma once
// A periodic lattice of n x n fluid particles on the unit square with its grid, cells and
// neighbourhood: the test bed of the operator tests (test_momentum, test_density,
// test_riemann), which set fields on it and compare the operators with analytic values.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/momentum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sluice::testing {

struct Lattice {
    Particles<2> P;
    CellGrid<2> grid;
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    WendlandC2Kernel<2> kernel;
    double dx;

    Lattice(int n, double h_over_dx) : kernel(h_over_dx / n), dx(1.0 / n) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                P.push_back(static_cast<ParticleId>(j * n + i), Kind::fluid,
                            Vec<2>((i + 0.5) * dx, (j + 0.5) * dx), Vec<2>::Zero(), 1000,
                            1000 * dx * dx);
        grid = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(1, 1), kernel.support(), {true, true});
        rebin(grid, P, ranges, occ);
    }
    Neighbourhood<2> nb() const {
        return {&grid, &ranges, std::span<const Vec<2>>(P.x), kernel.support()};
    }
    // The per-particle factors the density stage computes with the pressure (p/rho^2, m/rho),
    // for fields set directly by a test.
    void derive_factors() {
        for (std::size_t i = 0; i < P.size(); ++i) {
            P.p_over_rho2[i] = P.p[i] / (P.rho[i] * P.rho[i]);
            P.volume[i] = P.mass[i] / P.rho[i];
        }
    }
    // The continuity tests' field: v = (sin 2 pi x, 0), whose rate is -rho0 2 pi cos(2 pi x).
    void set_sine_velocity() {
        for (std::size_t i = 0; i < P.size(); ++i)
            P.v[i] = Vec<2>(std::sin(2 * std::numbers::pi * P.x[i][0]), 0);
    }
    // Largest |drho - exact| over the particles, and the largest |exact|, for that field.
    [[nodiscard]] std::pair<double, double> sine_continuity_error() const {
        const double k = 2 * std::numbers::pi;
        double err = 0, ref = 0;
        for (std::size_t i = 0; i < P.size(); ++i) {
            const double exact = -1000 * k * std::cos(k * P.x[i][0]);
            err = std::max(err, std::abs(P.drho[i] - exact));
            ref = std::max(ref, std::abs(exact));
        }
        return {err, ref};
    }
    void accelerate(const MomentumParams<2>& prm) {
        derive_factors();
        for (const auto& c : occ)
            acceleration(nb(), kernel, prm, c.cell, P, std::span<Vec<2>>(P.a));
    }
};

} // namespace sluice::testing
