// Blow-up detection: state_fault names the first thing wrong with a fluid particle's new state
// (non-finite values, a position outside the domain, a density or speed outside the case's
// limits) and says nothing about a healthy one.
#include "sluice/solver/state_check.hpp"

#include <doctest/doctest.h>

#include <limits>
#include <string>

using namespace sluice;

namespace {

StateBounds<2> bounds() {
    StateBounds<2> b;
    b.lo = Vec<2>(0.0, -0.1);
    b.hi = Vec<2>(2.0, 1.0);
    b.periodic = {true, false};
    b.max_speed = 10;
    b.min_density = 10;
    b.max_density = 2000;
    return b;
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

bool starts_with(const std::string& s, const std::string& part) {
    return s.rfind(part, 0) == 0;
}

} // namespace

TEST_CASE("healthy states pass, including on the bounds and across a periodic axis") {
    const auto b = bounds();
    CHECK(state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(3.0, -4.0), 1000.0).empty());
    CHECK(state_fault(b, Vec<2>(0.0, -0.1), Vec<2>(6.0, 8.0), 10.0).empty()); // |v| = 10
    CHECK(state_fault(b, Vec<2>(2.0, 1.0), Vec<2>(0.0, 0.0), 2000.0).empty());
    CHECK(state_fault(b, Vec<2>(-5.0, 0.5), Vec<2>(0.0, 0.0), 1000.0).empty()); // x is periodic
}

TEST_CASE("each kind of fault is named with its value and the limit") {
    const auto b = bounds();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(state_fault(b, Vec<2>(nan, 0.5), Vec<2>(0, 0), 1000.0) == "a non-finite position");
    CHECK(state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(0, inf), 1000.0) == "a non-finite velocity");
    CHECK(state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(0, 0), nan) == "a non-finite density");
    CHECK(starts_with(state_fault(b, Vec<2>(1.0, 1.0 + 1e-12), Vec<2>(0, 0), 1000.0),
                      "a position outside the domain"));
    CHECK(starts_with(state_fault(b, Vec<2>(1.0, -0.2), Vec<2>(0, 0), 1000.0),
                      "a position outside the domain"));
    // The message says how to drop such particles instead.
    CHECK(contains(state_fault(b, Vec<2>(1.0, -0.2), Vec<2>(0, 0), 1000.0),
                   "domain.particle_exit = \"remove\""));
    CHECK(
        contains(state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(0, 0), -3.0), "non-positive density -3"));
    const std::string low = state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(0, 0), 9.5);
    CHECK(contains(low, "a density of 9.5 kg/m^3"));
    CHECK(contains(low, "limits.min_density = 10"));
    CHECK(contains(state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(0, 0), 2000.5), "limits.max_density"));
    const std::string fast = state_fault(b, Vec<2>(1.0, 0.5), Vec<2>(6.0, 8.0001), 1000.0);
    CHECK(contains(fast, "a speed of 10.0001 m/s"));
    CHECK(contains(fast, "limits.max_speed = 10 m/s"));
}

TEST_CASE("state_healthy, the drift's fast test, agrees with state_fault on every case above") {
    const auto b = bounds();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    struct State {
        Vec<2> x, v;
        double rho;
    };
    const State states[] = {
        {Vec<2>(1.0, 0.5), Vec<2>(3.0, -4.0), 1000.0},
        {Vec<2>(0.0, -0.1), Vec<2>(6.0, 8.0), 10.0},
        {Vec<2>(2.0, 1.0), Vec<2>(0.0, 0.0), 2000.0},
        {Vec<2>(-5.0, 0.5), Vec<2>(0.0, 0.0), 1000.0},
        {Vec<2>(nan, 0.5), Vec<2>(0, 0), 1000.0},
        {Vec<2>(1.0, 0.5), Vec<2>(0, inf), 1000.0},
        {Vec<2>(1.0, 0.5), Vec<2>(0, 0), nan},
        {Vec<2>(1.0, 1.0 + 1e-12), Vec<2>(0, 0), 1000.0},
        {Vec<2>(1.0, -0.2), Vec<2>(0, 0), 1000.0},
        {Vec<2>(1.0, 0.5), Vec<2>(0, 0), -3.0},
        {Vec<2>(1.0, 0.5), Vec<2>(0, 0), 9.5},
        {Vec<2>(1.0, 0.5), Vec<2>(0, 0), 2000.5},
        {Vec<2>(1.0, 0.5), Vec<2>(6.0, 8.0001), 1000.0},
        {Vec<2>(1.0, 0.5), Vec<2>(0, 0), 0.0},
    };
    int healthy = 0;
    for (const State& s : states) {
        const bool fast = state_healthy(b, s.x, s.v, s.rho);
        CHECK(fast == state_fault(b, s.x, s.v, s.rho).empty());
        healthy += fast ? 1 : 0;
    }
    CHECK(healthy == 4);
}

TEST_CASE("with particle_exit = \"remove\" a position outside the domain is healthy, and only "
          "that") {
    auto b = bounds();
    b.remove_outside = true;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Outside along a bounded axis: healthy, and outside_domain says so (the drift counts it).
    for (const Vec<2>& x : {Vec<2>(1.0, 1.0 + 1e-12), Vec<2>(1.0, -0.2)}) {
        CHECK(state_healthy(b, x, Vec<2>(0, 0), 1000.0));
        CHECK(state_fault(b, x, Vec<2>(0, 0), 1000.0).empty());
        CHECK(outside_domain(b, x));
    }
    // Along the periodic axis nothing is outside; on the bounds is inside.
    CHECK_FALSE(outside_domain(b, Vec<2>(-5.0, 0.5)));
    CHECK_FALSE(outside_domain(b, Vec<2>(0.0, -0.1)));
    CHECK_FALSE(outside_domain(b, Vec<2>(2.0, 1.0)));
    // Every other fault still stops the run, also outside the box.
    CHECK(state_fault(b, Vec<2>(nan, 0.5), Vec<2>(0, 0), 1000.0) == "a non-finite position");
    CHECK(contains(state_fault(b, Vec<2>(1.0, 3.0), Vec<2>(6.0, 8.0001), 1000.0), "a speed of"));
    CHECK(contains(state_fault(b, Vec<2>(1.0, 3.0), Vec<2>(0, 0), 9.5), "a density of 9.5"));
    CHECK_FALSE(state_healthy(b, Vec<2>(1.0, 3.0), Vec<2>(0, 0), 9.5));
}
