// The message/task wiring of the step graph: a boundary group's task never runs before the
// halo data it needs has arrived and been unpacked, even when every message is held back
// (an injected delay between MPI reporting a receive and the graph learning of it), while
// interior groups keep computing. Delays change timing only, never results.
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/simulation.hpp"

#include <doctest/doctest.h>

#include <cstdlib>

using namespace sluice;

namespace {

std::string case_file(const char* name) {
    return std::string(SLUICE_SOURCE_DIR) + "/cases/" + name;
}

struct WiringStats {
    long violations = 0;     // a consumer started before its halo was unpacked
    long unpack_early = 0;   // an unpack started before its message was reported
    long interior_early = 0; // interior tasks that started while a receive was outstanding
    long checked = 0;
    long cpu_beyond_wall = 0; // a task whose thread CPU time exceeds its wall interval
    double cpu = 0;           // thread CPU seconds of all tasks
};

void check_step(const tasks::StepGraph& g, WiringStats& st) {
    const auto& halo = g.halo();
    const auto& rec = g.task_records();
    const int P = static_cast<int>(halo.peers.size());
    const std::size_t n = static_cast<std::size_t>(g.stage_count() * g.group_count());
    const std::size_t m = halo.exchanges.size() * static_cast<std::size_t>(P);
    // A task runs on one thread: its CPU time lies within its wall interval (1 ms of slack
    // for the two clocks' reads).
    for (const tasks::TaskRecord& r : rec) {
        if (r.end <= 0)
            continue;
        st.cpu_beyond_wall += (r.cpu < 0 || r.cpu > r.end - r.start + 1e-3) ? 1 : 0;
        st.cpu += r.cpu;
    }
    double last_arrival = 0;
    for (std::size_t e = 0; e < halo.exchanges.size(); ++e)
        for (int p = 0; p < P; ++p) {
            const auto k = e * static_cast<std::size_t>(P) + static_cast<std::size_t>(p);
            const tasks::TaskRecord& unpack = rec[n + m + k];
            for (const auto& msg : g.message_records())
                if (!msg.send && msg.name == halo.exchanges[e].name &&
                    msg.peer == halo.peers[static_cast<std::size_t>(p)]) {
                    st.unpack_early += unpack.start < msg.done ? 1 : 0;
                    last_arrival = std::max(last_arrival, msg.done);
                }
            const int consumer = halo.exchanges[e].after_stage + 1;
            for (int grp : halo.boundary[static_cast<std::size_t>(p)]) {
                const auto& c = rec[static_cast<std::size_t>(consumer * g.group_count() + grp)];
                st.violations += c.start < unpack.end ? 1 : 0;
                ++st.checked;
            }
        }
    std::vector<bool> boundary(static_cast<std::size_t>(g.group_count()), false);
    for (const auto& b : halo.boundary)
        for (int grp : b)
            boundary[static_cast<std::size_t>(grp)] = true;
    for (std::size_t i = 0; i < n; ++i)
        if (!boundary[static_cast<std::size_t>(rec[i].group)] && rec[i].start < last_arrival)
            ++st.interior_early;
}

} // namespace

TEST_CASE("boundary tasks wait for their messages; delays do not change results") {
    const CaseConfig cfg = read_case(case_file("dam_break_2d.toml"),
                                     {"particles.dx=0.02", "runtime.particles_per_group=60"});
    SimulationOptions opts;
    opts.threads = 1;

    Simulation<2> plain(cfg, opts);
    for (int s = 0; s < 30; ++s)
        plain.step();
    const Particles<2> a = plain.gather_particles();

    Simulation<2> delayed(cfg, opts);
    REQUIRE(delayed.comm().size() >= 2);
    delayed.inject_receive_delay(0.003);
    WiringStats st;
    for (int s = 0; s < 30; ++s) {
        delayed.step();
        check_step(delayed.graph(), st);
    }
    const Particles<2> b = delayed.gather_particles();

    CHECK(st.checked > 0);
    CHECK(st.violations == 0);
    CHECK(st.unpack_early == 0);
    CHECK(st.cpu_beyond_wall == 0);
    CHECK(st.cpu > 0);
    if (delayed.comm().rank() == 0) {
        REQUIRE(a.size() == b.size());
        CHECK(a.id == b.id);
        CHECK(a.x == b.x);
        CHECK(a.v == b.v);
        CHECK(a.rho == b.rho);
        CHECK(a.p == b.p);
    }
    // Interior groups computed while halo messages were held back (on some rank).
    long early = st.interior_early, total = 0;
    for (const auto& bytes : delayed.comm().all_gather(std::span<const std::byte>(
             reinterpret_cast<const std::byte*>(&early), sizeof(early)))) {
        std::size_t pos = 0;
        total += tasks::take<long>(bytes, pos);
    }
    CHECK(total > 0);
}

// The pack task posts its own message when MPI gives MPI_THREAD_MULTIPLE; the main thread
// posts it when it does not (or SLUICE_POST_FROM_MAIN says so). Same results either way.
TEST_CASE("halo messages posted by the pack task or by the main thread give the same results") {
    const CaseConfig cfg = read_case(case_file("dam_break_2d.toml"),
                                     {"particles.dx=0.02", "runtime.particles_per_group=60"});
    SimulationOptions opts;
    opts.threads = 1;
    REQUIRE(tasks::Comm::workers_may_post()); // Debian's Open MPI gives MPI_THREAD_MULTIPLE
    auto run = [&](bool by_main) {
        if (by_main)
            setenv("SLUICE_POST_FROM_MAIN", "1", 1);
        Simulation<2> sim(cfg, opts);
        for (int s = 0; s < 30; ++s) {
            sim.step();
            CHECK(sim.graph().workers_post() == !by_main);
        }
        unsetenv("SLUICE_POST_FROM_MAIN");
        return sim.gather_particles();
    };
    const Particles<2> by_task = run(false);
    const Particles<2> by_main = run(true);
    if (tasks::Comm::world().rank() == 0) {
        REQUIRE(by_task.size() == by_main.size());
        CHECK(by_task.id == by_main.id);
        CHECK(by_task.x == by_main.x);
        CHECK(by_task.v == by_main.v);
        CHECK(by_task.rho == by_main.rho);
    }
}
