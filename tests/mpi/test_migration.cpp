// Migration conserves particles exactly: in a periodic box where everything moves
// diagonally, particles cross rank boundaries (and periodic seams) every few steps; after
// every step the union of all ranks' particles is exactly the initial set of ids, each once,
// with the same total mass, and ownership has really changed hands. The halo counts that
// travel with the migrants match what each peer then sends.
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/simulation.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>

using namespace sluice;

namespace {
std::string data(const char* name) {
    return std::string(SLUICE_SOURCE_DIR) + "/tests/data/" + name;
}
} // namespace

TEST_CASE("particles migrate between ranks without loss or duplication") {
    const CaseConfig cfg =
        read_case(data("uniform_flow_periodic.toml"), {"runtime.rebalance_every=40"});
    SimulationOptions opts;
    opts.threads = 1;
    Simulation<2> sim(cfg, opts);
    const tasks::Comm& comm = sim.comm();
    REQUIRE(comm.size() >= 2);

    const Particles<2> first = sim.gather_particles();
    const std::size_t n = comm.rank() == 0 ? first.size() : 0;
    const Real mass0 = comm.rank() == 0 ? first.total_mass() : 0;
    std::vector<ParticleId> mine0(sim.particles().id.begin(),
                                  sim.particles().id.begin() +
                                      static_cast<std::ptrdiff_t>(sim.owned()));
    std::sort(mine0.begin(), mine0.end());

    int bad_steps = 0, bad_plans = 0;
    for (int s = 0; s < 120; ++s) {
        sim.step();
        // The halo counts travel with the migrants (rank_migration.cpp): every peer must send
        // exactly what this rank sized its arrays for.
        bad_plans += sim.halo_plan_agrees() ? 0 : 1;
        const Particles<2> all = sim.gather_particles();
        if (comm.rank() != 0)
            continue;
        std::vector<ParticleId> ids = all.id;
        std::sort(ids.begin(), ids.end());
        std::vector<ParticleId> expected(n);
        std::iota(expected.begin(), expected.end(), ParticleId{0});
        if (ids != expected || all.total_mass() != mass0)
            ++bad_steps;
    }
    CHECK(bad_steps == 0);
    CHECK(bad_plans == 0);
    CHECK(sim.list_rebuilds() >= 2);
    CHECK(sim.rebalances().size() >= 2);

    // The flow moved 0.1 m or more: this rank's set of particles is not the one it started with.
    std::vector<ParticleId> mine(sim.particles().id.begin(),
                                 sim.particles().id.begin() +
                                     static_cast<std::ptrdiff_t>(sim.owned()));
    std::sort(mine.begin(), mine.end());
    CHECK(mine != mine0);
    CHECK(sim.time() > 0.1);
}
