// Moving walls under numerics.dissipation = "riemann" (Zhang, Hu & Adams 2017; riemann.hpp):
// - Galilean check: a 0.4 m tank with 0.2 m of water (dx = 0.01 m) moving at a constant
//   0.5 m/s with its water stays hydrostatic in its frame: the water's speed relative to the
//   tank and the pressure 5 cm above the floor are those of the tank at rest, under the
//   Riemann dissipation as under the default one. (With the wall pairs' density rate taking
//   v_i alone, as for a fixed wall, water passed through the moving tank's rear wall: a
//   particle left the domain at t = 0.15 s.);
// - a piston flume (h = 0.2 m, dx = 0.02 m, waves 2 cm high, T = 1 s) runs 2 s stably and its
//   paddle carries on average the force the default dissipation gives it, within 1 %, near
//   the hydrostatic rho g h^2 / 2 (the force reading of a wall 10 dx deep reads 5 % low under
//   either); an area sensor on the paddle's face rides with it and reads the hydrostatic
//   pressure at its depth on average, within 3 %.
#include "validation_support.hpp"

#include "sluice/physics/probes.hpp"
#include "sluice/solver/simulation.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

using namespace sluice;
using namespace sluice::testing;

namespace {

constexpr double kRho = 1000, kG = 9.81;

std::string dissipation_keys(bool riemann) {
    return riemann ? "dissipation = \"riemann\"\n" : "artificial_viscosity = 0.02\n";
}

// The tank of test_moving_tank_2d, at rest or moving at u with its water.
std::string tank_text(bool riemann, double u, double end) {
    const bool moving = u != 0;
    return "[case]\ndimension = 2\n[domain]\nlo = [0, 0]\nhi = [" + std::to_string(0.6 + u * end) +
           ", 0.3]\n"
           "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 15\ngravity = [0, -9.81]\n"
           "[particles]\ndx = 0.01\n[[blocks]]\nlo = [0, 0]\nhi = [0.4, 0.2]\nvelocity = [" +
           std::to_string(u) +
           ", 0]\n"
           "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\n" +
           dissipation_keys(riemann) +
           "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0]\ntank_hi = [0.4, 0.3]\n"
           "tank_faces = [\"x-\", \"x+\", \"y-\"]\n" +
           (moving ? "tank_motion = \"tank\"\n[[motions]]\nname = \"tank\"\n"
                     "kind = \"constant_velocity\"\nvelocity = [" +
                         std::to_string(u) + ", 0]\n"
                   : std::string()) +
           "[time]\nend_time = " + std::to_string(end) + "\n";
}

struct TankFigures {
    double pressure = 0;    // mean over [0.3 s, end] 5 cm above the floor, 5 cm from the rear
    double worst_speed = 0; // largest fluid speed relative to the tank over [0.3 s, end]
    double mean_speed = 0;  // mean over the fluid and the samples of that speed
};

TankFigures run_tank(bool riemann, double u) {
    const double end = 0.6;
    const CaseConfig cfg = read_case_text(tank_text(riemann, u, end), "riemann_tank.toml");
    SimulationOptions opts;
    opts.threads = 1;
    Simulation<2> sim(cfg, opts);
    TankFigures out;
    double sum_p = 0, sum_speed = 0, next = 0.3;
    int samples = 0;
    long speeds = 0;
    while (sim.time() < end - 1e-9) {
        sim.step();
        if (sim.time() < next - 1e-9)
            continue;
        next += 0.01;
        const double t = sim.time();
        const Particles<2>& P = sim.particles();
        sum_p += pressure_probe(P, sim.kernel(), Vec<2>(Real(0.05 + u * t), Real(0.05)));
        ++samples;
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid) {
                const double s = std::hypot(double(P.v[i].x()) - u, double(P.v[i].y()));
                out.worst_speed = std::max(out.worst_speed, s);
                sum_speed += s;
                ++speeds;
            }
    }
    REQUIRE(samples > 25);
    out.pressure = sum_p / samples;
    out.mean_speed = sum_speed / double(speeds);
    return out;
}

} // namespace

TEST_CASE("Galilean check under the Riemann dissipation: a tank moving uniformly stays still") {
    const double p_hyd = kRho * kG * (0.2 - 0.05);
    for (const bool riemann : {true, false}) {
        const TankFigures rest = run_tank(riemann, 0), moving = run_tank(riemann, 0.5);
        std::printf("%s: pressure at rest %.2f Pa, moving %.2f Pa (hydrostatic %.2f Pa); speed "
                    "relative to the tank, mean / largest: at rest %.2e / %.2e m/s, moving "
                    "%.2e / %.2e m/s\n",
                    riemann ? "riemann" : "artificial", rest.pressure, moving.pressure, p_hyd,
                    rest.mean_speed, rest.worst_speed, moving.mean_speed, moving.worst_speed);
        CHECK(std::abs(moving.pressure - rest.pressure) < 0.005 * p_hyd);
        CHECK(std::abs(rest.pressure - p_hyd) < 0.02 * p_hyd);
        // The water at rest in the tank's frame: no more than a few mm/s anywhere.
        CHECK(moving.worst_speed < 2 * rest.worst_speed + 0.005);
        CHECK(moving.mean_speed < 2 * rest.mean_speed + 0.001);
    }
}

TEST_CASE("A piston flume under the Riemann dissipation runs stably, paddle force hydrostatic") {
    const double h = 0.2, end = 2.0;
    double means[2] = {0, 0}, sensor[2] = {0, 0}, worst_place = 0;
    for (const bool riemann : {true, false}) {
        const std::string text =
            "[case]\ndimension = 2\n[domain]\nlo = [-0.2, 0]\nhi = [3.0, 0.4]\n"
            "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 28\ngravity = [0, -9.81]\n"
            "[particles]\ndx = 0.02\n[[blocks]]\nlo = [0, 0]\nhi = [3.0, 0.2]\n"
            "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\n" +
            dissipation_keys(riemann) +
            "[walls]\nmodel = \"dummy\"\ntank_lo = [-0.2, 0]\ntank_hi = [3.0, 0.4]\n"
            "tank_faces = [\"x+\", \"y-\"]\n"
            "[[walls.boxes]]\nlo = [-0.06, 0]\nhi = [0, 0.4]\nmotion = \"paddle\"\n"
            "[[motions]]\nname = \"paddle\"\nkind = \"piston\"\nwave_height = 0.02\n"
            "wave_period = 1.0\ndepth = 0.2\nramp = 1.0\n"
            "[[damping_zones]]\nstart = [2.0, 0]\nend = [3.0, 0]\nstrength = 10.0\n"
            "[time]\nend_time = 2.0\n"
            "[[probes]]\nname = \"paddle\"\ntype = \"force\"\nbox = 0\ninterval = 0.01\n"
            "[[probes]]\nname = \"face\"\ntype = \"pressure\"\nposition = [0, 0.1]\n"
            "diameter = 0.04\ninterval = 0.01\n"
            "[[probes]]\nname = \"stroke\"\ntype = \"motion\"\nframe = \"paddle\"\n"
            "interval = 0.01\n";
        const CaseConfig cfg = read_case_text(text, "riemann_piston.toml");
        const FolderRun run = run_in_temp_folder(cfg, riemann ? "riemann_piston" : "av_piston", 2);
        const auto rows = read_csv(run.folder + "/probes/paddle.csv");
        const auto face = read_csv(run.folder + "/probes/face.csv");
        const auto stroke = read_csv(run.folder + "/probes/stroke.csv");
        std::filesystem::remove_all(run.folder);
        CHECK(run.result.simulated_time >= end - 1e-9);
        // The force on the paddle's wet face over the last wave period, after the ramp (the
        // fluid pushes the paddle towards -x).
        double sum = 0;
        int n = 0;
        for (const auto& row : rows)
            if (std::stod(row.at(0)) >= 1.0) {
                sum += -std::stod(row.at(1));
                ++n;
            }
        REQUIRE(n > 90);
        means[riemann ? 0 : 1] = sum / n;
        // The area sensor on the paddle's face rides with it: its centre is the paddle's
        // displacement from (0, 0.1); its mean over the same period.
        REQUIRE(face.size() == rows.size());
        REQUIRE(stroke.size() == rows.size());
        double p = 0;
        for (std::size_t k = 0; k < face.size(); ++k) {
            worst_place = std::max({worst_place,
                                    std::abs(std::stod(face[k].at(2)) - std::stod(stroke[k].at(1))),
                                    std::abs(std::stod(face[k].at(3)) - 0.1)});
            if (std::stod(face[k].at(0)) >= 1.0)
                p += std::stod(face[k].at(1));
        }
        sensor[riemann ? 0 : 1] = p / n;
    }
    const double hydrostatic = kRho * kG * h * h / 2;
    std::printf("piston: mean paddle force over 1-2 s, riemann %.2f N/m, artificial %.2f N/m "
                "(hydrostatic %.2f N/m: %+.2f %%, %+.2f %%)\n",
                means[0], means[1], hydrostatic, 100 * (means[0] / hydrostatic - 1),
                100 * (means[1] / hydrostatic - 1));
    const double p_face = kRho * kG * (h - 0.1);
    std::printf("piston: mean pressure of the sensor on the paddle's face 0.1 m above the bed, "
                "riemann %.2f Pa, artificial %.2f Pa (hydrostatic %.2f Pa: %+.2f %%, %+.2f %%); "
                "its centre against the paddle's: %.2g m\n",
                sensor[0], sensor[1], p_face, 100 * (sensor[0] / p_face - 1),
                100 * (sensor[1] / p_face - 1), worst_place);
    CHECK(worst_place < 1e-9);
    CHECK(std::abs(sensor[0] / p_face - 1) < 0.03);
    CHECK(std::abs(sensor[1] / p_face - 1) < 0.03);
    CHECK(std::abs(means[0] / hydrostatic - 1) < 0.08);
    CHECK(std::abs(means[0] / means[1] - 1) < 0.01);
}
