#include "sluice/solver/initial_share.hpp"

#include "sluice/solver/initial_state.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace sluice {

namespace {

template <int D>
void visit_case(const CaseConfig& cfg, const Eos& eos, int layers, const InitialSink<D>& sink) {
    const ParticleId walls_from = visit_fluid_blocks<D>(cfg, eos, 0, sink);
    if (cfg.walls == WallModel::dummy)
        visit_wall_particles<D>(cfg, layers, walls_from, sink);
}

} // namespace

template <int D>
InitialCensus initial_census(const CaseConfig& cfg, const Eos& eos, int layers,
                             const CellGrid<D>& grid) {
    InitialCensus census;
    // Particles per occupied cell (by key): memory per occupied cell, none per cell of the grid.
    std::unordered_map<MortonKey, std::uint32_t> count;
    visit_case<D>(cfg, eos, layers, [&](const InitialParticle<D>& q) {
        ++count[grid.morton(grid.coords(q.x))];
        ++census.particles;
        census.max_speed = std::max(census.max_speed, q.v.norm());
    });
    census.cells.reserve(count.size());
    for (const auto& [key, n] : count)
        census.cells.push_back({key, double(n)});
    std::sort(census.cells.begin(), census.cells.end(),
              [](const auto& a, const auto& b) { return a.key < b.key; });
    return census;
}

template <int D>
tasks::RankLayout initial_layout(const CaseConfig& cfg, const CellGrid<D>& grid,
                                 const InitialCensus& census, int ranks) {
    if (ranks <= 1)
        return {};
    if (cfg.initial_decomposition == InitialDecomposition::key_range)
        return tasks::cut_ranks_by_key(grid, ranks);
    return tasks::cut_ranks(census.cells, ranks);
}

template <int D>
InitialShare initial_share(const CaseConfig& cfg, const Eos& eos, int layers,
                           const CellGrid<D>& grid, int rank, int ranks, Particles<D>* P) {
    InitialShare share;
    std::size_t own = count_fluid_particles(cfg) + count_wall_particles(cfg, layers);
    if (ranks > 1 && P != nullptr) {
        const InitialCensus census = initial_census<D>(cfg, eos, layers, grid);
        share.layout = initial_layout<D>(cfg, grid, census, ranks);
        own = 0;
        for (const auto& c : census.cells)
            if (share.layout.rank_of(c.key) == rank)
                own += static_cast<std::size_t>(c.cost);
    }
    if (P != nullptr)
        P->reserve(P->size() + own); // exactly: appending never doubles an array
    visit_case<D>(cfg, eos, layers, [&](const InitialParticle<D>& q) {
        share.max_speed = std::max(share.max_speed, q.v.norm());
        if (P != nullptr && share.layout.rank_of(grid.morton(grid.coords(q.x))) == rank)
            P->push_back(q.id, q.kind, q.x, q.v, q.rho, q.mass);
    });
    return share;
}

template InitialCensus initial_census<2>(const CaseConfig&, const Eos&, int, const CellGrid<2>&);
template InitialCensus initial_census<3>(const CaseConfig&, const Eos&, int, const CellGrid<3>&);
template tasks::RankLayout initial_layout<2>(const CaseConfig&, const CellGrid<2>&,
                                             const InitialCensus&, int);
template tasks::RankLayout initial_layout<3>(const CaseConfig&, const CellGrid<3>&,
                                             const InitialCensus&, int);
template InitialShare initial_share<2>(const CaseConfig&, const Eos&, int, const CellGrid<2>&, int,
                                       int, Particles<2>*);
template InitialShare initial_share<3>(const CaseConfig&, const Eos&, int, const CellGrid<3>&, int,
                                       int, Particles<3>*);

} // namespace sluice
