// Piston and flap wave-makers in a short 2-D flume (h = 0.2 m, kh = 1, H = 3 cm, dx = 2 cm,
// a damping zone from one wavelength on): a quarter wavelength from the paddle the wave's
// height (twice the first-harmonic amplitude over the last three periods) is the requested
// one, which linear wave-maker theory turned into the paddle's stroke, within 5 %, and its
// zero up-crossing period is the paddle's within 1 %. A guard on the generation: the wave
// then loses height along the flume (about 2 % per quarter wavelength over the first half
// wavelength here); perf/wave_flume/flume.py measures the height at two wavelengths over
// kh = 0.3 to 3 (docs/MOVING_WALLS.md).
#include "sluice/motion/wave_theory.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

using namespace sluice;
using namespace sluice::testing;

namespace {

constexpr double kH = 0.2, kKh = 1.0, kHeight = 0.03, kG = 9.81, kDx = 0.02;

struct Flume {
    double k, T, L, gauge, end;
};

Flume flume() {
    Flume f;
    f.k = kKh / kH;
    f.T = 2 * std::numbers::pi / std::sqrt(kG * f.k * std::tanh(kKh));
    f.L = 2 * std::numbers::pi / f.k;
    f.gauge = 0.25 * f.L;
    const double c = f.L / f.T;
    const double cg = c / 2 * (1 + 2 * kKh / std::sinh(2 * kKh));
    f.end = 2 * f.T + f.gauge / cg + 3.5 * f.T;
    return f;
}

std::string flume_case(const std::string& motion, const Flume& f) {
    const double length = 1.75 * f.L;
    const auto n = [](double v) { return std::to_string(v); };
    return "[case]\ndimension = 2\n"
           "[domain]\nlo = [-0.2, 0]\nhi = [" +
           n(length) +
           ", 0.35]\n"
           "[fluid]\nrho0 = 1000\nviscosity = 1e-6\nsound_speed = 14\ngravity = [0, -9.81]\n"
           "[particles]\ndx = " +
           n(kDx) +
           "\n"
           "[[blocks]]\nlo = [0, 0]\nhi = [" +
           n(length) +
           ", 0.2]\n"
           "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.02\n"
           "[walls]\nmodel = \"dummy\"\ntank_lo = [-0.2, 0]\ntank_hi = [" +
           n(length) +
           ", 0.35]\ntank_faces = [\"x+\", \"y-\"]\n"
           "[[walls.boxes]]\nlo = [" +
           n(-4 * kDx) + ", 0]\nhi = [0, 0.35]\nmotion = \"paddle\"\n" + motion +
           "wave_height = " + n(kHeight) + "\nwave_period = " + n(f.T) +
           "\ndepth = 0.2\nramp = " + n(2 * f.T) +
           "\n"
           "[[damping_zones]]\nstart = [" +
           n(f.L) + ", 0]\nend = [" + n(length) + ", 0]\nstrength = " + n(10 / f.T) +
           "\n"
           "[time]\nend_time = " +
           n(f.end) +
           "\n"
           "[[probes]]\nname = \"eta\"\ntype = \"water_level\"\nx = " +
           n(f.gauge) + "\ninterval = " + n(f.T / 50) + "\n";
}

struct Wave {
    double height, period;
};

// The first two harmonics of the gauge's record over its last three periods (least squares)
// and its mean zero up-crossing period there.
Wave measure(const std::string& motion, const std::string& tag) {
    const Flume f = flume();
    const CaseConfig cfg = read_case_text(flume_case(motion, f), tag + ".toml");
    const FolderRun run = run_in_temp_folder(cfg, tag, 2);
    std::vector<double> t, eta;
    for (const auto& row : read_csv(run.folder + "/probes/eta.csv")) {
        const double s = std::stod(row.at(0));
        if (s >= f.end - 3 * f.T) {
            t.push_back(s);
            eta.push_back(std::stod(row.at(1)));
        }
    }
    std::filesystem::remove_all(run.folder);
    REQUIRE(t.size() > 100);
    const double w = 2 * std::numbers::pi / f.T;
    Eigen::MatrixXd A(static_cast<Eigen::Index>(t.size()), 5);
    Eigen::VectorXd b(static_cast<Eigen::Index>(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i) {
        const auto r = static_cast<Eigen::Index>(i);
        A.row(r) << std::cos(w * t[i]), std::sin(w * t[i]), std::cos(2 * w * t[i]),
            std::sin(2 * w * t[i]), 1.0;
        b[r] = eta[i];
    }
    const Eigen::VectorXd c = A.colPivHouseholderQr().solve(b);
    double mean = 0;
    for (double e : eta)
        mean += e / static_cast<double>(eta.size());
    const double band = 0.1 * kHeight;
    std::vector<double> up;
    bool armed = false;
    for (std::size_t i = 1; i < t.size(); ++i) {
        const double a = eta[i - 1] - mean, e = eta[i] - mean;
        armed = armed || a < -band;
        if (armed && a < 0 && e >= 0) {
            up.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-a) / (e - a));
            armed = false;
        }
    }
    REQUIRE(up.size() >= 3);
    return {2 * std::hypot(c[0], c[1]),
            (up.back() - up.front()) / static_cast<double>(up.size() - 1)};
}

void check(const char* what, const Wave& w) {
    const double T = flume().T;
    std::printf("%s (kh = %.2f, H = %.3f m, T = %.4f s): height a quarter wavelength out %.4f m "
                "(%+.2f %%), period %.4f s (%+.2f %%)\n",
                what, kKh, kHeight, T, w.height, 100 * (w.height / kHeight - 1), w.period,
                100 * (w.period / T - 1));
    CHECK(std::abs(w.height / kHeight - 1) < 0.05);
    CHECK(std::abs(w.period / T - 1) < 0.01);
}

} // namespace

TEST_CASE("Piston wave-maker: the requested height and period a quarter wavelength out") {
    check("piston", measure("[[motions]]\nname = \"paddle\"\nkind = \"piston\"\n", "piston"));
}

TEST_CASE("Flap wave-maker hinged at the bed: the requested height and period") {
    check("flap",
          measure("[[motions]]\nname = \"paddle\"\nkind = \"flap\"\ncentre = [0, 0]\n", "flap"));
}
