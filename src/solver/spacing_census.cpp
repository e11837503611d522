// The fluid's spacing over every rank (spacing_census.hpp).
#include "spacing_census.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sluice {

namespace {

constexpr std::size_t kCounters = 8;

std::array<std::uint64_t, kCounters> counters(const NeighbourCensus& c) {
    return {c.fluid,      c.wall,      c.fluid_fluid,   c.fluid_wall,
            c.wall_fluid, c.wall_wall, c.fluid_crowded, c.fluid_isolated};
}

void set_counters(NeighbourCensus& c, const std::array<std::uint64_t, kCounters>& v) {
    c.fluid = v[0];
    c.wall = v[1];
    c.fluid_fluid = v[2];
    c.fluid_wall = v[3];
    c.wall_fluid = v[4];
    c.wall_wall = v[5];
    c.fluid_crowded = v[6];
    c.fluid_isolated = v[7];
}

// The wall particles' entries, which count_neighbours leaves alone, and those of particles
// counted on another rank before their values come back.
constexpr Real kUnset = std::numeric_limits<Real>::quiet_NaN();

} // namespace

template <int D>
SpacingCensus spacing_census(const Simulation<D>& sim, Real support, Real crowded,
                             bool per_particle) {
    const tasks::Comm& comm = sim.comm();
    const Particles<D>& P = sim.particles();
    const std::size_t n = sim.owned();
    const CellGrid<D>& grid = sim.grid();
    SpacingCensus out;
    if (per_particle)
        out.nearest.assign(n, kUnset);

    if (!comm.parallel()) {
        out.census = count_neighbours<D>(
            grid, std::span<const Vec<D>>(P.x.data(), n), std::span<const Kind>(P.kind.data(), n),
            support, crowded, [](MortonKey) { return true; }, std::span<Real>(out.nearest));
        return out;
    }

    // A particle counts on the owner of the cell it is in now, and goes to the owner of every
    // cell adjacent to that one (its neighbours lie there, cells being at least a support
    // wide), so each owner sees every neighbour of the particles it counts. With per_particle
    // it travels with its index on the sender, for the way back.
    const int me = comm.rank();
    const tasks::RankLayout& layout = sim.rank_layout();
    std::vector<tasks::Bytes> sent(static_cast<std::size_t>(comm.size())), in;
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
            tasks::Bytes& b = sent[static_cast<std::size_t>(r)];
            tasks::put(b, P.kind[i]);
            tasks::put(b, P.x[i]);
            if (per_particle)
                tasks::put(b, static_cast<std::uint32_t>(i));
        }
    }
    comm.all_to_all(sent, in);
    sent = {};
    std::vector<Vec<D>> x(P.x.begin(), P.x.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<Kind> kind(P.kind.begin(), P.kind.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<std::pair<int, std::uint32_t>> origin; // of each received particle
    for (std::size_t r = 0; r < in.size(); ++r) {
        std::size_t pos = 0;
        while (pos < in[r].size()) {
            kind.push_back(tasks::take<Kind>(in[r], pos));
            x.push_back(tasks::take<Vec<D>>(in[r], pos));
            if (per_particle)
                origin.emplace_back(static_cast<int>(r), tasks::take<std::uint32_t>(in[r], pos));
        }
    }
    in = {};
    std::vector<Real> nearest;
    if (per_particle)
        nearest.assign(x.size(), kUnset);
    out.census = count_neighbours<D>(
        grid, x, kind, support, crowded, [&](MortonKey key) { return layout.rank_of(key) == me; },
        std::span<Real>(nearest));

    if (per_particle) {
        std::copy(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(n),
                  out.nearest.begin());
        // Received fluid particles counted here: their values go back to their holders.
        std::vector<tasks::Bytes> back(static_cast<std::size_t>(comm.size()));
        for (std::size_t k = 0; k < origin.size(); ++k) {
            const Real v = nearest[n + k];
            if (std::isnan(v))
                continue;
            tasks::Bytes& b = back[static_cast<std::size_t>(origin[k].first)];
            tasks::put(b, origin[k].second);
            tasks::put(b, v);
        }
        std::vector<tasks::Bytes> returned;
        comm.all_to_all(back, returned);
        for (const auto& b : returned) {
            std::size_t pos = 0;
            while (pos < b.size()) {
                const auto i = tasks::take<std::uint32_t>(b, pos);
                out.nearest[i] = tasks::take<Real>(b, pos);
            }
        }
    }

    // Every rank's counts, added (integers: exact in any order), and the least of the ranks'
    // closest fluid pairs.
    tasks::Bytes report;
    for (const std::uint64_t c : counters(out.census))
        tasks::put(report, c);
    tasks::put(report, out.census.closest_fluid_pair);
    std::array<std::uint64_t, kCounters> sum{};
    Real closest = std::numeric_limits<Real>::infinity();
    for (const auto& b : comm.all_gather(report)) {
        std::size_t pos = 0;
        for (auto& s : sum)
            s += tasks::take<std::uint64_t>(b, pos);
        closest = std::min(closest, tasks::take<Real>(b, pos));
    }
    set_counters(out.census, sum);
    out.census.closest_fluid_pair = closest;
    return out;
}

template SpacingCensus spacing_census<2>(const Simulation<2>&, Real, Real, bool);
template SpacingCensus spacing_census<3>(const Simulation<3>&, Real, Real, bool);

} // namespace sluice
