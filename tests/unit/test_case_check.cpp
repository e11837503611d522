// `sluice info` / `sluice check` advice and refusals, derived from the configuration alone:
// warnings for coarse resolution, tiny time steps and a too-low speed of sound, with the
// numbers they quote checked by hand; the solver's refusals made before any particle exists.
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/solver/case_check.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace sluice;

namespace {

// A 0.4 m x 0.8 m column in a 1.6 m x 1.0 m tank with dummy walls, dx = 0.01 m (40 particles
// across the column), c0 = 30 m/s >= 10 sqrt(9.81 * 0.8) = 28.01 m/s.
const std::string kCase = R"(
[case]
dimension = 2
[domain]
lo = [0, 0]
hi = [1.6, 1.0]
[fluid]
rho0 = 1000
viscosity = 1e-3
sound_speed = 30
[particles]
dx = 0.01
[[blocks]]
lo = [0, 0]
hi = [0.4, 0.8]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
[walls]
model = "dummy"
tank_lo = [0, 0]
tank_hi = [1.6, 1.0]
[time]
end_time = 1
)";

std::vector<CaseWarning> warnings_for(const std::vector<std::string>& sets) {
    const CaseConfig cfg = read_case_text(kCase, "check.toml", sets);
    return case_warnings(cfg, describe_case(cfg));
}

const CaseWarning* find(const std::vector<CaseWarning>& w, const std::string& key) {
    for (const auto& x : w)
        if (x.key == key)
            return &x;
    return nullptr;
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("a well-resolved case with a fast enough sound speed gets no warning") {
    CHECK(warnings_for({}).empty());
}

TEST_CASE("fewer than 20 particles across the smallest feature is flagged with the count") {
    // 0.4 m / 0.025 m = 16 particles across the column's width.
    const auto w = warnings_for({"particles.dx=0.025"});
    const auto* r = find(w, "particles.dx");
    REQUIRE(r != nullptr);
    CHECK(contains(r->message, "only 16 particles across blocks[0] along x"));
    CHECK(contains(r->message, "dx <= 0.02 m gives 20"));
    // 20 across is enough: 0.4 / 0.02.
    CHECK(find(warnings_for({"particles.dx=0.02"}), "particles.dx") == nullptr);
    // A narrow tank is a feature too: 0.15 m / 0.01 m = 15.
    const auto t = warnings_for(
        {"walls.tank_hi=[1.6, 0.15]", "domain.hi=[1.6, 1.0]", "blocks.0.hi=[0.4, 0.15]"});
    REQUIRE(find(t, "particles.dx") != nullptr);
    CHECK(contains(find(t, "particles.dx")->message, "only 15 particles across"));
}

TEST_CASE("a time step below 1e-7 s is flagged with the number of steps") {
    const auto w = warnings_for({"numerics.dt=5e-8"});
    const auto* r = find(w, "numerics.dt");
    REQUIRE(r != nullptr);
    CHECK(contains(r->message, "time step 5e-08 s"));
    CHECK(contains(r->message, "about 2e+07 steps")); // 1 s / 5e-8 s
    CHECK(find(warnings_for({"numerics.dt=2e-7"}), "numerics.dt") == nullptr);
}

TEST_CASE("c0 below 10 sqrt(g H) is flagged; H runs from the tank floor to the top of the fluid") {
    // 10 sqrt(9.81 * 0.8) = 28.01 m/s.
    const auto w = warnings_for({"fluid.sound_speed=20"});
    const auto* r = find(w, "fluid.sound_speed");
    REQUIRE(r != nullptr);
    CHECK(contains(r->message, "10 sqrt(g H) = 28.01 m/s"));
    CHECK(contains(r->message, "H = 0.8 m"));
    // A block held 0.1 m above the floor falls to it: H = 0.9 m, 10 sqrt(9.81 * 0.9) = 29.71.
    const auto f =
        warnings_for({"fluid.sound_speed=29", "blocks.0.lo=[0, 0.1]", "blocks.0.hi=[0.4, 0.9]"});
    REQUIRE(find(f, "fluid.sound_speed") != nullptr);
    CHECK(contains(find(f, "fluid.sound_speed")->message, "= 29.71 m/s"));
    // Gravity along a periodic axis builds no column (Poiseuille-like driving force).
    const auto p =
        warnings_for({"fluid.sound_speed=0.001", "fluid.gravity=[2e-4, 0]",
                      "domain.periodic=[true, false]", "walls.tank_faces=[\"y-\", \"y+\"]"});
    CHECK(find(p, "fluid.sound_speed") == nullptr);
}

TEST_CASE("a case that measures loads is flagged below 20 sqrt(g H)") {
    // 20 sqrt(9.81 * 0.8) = 56.03 m/s; the case's c0 = 30 m/s passes the 10 sqrt(g H) rule.
    const auto loads = [](const char* probe, const std::string& c0) {
        const CaseConfig cfg =
            read_case_text(std::string(kCase) + probe, "check.toml", {"fluid.sound_speed=" + c0});
        return case_warnings(cfg, describe_case(cfg));
    };
    const char* pressure =
        "[[probes]]\nname = \"p\"\ntype = \"pressure\"\nposition = [1.595, 0.02]\n";
    const char* front = "[[probes]]\nname = \"f\"\ntype = \"surge_front\"\n";
    const auto w = loads(pressure, "30");
    REQUIRE(find(w, "fluid.sound_speed") != nullptr);
    CHECK(contains(find(w, "fluid.sound_speed")->message, "20 sqrt(g H) = 56.03 m/s"));
    CHECK(find(loads(pressure, "57"), "fluid.sound_speed") == nullptr);
    CHECK(find(loads(front, "30"), "fluid.sound_speed") == nullptr); // fronts: 10 sqrt(g H) will do
    // Water over the whole floor cannot surge into a wall (a still tank's pressure probe).
    const CaseConfig layer = read_case_text(std::string(kCase) + pressure, "check.toml",
                                            {"fluid.sound_speed=30", "blocks.0.hi=[1.6, 0.8]"});
    CHECK(find(case_warnings(layer, describe_case(layer)), "fluid.sound_speed") == nullptr);
}

TEST_CASE("numerics that cost accuracy are flagged: a resolved viscous flow, alpha = 0 in a "
          "free-surface flow") {
    // kCase: nu = 1e-6 m^2/s, c0 = 30 m/s, dx = 0.01 m: Re_dx = 3 * 0.01 / 1e-6 = 3e4, a
    // free-surface flow with the defaults (alpha = 0.02): nothing to say.
    CHECK(find(warnings_for({}), "numerics.kernel") == nullptr);
    CHECK(find(warnings_for({}), "numerics.artificial_viscosity") == nullptr);
    // alpha = 0 there costs still water and impact peaks.
    const auto no_alpha = warnings_for({"numerics.artificial_viscosity=0"});
    REQUIRE(find(no_alpha, "numerics.artificial_viscosity") != nullptr);
    CHECK(contains(find(no_alpha, "numerics.artificial_viscosity")->message, "free-surface"));
    // ... but not under the Riemann solver, whose own dissipation replaces it.
    CHECK(find(warnings_for({"numerics.dissipation=riemann", "numerics.delta_sph=0"}),
               "numerics.artificial_viscosity") == nullptr);
    // mu = 30 Pa s: nu = 0.03 m^2/s, Re_dx = 3 * 0.01 / 0.03 = 1 < 10, viscosity resolved.
    const auto viscous = warnings_for({"fluid.viscosity=30"});
    REQUIRE(find(viscous, "numerics.kernel") != nullptr);
    CHECK(contains(find(viscous, "numerics.kernel")->message, "= 1, below 10"));
    // alpha h c0 / 8 = 0.02 * 0.015 * 30 / 8 = 1.125e-3 m^2/s, 3.75 % of nu.
    REQUIRE(find(viscous, "numerics.artificial_viscosity") != nullptr);
    CHECK(contains(find(viscous, "numerics.artificial_viscosity")->message,
                   "m^2/s, 3.75 % of the laminar nu = 0.03 m^2/s"));
    const auto quintic = warnings_for({"fluid.viscosity=30", "numerics.kernel=quintic",
                                       "numerics.h_over_dx=1", "numerics.artificial_viscosity=0"});
    CHECK(find(quintic, "numerics.kernel") == nullptr);
    CHECK(find(quintic, "numerics.artificial_viscosity") == nullptr);
    // The projection scheme has neither.
    CHECK(find(warnings_for({"fluid.viscosity=30", "numerics.scheme=projection"}),
               "numerics.kernel") == nullptr);
}

TEST_CASE("the solver's refusals are made from the configuration alone") {
    const CaseConfig ok = read_case_text(kCase, "check.toml");
    CHECK_NOTHROW(check_runnable(ok, describe_case(ok)));
    // Acoustic limit at rest: 0.25 h / c0 = 0.25 * 0.015 / 30 = 1.25e-4 s.
    const CaseConfig fast = read_case_text(kCase, "check.toml", {"numerics.dt=1.3e-4"});
    CHECK(describe_case(fast).dt_stable == doctest::Approx(1.25e-4));
    try {
        check_runnable(fast, describe_case(fast));
        FAIL("a fixed dt above the limit was accepted");
    } catch (const CaseError& e) {
        CHECK(e.key() == "numerics.dt");
    }
    const CaseConfig slow = read_case_text(kCase, "check.toml", {"numerics.dt=1.2e-4"});
    CHECK_NOTHROW(check_runnable(slow, describe_case(slow)));
    // Wendland support 2h = 0.03 m: a periodic axis needs at least 0.09 m.
    const CaseConfig narrow = read_case_text(
        kCase, "check.toml",
        {"domain.hi=[0.08, 1.0]", "domain.periodic=[true, false]", "walls.tank_hi=[0.08, 1.0]",
         "walls.tank_faces=[\"y-\"]", "blocks.0.hi=[0.08, 0.8]"});
    try {
        check_runnable(narrow, describe_case(narrow));
        FAIL("a periodic axis shorter than three supports was accepted");
    } catch (const CaseError& e) {
        CHECK(e.key() == "domain.periodic");
    }
}

TEST_CASE("a case whose time step cannot reach the end time is refused, naming the key") {
    const auto refused_key = [](const std::vector<std::string>& sets) -> std::string {
        const CaseConfig cfg = read_case_text(kCase, "check.toml", sets);
        try {
            check_runnable(cfg, describe_case(cfg));
        } catch (const CaseError& e) {
            return e.key();
        }
        return "";
    };
    // Each CFL factor at the smallest double underflows its limit to a step of zero.
    CHECK(refused_key({"numerics.cfl=5e-324"}) == "numerics.cfl");
    CHECK(refused_key({"numerics.viscous_cfl=5e-324"}) == "numerics.viscous_cfl");
    CHECK(refused_key({"numerics.force_cfl=5e-324"}) == "numerics.force_cfl");
    // The projection scheme's CFL limit has no sound speed: at rest, without gravity or
    // viscosity, nothing limits the step...
    const std::vector<std::string> still = {"numerics.scheme=\"projection\"",
                                            "fluid.gravity=[0, 0]", "fluid.viscosity=0"};
    CHECK(refused_key(still) == "numerics.dt");
    // ... and a fixed step makes it runnable.
    auto fixed = still;
    fixed.emplace_back("numerics.dt=1e-3");
    CHECK(refused_key(fixed).empty());
    // A sane step below the end time's resolution: 1e300 s + 1.25e-4 s == 1e300 s.
    CHECK(refused_key({"time.end_time=1e300"}) == "time.end_time");
    CHECK(refused_key({"time.end_time=1e9"}).empty());
}

TEST_CASE("wall-plane normals of extreme magnitude are normalised without overflow") {
    const auto normal = [](const std::string& n) {
        const CaseConfig c = read_case_text(
            kCase + "[[walls.planes]]\npoint = [0, 0]\nnormal = " + n + "\n", "check.toml");
        REQUIRE(c.planes.size() == 1);
        return c.planes[0].normal;
    };
    const auto big = normal("[1e200, 1e200]");
    CHECK(big[0] == doctest::Approx(std::sqrt(0.5)));
    CHECK(big[1] == doctest::Approx(std::sqrt(0.5)));
    const auto tiny = normal("[5e-324, 0]");
    CHECK(tiny[0] == 1.0);
    CHECK(tiny[1] == 0.0);
}

TEST_CASE("control characters in a refused value are shown escaped") {
    try {
        (void)read_case_text(kCase, "check.toml", {"case.name=\"a\\u0000b\\nc\""});
        FAIL("a name with control characters was accepted");
    } catch (const CaseError& e) {
        const std::string what = e.what();
        CHECK(contains(what, "\"a\\x00b\\x0ac\""));
        CHECK(what.find('\n') == std::string::npos);
    }
}
