// Wall loads (physics/wall_loads.hpp) on hand-built particle sets: Newton's third law against
// the momentum equation's fluid accelerations, the moment; and the directed surge front and
// point water gauge (probes.hpp). The area sensors: test_wall_sensors.cpp.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/physics/momentum.hpp"
#include "sluice/physics/probes.hpp"
#include "sluice/physics/riemann.hpp"
#include "sluice/physics/wall_loads.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sluice;

namespace {

constexpr Real kRho = 1000, kG = 9.81;

// Deterministic pseudo-random numbers in [-1, 1].
struct Noise {
    std::uint64_t s = 12345;
    Real operator()() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return Real(static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0)) * 2 - 1;
    }
};

// A fluid block [0, 0.2] x [0, 0.1] (dx = 0.01) over a floor and beside a left wall of
// three layers each, with random pressures, densities and velocities: fluid first, then walls.
struct Tank {
    Real dx = 0.01;
    Particles<2> P;
    Tank() {
        Noise n;
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 20; ++i) {
                const Vec<2> x((i + 0.5) * dx + 0.1 * dx * n(), (j + 0.5) * dx + 0.1 * dx * n());
                P.push_back(P.size(), Kind::fluid, x, Vec<2>(n(), n()), kRho * (1 + 0.01 * n()),
                            kRho * dx * dx);
                P.p.back() = 1000 * (1 + n()); // some negative: the wall pairs clip them
            }
        for (int j = -3; j < 10; ++j)
            for (int i = -3; i < 20; ++i) {
                if (i >= 0 && j >= 0)
                    continue;
                P.push_back(P.size(), Kind::wall, Vec<2>((i + 0.5) * dx, (j + 0.5) * dx),
                            Vec<2>::Zero(), kRho * (1 + 0.01 * n()), kRho * dx * dx);
                P.p.back() = 1000 * (1 + n());
                P.v_bc.back() = Vec<2>(n(), n());
            }
        for (std::size_t i = 0; i < P.size(); ++i) {
            P.p_over_rho2[i] = P.p[i] / (P.rho[i] * P.rho[i]);
            P.volume[i] = P.mass[i] / P.rho[i];
        }
    }
    // sum_i m_i a_i over the fluid with the given momentum routine (gravity off).
    template <class Accelerate>
    Vec<2> fluid_momentum_rate(const AnyKernel<2>& any, Accelerate&& accelerate) {
        const Real support = std::visit([](const auto& k) { return k.support(); }, any);
        CellGrid<2> grid =
            CellGrid<2>::make(Vec<2>(-0.1, -0.1), Vec<2>(0.3, 0.2), support, {false, false});
        CellRanges ranges;
        std::vector<CellOccupancy> occ;
        rebin(grid, P, ranges, occ);
        const Neighbourhood<2> nb{&grid, &ranges, std::span<const Vec<2>>(P.x), support};
        std::visit(
            [&](const auto& k) {
                for (const auto& c : occ)
                    accelerate(nb, k, c.cell);
            },
            any);
        Vec<2> sum = Vec<2>::Zero();
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid)
                sum += P.mass[i] * P.a[i];
        return sum;
    }
    std::vector<std::size_t> walls() const {
        return wall_particles_in(P, Vec<2>(-1, -1), Vec<2>(1, 1));
    }
};

} // namespace

TEST_CASE("wall load: Newton's third law against the momentum equation") {
    const Real h = Real(1.3) * Real(0.01);
    for (bool viscous : {false, true}) {
        Tank t;
        const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, h);
        MomentumParams<2> m;
        m.h = h;
        m.c0 = 20;
        m.p_floor = 100; // clipping acts on wall pairs only
        if (viscous) {
            m.mu = Real(0.5);
            m.alpha = Real(0.1);
            m.wall_artificial = true;
        }
        const Vec<2> rate =
            t.fluid_momentum_rate(kernel, [&](const auto& nb, const auto& k, CellIndex c) {
                acceleration(nb, k, m, c, t.P, std::span<Vec<2>>(t.P.a));
            });
        WallLoadParams<2> w = wall_load_params(m);
        w.adami_v_bc = false; // the v_bc the momentum loop read
        const WallLoad load = wall_load(t.P, kernel, w, t.walls(), Vec<2>(Vec<2>::Zero()));
        // Fluid-fluid pairs cancel; what is left is the walls' push, opposite to their load.
        const double scale = std::abs(load.force[0]) + std::abs(load.force[1]);
        CHECK(load.pairs > 0);
        CHECK(scale > 1);
        CHECK(std::abs(rate[0] + load.force[0]) < 1e-9 * scale);
        CHECK(std::abs(rate[1] + load.force[1]) < 1e-9 * scale);
    }
}

TEST_CASE("wall load: Newton's third law with the Riemann solver") {
    const Real h = Real(1.3) * Real(0.01);
    Tank t;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::quintic, h);
    RiemannParams<2> r;
    r.c0 = 20;
    r.h = h;
    r.mu = Real(0.2);
    r.p_floor = 50;
    const Vec<2> rate =
        t.fluid_momentum_rate(kernel, [&](const auto& nb, const auto& k, CellIndex c) {
            riemann_acceleration(nb, k, r, c, t.P, std::span<Vec<2>>(t.P.a));
        });
    WallLoadParams<2> w;
    w.riemann = true;
    w.p_floor = r.p_floor;
    w.mu = r.mu;
    w.wall_viscous = true;
    w.c0 = r.c0;
    w.h = h;
    w.adami_v_bc = false;
    const WallLoad load = wall_load(t.P, kernel, w, t.walls(), Vec<2>(Vec<2>::Zero()));
    const double scale = std::abs(load.force[0]) + std::abs(load.force[1]);
    CHECK(std::abs(rate[0] + load.force[0]) < 1e-9 * scale);
    CHECK(std::abs(rate[1] + load.force[1]) < 1e-9 * scale);
}

TEST_CASE("wall load: parts add up, moment is r x F, background pressure removed") {
    const Real h = Real(1.3) * Real(0.01);
    Tank t;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, h);
    WallLoadParams<2> w;
    w.h = h;
    const auto all = t.walls();
    const auto floor = wall_particles_in(t.P, Vec<2>(-1, -1), Vec<2>(1, 0));
    const auto left = wall_particles_in(t.P, Vec<2>(-1, Real(1e-9)), Vec<2>(0, 1));
    CHECK(floor.size() + left.size() == all.size());
    const Vec<2> c(Real(0.05), Real(0.3));
    const WallLoad a = wall_load(t.P, kernel, w, all, c);
    const WallLoad f = wall_load(t.P, kernel, w, floor, c);
    const WallLoad l = wall_load(t.P, kernel, w, left, c);
    for (std::size_t k : {0U, 1U, 2U}) {
        CHECK(a.force[k] == doctest::Approx(f.force[k] + l.force[k]).epsilon(1e-12));
        CHECK(a.moment[k] == doctest::Approx(f.moment[k] + l.moment[k]).epsilon(1e-12));
    }
    // One wall particle: its moment is (x_j - c) x F_j.
    const std::size_t j = floor.at(30);
    const WallLoad one = wall_load(t.P, kernel, w, {j}, c);
    const Vec<2> r = t.P.x[j] - c;
    CHECK(one.moment[2] ==
          doctest::Approx(r[0] * one.force[1] - r[1] * one.force[0]).epsilon(1e-12));

    // A uniform pressure everywhere with p_gauge = that pressure loads nothing.
    for (std::size_t i = 0; i < t.P.size(); ++i) {
        t.P.p[i] = 3000;
        t.P.rho[i] = kRho;
        t.P.v[i].setZero();
    }
    w.p_gauge = 3000;
    const WallLoad none = wall_load(t.P, kernel, w, all, c);
    CHECK(std::abs(none.force[0]) < 1e-9);
    CHECK(std::abs(none.force[1]) < 1e-9);
}

TEST_CASE("directed surge front follows a thin tip, ignores droplets") {
    const Real dx = 0.01;
    Particles<2> P;
    auto add = [&](Real x, Real y) {
        P.push_back(P.size(), Kind::fluid, Vec<2>(x, y), Vec<2>::Zero(), kRho, kRho * dx * dx);
    };
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 10; ++j)
            add((i + 0.5) * dx, (j + 0.5) * dx);
    // A detached tip two particles deep at x = 0.5 (15 dx ahead of the bulk).
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j)
            add(Real(0.5) + i * dx, (j + 0.5) * dx);
    // A lone droplet further on.
    add(Real(0.8), Real(0.3));
    CHECK(surge_front_directed(P, dx, 0, false, 2 * dx) == doctest::Approx(0.525));
    // The old definition stops at the bulk: that is the jump back the new one avoids.
    CHECK(surge_front(P, dx) == doctest::Approx(0.2));
    // One particle deep is enough when asked.
    CHECK(surge_front_directed(P, dx, 0, false, dx) == doctest::Approx(0.805));
    // Towards -x: the bulk's left edge at 0. Upwards (+y): the block's top.
    CHECK(surge_front_directed(P, dx, 0, true, 2 * dx) == doctest::Approx(0.0));
    CHECK(surge_front_directed(P, dx, 1, false, 2 * dx) == doctest::Approx(0.1));
    // No column deep enough: NaN.
    CHECK(std::isnan(surge_front_directed(P, dx, 0, false, 20 * dx)));
}

TEST_CASE("water level at a point in 3-D") {
    const Real dx = 0.01;
    Particles<3> P;
    // A block of 0.1 m deep water over 0 <= y < 0.1, 0.3 m deep over 0.1 <= y < 0.2.
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 20; ++j)
            for (int k = 0; k < (j < 10 ? 10 : 30); ++k)
                P.push_back(P.size(), Kind::fluid,
                            Vec<3>((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx), Vec<3>::Zero(),
                            kRho, kRho * dx * dx * dx);
    const auto bulk = bulk_fluid(P, dx);
    CHECK(water_level_at(P, bulk, dx, Real(0.05), Real(0.05)) == doctest::Approx(0.1));
    CHECK(water_level_at(P, bulk, dx, Real(0.05), Real(0.15)) == doctest::Approx(0.3));
    CHECK(water_level(P, bulk, dx, Real(0.05)) == doctest::Approx(0.3)); // whole width
    CHECK(std::isnan(water_level_at(P, bulk, dx, Real(0.05), Real(0.5))));
}
