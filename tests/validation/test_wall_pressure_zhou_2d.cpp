// The Zhou/Buchner dam break (perf/impact/zhou_2d.toml) at H/30: the wall pressure at Buchner's
// sensor P1 (0.16 m above the floor), as the case's area sensor P1_area reads it (the fluid's
// normal force on a 9 mm face of the wall), against De Courcy et al. (2024)'s incompressible
// delta-SPH at H/400 sampled at the same height (perf/impact/data/decourcy2024_y160mm_sim.csv).
//
// Two windows of t* = t sqrt(g/H) after the first impact: 3.4-5.0 (the water piling up against
// the wall) and 5.0-6.0 (before the second impact), and the arrival of the second impact (the
// first t* after 5.5 where the 10 ms average exceeds 0.75 rho g H). Measured (2026-11-29, one
// thread): this run reads 0.377 and 0.441 rho g H and t* = 6.33, against De Courcy's 0.363,
// 0.465 and 6.32. Four runs of perf/impact/run.sh at H/30 (c0 = 20 sqrt(gH) = 48.522 m/s where
// the case says 48.52, lattice jitter 0 to 0.01 dx) read 0.367-0.383, 0.459-0.484 and
// 6.16-6.41: that is how far a harmless change moves these figures. Guards: 0.05 rho g H and
// 0.25 t*. At H/60 sluice reads 0.371, 0.470 and 6.35, and TrixiParticles.jl at H/400 (WCSPH
// and EDAC) 0.368-0.372, 0.463-0.469 and 6.38-6.41 (perf/impact/p1_references.py).
//
// Buchner's record at the same sensor reads 0.543 and 0.598 over the two windows and its second
// impact arrives at t* = 5.81: the four simulations agree with each other and not with the
// record there (docs/IMPACT_LOADS.md, "P1 against three other codes"). The test prints that gap;
// it guards sluice's agreement with an independent code, not a match with the record.
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace sluice;
using namespace sluice::testing;

namespace {

constexpr double H = 0.6, g = 9.81, rho0 = 1000.0;
const double t_scale = std::sqrt(g / H); // t* = t * t_scale
constexpr double p_scale = rho0 * g * H;

// A signal p*(t*) on increasing times (a dry probe's NaN counts as zero).
struct PressureRecord {
    std::vector<double> t, p;
};

PressureRecord read_signal(const std::string& path, double t_factor, double p_factor) {
    std::vector<std::pair<double, double>> rows;
    for (const auto& r : read_csv(path)) {
        const double p = std::stod(r.at(1));
        rows.emplace_back(std::stod(r.at(0)) * t_factor, std::isfinite(p) ? p * p_factor : 0.0);
    }
    // A digitised curve has a few points out of time order (as in its source).
    std::stable_sort(rows.begin(), rows.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    PressureRecord s;
    for (const auto& [t, p] : rows) {
        s.t.push_back(t);
        s.p.push_back(p);
    }
    return s;
}

// Integral of the piecewise-linear signal from its start to every sample.
std::vector<double> cumulative(const PressureRecord& s) {
    std::vector<double> c(s.t.size(), 0.0);
    for (std::size_t k = 1; k < s.t.size(); ++k)
        c[k] = c[k - 1] + 0.5 * (s.p[k] + s.p[k - 1]) * (s.t[k] - s.t[k - 1]);
    return c;
}

// Mean over [a, b] (inside the record).
double window_mean(const PressureRecord& s, double a, double b) {
    REQUIRE(s.t.front() <= a);
    REQUIRE(s.t.back() >= b);
    const std::vector<double> c = cumulative(s);
    return (interpolate(s.t, c, b) - interpolate(s.t, c, a)) / (b - a);
}

// First t* >= from where the centred moving average over `width` (t*) exceeds `level`; NaN
// if it never does.
double first_exceeding(const PressureRecord& s, double from, double width, double level) {
    const std::vector<double> c = cumulative(s);
    for (double t = from; t + width / 2 <= s.t.back(); t += 1e-3) {
        const double mean =
            (interpolate(s.t, c, t + width / 2) - interpolate(s.t, c, t - width / 2)) / width;
        if (mean > level)
            return t;
    }
    return std::nan("");
}

} // namespace

TEST_CASE("Zhou/Buchner wall pressure at P1 (0.16 m) agrees with De Courcy et al. (2024)") {
    const std::string root = SLUICE_SOURCE_DIR;
    const CaseConfig cfg =
        read_case(root + "/perf/impact/zhou_2d.toml",
                  {"particles.dx=0.02", "time.end_time=1.65", "output.snapshots=false"});
    const FolderRun run = run_in_temp_folder(cfg, "wall_pressure_zhou", 1);
    const PressureRecord sim =
        read_signal(run.folder + "/probes/P1_area.csv", t_scale, 1.0 / p_scale);
    std::filesystem::remove_all(run.folder);

    const std::string data = root + "/perf/impact/data/";
    const PressureRecord code = read_signal(data + "decourcy2024_y160mm_sim.csv", 1.0, 1.0);
    const PressureRecord record = read_signal(data + "buchner2002_P1.csv", 1.0, 1.0);

    const double average = 0.010 * t_scale; // 10 ms in t*
    struct Reading {
        double piling, before, arrival;
    };
    auto reading = [&](const PressureRecord& s) {
        return Reading{window_mean(s, 3.4, 5.0), window_mean(s, 5.0, 6.0),
                       first_exceeding(s, 5.5, average, 0.75)};
    };
    const Reading r_sim = reading(sim), r_code = reading(code), r_record = reading(record);
    std::printf("Zhou P1 at H/30 (%ld steps): mean p/(rho g H) over t* 3.4-5.0 / 5.0-6.0 and the "
                "second impact's arrival:\n"
                "  sluice          %.3f / %.3f  t* = %.2f\n"
                "  De Courcy 2024  %.3f / %.3f  t* = %.2f\n"
                "  Buchner record  %.3f / %.3f  t* = %.2f  (not a guard: the codes agree with each "
                "other, not with it)\n",
                run.result.steps, r_sim.piling, r_sim.before, r_sim.arrival, r_code.piling,
                r_code.before, r_code.arrival, r_record.piling, r_record.before, r_record.arrival);
    CHECK(std::abs(r_sim.piling - r_code.piling) < 0.05);
    CHECK(std::abs(r_sim.before - r_code.before) < 0.05);
    REQUIRE(std::isfinite(r_sim.arrival));
    CHECK(std::abs(r_sim.arrival - r_code.arrival) < 0.25);
}
