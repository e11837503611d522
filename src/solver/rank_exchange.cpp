// The rank plumbing: cut points and peers, the halo plan, particles changing owner (the
// migration of a rebuild is in rank_migration.cpp), the gathered cost list, the test gather. Pure
// data movement and bookkeeping (rank_exchange.hpp).
#include "sluice/solver/rank_exchange.hpp"

#include "particle_messages.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

namespace sluice {

template <int D>
void RankExchange<D>::find_peers() {
    // From the cells of this rank's range and its peers' ranges only, not the whole grid:
    // the other ranks' lists stay empty, two_step_ranks reads none of them.
    std::vector<std::vector<int>> known(static_cast<std::size_t>(layout_.ranks()));
    peers_ = known[static_cast<std::size_t>(comm_.rank())] =
        tasks::peers_of(grid_, layout_, comm_.rank());
    for (const int p : peers_)
        known[static_cast<std::size_t>(p)] = tasks::peers_of(grid_, layout_, p);
    reach_ = tasks::two_step_ranks(known, comm_.rank());
    halo_in_known_ = false; // counts of the old peers
}

template <int D>
void RankExchange<D>::distribute(Particles<D>& P, bool shares, bool key_range) {
    if (!comm_.parallel())
        return;
    if (!shares) {
        // A fresh start: initial_share built only this rank's particles, under layout_.
        find_peers();
        return;
    }
    // A restart: each rank holds a share of the checkpoint's particles; each ends with the
    // cells of its part of the curve, cut as one rank holding every particle would cut it.
    CellRanges ranges;
    std::vector<CellOccupancy> occupied;
    rebin(grid_, P, ranges, occupied);
    if (key_range) {
        layout_ = tasks::cut_ranks_by_key(grid_, comm_.size());
    } else {
        std::vector<tasks::CurveUnit> units;
        units.reserve(occupied.size());
        for (const auto& c : occupied)
            units.push_back({c.key, static_cast<double>(c.count)});
        layout_ = tasks::cut_ranks(all_occupied_cells(units), comm_.size());
    }
    find_peers();
    std::vector<std::size_t> keep;
    std::vector<tasks::Bytes> out(static_cast<std::size_t>(comm_.size())), in;
    for (const auto& c : occupied) {
        const int owner = layout_.rank_of(c.key);
        for (std::uint32_t i = ranges.begin(c.cell), stop = ranges.end(c.cell); i < stop; ++i)
            if (owner == comm_.rank())
                keep.push_back(i);
            else
                messages::pack_particle(P, i, out[static_cast<std::size_t>(owner)]);
    }
    comm_.all_to_all(out, in);
    P.permute(keep);
    P.resize(keep.size());
    // Arrival order does not matter: the rebin sorts by (cell key, id).
    for (const auto& b : in)
        messages::unpack_particles<D>(b, P);
    // The arrays not permuted kept the share's size, and appending may have doubled others.
    P.shrink_to_fit();
}

template <int D>
std::vector<tasks::CurveUnit>
RankExchange<D>::all_units(const std::vector<tasks::CurveUnit>& mine) const {
    tasks::Bytes b;
    for (const auto& u : mine) {
        tasks::put(b, u.key);
        tasks::put(b, u.cost);
    }
    std::vector<tasks::CurveUnit> all;
    for (const auto& part : comm_.all_gather(b)) {
        std::size_t pos = 0;
        while (pos < part.size()) {
            tasks::CurveUnit u{};
            u.key = tasks::take<MortonKey>(part, pos);
            u.cost = tasks::take<double>(part, pos);
            all.push_back(u);
        }
    }
    return all;
}

template <int D>
std::vector<tasks::CurveUnit>
RankExchange<D>::all_occupied_cells(const std::vector<tasks::CurveUnit>& mine) const {
    // Every rank's occupied cells with their particle counts; a cell may straddle two shares,
    // so equal keys are merged. The result is the list one rank holding every particle makes.
    std::vector<tasks::CurveUnit> all = all_units(mine);
    std::stable_sort(all.begin(), all.end(),
                     [](const auto& a, const auto& b2) { return a.key < b2.key; });
    std::vector<tasks::CurveUnit> merged;
    for (const auto& u : all)
        if (!merged.empty() && merged.back().key == u.key)
            merged.back().cost += u.cost; // whole particle counts: exact
        else
            merged.push_back(u);
    return merged;
}

template <int D>
std::optional<tasks::MessageRecord>
RankExchange<D>::plan_halo(Particles<D>& P, const CellRanges& ranges,
                           const std::vector<CellOccupancy>& occupied, std::size_t owned) {
    const double t0 = tasks::clock_seconds();
    const std::size_t npeers = peers_.size();
    std::vector<CellIndex> cells;
    cells.reserve(occupied.size());
    for (const auto& c : occupied)
        cells.push_back(c.cell);
    occupied_targets_ = tasks::halo_targets(grid_, layout_, comm_.rank(), peers_, cells);
    plan_.send_cells.assign(npeers, {});
    plan_.send_count.assign(npeers, 0);
    plan_.send_walls.assign(npeers, 0);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (occupied_targets_[k].empty())
            continue;
        std::size_t walls = 0;
        for (std::uint32_t i = ranges.begin(cells[k]), stop = ranges.end(cells[k]); i < stop; ++i)
            walls += P.kind[i] == Kind::wall ? 1 : 0;
        for (int p : occupied_targets_[k]) {
            const auto pu = static_cast<std::size_t>(p);
            plan_.send_cells[pu].push_back(cells[k]);
            plan_.send_count[pu] += occupied[k].count;
            plan_.send_walls[pu] += walls;
        }
    }
    std::optional<tasks::MessageRecord> record;
    if (halo_in_known_) {
        // The migration's round brought them (rank_migration.cpp).
        plan_.recv_count = halo_in_count_;
        plan_.recv_walls = halo_in_walls_;
        halo_in_known_ = false;
    } else {
        // Each peer learns how many particles (and walls) it will receive, so that it can size
        // its arrays and post exact receives before the step starts.
        std::vector<tasks::Bytes> out(npeers), in;
        for (std::size_t p = 0; p < npeers; ++p) {
            tasks::put(out[p], static_cast<std::uint64_t>(plan_.send_count[p]));
            tasks::put(out[p], static_cast<std::uint64_t>(plan_.send_walls[p]));
        }
        comm_.exchange(peers_, out, in, 12);
        plan_.recv_count.assign(npeers, 0);
        plan_.recv_walls.assign(npeers, 0);
        for (std::size_t p = 0; p < npeers; ++p) {
            std::size_t pos = 0;
            plan_.recv_count[p] = tasks::take<std::uint64_t>(in[p], pos);
            plan_.recv_walls[p] = tasks::take<std::uint64_t>(in[p], pos);
        }
        record =
            tasks::MessageRecord{"halo counts", -1, true, 16 * npeers, t0, tasks::clock_seconds()};
    }
    plan_.recv_offset.assign(npeers, 0);
    std::size_t next = owned;
    for (std::size_t p = 0; p < npeers; ++p) {
        plan_.recv_offset[p] = next;
        next += plan_.recv_count[p];
    }
    P.resize(next);
    return record;
}

template <int D>
bool RankExchange<D>::halo_counts_agree() const {
    std::vector<tasks::Bytes> out(peers_.size()), in;
    for (std::size_t p = 0; p < peers_.size(); ++p) {
        tasks::put(out[p], static_cast<std::uint64_t>(plan_.send_count[p]));
        tasks::put(out[p], static_cast<std::uint64_t>(plan_.send_walls[p]));
    }
    comm_.exchange(peers_, out, in, 13);
    bool agree = true;
    for (std::size_t p = 0; p < peers_.size(); ++p) {
        std::size_t pos = 0;
        agree = agree && tasks::take<std::uint64_t>(in[p], pos) == plan_.recv_count[p] &&
                tasks::take<std::uint64_t>(in[p], pos) == plan_.recv_walls[p];
    }
    return agree;
}

template <int D>
std::vector<std::vector<int>>
RankExchange<D>::boundary_groups(const tasks::GroupTopology& topo) const {
    // The occupied cells of the halo plan and the concatenated group cell lists are in the
    // same (key) order.
    std::vector<std::vector<int>> facing(peers_.size());
    std::size_t k = 0;
    for (int g = 0; g < topo.group_count(); ++g)
        for (std::size_t c = 0; c < topo.cells[static_cast<std::size_t>(g)].size(); ++c, ++k)
            for (int p : occupied_targets_[k]) {
                auto& f = facing[static_cast<std::size_t>(p)];
                if (f.empty() || f.back() != g)
                    f.push_back(g);
            }
    return facing;
}

template <int D>
std::uint64_t RankExchange<D>::move_to(const tasks::RankLayout& next, Particles<D>& P) {
    std::vector<tasks::Bytes> out(static_cast<std::size_t>(comm_.size())), in;
    std::vector<std::size_t> keep;
    std::uint64_t moved = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        const int owner = next.rank_of(grid_.morton(grid_.coords(P.x[i])));
        if (owner == comm_.rank()) {
            keep.push_back(i);
        } else {
            messages::pack_particle(P, i, out[static_cast<std::size_t>(owner)]);
            ++moved;
        }
    }
    comm_.all_to_all(out, in);
    P.permute(keep);
    P.resize(keep.size());
    for (const auto& b : in)
        messages::unpack_particles<D>(b, P);
    std::uint64_t moved_total = 0;
    for (const auto& b : comm_.all_gather(std::span<const std::byte>(
             reinterpret_cast<const std::byte*>(&moved), sizeof(moved)))) {
        std::size_t pos = 0;
        moved_total += tasks::take<std::uint64_t>(b, pos);
    }
    layout_ = next;
    find_peers();
    return moved_total;
}

template <int D>
Particles<D> RankExchange<D>::gather(const Particles<D>& P, std::size_t owned) const {
    if (!comm_.parallel()) {
        Particles<D> copy = P;
        copy.resize(owned);
        return copy;
    }
    tasks::Bytes mine;
    mine.reserve(owned * messages::particle_bytes<D>);
    for (std::size_t i = 0; i < owned; ++i)
        messages::pack_particle(P, i, mine);
    Particles<D> out;
    // Ranks own consecutive runs of the curve, so rank order is (cell key, id) order.
    for (const auto& b : comm_.gather(mine, 0))
        messages::unpack_particles<D>(b, out);
    return out;
}

template class RankExchange<2>;
template class RankExchange<3>;

} // namespace sluice
