// Force, moment and area-sensor probes on still water (tests/data/wall_loads/
// hydrostatic_loads_2d.toml: 0.4 m of water in a 0.4 m wide tank, dx = 0.02), through the
// whole pipeline (case reader, run loop, probe CSVs). From 0.5 s to 2 s, every sample:
//   floor force = the water's weight per unit width, side walls rho g H^2/2, within 1 %;
//   the left wall's lower half's force within 1 %, its moment about its foot rho g H^3/6
//   within 2 % (measured 1.15 % low: the reference ignores that the compressed column stands
//   g H^2/(2 c0^2) = 2 mm = 0.5 % lower, and the forces act at the wall particles, the corner
//   ones below the floor, which shortens the arm);
//   area sensors on a side wall and on the floor read rho g (H - y) within 2 %.
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/run.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h> // getpid: a folder of its own when suites run side by side

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

} // namespace

TEST_CASE("Hydrostatic tank: wall forces, moment and area sensors") {
    const std::string path = data_path("wall_loads/hydrostatic_loads_2d.toml");
    const CaseConfig cfg = read_case(path);
    const std::string out = (std::filesystem::temp_directory_path() /
                             ("sluice_test_wall_loads_hydrostatic_" + std::to_string(::getpid())))
                                .string();
    std::filesystem::remove_all(out);
    RunOptions opts;
    opts.out_dir = out;
    opts.threads = 2;
    opts.quiet = true;
    run_case(cfg, opts);

    const double rho = cfg.rho0, g = std::abs(cfg.gravity[1]), H = cfg.blocks.at(0).hi[1];
    const double width = cfg.blocks.at(0).hi[0] - cfg.blocks.at(0).lo[0];
    const double dx = cfg.dx;
    // The water's weight per unit width: its mass (rho0 dx^2 per particle) times g.
    const double weight = rho * width * H * g;
    const double side = rho * g * H * H / 2;
    struct Check {
        const char* probe;
        std::size_t col;
        double ref, tol;
    };
    const Check checks[] = {
        {"floor", 2, -weight, 0.01},
        {"right_wall", 1, side, 0.01},
        {"left_wall", 1, -side, 0.01},
        {"left_wall", 3, side * H / 3, 0.02},
        {"left_wall_lower_half", 1, -rho * g * (H * 0.2 - 0.2 * 0.2 / 2), 0.01},
        {"sensor", 1, rho * g * (H - 0.1), 0.02},
        {"floor_sensor", 1, rho * g * H, 0.02},
    };
    for (const auto& c : checks) {
        int rows = 0;
        const double w = worst(out + "/probes/" + c.probe + ".csv", c.col, c.ref, 0.5, rows);
        std::printf("wall loads: %-22s column %zu: reference %10.3f, worst deviation %.3f %% "
                    "(%d samples)\n",
                    c.probe, c.col, c.ref, 100 * w, rows);
        INFO(c.probe << " column " << c.col);
        CHECK(rows >= 30);
        CHECK(w < c.tol);
    }
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
