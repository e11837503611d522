// WMLS gradient/Laplacian error and stencil quality with radius against convex-hull
// neighbours on particle sets deformed by motion (perf/convex_hull/README.md, "Operator error
// on deformed sets"): a block carried by a shear flow and by a stretching flow
// (tests/validation/hull_deformed_sets.hpp gives the sets, the field and the measures), and
// snapshots of the 2-D dam break (cases/dam_break_2d.toml, WCSPH) in its run-up jet and its
// splash, fluid and wall particles as the run left them. Everything goes through
// selected_operators, the function the projection scheme's stencil stage calls, with its
// settings (re = 3.1 dx, PNU-MPS weight, candidates within re).
// Usage: bench_hull_deformed [dam-break dx = 0.02] [snapshot times = 0.6,1.1]
#include "hull_deformed_sets.hpp"

#include "sluice/io/case_reader.hpp"
#include "sluice/physics/free_surface.hpp"
#include "sluice/solver/simulation.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

using namespace sluice;
using namespace sluice::testing;

namespace {

constexpr DeformedSelection kSelections[] = {DeformedSelection::radius, DeformedSelection::hull,
                                             DeformedSelection::hull_union};

template <class Which>
void print_rows(const DeformedSet& s, const char* part, Which which) {
    for (DeformedSelection sel : kSelections) {
        const DeformedErrors e = deformed_errors(s, sel, which);
        std::printf("%-24s %-9s %-14s %6d %10.3e %10.3e %7d %7.1f %7.2f %8.2f\n", s.name.c_str(),
                    part, deformed_selection_name(sel), e.scored, e.gradient, e.laplacian, e.not_ok,
                    e.mean_neighbours, e.mean_abs_ratio, e.max_abs_ratio);
    }
}

void header() {
    std::printf("%-24s %-9s %-14s %6s %10s %10s %7s %7s %7s %8s\n", "set", "part", "neighbours",
                "scored", "E_grad", "E_lap", "not ok", "mean n", "|L|/L", "max|L|/L");
}

// The dam break at time t: fluid and wall particles; scored: fluid. `surface` marks the fluid
// particles the radius arc test (2.1 dx) puts on the free surface.
DeformedSet dam_break_snapshot(double dx, double t, std::vector<char>& surface) {
    const CaseConfig cfg =
        read_case(std::string(SLUICE_SOURCE_DIR) + "/cases/dam_break_2d.toml",
                  {"particles.dx=" + std::to_string(dx), "time.end_time=" + std::to_string(t)});
    Simulation<2> sim(cfg);
    while (sim.time() < t * (1 - 1e-12))
        sim.step();
    const Particles<2>& P = sim.particles();
    DeformedSet s;
    char name[64];
    std::snprintf(name, sizeof name, "dam break t = %.2f s", t);
    s.name = name;
    s.dx = Real(cfg.dx);
    for (std::size_t i = 0; i < P.size(); ++i) {
        s.x.push_back(P.x[i]);
        s.scored.push_back(P.kind[i] == Kind::fluid ? 1 : 0);
    }
    const Real re = 3.1 * s.dx;
    surface.assign(s.x.size(), 0);
    std::vector<Vec<2>> off;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (s.scored[i] == 0)
            continue;
        off.clear();
        for (std::size_t j = 0; j < s.x.size(); ++j)
            if (j != i && (s.x[j] - s.x[i]).squaredNorm() < re * re)
                off.push_back(s.x[j] - s.x[i]);
        surface[i] = is_free_surface<2>(off, 2.1 * s.dx) ? 1 : 0;
    }
    Real ymax = 0;
    for (std::size_t i = 0; i < s.x.size(); ++i)
        if (s.scored[i] != 0)
            ymax = std::max(ymax, s.x[i].y());
    std::printf("# %s: %zu particles, highest fluid particle at y = %.3f m, %ld steps\n", name,
                s.x.size(), static_cast<double>(ymax), sim.steps());
    return s;
}

} // namespace

int main(int argc, char** argv) {
    const double dx = argc > 1 ? std::atof(argv[1]) : 0.02;
    std::vector<double> times = {0.6, 1.1};
    if (argc > 2) {
        times.clear();
        std::stringstream in(argv[2]);
        for (std::string t; std::getline(in, t, ',');)
            times.push_back(std::atof(t.c_str()));
    }
    std::printf("WMLS (PNU-MPS, re = 3.1 dx) relative L2 errors, f = sin(x/L) cos(y/L), "
                "L = 10 dx\n");
    header();
    const auto all = [](std::size_t) { return true; };
    for (Real strain : {0.0, 1.0, 2.0, 4.0}) {
        char name[64];
        std::snprintf(name, sizeof name, "sheared, strain %.0f", strain);
        print_rows(deformed_block(name, shear_map(strain), 60, 0.01, 11), "all", all);
    }
    for (Real aspect : {1.0, 4.0, 16.0}) {
        char name[64];
        std::snprintf(name, sizeof name, "stretched, aspect %.0f", aspect);
        print_rows(deformed_block(name, stretch_map(aspect), 60, 0.01, 12), "all", all);
    }
    for (double t : times) {
        std::vector<char> surface;
        const DeformedSet s = dam_break_snapshot(dx, t, surface);
        print_rows(s, "interior", [&](std::size_t i) { return surface[i] == 0; });
        print_rows(s, "surface", [&](std::size_t i) { return surface[i] != 0; });
    }
    return 0;
}
