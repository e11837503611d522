// The parts of Simulation<D> that share particles between ranks: the peers of the initial cuts
// (a fresh start builds only its own particles: initial_share.hpp), the distribution of a
// checkpoint's shares at a restart, the halo plan of a rebuild, migration to neighbouring
// ranks, the rebalance (the costs gathered for the balancer's policy, tasks/balance_policy.hpp,
// and the move to its cuts, at a rebuild or between rebuilds), and the gather to rank 0 that
// tests use.
// Pure data movement and bookkeeping; the step itself is in simulation.cpp.
#include "sluice/solver/simulation.hpp"

#include "particle_messages.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

namespace sluice {

template <int D>
void Simulation<D>::distribute_initial_particles(bool shares) {
    if (!comm_.parallel())
        return;
    if (!shares) {
        // A fresh start: initial_share built only this rank's particles, under layout_.
        peers_ = tasks::peer_ranks(grid_, layout_)[static_cast<std::size_t>(comm_.rank())];
        return;
    }
    // A restart: each rank holds a share of the checkpoint's particles; each ends with the
    // cells of its part of the curve, cut as one rank holding every particle would cut it.
    rebinner_(grid_, P_, ranges_, occupied_);
    if (cfg_.initial_decomposition == InitialDecomposition::key_range) {
        layout_ = tasks::cut_ranks_by_key(grid_, comm_.size());
    } else {
        std::vector<tasks::CurveUnit> units;
        units.reserve(occupied_.size());
        for (const auto& c : occupied_)
            units.push_back({c.key, static_cast<double>(c.count)});
        layout_ = tasks::cut_ranks(all_occupied_cells(units), comm_.size());
    }
    peers_ = tasks::peer_ranks(grid_, layout_)[static_cast<std::size_t>(comm_.rank())];
    std::vector<std::size_t> keep;
    std::vector<tasks::Bytes> out(static_cast<std::size_t>(comm_.size())), in;
    for (const auto& c : occupied_) {
        const int owner = layout_.rank_of(c.key);
        for (std::uint32_t i = ranges_.begin[c.cell]; i < ranges_.end[c.cell]; ++i)
            if (owner == comm_.rank())
                keep.push_back(i);
            else
                messages::pack_particle(P_, i, out[static_cast<std::size_t>(owner)]);
    }
    comm_.all_to_all(out, in);
    P_.permute(keep);
    P_.resize(keep.size());
    // Arrival order does not matter: the rebin sorts by (cell key, id).
    for (const auto& b : in)
        messages::unpack_particles<D>(b, P_);
    // The arrays not permuted kept the share's size, and appending may have doubled others.
    P_.shrink_to_fit();
}

template <int D>
std::vector<tasks::CurveUnit>
Simulation<D>::all_occupied_cells(const std::vector<tasks::CurveUnit>& mine) const {
    // Every rank's occupied cells with their particle counts; a cell may straddle two shares,
    // so equal keys are merged. The result is the list one rank holding every particle makes.
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
void Simulation<D>::plan_halo() {
    if (!comm_.parallel())
        return;
    const double t0 = tasks::clock_seconds();
    const std::size_t P = peers_.size();
    std::vector<CellIndex> cells;
    cells.reserve(occupied_.size());
    for (const auto& c : occupied_)
        cells.push_back(c.cell);
    occupied_targets_ = tasks::halo_targets(grid_, layout_, comm_.rank(), peers_, cells);
    plan_.send_cells.assign(P, {});
    plan_.send_count.assign(P, 0);
    plan_.send_walls.assign(P, 0);
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (occupied_targets_[k].empty())
            continue;
        std::size_t walls = 0;
        for (std::uint32_t i = ranges_.begin[cells[k]]; i < ranges_.end[cells[k]]; ++i)
            walls += P_.kind[i] == Kind::wall ? 1 : 0;
        for (int p : occupied_targets_[k]) {
            const auto pu = static_cast<std::size_t>(p);
            plan_.send_cells[pu].push_back(cells[k]);
            plan_.send_count[pu] += occupied_[k].count;
            plan_.send_walls[pu] += walls;
        }
    }
    // Each peer learns how many particles (and walls) it will receive, so that it can size
    // its arrays and post exact receives before the step starts.
    std::vector<tasks::Bytes> out(P), in;
    for (std::size_t p = 0; p < P; ++p) {
        tasks::put(out[p], static_cast<std::uint64_t>(plan_.send_count[p]));
        tasks::put(out[p], static_cast<std::uint64_t>(plan_.send_walls[p]));
    }
    comm_.exchange(peers_, out, in, 12);
    plan_.recv_count.assign(P, 0);
    plan_.recv_walls.assign(P, 0);
    plan_.recv_offset.assign(P, 0);
    std::size_t next = owned_;
    for (std::size_t p = 0; p < P; ++p) {
        std::size_t pos = 0;
        plan_.recv_count[p] = tasks::take<std::uint64_t>(in[p], pos);
        plan_.recv_walls[p] = tasks::take<std::uint64_t>(in[p], pos);
        plan_.recv_offset[p] = next;
        next += plan_.recv_count[p];
    }
    P_.resize(next);
    between_.push_back({"halo counts", -1, true, 16 * P, t0, tasks::clock_seconds()});
}

template <int D>
std::vector<std::vector<int>> Simulation<D>::boundary_groups() const {
    // Groups holding a halo cell of each peer; occupied_ and the concatenated group cell
    // lists are in the same (key) order.
    std::vector<std::vector<int>> facing(peers_.size());
    std::size_t k = 0;
    for (int g = 0; g < topo_.group_count(); ++g)
        for (std::size_t c = 0; c < topo_.cells[static_cast<std::size_t>(g)].size(); ++c, ++k)
            for (int p : occupied_targets_[k]) {
                auto& f = facing[static_cast<std::size_t>(p)];
                if (f.empty() || f.back() != g)
                    f.push_back(g);
            }
    return facing;
}

template <int D>
void Simulation<D>::migrate_to_neighbours() {
    // A particle moves less than one cell per step, so it can only enter a peer's cell.
    const double t0 = tasks::clock_seconds();
    std::vector<tasks::Bytes> out(peers_.size()), in;
    std::vector<std::size_t> keep;
    keep.reserve(P_.size());
    for (std::size_t i = 0; i < P_.size(); ++i) {
        const int owner = layout_.rank_of(grid_.morton(grid_.coords(P_.x[i])));
        if (owner == comm_.rank()) {
            keep.push_back(i);
            continue;
        }
        const auto it = std::lower_bound(peers_.begin(), peers_.end(), owner);
        if (it == peers_.end() || *it != owner)
            throw std::logic_error(fmt::format("particle {} jumped to rank {}, not a neighbour "
                                               "of rank {}",
                                               P_.id[i], owner, comm_.rank()));
        messages::pack_particle(P_, i, out[static_cast<std::size_t>(it - peers_.begin())]);
    }
    comm_.exchange(peers_, out, in, 11);
    std::size_t bytes = 0;
    for (const auto& b : out)
        bytes += b.size();
    if (keep.size() != P_.size()) {
        P_.permute(keep);
        P_.resize(keep.size());
    }
    for (const auto& b : in)
        messages::unpack_particles<D>(b, P_);
    between_.push_back({"migrate", -1, true, bytes, t0, tasks::clock_seconds()});
}

template <int D>
std::optional<typename Simulation<D>::PlannedCut> Simulation<D>::plan_rebalance() {
    // Every rank offers its occupied cells as units of the curve, each with its share (by
    // particle count) of its group's measured cost per step; all ranks compute the same new cut
    // points from the same gathered list.
    const double t0 = tasks::clock_seconds();
    tasks::Bytes mine;
    for (int g = 0; g < topo_.group_count(); ++g) {
        const auto& cells = topo_.cells[static_cast<std::size_t>(g)];
        double particles = 0;
        for (CellIndex c : cells)
            particles += ranges_.end[c] - ranges_.begin[c];
        const double per_particle = tasks::cost_per_particle(
            cfg_.balance_cost == BalanceCost::time, group_busy_[static_cast<std::size_t>(g)],
            graph_steps_, particles);
        for (CellIndex c : cells) {
            tasks::put(mine, grid_.morton(grid_.unlinear(c)));
            tasks::put(mine, per_particle * (ranges_.end[c] - ranges_.begin[c]));
        }
    }
    std::vector<tasks::CurveUnit> units;
    for (const auto& b : comm_.all_gather(mine)) {
        std::size_t pos = 0;
        while (pos < b.size()) {
            tasks::CurveUnit u{};
            u.key = tasks::take<MortonKey>(b, pos);
            u.cost = tasks::take<double>(b, pos);
            units.push_back(u);
        }
    }
    auto plan = balance_.plan(units, layout_);
    if (!plan)
        return std::nullopt;
    return PlannedCut{std::move(*plan), t0};
}

template <int D>
void Simulation<D>::apply_rebalance(const PlannedCut& cut, bool at_rebuild) {
    // Here P_ holds exactly this rank's particles. Every particle goes to its owner under the
    // new cuts.
    const tasks::RankLayout& next = cut.plan.layout;
    std::vector<tasks::Bytes> out(static_cast<std::size_t>(comm_.size())), in;
    std::vector<std::size_t> keep;
    std::uint64_t moved = 0;
    for (std::size_t i = 0; i < P_.size(); ++i) {
        const int owner = next.rank_of(grid_.morton(grid_.coords(P_.x[i])));
        if (owner == comm_.rank()) {
            keep.push_back(i);
        } else {
            messages::pack_particle(P_, i, out[static_cast<std::size_t>(owner)]);
            ++moved;
        }
    }
    comm_.all_to_all(out, in);
    P_.permute(keep);
    P_.resize(keep.size());
    for (const auto& b : in)
        messages::unpack_particles<D>(b, P_);
    std::uint64_t moved_total = 0;
    for (const auto& b : comm_.all_gather(std::span<const std::byte>(
             reinterpret_cast<const std::byte*>(&moved), sizeof(moved)))) {
        std::size_t pos = 0;
        moved_total += tasks::take<std::uint64_t>(b, pos);
    }
    layout_ = next;
    peers_ = tasks::peer_ranks(grid_, layout_)[static_cast<std::size_t>(comm_.rank())];
    force_regroup_ = true;
    balance_.cuts_moved();
    const double t1 = tasks::clock_seconds();
    rebalances_.push_back(
        {steps_, balance_.measured(), cut.plan.predicted, moved_total, t1 - cut.t0, at_rebuild});
    between_.push_back({"rebalance", -1, true, 0, cut.t0, t1});
    if (opts_.log_rebalances && comm_.rank() == 0)
        fmt::print(stderr,
                   "sluice: rebalance at step {}{}: imbalance {:.3f} -> {:.3f} (predicted), {} "
                   "particles moved, {:.1f} ms\n",
                   steps_, at_rebuild ? "" : " (between rebuilds)", balance_.measured(),
                   cut.plan.predicted, moved_total, (t1 - cut.t0) * 1e3);
}

template <int D>
bool Simulation<D>::rebalance_between_rebuilds() {
    // Without this, a rebalance found due waits for the next rebuild, which in a flow that
    // moves slowly (or not at all) can be hundreds of steps away, or never come.
    balance_.clear_due();
    const auto cut = plan_rebalance();
    if (!cut)
        return false;
    P_.resize(owned_); // drop the halo copies: they are received afresh next step
    // Owner, sort, groups and lists follow the positions of the last rebuild, as after a
    // restart: the lists the next step builds are those that rebuild built, so results stay
    // bitwise those of any other layout, and the next rebuild comes at the same step.
    std::swap(P_.x, P_.x_ref);
    apply_rebalance(*cut, false);
    rebin_and_decompose();
    std::swap(P_.x, P_.x_ref);
    return true;
}

template <int D>
Particles<D> Simulation<D>::gather_particles() const {
    if (!comm_.parallel()) {
        Particles<D> copy = P_;
        copy.resize(owned_);
        return copy;
    }
    tasks::Bytes mine;
    mine.reserve(owned_ * messages::particle_bytes<D>);
    for (std::size_t i = 0; i < owned_; ++i)
        messages::pack_particle(P_, i, mine);
    Particles<D> out;
    // Ranks own consecutive runs of the curve, so rank order is (cell key, id) order.
    for (const auto& b : comm_.gather(mine, 0))
        messages::unpack_particles<D>(b, out);
    return out;
}

#define SLUICE_RANK_MEMBERS(D)                                                                     \
    template void Simulation<D>::distribute_initial_particles(bool);                               \
    template std::vector<tasks::CurveUnit> Simulation<D>::all_occupied_cells(                      \
        const std::vector<tasks::CurveUnit>&) const;                                               \
    template void Simulation<D>::plan_halo();                                                      \
    template std::vector<std::vector<int>> Simulation<D>::boundary_groups() const;                 \
    template void Simulation<D>::migrate_to_neighbours();                                          \
    template std::optional<Simulation<D>::PlannedCut> Simulation<D>::plan_rebalance();             \
    template void Simulation<D>::apply_rebalance(const PlannedCut&, bool);                         \
    template bool Simulation<D>::rebalance_between_rebuilds();                                     \
    template Particles<D> Simulation<D>::gather_particles() const;
SLUICE_RANK_MEMBERS(2)
SLUICE_RANK_MEMBERS(3)
#undef SLUICE_RANK_MEMBERS

} // namespace sluice
