// Particle counts, fluid mass and neighbour census without a gather (run_totals.hpp).
#include "run_totals.hpp"

#include "spacing_census.hpp"

#include <utility>
#include <vector>

namespace sluice {

template <int D>
RunTotals run_totals(const Simulation<D>& sim, Real support, Real crowded,
                     const NeighbourCensus* known) {
    const tasks::Comm& comm = sim.comm();
    const Particles<D>& P = sim.particles();
    const std::size_t n = sim.owned();
    RunTotals t;
    // The census counts every particle once, on the owner of its cell: its totals are every
    // rank's particle counts together.
    t.census = known != nullptr ? *known : spacing_census<D>(sim, support, crowded, false).census;
    t.particles = t.census.fluid + t.census.wall;
    t.fluid = t.census.fluid;
    std::vector<std::pair<ParticleId, Real>> masses;
    for (std::size_t i = 0; i < n; ++i)
        if (P.kind[i] == Kind::fluid)
            masses.emplace_back(P.id[i], P.mass[i]);
    if (!comm.parallel()) {
        t.mass = sum_in_id_order(std::move(masses));
        return t;
    }

    // The fluid mass: ids and masses to rank 0, summed there in id order.
    tasks::Bytes mine;
    mine.reserve(masses.size() * (sizeof(ParticleId) + sizeof(Real)));
    for (const auto& [id, m] : masses) {
        tasks::put(mine, id);
        tasks::put(mine, m);
    }
    masses = {};
    const auto parts = comm.gather(mine, 0);
    mine = {};
    if (comm.rank() == 0) {
        for (const auto& b : parts) {
            std::size_t pos = 0;
            while (pos < b.size()) {
                const auto id = tasks::take<ParticleId>(b, pos);
                masses.emplace_back(id, tasks::take<Real>(b, pos));
            }
        }
        t.mass = sum_in_id_order(std::move(masses));
    }
    return t;
}

template RunTotals run_totals<2>(const Simulation<2>&, Real, Real, const NeighbourCensus*);
template RunTotals run_totals<3>(const Simulation<3>&, Real, Real, const NeighbourCensus*);

} // namespace sluice
