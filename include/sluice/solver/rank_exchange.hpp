#pragma once
// The rank plumbing (docs/ARCHITECTURE.md, "Ranks"): which part of the Morton curve this rank
// owns and who its peers are, the halo plan (which particles each peer gets before a step),
// the particles that change owner (migration to a neighbour after a rebuild; the all-to-all of
// a restart or a rebalance), the cost list the balancer's policy cuts, and the gather that
// tests use. It moves particles and counts them; it knows no formula and no stage, and it
// holds no particles: the rank's arrays are passed in. Collective member functions are marked;
// on one rank they do nothing that needs a peer.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/solver/halo_plan.hpp"
#include "sluice/tasks/comm.hpp"
#include "sluice/tasks/decomposition.hpp"
#include "sluice/tasks/profile.hpp"
#include "sluice/tasks/rank_layout.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace sluice {

template <int D>
class RankExchange {
public:
    // `grid` is the rank's grid, read at each call (it may be set after construction).
    RankExchange(tasks::Comm comm, const CellGrid<D>& grid) : comm_(comm), grid_(grid) {}

    [[nodiscard]] const tasks::RankLayout& layout() const { return layout_; }
    [[nodiscard]] const std::vector<int>& peers() const { return peers_; }
    [[nodiscard]] const HaloPlan& plan() const { return plan_; }

    // The cut points of the start (initial_share's, every rank the same); peers follow in
    // distribute().
    void set_layout(const tasks::RankLayout& layout) { layout_ = layout; }
    // `shares`: every rank holds a share of a checkpoint's particles (a restart), sent here to
    // their owners under cut points computed as one rank holding every particle would (or the
    // key-range cut); otherwise each holds its own already and learns its peers. Collective.
    void distribute(Particles<D>& P, bool shares, bool key_range);

    // The halo plan of the sorted owned particles P[0, owned) (`ranges`, `occupied`: the rebin
    // of them): which cells go to which peer, and how many particles come from each; P grows
    // to hold them. After migrate() the counts came with the migrants and nothing is sent;
    // otherwise (start, rebalance) it is collective among peers and returns the record of its
    // count exchange.
    std::optional<tasks::MessageRecord> plan_halo(Particles<D>& P, const CellRanges& ranges,
                                                  const std::vector<CellOccupancy>& occupied,
                                                  std::size_t owned);
    // Whether every peer will send exactly the particles (and walls) this rank's plan expects
    // from it: each rank sends its peers its send counts and compares (an extra round, for
    // tests). Collective among peers.
    [[nodiscard]] bool halo_counts_agree() const;
    // Per peer, the local groups holding a halo cell of it (after plan_halo, whose occupied
    // cells are the concatenated cell lists of `topo`).
    [[nodiscard]] std::vector<std::vector<int>>
    boundary_groups(const tasks::GroupTopology& topo) const;

    // Sends every particle of P whose cell is a peer's to that peer and appends those
    // received (P holds owned particles only). The same round carries the halo counts of the
    // next plan_halo (rank_migration.cpp), so a rebuild exchanges once. Collective among the
    // ranks within two peer steps.
    tasks::MessageRecord migrate(Particles<D>& P);

    // Every rank's `mine` (cells with their cost, in curve order) in rank order, hence in curve
    // order. Collective.
    [[nodiscard]] std::vector<tasks::CurveUnit>
    all_units(const std::vector<tasks::CurveUnit>& mine) const;
    // Sends every particle of P to its owner under `next` and adopts `next` (and its peers).
    // Returns the particles moved over all ranks. Collective.
    std::uint64_t move_to(const tasks::RankLayout& next, Particles<D>& P);

    // Every rank's P[0, owned) on rank 0, in (cell key, id) order (empty elsewhere; on one
    // rank a copy). Collective.
    [[nodiscard]] Particles<D> gather(const Particles<D>& P, std::size_t owned) const;

private:
    // all_units with a cell that straddles two shares merged (whole particle counts).
    [[nodiscard]] std::vector<tasks::CurveUnit>
    all_occupied_cells(const std::vector<tasks::CurveUnit>& mine) const;
    void find_peers();

    tasks::Comm comm_;
    const CellGrid<D>& grid_;
    tasks::RankLayout layout_;
    std::vector<int> peers_;
    std::vector<int> reach_; // peers and their peers: whom a migration's halo counts concern
    HaloPlan plan_;
    // Per peer, the particles (and walls) it will send as halo after the last migrate(); used
    // by the next plan_halo instead of a count round when `halo_in_known_`.
    std::vector<std::size_t> halo_in_count_, halo_in_walls_;
    bool halo_in_known_ = false;
    std::vector<std::vector<int>> occupied_targets_; // per occupied cell: peers it is halo of
};

extern template class RankExchange<2>;
extern template class RankExchange<3>;

} // namespace sluice
