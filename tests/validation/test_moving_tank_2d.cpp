// A 2-D tank (0.4 m long, 0.2 m of water, dx = 0.01 m) that moves, read by probes that move
// with it (cases written here, run the command line's way):
// - Galilean check: the tank and its water moving at a constant 0.5 m/s read the same pressure
//   and level in the tank's frame as the tank at rest;
// - constant acceleration a = 1 m/s^2 along x: the free surface tilts by atan(a/g) and the
//   pressure in the tilted frame is hydrostatic under g - a, both within 2 %;
// - free sloshing after a velocity step: the first natural period against linear theory,
//   omega1^2 = g k1 tanh(k1 h), k1 = pi / L, within 2 %;
// - an area sensor on the rear wall (2 cm face, 5 cm above the floor) moves with the tank: it
//   reads the same in the Galilean check, the hydrostatics under g - a in the accelerating
//   tank, and rho g times its depth in a tank rolled slowly by 5 degrees (the force reading
//   on both side walls, the interpolated one on the rear wall).
#include "validation_support.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <vector>

using namespace sluice;
using namespace sluice::testing;

namespace {

constexpr double kL = 0.4, kH = 0.2, kRho = 1000, kG = 9.81;

// The gauges' positions along the tank (in its frame) and their probe names.
const std::vector<double> kGaugeX{0.05, 0.10, 0.15, 0.20, 0.25, 0.30, 0.35};
std::string gauge_name(std::size_t k) {
    return fmt::format("h{}", k);
}

// The tank case; `motion` is the [[motions]] entry (empty: a fixed tank), `domain_hi_x` how far
// the tank may travel, `velocity` the water's initial velocity. Probes: pressure 5 cm above the
// floor 5 cm from the rear (x-) and the front (x+) wall, the gauges, a gauge by the rear
// wall (1.5 dx from it), and an area sensor on the rear wall 5 cm above the floor (it moves
// with its wall without being told).
std::string tank_case(const std::string& motion, double end_time, double domain_hi_x,
                      double velocity = 0) {
    const bool moving = !motion.empty();
    const std::string frame =
        std::string("interval = 0.005\n") + (moving ? "frame = \"tank\"\n" : "");
    std::string probes =
        "[[probes]]\nname = \"p_rear\"\ntype = \"pressure\"\nposition = [0.05, 0.05]\n" + frame +
        "[[probes]]\nname = \"p_front\"\ntype = \"pressure\"\nposition = [0.35, 0.05]\n" + frame +
        "[[probes]]\nname = \"h_wall\"\ntype = \"water_level\"\nx = 0.015\n" + frame +
        "[[probes]]\nname = \"s_rear\"\ntype = \"pressure\"\nposition = [0, 0.05]\n"
        "diameter = 0.02\ninterval = 0.005\n";
    for (std::size_t k = 0; k < kGaugeX.size(); ++k)
        probes += "[[probes]]\nname = \"" + gauge_name(k) +
                  "\"\ntype = \"water_level\"\nx = " + std::to_string(kGaugeX[k]) + "\n" + frame;
    return "[case]\ndimension = 2\n"
           "[domain]\nlo = [0, 0]\nhi = [" +
           std::to_string(domain_hi_x) +
           ", 0.3]\n"
           "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 15\ngravity = [0, -9.81]\n"
           "[particles]\ndx = 0.01\n"
           "[[blocks]]\nlo = [0, 0]\nhi = [0.4, 0.2]\nvelocity = [" +
           std::to_string(velocity) +
           ", 0]\n"
           "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.02\n"
           "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0]\ntank_hi = [0.4, 0.3]\n"
           "tank_faces = [\"x-\", \"x+\", \"y-\"]\n" +
           (moving ? "tank_motion = \"tank\"\n" + motion : std::string()) +
           "[time]\nend_time = " + std::to_string(end_time) + "\n" + probes;
}

struct Series {
    std::vector<double> t, v;
    // Mean over [t0, t1].
    [[nodiscard]] double mean(double t0, double t1) const {
        double s = 0;
        int n = 0;
        for (std::size_t i = 0; i < t.size(); ++i)
            if (t[i] >= t0 && t[i] <= t1) {
                s += v[i];
                ++n;
            }
        REQUIRE(n > 10);
        return s / n;
    }
};

// Runs the case text and returns its probes' series by name.
struct TankRun {
    std::map<std::string, Series> probe;
    [[nodiscard]] const Series& operator[](const std::string& name) const { return probe.at(name); }
};
TankRun run_tank(const std::string& text, const std::string& tag) {
    const CaseConfig cfg = read_case_text(text, tag + ".toml");
    const FolderRun run = run_in_temp_folder(cfg, tag, 2);
    TankRun r;
    for (const ProbeConfig& p : cfg.probes) {
        Series s;
        for (const auto& row : read_csv(run.folder + "/probes/" + p.name + ".csv")) {
            s.t.push_back(std::stod(row.at(0)));
            s.v.push_back(std::stod(row.at(1)));
        }
        REQUIRE(s.t.size() > 100);
        r.probe[p.name] = s;
    }
    std::filesystem::remove_all(run.folder);
    return r;
}

// The least-squares slope of the gauges' mean levels over [t0, t1] against their positions.
double surface_slope(const TankRun& r, double t0, double t1) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const auto n = static_cast<double>(kGaugeX.size());
    for (std::size_t k = 0; k < kGaugeX.size(); ++k) {
        const double x = kGaugeX[k], y = r[gauge_name(k)].mean(t0, t1);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

TEST_CASE("Galilean check: a tank moving at constant velocity reads as one at rest") {
    const double u = 0.5, end = 1.0;
    const TankRun rest = run_tank(tank_case("", end, 0.4), "tank_rest");
    const TankRun moving =
        run_tank(tank_case("[[motions]]\nname = \"tank\"\nkind = \"constant_velocity\"\n"
                           "velocity = [0.5, 0]\n",
                           end, 0.4 + u * end + 0.2, u),
                 "tank_moving");
    const double p_rest = rest["p_rear"].mean(0.3, end);
    const double p_moving = moving["p_rear"].mean(0.3, end);
    const double h_rest = rest["h0"].mean(0.3, end), h_moving = moving["h0"].mean(0.3, end);
    const double s_rest = rest["s_rear"].mean(0.3, end);
    const double s_moving = moving["s_rear"].mean(0.3, end);
    const double p_hyd = kRho * kG * (kH - 0.05);
    std::printf("Galilean: rear pressure at rest %.2f Pa, moving %.2f Pa (hydrostatic %.2f Pa); "
                "rear level at rest %.5f m, moving %.5f m; rear wall sensor at rest %.2f Pa, "
                "moving %.2f Pa\n",
                p_rest, p_moving, p_hyd, h_rest, h_moving, s_rest, s_moving);
    CHECK(std::abs(p_moving - p_rest) < 0.005 * p_hyd);
    CHECK(std::abs(h_moving - h_rest) < 0.001);
    CHECK(std::abs(p_rest - p_hyd) < 0.02 * p_hyd);
    CHECK(std::abs(s_moving - s_rest) < 0.005 * p_hyd);
    CHECK(std::abs(s_rest - p_hyd) < 0.02 * p_hyd);
}

TEST_CASE("Constant acceleration: the surface tilts by atan(a/g), hydrostatics under g - a") {
    const double a = 1.0, ramp = 1.5, end = 3.5;
    const TankRun r =
        run_tank(tank_case("[[motions]]\nname = \"tank\"\nkind = \"constant_acceleration\"\n"
                           "acceleration = [1.0, 0]\nramp = 1.5\n",
                           end, 4.6),
                 "tank_accel");
    // After the ramp: averaged over two first-mode periods (0.75 s each) of residual sloshing.
    const double t0 = ramp + 0.5;
    const double slope = -surface_slope(r, t0, end);
    const double p_rear = r["p_rear"].mean(t0, end), p_front = r["p_front"].mean(t0, end);
    // Hydrostatics under g - a: the surface through the tank's middle at the rest level
    // (volume), p = rho (g (h - y) - a (x - L/2)); its horizontal gradient is rho a.
    const double p_theory = kRho * (kG * (kH - 0.05) + a * (kL / 2 - 0.05));
    const double gradient = (p_rear - p_front) / 0.3;
    // The wall sensor at x = 0: the wall's pressure, extrapolated with g - a_w.
    const double s_rear = r["s_rear"].mean(t0, end);
    const double s_theory = kRho * (kG * (kH - 0.05) + a * kL / 2);
    std::printf("acceleration: rear wall sensor %.2f Pa (theory %.2f Pa, %+.2f %%)\n", s_rear,
                s_theory, 100 * (s_rear / s_theory - 1));
    CHECK(std::abs(s_rear / s_theory - 1) < 0.02);
    std::printf("acceleration: surface slope %.5f over %zu gauges (a/g = %.5f, %+.2f %%), rear "
                "pressure %.2f Pa (theory %.2f Pa, %+.2f %%), horizontal pressure gradient "
                "%.2f Pa/m (rho a = %.2f, %+.2f %%)\n",
                slope, kGaugeX.size(), a / kG, 100 * (slope / (a / kG) - 1), p_rear, p_theory,
                100 * (p_rear / p_theory - 1), gradient, kRho * a,
                100 * (gradient / (kRho * a) - 1));
    CHECK(std::abs(std::atan(slope) / std::atan(a / kG) - 1) < 0.02);
    CHECK(std::abs(p_rear / p_theory - 1) < 0.02);
    CHECK(std::abs(gradient / (kRho * a) - 1) < 0.02);
}

TEST_CASE("Free sloshing: the first natural period against linear theory within 2 %") {
    const double end = 5.0;
    const TankRun r =
        run_tank(tank_case("[[motions]]\nname = \"tank\"\nkind = \"constant_velocity\"\n"
                           "velocity = [0.1, 0]\nramp = 0.2\n",
                           end, 0.4 + 0.1 * end + 0.2),
                 "tank_slosh");
    // Upward crossings of the level at the rear wall through its mean, after the ramp; a
    // crossing counts once the level has been a band below the mean (the gauge's noise).
    const double t0 = 0.5, band = 1e-3;
    const Series& h = r["h_wall"];
    const double mean = h.mean(t0, end);
    std::vector<double> crossings;
    bool armed = false;
    for (std::size_t i = 1; i < h.t.size(); ++i) {
        if (h.t[i - 1] < t0)
            continue;
        const double a = h.v[i - 1] - mean, b = h.v[i] - mean;
        armed = armed || a < -band;
        if (armed && a < 0 && b >= 0) {
            crossings.push_back(h.t[i - 1] + (h.t[i] - h.t[i - 1]) * (-a) / (b - a));
            armed = false;
        }
    }
    REQUIRE(crossings.size() >= 4);
    const double period =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    const double k1 = std::numbers::pi / kL;
    const double theory = 2 * std::numbers::pi / std::sqrt(kG * k1 * std::tanh(k1 * kH));
    std::printf("sloshing: first-mode period %.4f s over %zu crossings, linear theory %.4f s "
                "(%+.2f %%)\n",
                period, crossings.size(), theory, 100 * (period / theory - 1));
    CHECK(std::abs(period / theory - 1) < 0.02);
}

TEST_CASE("Quasi-static roll: a wall sensor on the rolling tank reads rho g times its depth") {
    // The tank rolls by theta(t) = 5 deg sin(2 pi t / 6 s) about the middle of its floor, with
    // a 1.5 s ramp: 8 first-mode periods per roll period, so the surface stays level (in the
    // tank's frame it tilts by -theta through the middle of the rest surface, (L/2, H), which
    // keeps the volume). A sensor at s on a side wall then reads rho g (up . ((L/2, H) - s)),
    // up = (sin theta, cos theta) the vertical seen from the tank: the rear (x = 0) and front
    // (x = L) sensors 5 cm above the floor differ by -rho g L sin theta, and their mean is
    // rho g (H - 0.05) cos theta. The roll's dynamics (forcing at (omega/omega1)^2 = 0.016 of
    // resonance, the horizontal acceleration of the water about the floor) leave about 3 % of
    // that difference.
    const double t0 = 1.5, y_s = 0.05;
    const std::string sensor = "type = \"pressure\"\ndiameter = 0.02\ninterval = 0.005\n";
    const std::string text =
        "[case]\ndimension = 2\n[domain]\nlo = [-0.1, -0.1]\nhi = [0.5, 0.4]\n"
        "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 15\ngravity = [0, -9.81]\n"
        "[particles]\ndx = 0.01\n[[blocks]]\nlo = [0, 0]\nhi = [0.4, 0.2]\n"
        "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.02\n"
        "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0]\ntank_hi = [0.4, 0.3]\n"
        "tank_faces = [\"x-\", \"x+\", \"y-\"]\ntank_motion = \"roll\"\n"
        "[[motions]]\nname = \"roll\"\nkind = \"roll\"\nangle = 5.0\nperiod = 6.0\n"
        "centre = [0.2, 0.0]\nramp = 1.5\n"
        "[time]\nend_time = 4.5\n"
        "[[probes]]\nname = \"s_rear\"\nposition = [0, 0.05]\n" +
        sensor + "[[probes]]\nname = \"s_front\"\nposition = [0.4, 0.05]\n" + sensor +
        "[[probes]]\nname = \"s_rear_interpolated\"\nposition = [0, 0.05]\nreading = "
        "\"interpolated\"\n" +
        sensor +
        "[[probes]]\nname = \"angle\"\ntype = \"motion\"\nframe = \"roll\"\ninterval = 0.005\n";
    const CaseConfig cfg = read_case_text(text, "tank_roll.toml");
    const FolderRun run = run_in_temp_folder(cfg, "tank_roll", 2);
    const auto rear = read_csv(run.folder + "/probes/s_rear.csv");
    const auto front = read_csv(run.folder + "/probes/s_front.csv");
    const auto interpolated = read_csv(run.folder + "/probes/s_rear_interpolated.csv");
    const auto angle = read_csv(run.folder + "/probes/angle.csv");
    std::filesystem::remove_all(run.folder);
    REQUIRE(rear.size() == angle.size());
    REQUIRE(front.size() == angle.size());
    REQUIRE(interpolated.size() == angle.size());
    // Least squares of the difference against -rho g L sin theta, of the mean against
    // rho g (H - y_s) cos theta; the sensor's reported centre against the rolled point.
    double sdd = 0, sdt = 0, stt = 0, mean_err = 0, worst_place = 0, swing = 0, interp_err = 0;
    int n = 0;
    for (std::size_t k = 0; k < angle.size(); ++k) {
        const double t = std::stod(angle[k].at(0));
        const double th = std::stod(angle[k].at(3)) * std::numbers::pi / 180;
        // The rear sensor's centre (0, y_s) turned about (L/2, 0).
        const double cx = kL / 2 + (0 - kL / 2) * std::cos(th) - y_s * std::sin(th);
        const double cy = (0 - kL / 2) * std::sin(th) + y_s * std::cos(th);
        worst_place = std::max({worst_place, std::abs(std::stod(rear[k].at(2)) - cx),
                                std::abs(std::stod(rear[k].at(3)) - cy),
                                std::abs(std::stod(rear[k].at(4)) + std::cos(th)),
                                std::abs(std::stod(rear[k].at(5)) + std::sin(th))});
        if (t < t0)
            continue;
        const double pr = std::stod(rear[k].at(1)), pf = std::stod(front[k].at(1));
        const double d_theory = -kRho * kG * kL * std::sin(th);
        sdd += (pf - pr) * d_theory;
        stt += d_theory * d_theory;
        sdt += (pf - pr) - d_theory;
        mean_err += (pf + pr) / 2 - kRho * kG * (kH - y_s) * std::cos(th);
        swing = std::max(swing, std::abs(d_theory));
        // The interpolated reading of the rear face against rho g times its depth.
        const double rear_theory = kRho * kG * (kL / 2 * std::sin(th) + (kH - y_s) * std::cos(th));
        interp_err += std::abs(std::stod(interpolated[k].at(1)) / rear_theory - 1);
        ++n;
    }
    REQUIRE(n > 500);
    const double gain = sdd / stt; // the measured difference over the theory's
    mean_err /= n;
    interp_err /= n;
    std::printf("roll: front - rear sensor difference against -rho g L sin theta: gain %.4f "
                "(%+.2f %%; swing %.1f Pa, mean offset %+.2f Pa); mean of the two against "
                "rho g (H - y) cos theta: %+.2f Pa (%+.2f %%); sensor centre and normal against "
                "the rolled ones: %.2g; interpolated rear reading against rho g depth: mean "
                "|deviation| %.2f %%\n",
                gain, 100 * (gain - 1), swing, sdt / n, mean_err,
                100 * mean_err / (kRho * kG * (kH - y_s)), worst_place, 100 * interp_err);
    CHECK(worst_place < 1e-9);
    CHECK(std::abs(gain - 1) < 0.06);
    CHECK(std::abs(mean_err) < 0.02 * kRho * kG * (kH - y_s));
    CHECK(interp_err < 0.03);
}
