// The step's agreement between ranks: the non-blocking all-gather that carries each rank's
// report (tasks::PendingAllGather) returns every rank's bytes in rank order, also while the rank
// did other work in between or moved the pending object; and a failure on one rank, which
// travels in it, stops every rank in the same step with that rank's message, before the
// failing step's state is swapped in.
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/solver/simulation.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstring>
#include <span>
#include <stdexcept>

using namespace sluice;

namespace {
std::string data(const char* name) {
    return std::string(SLUICE_SOURCE_DIR) + "/tests/data/" + name;
}

std::array<double, 3> values_of(int rank) {
    return {double(rank), 0.5 * rank * rank, -1.0 - rank};
}
} // namespace

TEST_CASE("a pending all-gather returns every rank's contribution in rank order") {
    const tasks::Comm comm = tasks::Comm::world();
    REQUIRE(comm.size() >= 2);
    const auto mine = values_of(comm.rank());
    const auto bytes = std::as_bytes(std::span(mine));
    tasks::PendingAllGather first = comm.start_all_gather(bytes);
    CHECK(first.active());
    // Work while it travels, including a second, blocking collective started after it.
    double sum = 0;
    for (int i = 1; i <= 100000; ++i)
        sum += 1.0 / i;
    const auto blocking = comm.all_gather(bytes);
    tasks::PendingAllGather moved = std::move(first);
    CHECK_FALSE(first.active());
    const auto all = moved.wait();
    CHECK_FALSE(moved.active());
    CHECK_THROWS_AS((void)moved.wait(), std::logic_error);
    REQUIRE(all.size() == static_cast<std::size_t>(comm.size()));
    for (int r = 0; r < comm.size(); ++r) {
        const auto& got = all[static_cast<std::size_t>(r)];
        REQUIRE(got.size() == sizeof(mine));
        std::array<double, 3> v{};
        std::memcpy(v.data(), got.data(), sizeof(v));
        CHECK(v == values_of(r));
        CHECK(got == blocking[static_cast<std::size_t>(r)]);
    }
    CHECK(sum > 12.0);
}

TEST_CASE("a task failing on one rank stops every rank in that step, before its state") {
    const CaseConfig cfg = read_case(data("uniform_flow_periodic.toml"));
    const tasks::Comm comm = tasks::Comm::world();
    const int failing = comm.size() - 1;
    SimulationOptions opts;
    opts.threads = 1;
    opts.debug_fail_rank = failing;
    opts.debug_fail_step = 3;
    Simulation<2> sim(cfg, opts);
    sim.step();
    sim.step();
    const double t2 = sim.time();
    const Particles<2> before = sim.gather_particles();
    std::string message;
    try {
        sim.step();
    } catch (const InternalError& e) {
        message = e.what();
    }
    // Every rank, not only the failing one, got the failing rank's message.
    CHECK(message.find("step 3: deliberate failure of rank " + std::to_string(failing)) !=
          std::string::npos);
    CHECK(message.find("(on rank " + std::to_string(failing) + ")") != std::string::npos);
    CHECK(sim.steps() == 2);
    CHECK(sim.time() == t2);
    const Particles<2> after = sim.gather_particles();
    if (comm.rank() == 0) {
        REQUIRE(after.size() == before.size());
        CHECK(after.id == before.id);
        CHECK(after.x == before.x);
        CHECK(after.rho == before.rho);
    }
}
