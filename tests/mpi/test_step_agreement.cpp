// The step's agreement between ranks: the non-blocking all-gather that carries each rank's
// report (tasks::PendingAllGather) returns every rank's bytes in rank order, also while the rank
// did other work in between or moved the pending object; and a failure on one rank, which
// travels in it, stops every rank in the same step with that rank's message, before the
// failing step's state is swapped in. Running the next step's graph ahead of the agreement
// (Simulation::allow_run_ahead) changes none of it: the same particles, bit for bit, the same
// failure with the same last good state.
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

// Every array a step reads or a snapshot writes, bit for bit (on rank 0, which gathers).
void check_same_state(const Simulation<2>& a, const Simulation<2>& b) {
    const Particles<2> pa = a.gather_particles();
    const Particles<2> pb = b.gather_particles();
    CHECK(a.steps() == b.steps());
    CHECK(a.time() == b.time());
    CHECK(a.dt() == b.dt());
    if (a.comm().rank() != 0)
        return;
    REQUIRE(pa.size() == pb.size());
    CHECK(pa.id == pb.id);
    CHECK(pa.x == pb.x);
    CHECK(pa.x_ref == pb.x_ref);
    CHECK(pa.v == pb.v);
    CHECK(pa.v_half == pb.v_half);
    CHECK(pa.rho == pb.rho);
    CHECK(pa.mass == pb.mass);
    CHECK(pa.p == pb.p);
    CHECK(pa.a == pb.a);
}

// Runs `steps` steps with and without running ahead; the checkpoint request in the middle
// makes one run-ahead be discarded, as do the rebuilds of the lists. No balancing window
// completes within the run, so the balancer never acts: a rebalance between rebuilds counts as
// a rebuild, and whether one falls due depends on measured busy times, i.e. on the machine's
// load (on a loaded 2-core machine 3 of 16 runs counted 7 rebuilds in one simulation and 8 in
// the other, with identical states), which is not what this test compares. Returns the number
// of list rebuilds.
long compare_running_ahead(CaseConfig cfg, int steps) {
    cfg.rebalance_window = steps + 1;
    cfg.rebalance_every = 0;
    SimulationOptions opts;
    opts.threads = 1;
    Simulation<2> plain(cfg, opts);
    Simulation<2> ahead(cfg, opts);
    for (int s = 0; s < steps; ++s) {
        if (s == steps / 2) {
            plain.post_request(request_checkpoint);
            ahead.post_request(request_checkpoint);
        }
        plain.step();
        ahead.allow_run_ahead(s + 1 < steps);
        ahead.step();
        CHECK(plain.agreed_requests() == ahead.agreed_requests());
    }
    check_same_state(plain, ahead);
    CHECK(plain.list_rebuilds() == ahead.list_rebuilds());
    CHECK(plain.steps_run_ahead() == 0);
    CHECK(ahead.steps_run_ahead() > 0);
    CHECK(ahead.steps_run_ahead_discarded() >= 1);
    CHECK(ahead.steps_run_ahead() + ahead.steps_run_ahead_discarded() == steps - 1);
    return plain.list_rebuilds();
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

// The case with summation density (and so without delta-SPH).
static CaseConfig with_summation(CaseConfig cfg) {
    cfg.density = DensityScheme::summation;
    cfg.delta_sph = 0;
    return cfg;
}

TEST_CASE("running the next step ahead of the agreement changes no result") {
    SUBCASE("continuity, delta-SPH, periodic flow across ranks (rebuilds)") {
        // The lists expire by displacement several times in 24 steps, each rebuild a
        // discarded run-ahead.
        CHECK(compare_running_ahead(read_case(data("uniform_flow_periodic.toml")), 24) >= 3);
    }
    SUBCASE("summation density, shifting (gated at the acceleration)") {
        CaseConfig cfg = with_summation(read_case(data("uniform_flow_periodic.toml")));
        cfg.shifting = 4;
        compare_running_ahead(cfg, 24);
    }
    SUBCASE("dummy walls, gravity") {
        compare_running_ahead(read_case(data("probe_kinds_2d.toml")), 16);
    }
    SUBCASE("dummy walls, summation density") {
        compare_running_ahead(with_summation(read_case(data("probe_kinds_2d.toml"))), 16);
    }
}

TEST_CASE("a failure found while the next step runs ahead leaves the same last good state") {
    // The failing step's graph itself ran ahead (its drift throws on the failing rank), and
    // the failure is found by the agreement that the following step's graph runs ahead of.
    for (const bool summation : {false, true}) {
        CAPTURE(summation);
        CaseConfig cfg = read_case(data("probe_kinds_2d.toml"));
        if (summation) {
            cfg.density = DensityScheme::summation;
            cfg.delta_sph = 0;
        }
        const tasks::Comm comm = tasks::Comm::world();
        const int failing = comm.size() - 1;
        SimulationOptions opts;
        opts.threads = 1;
        opts.debug_fail_rank = failing;
        opts.debug_fail_step = 3;
        Simulation<2> plain(cfg, opts);
        Simulation<2> ahead(cfg, opts);
        std::string plain_message, ahead_message;
        try {
            for (int s = 0; s < 4; ++s)
                plain.step();
        } catch (const InternalError& e) {
            plain_message = e.what();
        }
        try {
            for (int s = 0; s < 4; ++s) {
                ahead.allow_run_ahead(true);
                ahead.step();
            }
        } catch (const InternalError& e) {
            ahead_message = e.what();
        }
        CHECK(ahead_message.find("step 3: deliberate failure of rank " + std::to_string(failing)) !=
              std::string::npos);
        CHECK(ahead_message == plain_message);
        CHECK(ahead.steps() == 2);
        CHECK(ahead.steps_run_ahead() == 2); // steps 2 and 3; step 4 was discarded
        CHECK(ahead.steps_run_ahead_discarded() == 1);
        check_same_state(plain, ahead);
    }
}
