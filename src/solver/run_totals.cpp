// Particle counts, fluid mass and neighbour census without a gather (run_totals.hpp).
#include "run_totals.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace sluice {

namespace {

constexpr std::size_t kCounters = 10;

std::array<std::uint64_t, kCounters> counters(const RunTotals& t) {
    const NeighbourCensus& c = t.census;
    return {t.particles,  t.fluid,      c.fluid,     c.wall,          c.fluid_fluid,
            c.fluid_wall, c.wall_fluid, c.wall_wall, c.fluid_crowded, c.fluid_isolated};
}

void set_counters(RunTotals& t, const std::array<std::uint64_t, kCounters>& v) {
    NeighbourCensus& c = t.census;
    t.particles = v[0];
    t.fluid = v[1];
    c.fluid = v[2];
    c.wall = v[3];
    c.fluid_fluid = v[4];
    c.fluid_wall = v[5];
    c.wall_fluid = v[6];
    c.wall_wall = v[7];
    c.fluid_crowded = v[8];
    c.fluid_isolated = v[9];
}

} // namespace

template <int D>
RunTotals run_totals(const Simulation<D>& sim, Real support, Real crowded) {
    const tasks::Comm& comm = sim.comm();
    const Particles<D>& P = sim.particles();
    const std::size_t n = sim.owned();
    const CellGrid<D>& grid = sim.grid();
    RunTotals t;
    t.particles = n;
    std::vector<std::pair<ParticleId, Real>> masses;
    for (std::size_t i = 0; i < n; ++i)
        if (P.kind[i] == Kind::fluid)
            masses.emplace_back(P.id[i], P.mass[i]);
    t.fluid = masses.size();

    if (!comm.parallel()) {
        t.mass = sum_in_id_order(std::move(masses));
        t.census = count_neighbours<D>(grid, std::span<const Vec<D>>(P.x.data(), n),
                                       std::span<const Kind>(P.kind.data(), n), support, crowded,
                                       [](MortonKey) { return true; });
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

    // The census: a particle counts on the owner of the cell it is in now, and goes to the
    // owner of every cell adjacent to that one (its neighbours lie there, cells being at least
    // a support wide), so each owner sees every neighbour of the particles it counts.
    const int me = comm.rank();
    const tasks::RankLayout& layout = sim.rank_layout();
    std::vector<tasks::Bytes> out(static_cast<std::size_t>(comm.size())), in;
    std::array<NeighbourCell<D>, 27> adjacent{};
    std::vector<int> targets;
    for (std::size_t i = 0; i < n; ++i) {
        const CellIndex c = grid.linear(grid.coords(P.x[i]));
        const int k = adjacent_cells(grid, c, adjacent.data());
        targets.clear();
        for (int a = 0; a < k; ++a) {
            const int r = layout.rank_of(grid.morton(grid.unlinear(adjacent[a].cell)));
            if (r != me && std::find(targets.begin(), targets.end(), r) == targets.end())
                targets.push_back(r);
        }
        for (const int r : targets) {
            tasks::Bytes& b = out[static_cast<std::size_t>(r)];
            tasks::put(b, P.kind[i]);
            tasks::put(b, P.x[i]);
        }
    }
    comm.all_to_all(out, in);
    out = {};
    std::vector<Vec<D>> x(P.x.begin(), P.x.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<Kind> kind(P.kind.begin(), P.kind.begin() + static_cast<std::ptrdiff_t>(n));
    for (const auto& b : in) {
        std::size_t pos = 0;
        while (pos < b.size()) {
            kind.push_back(tasks::take<Kind>(b, pos));
            x.push_back(tasks::take<Vec<D>>(b, pos));
        }
    }
    in = {};
    t.census = count_neighbours<D>(grid, x, kind, support, crowded,
                                   [&](MortonKey key) { return layout.rank_of(key) == me; });

    // Every rank's counts, added (integers: exact in any order), and the smallest of the
    // ranks' closest fluid pairs.
    tasks::Bytes report;
    for (const std::uint64_t c : counters(t))
        tasks::put(report, c);
    tasks::put(report, t.census.closest_fluid_pair);
    std::array<std::uint64_t, kCounters> sum{};
    Real closest = std::numeric_limits<Real>::infinity();
    for (const auto& b : comm.all_gather(report)) {
        std::size_t pos = 0;
        for (auto& s : sum)
            s += tasks::take<std::uint64_t>(b, pos);
        closest = std::min(closest, tasks::take<Real>(b, pos));
    }
    set_counters(t, sum);
    t.census.closest_fluid_pair = closest;
    return t;
}

template RunTotals run_totals<2>(const Simulation<2>&, Real, Real);
template RunTotals run_totals<3>(const Simulation<3>&, Real, Real);

} // namespace sluice
