// Solid obstacles ([[walls.boxes]]): the box's lattice sites within `layers` of its surface
// become dummy wall particles; counts match `sluice info`'s estimate; the reader refuses boxes
// that overlap fluid, other boxes or the tank walls; and a surge cannot pass through a box.
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/solver/built_geometry.hpp"
#include "sluice/solver/case_check.hpp"
#include "sluice/solver/initial_state.hpp"
#include "sluice/solver/run.hpp"
#include "sluice/solver/simulation.hpp"

#include "case_files.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace sluice;
namespace fs = std::filesystem;
using sluice::testing::write_case;

namespace {

// A 0.2 m x 0.3 m column collapsing towards a 6 cm thick, 1 m tall solid box at x = 0.4 m.
std::string barrier_case(const std::string& box_lo = "[0.4, 0.0]",
                         const std::string& model = "dummy") {
    return R"(
[case]
name = "barrier"
dimension = 2
[domain]
lo = [0.0, 0.0]
hi = [1.0, 1.2]
[fluid]
rho0 = 1000.0
viscosity = 1.0e-3
sound_speed = 17.0
[particles]
dx = 0.01
[[blocks]]
lo = [0.0, 0.0]
hi = [0.2, 0.3]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
artificial_viscosity = 0.02
[walls]
model = ")" +
           model + R"("
tank_lo = [0.0, 0.0]
tank_hi = [1.0, 1.2]
tank_faces = ["x-", "x+", "y-"]
[[walls.boxes]]
lo = )" + box_lo +
           R"(
hi = [0.46, 1.0]
[time]
end_time = 0.25
)";
}

std::string error_key(const std::string& text, const std::vector<std::string>& overrides = {}) {
    try {
        (void)read_case(write_case("bad", text), overrides);
    } catch (const CaseError& e) {
        return e.key();
    }
    return "(no error)";
}

template <int D>
std::size_t walls_inside(const Particles<D>& P, const WallBox& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        bool in = P.kind[i] == Kind::wall;
        for (int d = 0; d < D; ++d)
            in = in && P.x[i][d] > b.lo[d] && P.x[i][d] < b.hi[d];
        n += in ? 1 : 0;
    }
    return n;
}

} // namespace

TEST_CASE("a wall box is its lattice sites within `layers` of its surface") {
    const CaseConfig cfg = read_case(write_case("barrier", barrier_case()));
    REQUIRE(cfg.boxes.size() == 1);
    // 6 x 100 sites; with 3 layers a 6-site-thick box has no interior to leave out.
    for (int layers : {2, 3}) {
        Particles<2> P;
        add_wall_particles<2>(cfg, layers, P);
        CHECK(P.size() == count_wall_particles(cfg, layers));
        CHECK(walls_inside(P, cfg.boxes[0]) == (layers == 3 ? 600u : 600u - 2u * 96u));
    }
    // A 10 x 20 site box, 3 layers: 200 - 4 x 14 interior sites.
    CaseConfig thick = cfg;
    thick.boxes[0] = WallBox{{0.5, 0.1, 0}, {0.6, 0.3, 0}};
    Particles<2> P;
    add_wall_particles<2>(thick, 3, P);
    CHECK(walls_inside(P, thick.boxes[0]) == 144u);
    CHECK(P.size() == count_wall_particles(thick, 3));
    // Every box particle sits on the lattice dx/2 inside the box and at most 3 dx deep.
    for (std::size_t i = 0; i < P.size(); ++i) {
        const Vec<2> x = P.x[i];
        if (!(x[0] > 0.5 && x[0] < 0.6 && x[1] > 0.1 && x[1] < 0.3))
            continue;
        const double depth = std::min({x[0] - 0.5, 0.6 - x[0], x[1] - 0.1, 0.3 - x[1]});
        CHECK(depth > 0.005 - 1e-12);
        CHECK(depth < 0.03);
    }
}

TEST_CASE("the 3-D obstacle of perf/cases/dam_break_3d_obstacle.toml") {
    const CaseConfig cfg =
        read_case(std::string(SLUICE_SOURCE_DIR) + "/perf/cases/dam_break_3d_obstacle.toml");
    REQUIRE(cfg.boxes.size() == 1);
    CHECK(count_fluid_particles(cfg) == 47u * 79u * 35u);
    const double support = 2 * cfg.h_over_dx * cfg.dx; // cubic spline: 2h
    const int layers = wall_layers(support, cfg.dx);
    CHECK(layers == 4);
    CaseConfig no_box = cfg;
    no_box.boxes.clear();
    // 14 x 14 x 53 sites, less the 6 x 6 x 45 more than 4 layers deep.
    CHECK(count_wall_particles(cfg, layers) - count_wall_particles(no_box, layers) ==
          14u * 14u * 53u - 6u * 6u * 45u);
    Particles<3> P;
    add_wall_particles<3>(cfg, layers, P);
    CHECK(P.size() == count_wall_particles(cfg, layers));
    CHECK(walls_inside(P, cfg.boxes[0]) == 14u * 14u * 53u - 6u * 6u * 45u);
}

TEST_CASE("wall boxes are validated") {
    CHECK(error_key(barrier_case("[0.1, 0.0]")) == "walls.boxes[0].lo");  // overlaps the fluid
    CHECK(error_key(barrier_case("[0.4, -0.1]")) == "walls.boxes[0].lo"); // into the floor wall
    CHECK(error_key(barrier_case("[0.4, 0.0]", "reflective")) == "walls.boxes[0].lo");
    CHECK(error_key(barrier_case("[0.5, 0.0, 0.0]")) == "walls.boxes[0].lo"); // 3 numbers in 2-D
    CHECK(error_key(barrier_case("[0.46, 0.0]")) == "walls.boxes[0].hi");     // zero thickness
    CHECK(error_key(barrier_case(), {"walls.boxes[0].hi=[1.1, 1.0]"}) == "walls.boxes[0].hi");
    CHECK(error_key(barrier_case() + "[[walls.boxes]]\nlo = [0.45, 0.5]\nhi = [0.5, 0.6]\n") ==
          "walls.boxes[1].lo"); // overlaps walls.boxes[0]
    CHECK(error_key(barrier_case() +
                    "[[walls.boxes]]\nlo = [0.6, 0.0]\nhi = [0.7, 0.1]\nside = 1\n") ==
          "walls.boxes[1].side"); // unknown key
    const CaseConfig moved =
        read_case(write_case("ok", barrier_case()), {"walls.boxes.0.lo=[0.42, 0.0]"});
    CHECK(moved.boxes[0].lo[0] == doctest::Approx(0.42));
}

TEST_CASE("a collapsing column piles up against a wall box and does not pass through it") {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    const CaseConfig cfg = read_case(write_case("barrier", barrier_case()));
    Simulation<2> sim(cfg);
    const double face = 0.4, dx = cfg.dx;
    double reach = 0; // largest fluid x seen
    while (sim.time() < cfg.end_time) {
        sim.step();
        const Particles<2>& P = sim.particles();
        for (std::size_t i = 0; i < sim.owned(); ++i)
            if (P.kind[i] == Kind::fluid)
                reach = std::max(reach, P.x[i][0]);
        // No fluid particle gets past the centre line of the box's first wall row.
        REQUIRE_MESSAGE(reach < face + 0.5 * dx, "fluid inside the box at t = " << sim.time());
    }
    // The surge did reach the box (so the check above was exercised).
    CHECK(reach > face - 1.5 * dx);
}

namespace {

// A tank with every face walled, an obstacle box standing on its floor and two blocks, one of
// which reaches the x+ and y+ (and z+) faces; no extent is a multiple of dx = 0.03 or 0.023.
std::string any_dx_case(int dim, double dx) {
    const bool d3 = dim == 3;
    return fmt::format(
        R"(
[case]
name = "any_dx"
dimension = {}
[domain]
lo = {}
hi = {}
[fluid]
rho0 = 1000.0
sound_speed = 20.0
viscosity = 0.0
[particles]
dx = {}
[[blocks]]
lo = {}
hi = {}
[[blocks]]
lo = {}
hi = {}
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
[walls]
model = "dummy"
tank_lo = {}
tank_hi = {}
[[walls.boxes]]
lo = {}
hi = {}
[time]
end_time = 0.1
)",
        dim, d3 ? "[0.0, 0.0, 0.0]" : "[0.0, 0.0]", d3 ? "[1.013, 0.417, 0.8]" : "[1.013, 0.8]", dx,
        d3 ? "[0.0, 0.0, 0.0]" : "[0.0, 0.0]", d3 ? "[0.301, 0.417, 0.5]" : "[0.301, 0.5]",
        d3 ? "[0.7, 0.0, 0.0]" : "[0.7, 0.0]", d3 ? "[1.013, 0.417, 0.8]" : "[1.013, 0.8]",
        d3 ? "[0.0, 0.0, 0.0]" : "[0.0, 0.0]", d3 ? "[1.013, 0.417, 0.8]" : "[1.013, 0.8]",
        d3 ? "[0.413, 0.107, 0.0]" : "[0.413, 0.0]",
        d3 ? "[0.617, 0.311, 0.337]" : "[0.617, 0.337]");
}

// Every wall surface as built (the fluid-side wall layer -/+ dx/2) within 0.05 dx of the
// case; no fluid particle within dx/4 of a walled face or beyond it.
template <int D>
void check_any_dx(double dx) {
    CAPTURE(D);
    CAPTURE(dx);
    const CaseConfig cfg = read_case(write_case("any_dx", any_dx_case(D, dx)));
    const int layers = wall_layers(kernel_support_factor(cfg.kernel) * cfg.h_over_dx * dx, dx);
    Particles<D> P;
    add_fluid_blocks<D>(cfg, Eos{EosType::linear, cfg.rho0, cfg.sound_speed, 7, 0}, P);
    CHECK(P.size() == count_fluid_particles(cfg));
    const std::size_t fluid = P.size();
    add_wall_particles<D>(cfg, layers, P);
    CHECK(P.size() - fluid == count_wall_particles(cfg, layers));
    const WallBox& box = cfg.boxes[0];
    for (int d = 0; d < D; ++d) {
        CAPTURE(d);
        double below = -1e300, above = 1e300; // tank walls' fluid-side layers
        double box_lo = 1e300, box_hi = -1e300;
        double fluid_lo = 1e300, fluid_hi = -1e300;
        for (std::size_t i = 0; i < P.size(); ++i) {
            const double x = P.x[i][d];
            if (P.kind[i] == Kind::fluid) {
                fluid_lo = std::min(fluid_lo, x);
                fluid_hi = std::max(fluid_hi, x);
                continue;
            }
            bool in_box = true;
            for (int e = 0; e < D; ++e)
                in_box = in_box && P.x[i][e] > box.lo[e] && P.x[i][e] < box.hi[e];
            if (in_box) {
                box_lo = std::min(box_lo, x);
                box_hi = std::max(box_hi, x);
            } else if (x < cfg.tank_lo[d]) {
                below = std::max(below, x);
            } else if (x > cfg.tank_hi[d]) {
                above = std::min(above, x);
            }
        }
        CHECK(std::abs(below + dx / 2 - cfg.tank_lo[d]) < 0.05 * dx);
        CHECK(std::abs(above - dx / 2 - cfg.tank_hi[d]) < 0.05 * dx);
        CHECK(std::abs(box_lo - dx / 2 - box.lo[d]) < 0.05 * dx);
        CHECK(std::abs(box_hi + dx / 2 - box.hi[d]) < 0.05 * dx);
        CHECK(fluid_lo >= cfg.tank_lo[d] + dx / 4);
        CHECK(fluid_hi <= cfg.tank_hi[d] - dx / 4 + 1e-12);
    }
    // The same surfaces as `sluice info` reports them.
    const BuiltGeometry g = built_geometry(cfg, layers);
    CHECK(g.faces.size() == 2u * D);
    for (const BuiltFace& f : g.faces)
        CHECK(std::abs(f.built - f.requested) < 1e-9 * dx);
    for (int d = 0; d < D; ++d) {
        CHECK(std::abs(g.boxes[0].lo[d] - box.lo[d]) < 1e-9 * dx);
        CHECK(std::abs(g.boxes[0].hi[d] - box.hi[d]) < 1e-9 * dx);
    }
}

} // namespace

TEST_CASE("wall surfaces sit where the case puts them for a dx that divides nothing") {
    for (double dx : {0.03, 0.023}) {
        check_any_dx<2>(dx);
        check_any_dx<3>(dx);
    }
}

TEST_CASE("a block reaching a walled face keeps its particles dx/4 inside it") {
    // 0.61 m at dx = 0.02: round(30.5) = 31 sites would put the last centre on the y+ face.
    const std::string text = barrier_case("[0.4, 0.0]");
    const CaseConfig cfg =
        read_case(write_case("b", text),
                  {"walls.tank_hi=[1.0, 0.61]", "domain.hi=[1.0, 0.61]", "blocks.0.hi=[0.2, 0.61]",
                   "walls.boxes.0.hi=[0.46, 0.5]", "particles.dx=0.02",
                   "walls.tank_faces=[\"x-\", \"x+\", \"y-\", \"y+\"]"});
    CHECK(block_lattice_count(cfg, cfg.blocks[0], 1) == 30);
    Particles<2> P;
    add_fluid_blocks<2>(cfg, Eos{EosType::linear, cfg.rho0, cfg.sound_speed, 7, 0}, P);
    for (std::size_t i = 0; i < P.size(); ++i)
        CHECK(P.x[i][1] < 0.61 - 0.02 / 4);
    const CaseInfo info = describe_case(cfg);
    const auto w = case_warnings(cfg, info);
    CHECK(std::any_of(w.begin(), w.end(),
                      [](const CaseWarning& x) { return x.key == "blocks[0].hi"; }));
}

TEST_CASE("a box thinner than its layers is filled symmetrically; thinner than dx is refused") {
    // 6 cm thick at dx = 0.025 (round(2.4) = 2 sites) with 3 layers: centred in the box.
    const CaseConfig cfg = read_case(write_case("thin", barrier_case()), {"particles.dx=0.025"});
    const BuiltGeometry g = built_geometry(cfg, 3);
    CHECK(g.boxes[0].thin[0]);
    CHECK(g.boxes[0].lo[0] + g.boxes[0].hi[0] == doctest::Approx(0.4 + 0.46));
    CHECK(g.boxes[0].hi[0] - g.boxes[0].lo[0] == doctest::Approx(0.05));
    const auto w = case_warnings(cfg, describe_case(cfg));
    CHECK(std::any_of(w.begin(), w.end(),
                      [](const CaseWarning& x) { return x.key == "walls.boxes[0].hi"; }));
    CHECK(error_key(barrier_case(), {"particles.dx=0.07"}) == "walls.boxes[0].hi");
}
