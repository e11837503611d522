#pragma once
// The particle block both four-lane tests (test_momentum_lanes, test_continuity_lanes) compare
// the lanes with the scalar loops on: 30 x 12 jittered fluid particles with random velocity,
// density, pressure (some below the background pressure), kicked velocity and density gradient,
// over three rows of wall particles with a boundary velocity (and a kicked velocity and a
// gradient the loops must ignore), binned, the cells disordered by the jitter, and listed as the
// WCSPH stages list them (wall centres with fluid partners only).
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/kernels.hpp"

#include <random>
#include <span>
#include <vector>

namespace sluice::test {

inline constexpr double dx = 0.01;

struct LaneBlock {
    Particles<2> P;
    CellGrid<2> grid;
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    std::vector<CellIndex> cells;
    WendlandC2Kernel<2> kernel{1.5 * dx};
    NeighbourList<2> list;

    LaneBlock(bool periodic, unsigned seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> jitter(-0.25, 0.25), unit(-1, 1);
        const int nx = 30, ny = 12;
        ParticleId id = 0;
        for (int row = 0; row < ny; ++row)
            for (int i = 0; i < nx; ++i) {
                const Vec<2> x((i + 0.5 + jitter(rng)) * dx, (row + 0.5 + jitter(rng)) * dx);
                const double rho = 1000 * (1 + 0.01 * unit(rng));
                P.push_back(id++, Kind::fluid, x, Vec<2>(unit(rng), unit(rng)), rho,
                            1000 * dx * dx * (1 + 0.05 * unit(rng)));
            }
        for (int row = 1; row <= 3; ++row)
            for (int i = 0; i < nx; ++i) {
                P.push_back(id++, Kind::wall, Vec<2>((i + 0.5) * dx, (0.5 - row) * dx),
                            Vec<2>::Zero(), 1000 * (1 + 0.01 * unit(rng)), 1000 * dx * dx);
                P.v_bc.back() = Vec<2>(unit(rng), unit(rng));
            }
        grid = CellGrid<2>::make(Vec<2>(0, -0.04), Vec<2>(nx * dx, ny * dx + 0.02),
                                 kernel.support(), {periodic, false});
        rebin(grid, P, ranges, occ);
        // Set after the rebin, which permutes the state, not the per-step fields (volume).
        for (std::size_t i = 0; i < P.size(); ++i) {
            P.v_half[i] = Vec<2>(unit(rng), unit(rng)); // a wall's must not count
            P.grad_rho[i] = Vec<2>(50 * unit(rng), 50 * unit(rng));
            P.p[i] = 2000 * unit(rng);
            P.p_over_rho2[i] = P.p[i] / (P.rho[i] * P.rho[i]);
            P.volume[i] = P.mass[i] / P.rho[i];
        }
        for (const auto& c : occ)
            cells.push_back(c.cell);
        const auto factor = [this](Real r2) { return grad_factor(kernel, r2); };
        neighbourhood().build_list(
            cells, list, factor, [this](std::uint32_t i) { return P.kind[i] == Kind::wall; },
            [this](std::uint32_t j) { return P.kind[j] == Kind::fluid; });
    }
    Neighbourhood<2> neighbourhood() const {
        return {&grid, &ranges, std::span<const Vec<2>>(P.x), kernel.support()};
    }
};

} // namespace sluice::test
