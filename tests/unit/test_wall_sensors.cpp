// Area pressure sensors on walls (physics/wall_loads.hpp): the force reading (the fluid's normal
// force on the wall columns under the face) and the interpolated reading, on hand-built
// hydrostatic fields in 2-D and 3-D, a lone spray particle, suction, and the identity between a
// sensor that covers whole columns and the force probe on those columns; and the force from the
// interpolated pressure integrated over wall surfaces (a wall's thrust, a box's buoyancy).
#include "sluice/physics/wall_loads.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace sluice;

namespace {

constexpr Real kRho = 1000, kG = 9.81;

// Water H deep against a wall at x = 0 (x < 0: four layers) over a floor (y < 0: four layers),
// on a lattice of spacing dx, every particle carrying the hydrostatic pressure rho g (H - y)
// (what the Adami extrapolation gives the wall particles of a hydrostatic field).
struct HydrostaticCorner {
    Real dx = 0.01, H = 0.5;
    Particles<2> P;
    HydrostaticCorner() {
        for (int j = -4; j < 50; ++j)
            for (int i = -4; i < 30; ++i) {
                const Vec<2> x((i + 0.5) * dx, (j + 0.5) * dx);
                const bool wall = i < 0 || j < 0;
                P.push_back(P.size(), wall ? Kind::wall : Kind::fluid, x, Vec<2>::Zero(), kRho,
                            kRho * dx * dx);
                P.p.back() = kRho * kG * (H - x[1]);
            }
    }
};

// The 3-D analogue: water H = 0.3 m deep in x in [0, 0.2], y >= 0, over walls at y < 0 and
// z < 0 (three layers each), dx = 0.02, hydrostatic pressure everywhere.
struct HydrostaticCorner3 {
    Real dx = 0.02, H = 0.3;
    Particles<3> P;
    HydrostaticCorner3() {
        for (int k = -3; k < 15; ++k)
            for (int j = -3; j < 10; ++j)
                for (int i = 0; i < 10; ++i) {
                    const Vec<3> x((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx);
                    const bool wall = j < 0 || k < 0;
                    P.push_back(P.size(), wall ? Kind::wall : Kind::fluid, x, Vec<3>::Zero(), kRho,
                                kRho * dx * dx * dx);
                    P.p.back() = kRho * kG * (H - x[2]);
                }
    }
};

// The pair terms of a case with dummy walls: no clipping below zero pressure, no viscosity.
template <int D>
WallLoadParams<D> inviscid(Real h) {
    WallLoadParams<D> w;
    w.h = h;
    w.c0 = 20;
    return w;
}

} // namespace

TEST_CASE("force sensor on a hydrostatic side wall reads rho g (H - y)") {
    const HydrostaticCorner t;
    const Real dx = t.dx;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    const WallLoadParams<2> prm = inviscid<2>(Real(1.5) * dx);
    // Faces of several sizes, centred on a column boundary (0.25) or a column (0.105, 0.405):
    // a face symmetric about its centre averages the columns' linear profile to the centre's.
    for (Real y : {Real(0.105), Real(0.25), Real(0.405)})
        for (Real d : {Real(0.01), Real(0.05)}) {
            const SensorFace<2> face{Vec<2>(0, y), 0, -1, d};
            const Real p = wall_force_sensor(t.P, kernel, prm, face, dx);
            INFO("y = " << y << ", diameter = " << d);
            CHECK(p == doctest::Approx(kRho * kG * (t.H - y)).epsilon(0.01));
        }
    // The floor under a 4 cm face carries the full depth.
    const SensorFace<2> floor{Vec<2>(Real(0.15), 0), 1, -1, Real(0.04)};
    CHECK(wall_force_sensor(t.P, kernel, prm, floor, dx) ==
          doctest::Approx(kRho * kG * t.H).epsilon(0.01));
    // A face of zero size reads the column it lies on: the mean over that column's dx.
    const SensorFace<2> point{Vec<2>(0, Real(0.103)), 0, -1, 0};
    CHECK(wall_force_sensor(t.P, kernel, prm, point, dx) ==
          doctest::Approx(kRho * kG * (t.H - Real(0.105))).epsilon(0.01));
    // The wrong side of the surface holds no wall: nothing loads it.
    const SensorFace<2> outside{Vec<2>(0, Real(0.25)), 0, 1, Real(0.05)};
    CHECK(std::isnan(wall_force_sensor(t.P, kernel, prm, outside, dx)));
}

TEST_CASE("force sensor covering whole columns is the force probe on them over their area") {
    const HydrostaticCorner t;
    const Real dx = t.dx;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    WallLoadParams<2> prm = inviscid<2>(Real(1.5) * dx);
    prm.p_gauge = 1000; // loads relative to a background pressure; the reading adds it back
    // Columns at y = 0.205 ... 0.235 (four), the face [0.2, 0.24] covers them exactly.
    const SensorFace<2> face{Vec<2>(0, Real(0.22)), 0, -1, 4 * dx};
    const WallLoad load = wall_load(
        t.P, kernel, prm, wall_particles_in(t.P, Vec<2>(-1, Real(0.2)), Vec<2>(0, Real(0.24))),
        Vec<2>(0, 0));
    const double expected = prm.p_gauge - load.force[0] / (4 * double(dx));
    CHECK(double(wall_force_sensor(t.P, kernel, prm, face, dx)) ==
          doctest::Approx(expected).epsilon(1e-12));
}

TEST_CASE("a lone spray particle loads the wall by its share, not by its pressure") {
    // One fluid particle half a dx from a wall, at 10 kPa (the pressure it carried out of the
    // bulk). Shepard interpolation on the face reads its full pressure; the wall feels the
    // pair force of one particle, spread by the kernel over the columns it reaches.
    const Real dx = 0.01;
    Particles<2> P;
    for (int j = 0; j < 60; ++j)
        for (int i = -3; i < 0; ++i)
            P.push_back(P.size(), Kind::wall, Vec<2>((i + 0.5) * dx, (j + 0.5) * dx),
                        Vec<2>::Zero(), kRho, kRho * dx * dx);
    P.push_back(P.size(), Kind::fluid, Vec<2>(dx / 2, Real(0.305)), Vec<2>::Zero(), kRho,
                kRho * dx * dx);
    P.p.back() = 10000;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    Eos eos;
    eos.rho0 = kRho;
    eos.c0 = 20;
    refresh_dummy_walls(P, kernel, eos, Vec<2>(0, -kG), dx * dx);
    const SensorFace<2> face{Vec<2>(0, Real(0.305)), 0, -1, dx};
    const Real interpolated = wall_pressure_sensor(P, kernel, face, dx / 4);
    const Real force = wall_force_sensor(P, kernel, inviscid<2>(Real(1.5) * dx), face, dx);
    INFO("interpolated " << interpolated << " Pa, force " << force << " Pa");
    CHECK(interpolated == doctest::Approx(10000).epsilon(0.02));
    CHECK(force > 0);
    CHECK(force < Real(0.5) * interpolated); // 0.41 here: the kernel spreads it over ~5 columns
}

TEST_CASE("force sensor reads no suction where the wall pairs clip at the floor pressure") {
    HydrostaticCorner t;
    for (std::size_t i = 0; i < t.P.size(); ++i)
        t.P.p[i] = -2000; // tension everywhere
    const Real dx = t.dx;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    WallLoadParams<2> prm = inviscid<2>(Real(1.5) * dx);
    prm.p_floor = 0; // the momentum equation's clipping in fluid-wall pairs (momentum.hpp)
    const SensorFace<2> face{Vec<2>(0, Real(0.25)), 0, -1, Real(0.05)};
    CHECK(wall_force_sensor(t.P, kernel, prm, face, dx) == 0);
    CHECK(wall_pressure_sensor(t.P, kernel, face, dx / 4) == doctest::Approx(-2000));
    // Read as the pressure a scheme applies (the projection scheme: max(p, 0)), no suction.
    CHECK(wall_pressure_sensor(t.P, kernel, face, dx / 4, Real(0)) == 0);
}

TEST_CASE("interpolated sensor reads each particle's pressure above the applied floor") {
    // Hydrostatic below y = 0.3, tension above it: with the floor at 0 the sensor reads the
    // Shepard mean of max(p, 0), which is the hydrostatic reading where the kernel sees only
    // y < 0.3 and less than it (never below 0) where it reaches the tension.
    HydrostaticCorner t;
    const Real dx = t.dx, H = t.H;
    for (std::size_t i = 0; i < t.P.size(); ++i)
        if (t.P.x[i][1] > Real(0.3))
            t.P.p[i] = -3000;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    const SensorFace<2> low{Vec<2>(0, Real(0.1)), 0, -1, Real(0.02)};
    CHECK(wall_pressure_sensor(t.P, kernel, low, dx / 4, Real(0)) ==
          doctest::Approx(kRho * kG * (H - Real(0.1))).epsilon(0.002));
    CHECK(wall_pressure_sensor(t.P, kernel, low, dx / 4, Real(0)) ==
          wall_pressure_sensor(t.P, kernel, low, dx / 4));
    // Straddling y = 0.3: half the kernel weight at rho g (H - y) ~ 1962 Pa, half at -3000.
    const SensorFace<2> edge{Vec<2>(0, Real(0.3)), 0, -1, 0};
    const Real clipped = wall_pressure_sensor(t.P, kernel, edge, dx / 4, Real(0));
    const Real raw = wall_pressure_sensor(t.P, kernel, edge, dx / 4);
    CHECK(raw < 0);
    CHECK(clipped > 0);
    CHECK(clipped == doctest::Approx(kRho * kG * (H - Real(0.3)) / 2).epsilon(0.05));
    // Tension everywhere near the sensor reads exactly the floor.
    const SensorFace<2> high{Vec<2>(0, Real(0.45)), 0, -1, Real(0.02)};
    CHECK(wall_pressure_sensor(t.P, kernel, high, dx / 4, Real(0)) == 0);
    CHECK(wall_pressure_sensor(t.P, kernel, high, dx / 4) == doctest::Approx(-3000));
}

TEST_CASE("force sensor in 3-D averages its disc") {
    const HydrostaticCorner3 t;
    const Real dx = t.dx, H = t.H;
    const Particles<3>& P = t.P;
    const AnyKernel<3> kernel = make_kernel<3>(KernelType::wendland_c2, Real(1.5) * dx);
    // A disc on the y = 0 wall centred at z = 0.15, symmetric about its centre.
    const SensorFace<3> face{Vec<3>(Real(0.1), 0, Real(0.15)), 1, -1, Real(0.06)};
    const Real p = wall_force_sensor(P, kernel, inviscid<3>(Real(1.5) * dx), face, dx);
    CHECK(p == doctest::Approx(kRho * kG * (H - Real(0.15))).epsilon(0.01));
}

TEST_CASE("interpolated sensor on a hydrostatic side wall reads rho g (H - y)") {
    const HydrostaticCorner t;
    const Real dx = t.dx, H = t.H;
    const Particles<2>& P = t.P;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    for (Real y : {Real(0.1), Real(0.25), Real(0.4)})
        for (Real d : {Real(0), Real(0.005), Real(0.05)}) {
            const Real p =
                wall_pressure_sensor(P, kernel, SensorFace<2>{Vec<2>(0, y), 0, -1, d}, dx / 4);
            INFO("y = " << y << ", diameter = " << d);
            CHECK(p == doctest::Approx(kRho * kG * (H - y)).epsilon(0.002));
        }
    // On the floor (normal y): a 4 cm sensor averages the uniform floor pressure.
    CHECK(wall_pressure_sensor(P, kernel, SensorFace<2>{Vec<2>(Real(0.15), 0), 1, -1, Real(0.04)},
                               dx / 4) == doctest::Approx(kRho * kG * H).epsilon(0.002));
    // Dry: far above the water.
    Particles<2> dry;
    dry.push_back(0, Kind::wall, Vec<2>(-dx / 2, Real(2)), Vec<2>::Zero(), kRho, kRho * dx * dx);
    CHECK(std::isnan(
        wall_pressure_sensor(dry, kernel, SensorFace<2>{Vec<2>(0, Real(2)), 0, -1, dx}, dx / 4)));
}

TEST_CASE("interpolated sensor in 3-D averages over its disc") {
    const HydrostaticCorner3 t;
    const Real dx = t.dx, H = t.H;
    const Particles<3>& P = t.P;
    const AnyKernel<3> kernel = make_kernel<3>(KernelType::wendland_c2, Real(1.5) * dx);
    // A sensor on the y = 0 wall, centre at z = 0.15: the disc is symmetric about its centre,
    // so a linear field averages to the centre's value.
    const Real p = wall_pressure_sensor(
        P, kernel, SensorFace<3>{Vec<3>(Real(0.1), 0, Real(0.15)), 1, -1, Real(0.06)}, dx / 4);
    CHECK(p == doctest::Approx(kRho * kG * (H - Real(0.15))).epsilon(0.003));
}

TEST_CASE("interpolated force on a hydrostatic wall is rho g H^2 / 2, as the pair forces say") {
    const HydrostaticCorner t;
    const Real dx = t.dx, H = t.H;
    const AnyKernel<2> kernel = make_kernel<2>(KernelType::wendland_c2, Real(1.5) * dx);
    // The side wall's surface x = 0 (wall at x < 0) from the floor to above the water: the part
    // above the water's reach is dry and adds nothing.
    WallPatch<2> side;
    side.normal_axis = 0;
    side.into_wall = -1;
    side.at = 0;
    side.lo = Vec<2>(0, 0);
    side.hi = Vec<2>(0, Real(0.6));
    const WallLoad surface = interpolated_wall_load(t.P, kernel, {side}, dx / 2, 0, Vec<2>(0, 0));
    const double thrust = double(kRho * kG * H * H / 2); // 1226 N/m
    INFO("interpolated Fx " << surface.force[0] << " N/m, Fy " << surface.force[1]);
    CHECK(surface.force[0] == doctest::Approx(-thrust).epsilon(0.01));
    CHECK(surface.force[1] == 0);
    CHECK(surface.wall_particles == 120);    // 0.6 m at dx/2
    CHECK(surface.pairs < 120);              // the top is dry
    CHECK(surface.pairs > std::size_t(100)); // 0.5 m of water and the kernel's reach
    // Its moment about the corner, sum y (p dy): rho g H^3 / 6.
    CHECK(surface.moment[2] == doctest::Approx(double(kRho * kG * H * H * H / 6)).epsilon(0.02));
    // The same wall read by the momentum equation's pair forces on its particles (x < 0,
    // y >= 0: the corner block belongs to the floor).
    const WallLoad pairs =
        wall_load(t.P, kernel, inviscid<2>(Real(1.5) * dx),
                  wall_particles_in(t.P, Vec<2>(-1, 0), Vec<2>(0, 1)), Vec<2>(0, 0));
    INFO("pair-force Fx " << pairs.force[0]);
    CHECK(surface.force[0] == doctest::Approx(pairs.force[0]).epsilon(0.02));

    // The floor under the 0.3 m of water: the water's weight per metre, pointing down.
    WallPatch<2> floor;
    floor.normal_axis = 1;
    floor.into_wall = -1;
    floor.at = 0;
    floor.lo = Vec<2>(0, 0);
    floor.hi = Vec<2>(Real(0.3), 0);
    const WallLoad bottom = interpolated_wall_load(t.P, kernel, {floor}, dx / 2, 0, Vec<2>(0, 0));
    CHECK(bottom.force[0] == 0);
    CHECK(bottom.force[1] == doctest::Approx(-double(kRho * kG * H) * 0.3).epsilon(0.005));
    // The load is relative to the background pressure, below which pressures are clipped: a
    // floor of 1000 Pa takes 1000 Pa off the floor's load, and tension loads no wall.
    const WallLoad gauged =
        interpolated_wall_load(t.P, kernel, {floor}, dx / 2, Real(1000), Vec<2>(0, 0));
    CHECK(gauged.force[1] - bottom.force[1] == doctest::Approx(1000 * 0.3));
    HydrostaticCorner tension;
    for (std::size_t i = 0; i < tension.P.size(); ++i)
        tension.P.p[i] = -2000;
    const WallLoad pulled =
        interpolated_wall_load(tension.P, kernel, {side, floor}, dx / 2, 0, Vec<2>(0, 0));
    CHECK(pulled.force[0] == 0);
    CHECK(pulled.force[1] == 0);
    CHECK(pulled.pairs > 0);
}

TEST_CASE("interpolated force on a submerged box is Archimedes' buoyancy") {
    // Water 0.4 m deep over [0, 0.4]^3 (dx = 0.02) holding a fixed box [0.12, 0.28]^3 of wall
    // particles; every particle carries the hydrostatic pressure rho g (H - z), which is what
    // the Adami extrapolation gives the box's particles.
    const Real dx = 0.02, H = 0.4, lo = 0.12, hi = 0.28;
    Particles<3> P;
    for (int k = 0; k < 20; ++k)
        for (int j = 0; j < 20; ++j)
            for (int i = 0; i < 20; ++i) {
                const Vec<3> x((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx);
                const bool inside = (x.array() > lo).all() && (x.array() < hi).all();
                P.push_back(P.size(), inside ? Kind::wall : Kind::fluid, x, Vec<3>::Zero(), kRho,
                            kRho * dx * dx * dx);
                P.p.back() = kRho * kG * (H - x[2]);
            }
    const AnyKernel<3> kernel = make_kernel<3>(KernelType::wendland_c2, Real(1.5) * dx);
    std::vector<WallPatch<3>> faces;
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
            WallPatch<3> f;
            f.normal_axis = a;
            f.into_wall = side == 0 ? 1 : -1; // the lo face has the box above it
            f.at = side == 0 ? lo : hi;
            f.lo = Vec<3>::Constant(lo);
            f.hi = Vec<3>::Constant(hi);
            faces.push_back(f);
        }
    const Vec<3> centre = Vec<3>::Constant((lo + hi) / 2);
    const WallLoad load = interpolated_wall_load(P, kernel, faces, dx / 2, 0, centre);
    const double weight = double(kRho * kG) * std::pow(double(hi - lo), 3); // 40.2 N
    INFO("F = (" << load.force[0] << ", " << load.force[1] << ", " << load.force[2] << ") N");
    CHECK(load.force[2] ==
          doctest::Approx(weight).epsilon(1e-9)); // exact: a linear field, a symmetric lattice
    CHECK(std::abs(load.force[0]) < 1e-9 * weight);
    CHECK(std::abs(load.force[1]) < 1e-9 * weight);
    CHECK(load.wall_particles == 6 * 16 * 16);
    CHECK(load.pairs == load.wall_particles);
    // The pressures are symmetric about the box's vertical axis: no moment about its centre.
    for (double m : load.moment)
        CHECK(std::abs(m) < 1e-9 * weight * double(hi - lo));
    // Leaving out the bottom face leaves the top's push: rho g (H - hi) A downwards.
    faces.erase(faces.begin() + 4);
    const WallLoad no_bottom = interpolated_wall_load(P, kernel, faces, dx / 2, 0, centre);
    CHECK(no_bottom.force[2] ==
          doctest::Approx(-double(kRho * kG * (H - hi)) * double((hi - lo) * (hi - lo)))
              .epsilon(0.005));
}

TEST_CASE("wall contacts load the walls of their region, in an order of their own") {
    // Three collisions: two on the x+ wall (at x = 1), one on the floor (y = 0).
    std::vector<WallContact<2>> contacts{
        {7, 100, Vec<2>(Real(1.005), Real(0.2)), Vec<2>(Real(3), Real(0.5))},
        {2, 101, Vec<2>(Real(1.005), Real(0.4)), Vec<2>(Real(2), 0)},
        {5, 200, Vec<2>(Real(0.5), Real(-0.005)), Vec<2>(0, Real(-4))},
    };
    const Vec<2> lo(1, -1), hi(2, 2), about(1, 0);
    const WallLoad wall = contact_wall_load(contacts, lo, hi, about);
    CHECK(wall.pairs == 2);
    CHECK(wall.force[0] == doctest::Approx(5));
    CHECK(wall.force[1] == doctest::Approx(0.5));
    // M = sum (x_w - c) x F: (0.005, 0.2) x (3, 0.5) + (0.005, 0.4) x (2, 0).
    CHECK(wall.moment[2] == doctest::Approx(0.005 * 0.5 - 0.2 * 3 + 0.005 * 0 - 0.4 * 2));
    // The floor's contact alone.
    const WallLoad floor = contact_wall_load(contacts, Vec<2>(-1, -1), Vec<2>(Real(0.9), 0), about);
    CHECK(floor.pairs == 1);
    CHECK(floor.force[1] == doctest::Approx(-4));
    // The sum does not depend on the order the contacts come in (ranks, threads), bit for bit,
    // even where a plain sum would round differently: 1 + 1e17 - 1e17 is 0 in one order, 1 in
    // the other.
    const Vec<2> at(Real(1.005), Real(0.3));
    const std::vector<WallContact<2>> rounding{{1, 100, at, Vec<2>(1, 0)},
                                               {2, 101, at, Vec<2>(Real(1e17), 0)},
                                               {3, 102, at, Vec<2>(Real(-1e17), 0)}};
    const std::vector<WallContact<2>> reversed(rounding.rbegin(), rounding.rend());
    const WallLoad forward = contact_wall_load(rounding, lo, hi, about);
    const WallLoad backward = contact_wall_load(reversed, lo, hi, about);
    CHECK(forward.force == backward.force);
    CHECK(forward.moment == backward.moment);
    // Nothing in the region: no load.
    CHECK(contact_wall_load(contacts, Vec<2>(5, 5), Vec<2>(6, 6), about).force ==
          std::array<double, 3>{});
}

TEST_CASE("wall contacts near an area sensor read as traction spread over h") {
    // The x+ wall at x = 1, wall particles on a dx = 0.01 lattice behind it (x = 1.005, ...),
    // h = 0.015: each contact's normal force is spread over a strip 0.03 wide.
    const Real dx = 0.01, h = 0.015;
    const std::vector<WallContact<2>> contacts{
        {1, 10, Vec<2>(Real(1.005), Real(0.205)), Vec<2>(Real(0.4), Real(0.1))},
        {2, 11, Vec<2>(Real(1.015), Real(0.205)), Vec<2>(Real(0.2), 0)}, // second layer
        {3, 12, Vec<2>(Real(1.005), Real(0.215)), Vec<2>(Real(0.3), 0)},
        {4, 13, Vec<2>(Real(0.5), Real(-0.005)), Vec<2>(0, Real(-9))}, // the floor
    };
    // A face inside every strip ([0.2, 0.22] meets [0.19, 0.22] and [0.2, 0.23]): at
    // y in (0.2, 0.22) all three wall-side contacts count, 0.9 N/m over 0.03 m.
    const SensorFace<2> inside{Vec<2>(1, Real(0.21)), 0, 1, Real(0.018)};
    CHECK(contact_traction(contacts, inside, dx, Real(0.03), h) == doctest::Approx(0.9 / 0.03));
    // Too shallow a depth leaves the second layer out.
    CHECK(contact_traction(contacts, inside, dx, Real(0.01), h) == doctest::Approx(0.7 / 0.03));
    // A face covering a whole wall reads each contact's whole force over its area: here a
    // 0.2 m face centred on the contacts, 0.9 N/m over 0.2 m.
    const SensorFace<2> wide{Vec<2>(1, Real(0.21)), 0, 1, Real(0.2)};
    CHECK(contact_traction(contacts, wide, dx, Real(0.03), h) ==
          doctest::Approx(0.9 / 0.2).epsilon(1e-3));
    // Half in the strips of the contacts at 0.205 only: [0.17, 0.19] is outside all,
    // [0.19, 0.2] within 0.015 of 0.205 only.
    const SensorFace<2> edge{Vec<2>(1, Real(0.19)), 0, 1, Real(0.02)};
    CHECK(contact_traction(contacts, edge, dx, Real(0.03), h) ==
          doctest::Approx(0.6 / 0.03 / 2).epsilon(0.02));
    // No contact near the face: nothing.
    const SensorFace<2> away{Vec<2>(1, Real(0.5)), 0, 1, 2 * dx};
    CHECK(contact_traction(contacts, away, dx, Real(0.03), h) == 0);
}
