// The rebalance of Simulation<D> (docs/ARCHITECTURE.md, "Balance"): the measured cost of
// every cell offered to the balancer's policy (tasks/balance_policy.hpp), which decides when
// and where the cut points move, and the move to its cuts (RankExchange), at a rebuild or
// between rebuilds. The step itself is in simulation.cpp.
#include "sluice/solver/simulation.hpp"

#include <fmt/format.h>

namespace sluice {

template <int D>
std::optional<typename Simulation<D>::PlannedCut> Simulation<D>::plan_rebalance() {
    // Every rank offers its occupied cells as units of the curve, each with its share (by
    // particle count) of its group's measured cost per step; all ranks compute the same new cut
    // points from the same gathered list.
    const double t0 = tasks::clock_seconds();
    std::vector<tasks::CurveUnit> mine;
    for (int g = 0; g < topo_.group_count(); ++g) {
        const auto& cells = topo_.cells[static_cast<std::size_t>(g)];
        double particles = 0;
        for (CellIndex c : cells)
            particles += ranges_.end(c) - ranges_.begin(c);
        const double per_particle = tasks::cost_per_particle(
            cfg_.balance_cost == BalanceCost::time, group_busy_[static_cast<std::size_t>(g)],
            graph_steps_, particles);
        for (CellIndex c : cells)
            mine.push_back({grid_.morton(grid_.unlinear(c)),
                            per_particle * (ranges_.end(c) - ranges_.begin(c))});
    }
    auto plan = balance_.plan(ranks_.all_units(mine), ranks_.layout());
    if (!plan)
        return std::nullopt;
    return PlannedCut{std::move(*plan), t0};
}

template <int D>
void Simulation<D>::apply_rebalance(const PlannedCut& cut, bool at_rebuild) {
    // Here P_ holds exactly this rank's particles. Every particle goes to its owner under the
    // new cuts, and the exchange adopts them.
    const std::uint64_t moved_total = ranks_.move_to(cut.plan.layout, P_);
    force_regroup_ = true;
    balance_.cuts_moved();
    const double t1 = tasks::clock_seconds();
    rebalances_.push_back({clock_.steps, balance_.measured(), cut.plan.predicted, moved_total,
                           t1 - cut.t0, at_rebuild});
    between_.push_back({"rebalance", -1, true, 0, cut.t0, t1});
    if (opts_.log_rebalances && comm_.rank() == 0)
        fmt::print(stderr,
                   "sluice: rebalance at step {}{}: imbalance {:.3f} -> {:.3f} (predicted), {} "
                   "particles moved, {:.1f} ms\n",
                   clock_.steps, at_rebuild ? "" : " (between rebuilds)", balance_.measured(),
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

#define SLUICE_BALANCE_MEMBERS(D)                                                                  \
    template std::optional<Simulation<D>::PlannedCut> Simulation<D>::plan_rebalance();             \
    template void Simulation<D>::apply_rebalance(const PlannedCut&, bool);                         \
    template bool Simulation<D>::rebalance_between_rebuilds();
SLUICE_BALANCE_MEMBERS(2)
SLUICE_BALANCE_MEMBERS(3)
#undef SLUICE_BALANCE_MEMBERS

} // namespace sluice
