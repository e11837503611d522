// Loads on walls given as meshes (2-D vertex files), read by force probes with `mesh = 0`,
// from still water; means over 0.5-1.5 s, sampled every 2 ms (tests/data/mesh_loads/):
//  - a container traced as one polyline, vertical sides and a bed tilted at 10 degrees: the
//    force on it is the water's weight straight down (1 %; measured 0.08 %), nothing sideways
//    (0.5 % of the weight; measured 0.01 %), and its moment about the origin that of the weight
//    at the water's centre of mass (2 %; measured 0.03 %); area sensors on its bed and its side
//    wall read the hydrostatic pressure at their centres (2 %; measured -0.3 % and -0.8 %);
//  - Archimedes: a 64-gon of radius 0.08 m (8 dx) held 0.2 m deep: the force on it is
//    rho0 g A upwards (guard 4 %; measured +2.9 %, and +2.0 % at dx = 0.005; the column's
//    compression alone makes the water 0.5 % denser at that depth) and nothing sideways;
//  - a bed polyline's force probe reads its own wall particles only (the column's weight at t = 0).
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>

using namespace sluice;
using namespace sluice::testing;

namespace {

// Mean of column `col` over the rows with t >= t0.
double mean_from(const std::string& csv, std::size_t col, double t0, int& rows) {
    double sum = 0;
    rows = 0;
    for (const auto& r : read_csv(csv)) {
        if (std::stod(r.at(0)) < t0)
            continue;
        sum += std::stod(r.at(col));
        ++rows;
    }
    return rows > 0 ? sum / rows : 0;
}

} // namespace

TEST_CASE("A container traced as a polyline carries the water's weight at its centre of mass") {
    const CaseConfig cfg = read_case(data_path("mesh_loads/tilted_container_2d.toml"));
    REQUIRE(cfg.meshes.size() == 1);
    const double g = std::abs(cfg.gravity[1]);
    // The water as laid: its weight and the horizontal position of its centre of mass.
    double weight = 0, moment = 0;
    {
        const Simulation<2> sim(cfg);
        const auto& P = sim.particles();
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid) {
                weight += P.mass[i] * g;
                moment += P.mass[i] * g * P.x[i][0];
            }
    }
    const std::string out = run_in_temp_folder(cfg, "mesh_container", 2).folder;
    const std::string csv = out + "/probes/container.csv";
    int rows = 0;
    const double fx = mean_from(csv, 1, 0.5, rows);
    const double fy = mean_from(csv, 2, 0.5, rows);
    const double mz = mean_from(csv, 3, 0.5, rows);
    std::printf("tilted container: Fy %.2f N/m against -%.2f (%+.3f %%), Fx %.3f N/m, Mz %.3f "
                "N against %.3f (%+.3f %%), %d samples\n",
                fy, weight, 100 * (-fy / weight - 1), fx, mz, -moment, 100 * (-mz / moment - 1),
                rows);
    CHECK(rows >= 400);
    CHECK(fy == doctest::Approx(-weight).epsilon(0.01));
    CHECK(std::abs(fx) < 0.005 * weight);
    CHECK(mz == doctest::Approx(-moment).epsilon(0.02));
    // Area sensors on the mesh (its tilted bed at x = 0.2 m, its right wall at y = 0.25 m):
    // rho0 g times the depth of the centre below the settled surface, which the column's own
    // compression sets g H^2 / (2 c0^2) = 2 mm below the block's top.
    const double H = 0.4 - g * 0.4 * 0.4 / (2 * cfg.sound_speed * cfg.sound_speed);
    for (const auto& [name, y] : {std::pair{"bed_sensor", 0.0852654}, {"wall_sensor", 0.25}}) {
        const double p = mean_from(out + "/probes/" + name + ".csv", 1, 0.5, rows);
        const double ref = cfg.rho0 * g * (H - y);
        std::printf("tilted container: %s %.1f Pa against %.1f (%+.2f %%)\n", name, p, ref,
                    100 * (p / ref - 1));
        CHECK(p == doctest::Approx(ref).epsilon(0.02));
    }
    std::filesystem::remove_all(out);
}

TEST_CASE("Archimedes: a submerged polygon is pushed up by the weight of the water it displaces") {
    const CaseConfig cfg = read_case(data_path("mesh_loads/buoyancy_2d.toml"));
    REQUIRE(cfg.meshes.size() == 1);
    const double area = cfg.meshes[0].shape->enclosed_volume();
    CHECK(area == doctest::Approx(32 * 0.08 * 0.08 * std::sin(2 * std::numbers::pi / 64)));
    const double buoyancy = cfg.rho0 * std::abs(cfg.gravity[1]) * area;
    const std::string out = run_in_temp_folder(cfg, "mesh_buoyancy", 2).folder;
    const std::string csv = out + "/probes/body.csv";
    int rows = 0;
    const double fx = mean_from(csv, 1, 0.5, rows);
    const double fy = mean_from(csv, 2, 0.5, rows);
    std::printf("buoyancy: Fy %.2f N/m against rho0 g A = %.2f (%+.2f %%), Fx %.3f N/m, %d "
                "samples\n",
                fy, buoyancy, 100 * (fy / buoyancy - 1), fx, rows);
    CHECK(rows >= 400);
    CHECK(fy == doctest::Approx(buoyancy).epsilon(0.04));
    CHECK(std::abs(fx) < 0.005 * buoyancy);
    std::filesystem::remove_all(out);
}

TEST_CASE("A force probe on a bed mesh reads the bed's own wall particles, not the side walls") {
    // cases/dam_break_ramp_2d.toml at its start: the reservoir stands on the flat part of the
    // ramp polyline, whose region (its bounding box grown by the wall layers) also holds the
    // tank's side walls' layers. Before the gate opens the bed carries the column's weight,
    // 0.4 x 0.4 m x rho0 g (measured -1569.57 N/m against 1569.60; with the side walls'
    // particles counted it read -1574.6).
    const CaseConfig cfg = read_case(case_path("dam_break_ramp_2d.toml"),
                                     {"time.end_time=0.001", "output.snapshots=false"});
    const std::string out = run_in_temp_folder(cfg, "mesh_ramp_start", 2).folder;
    const auto rows = read_csv(out + "/probes/ramp_force.csv");
    REQUIRE(!rows.empty());
    const double weight = cfg.rho0 * std::abs(cfg.gravity[1]) * 0.4 * 0.4;
    const double fy = std::stod(rows[0].at(2));
    std::printf("ramp bed at t = 0: Fy %.3f N/m against -%.3f\n", fy, weight);
    CHECK(fy == doctest::Approx(-weight).epsilon(0.001));
    std::filesystem::remove_all(out);
}
