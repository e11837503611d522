// Force, moment and area-sensor probes on still water (tests/data/wall_loads/
// hydrostatic_loads_2d.toml: 0.4 m of water in a 0.4 m wide tank, dx = 0.02), through the
// whole pipeline (case reader, run loop, probe CSVs). From 0.5 s to 2 s, every sample:
//   floor force = the water's weight per unit width, side walls rho g H^2/2, within 1 %, by the
//   pair forces and by the interpolated pressure integrated over the walls' surfaces;
//   the left wall's lower half's force within 1 %, its moment about its foot rho g H^3/6
//   within 2 % (measured 1.15 % low: the reference ignores that the compressed column stands
//   g H^2/(2 c0^2) = 2 mm = 0.5 % lower, and the forces act at the wall particles, the corner
//   ones below the floor, which shortens the arm);
//   area sensors on a side wall and on the floor read rho g (H - y) within 2 %.
// The same tank under the projection scheme, whose force probes integrate the interpolated
// pressure: with p = 0 on the top particles' centres (docs/PROJECTION.md) the column's
// pressure is that of a depth H - dx/2, so the floor reads rho g (H - dx/2) per unit area, the
// side walls rho g (H - dx/2)^2/2, within 1 % (measured 0.4-0.7 %).
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/run.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

using namespace sluice;
using namespace sluice::testing;

namespace {

// Worst relative deviation of column `col` from `ref` over the rows with t >= t0.
double worst(const std::string& csv, std::size_t col, double ref, double t0, int& rows) {
    double w = 0;
    rows = 0;
    for (const auto& r : read_csv(csv)) {
        if (std::stod(r.at(0)) < t0)
            continue;
        w = std::max(w, std::abs(std::stod(r.at(col)) - ref) / std::abs(ref));
        ++rows;
    }
    return w;
}

struct Check {
    const char* probe;
    std::size_t col;
    double ref, tol;
};

// Runs `cfg` and checks every probe of `checks` from 0.5 s on; returns the results folder.
std::string run_and_check(const CaseConfig& cfg, const std::string& label,
                          std::initializer_list<Check> checks) {
    const std::string out = run_in_temp_folder(cfg, "wall_loads_" + label, 2).folder;
    for (const auto& c : checks) {
        int rows = 0;
        const double w = worst(out + "/probes/" + c.probe + ".csv", c.col, c.ref, 0.5, rows);
        std::printf("wall loads (%s): %-24s column %zu: reference %10.3f, worst deviation "
                    "%.3f %% (%d samples)\n",
                    label.c_str(), c.probe, c.col, c.ref, 100 * w, rows);
        INFO(label << ": " << c.probe << " column " << c.col);
        CHECK(rows >= 30);
        CHECK(w < c.tol);
    }
    return out;
}

} // namespace

TEST_CASE("Hydrostatic tank: wall forces, moment and area sensors") {
    const std::string path = data_path("wall_loads/hydrostatic_loads_2d.toml");
    const CaseConfig cfg = read_case(path);
    const double rho = cfg.rho0, g = std::abs(cfg.gravity[1]), H = cfg.blocks.at(0).hi[1];
    const double width = cfg.blocks.at(0).hi[0] - cfg.blocks.at(0).lo[0];
    const double dx = cfg.dx;
    // The water's weight per unit width: its mass (rho0 dx^2 per particle) times g.
    const double weight = rho * width * H * g;
    const double side = rho * g * H * H / 2;
    const std::string out =
        run_and_check(cfg, "wcsph",
                      {
                          {"floor", 2, -weight, 0.01},
                          {"right_wall", 1, side, 0.01},
                          {"left_wall", 1, -side, 0.01},
                          {"left_wall", 3, side * H / 3, 0.02},
                          {"left_wall_lower_half", 1, -rho * g * (H * 0.2 - 0.2 * 0.2 / 2), 0.01},
                          {"sensor", 1, rho * g * (H - 0.1), 0.02},
                          {"floor_sensor", 1, rho * g * H, 0.02},
                          {"floor_interpolated", 2, -weight, 0.01},
                          {"right_wall_interpolated", 1, side, 0.01},
                          {"left_wall_interpolated", 1, -side, 0.01},
                          {"left_wall_interpolated", 3, side * H / 3, 0.02},
                      });
    // The every-step surge front: one row per step (and the start), never two at one time,
    // and the still water's front stays at the wall.
    const auto front = read_csv(out + "/probes/front.csv");
    CHECK(front.size() > 1000);
    for (std::size_t k = 1; k < front.size(); ++k) {
        CHECK(std::stod(front[k][0]) > std::stod(front[k - 1][0]));
        CHECK(std::abs(std::stod(front[k][1]) - width) < dx);
    }
    std::filesystem::remove_all(out);
}

TEST_CASE("Hydrostatic tank under the projection scheme: interpolated wall forces") {
    // The case without the WCSPH-only keys, under the projection scheme (its force probes'
    // default reading there is the interpolated one; the area sensors interpolate too).
    std::ifstream in(data_path("wall_loads/hydrostatic_loads_2d.toml"));
    std::stringstream text;
    text << in.rdbuf();
    std::string t = text.str();
    for (const char* key :
         {"density = \"continuity\"\n", "delta_sph = 0.1\n", "artificial_viscosity = 0.02\n"}) {
        const auto pos = t.find(key);
        REQUIRE(pos != std::string::npos);
        t.erase(pos, std::string(key).size());
    }
    const std::string reading = "reading = \"interpolated\"\n"; // the scheme's default
    for (auto pos = t.find(reading); pos != std::string::npos; pos = t.find(reading))
        t.erase(pos, reading.size());
    const CaseConfig cfg = read_case_text(t, "hydrostatic_loads_projection_2d.toml",
                                          {"numerics.scheme=\"projection\""});
    for (const auto& p : cfg.probes)
        if (p.type == ProbeType::force)
            CHECK(p.reading == SensorReading::interpolated);
    const double rho = cfg.rho0, g = std::abs(cfg.gravity[1]);
    const double depth = cfg.blocks.at(0).hi[1] - cfg.dx / 2; // p = 0 on the top row's centres
    const double width = cfg.blocks.at(0).hi[0] - cfg.blocks.at(0).lo[0];
    const double side = rho * g * depth * depth / 2;
    const std::string out = run_and_check(cfg, "projection",
                                          {
                                              {"floor", 2, -rho * g * depth * width, 0.01},
                                              {"right_wall", 1, side, 0.01},
                                              {"left_wall", 1, -side, 0.01},
                                              {"left_wall", 3, side * depth / 3, 0.02},
                                              {"right_wall_interpolated", 1, side, 0.01},
                                          });
    std::filesystem::remove_all(out);
}
