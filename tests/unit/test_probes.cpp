// Probes on hand-built particle sets with known answers.
#include "sluice/physics/probes.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sluice;

namespace {

constexpr Real kRho = 1000, kG = 9.81;

// Fluid on a lattice of spacing dx filling [x0, x1] x [0, height], hydrostatic pressure.
void fill_block(Particles<2>& ps, Real x0, Real x1, Real height, Real dx) {
    const int nx = static_cast<int>(std::lround((x1 - x0) / dx));
    const int ny = static_cast<int>(std::lround(height / dx));
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            const Vec<2> x(x0 + (i + 0.5) * dx, (j + 0.5) * dx);
            ps.push_back(ps.size(), Kind::fluid, x, Vec<2>::Zero(), kRho, kRho * dx * dx);
            ps.p.back() = kRho * kG * (height - x[1]);
        }
}

void add(Particles<2>& ps, Kind kind, Vec<2> x, Real dx, Real p = 0) {
    ps.push_back(ps.size(), kind, x, Vec<2>::Zero(), kRho, kRho * dx * dx);
    ps.p.back() = p;
}

} // namespace

TEST_CASE("pressure probe interpolates a hydrostatic field") {
    const Real dx = 0.02, height = 1.0;
    Particles<2> ps;
    fill_block(ps, 0, 1, height, dx);
    // A wall particle with an absurd pressure right at the probe: must be ignored.
    add(ps, Kind::wall, Vec<2>(0.5, 0.4), dx, 1e9);

    for (auto type : {KernelType::quintic, KernelType::wendland_c2, KernelType::cubic_spline}) {
        const auto kernel = make_kernel<2>(type, 1.3 * dx);
        for (const Vec<2>& point : {Vec<2>(0.5, 0.4), Vec<2>(0.337, 0.611), Vec<2>(0.2, 0.1)}) {
            const Real expected = kRho * kG * (height - point[1]);
            const Real got = pressure_probe(ps, kernel, point);
            CHECK(got == doctest::Approx(expected).epsilon(1e-3));
        }
    }
    // The generic (non-variant) kernel path gives the same answer as the variant.
    const Vec<2> point(0.337, 0.611);
    CHECK(pressure_probe(ps, WendlandC2Kernel<2>(1.3 * dx), point) ==
          pressure_probe(ps, make_kernel<2>(KernelType::wendland_c2, 1.3 * dx), point));
    // Far from any fluid: NaN, not zero.
    CHECK(std::isnan(pressure_probe(ps, QuinticKernel<2>(1.3 * dx), Vec<2>(3, 3))));
}

TEST_CASE("pressure probe reads each pressure above the applied floor") {
    // A hydrostatic block whose top rows hold tension (as the projection scheme's solve can
    // leave in a stretching jet, which its correction does not apply: projection.hpp, P7).
    const Real dx = 0.02, height = 1.0;
    Particles<2> ps;
    fill_block(ps, 0, 1, height, dx);
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (ps.x[i][1] > Real(0.8))
            ps.p[i] = -5000;
    const auto kernel = make_kernel<2>(KernelType::wendland_c2, 1.3 * dx);
    // Deep: the floor changes nothing.
    const Vec<2> deep(0.5, 0.4);
    CHECK(pressure_probe(ps, kernel, deep, Real(0)) == pressure_probe(ps, kernel, deep));
    CHECK(pressure_probe(ps, kernel, deep, Real(0)) ==
          doctest::Approx(kRho * kG * (height - 0.4)).epsilon(1e-3));
    // In the tension: raw -5000, read 0 above the floor.
    const Vec<2> top(0.5, 0.9);
    CHECK(pressure_probe(ps, kernel, top) == doctest::Approx(-5000));
    CHECK(pressure_probe(ps, kernel, top, Real(0)) == 0);
    // On the edge the clipped reading is the Shepard mean of max(p, 0): between 0 and the
    // hydrostatic value, and above the raw mean.
    const Vec<2> edge(0.5, 0.8);
    const Real clipped = pressure_probe(ps, kernel, edge, Real(0));
    CHECK(clipped > 0);
    CHECK(clipped < kRho * kG * (height - 0.8));
    CHECK(pressure_probe(ps, kernel, edge) < 0);
}

TEST_CASE("surge front ignores a detached droplet") {
    const Real dx = 0.02;
    Particles<2> ps;
    fill_block(ps, 0, 1, 0.5, dx);
    // A small droplet far ahead of the front, and a wall particle even further.
    add(ps, Kind::fluid, Vec<2>(2.0, 0.3), dx);
    add(ps, Kind::fluid, Vec<2>(2.0 + dx, 0.3), dx);
    add(ps, Kind::fluid, Vec<2>(2.0, 0.3 + dx), dx);
    add(ps, Kind::wall, Vec<2>(3.0, 0.0), dx);
    CHECK(surge_front(ps, dx) == doctest::Approx(1.0).epsilon(1e-12));

    const auto bulk = bulk_fluid(ps, dx);
    CHECK(bulk.size() == 50 * 25);
    CHECK(surge_front(ps, bulk, dx) == surge_front(ps, dx));

    // A particle continuing the block within the link distance (1.5 dx) does count.
    add(ps, Kind::fluid, Vec<2>(0.99 + 1.4 * dx, 0.01), dx);
    CHECK(surge_front(ps, dx) == doctest::Approx(0.99 + 1.4 * dx + dx / 2).epsilon(1e-12));
    // One just beyond it does not.
    add(ps, Kind::fluid, Vec<2>(0.99 + 3.0 * dx, 0.01), dx);
    CHECK(surge_front(ps, dx) == doctest::Approx(0.99 + 1.4 * dx + dx / 2).epsilon(1e-12));
}

TEST_CASE("water level of a lattice block equals its height") {
    const Real dx = 0.02, height = 0.5;
    Particles<2> ps;
    fill_block(ps, 0, 1, height, dx);
    // Spray above the column: not connected to the bulk, so not the surface.
    add(ps, Kind::fluid, Vec<2>(0.5, 0.9), dx);
    for (Real x : {0.01, 0.5, 0.731, 0.99}) {
        const Real level = water_level(ps, dx, x);
        CHECK(std::abs(level - height) <= dx / 2);
    }
    CHECK(std::isnan(water_level(ps, dx, 1.5))); // dry
    Particles<2> empty;
    CHECK(std::isnan(water_level(empty, dx, 0.5)));
    CHECK(std::isnan(surge_front(empty, dx)));
}

TEST_CASE("3-D: the vertical axis is z") {
    const Real dx = 0.1;
    Particles<3> ps;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 3; ++k)
                ps.push_back(ps.size(), Kind::fluid,
                             Vec<3>((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx), Vec<3>::Zero(),
                             kRho, kRho * dx * dx * dx);
    ps.push_back(ps.size(), Kind::fluid, Vec<3>(0.5, 0.2, 2.0), Vec<3>::Zero(), kRho, 1);
    CHECK(water_level(ps, dx, 0.5) == doctest::Approx(0.3).epsilon(1e-12));
    CHECK(surge_front(ps, dx) == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(bulk_fluid(ps, dx).size() == 120);
}

TEST_CASE("surge front: columns binned in parts and merged give the front of the whole") {
    // A tilted block with a thin tip and a droplet, split between three "ranks" in an
    // interleaved way (every third particle), merged in two orders.
    const Real dx = 0.02;
    Particles<2> ps;
    fill_block(ps, 0, 0.6, 0.3, dx);
    for (int i = 0; i < 5; ++i) // a tip two particles deep
        for (int j = 0; j < 2; ++j)
            add(ps, Kind::fluid, Vec<2>(0.6 + (i + 0.5) * dx, (j + 0.5) * dx), dx);
    add(ps, Kind::fluid, Vec<2>(1.2, 0.5), dx); // a droplet: one particle, not a front
    add(ps, Kind::wall, Vec<2>(1.5, 0.01), dx);
    const Real whole = surge_front_directed(ps, dx, 0, false, 2 * dx);
    CHECK(whole == doctest::Approx(0.6 + 5 * dx).epsilon(1e-12));

    std::vector<Particles<2>> parts(3);
    for (std::size_t i = 0; i < ps.size(); ++i)
        parts[i % 3].push_back(ps.id[i], ps.kind[i], ps.x[i], ps.v[i], ps.rho[i], ps.mass[i]);
    for (const std::vector<int>& order : {std::vector<int>{0, 1, 2}, std::vector<int>{2, 0, 1}}) {
        FrontColumns<2> merged(dx, 0, false);
        for (int r : order) {
            FrontColumns<2> mine(dx, 0, false);
            mine.add(parts[static_cast<std::size_t>(r)], parts[static_cast<std::size_t>(r)].size());
            for (const auto& [key, c] : mine.columns())
                merged.merge(key, c);
        }
        CHECK(merged.front(2 * dx) == whole); // bit for bit
    }
    // Downwards ("-y"): the lowest particle's cell edge, 0.
    CHECK(surge_front_directed(ps, dx, 1, true, 2 * dx) == doctest::Approx(0).epsilon(1e-12));
}

TEST_CASE("gauge level: spray above the column is not its bulk; only the column is read") {
    const Real dx = 0.02;
    Particles<2> ps;
    fill_block(ps, 0, 1, 0.3, dx);
    add(ps, Kind::fluid, Vec<2>(0.5, 0.6), dx); // a droplet above the gauge
    CHECK(gauge_water_level(ps, dx, Real(0.5), std::nullopt) ==
          doctest::Approx(0.3).epsilon(1e-12));
    // The same value from the particles around the gauge alone, in any order (the run evaluates a
    // gauge on the particles of its footprint only).
    Particles<2> column;
    for (std::size_t i = ps.size(); i-- > 0;)
        if (std::abs(ps.x[i][0] - 0.5) <= (gauge_bulk_reach + 1) * dx)
            column.push_back(ps.id[i], ps.kind[i], ps.x[i], ps.v[i], ps.rho[i], ps.mass[i]);
    CHECK(gauge_water_level(column, dx, Real(0.5), std::nullopt) ==
          gauge_water_level(ps, dx, Real(0.5), std::nullopt));
    // A column of spray alone, 3 particles linked vertically over a dry bed: that is its bulk.
    Particles<2> dry;
    for (int j = 0; j < 3; ++j)
        add(dry, Kind::fluid, Vec<2>(0.5, 0.5 + j * dx), dx);
    add(dry, Kind::fluid, Vec<2>(0.5, 0.9), dx); // and a smaller droplet above it
    CHECK(gauge_water_level(dry, dx, Real(0.5), std::nullopt) ==
          doctest::Approx(0.5 + 2 * dx + dx / 2).epsilon(1e-12));
    CHECK(std::isnan(gauge_water_level(dry, dx, Real(0.2), std::nullopt)));
}
