#pragma once
// The balancer's policy (docs/ARCHITECTURE.md, "Balance"): when the cut points between ranks
// should move, and where to. Pure: busy times and costs in, a decision and cut points out. The
// caller gathers the numbers from the ranks (every rank feeds the same numbers, so every rank
// decides the same) and moves the particles. Like the rest of tasks/, it knows keys and costs,
// never what is computed in a cell.
#include "sluice/tasks/rank_layout.hpp"

#include <optional>
#include <vector>

namespace sluice::tasks {

struct BalanceSettings {
    int window = 10;         // runtime.rebalance_window: steps summed before a judgement
    double threshold = 0.10; // runtime.rebalance_threshold: tolerated max/mean - 1
    int every = 0;           // runtime.rebalance_every: force a rebalance this often (0: never)
};

// When a rebalance found due is done: at the next rebuild of the Verlet lists (where particles
// change owner anyway), or now, even without one (worth an extra rebuild).
enum class BalanceDue { no, at_rebuild, now };

// The imbalance measured over one window of steps (the "imbalance curve").
struct BalanceSample {
    long step = 0;
    double imbalance = 0;
};

// New cut points and what they are expected to give, judged on one list of unit costs.
struct BalancePlan {
    RankLayout layout;
    double predicted = 0; // max/mean cost under the new cuts
    double present = 0;   // max/mean cost under the present cuts
};

class BalancePolicy {
public:
    BalancePolicy() = default;
    BalancePolicy(BalanceSettings settings, int ranks);

    // After each step: every rank's busy seconds in it (rank order); `step` is the number of
    // the step just completed (it labels the window's sample).
    void add_step(long step, const std::vector<double>& busy_per_rank);

    // The decision of the last judged window (kept until clear_due()).
    [[nodiscard]] BalanceDue due() const { return due_; }
    // The imbalance that made the rebalance due.
    [[nodiscard]] double measured() const { return measured_; }
    // rebalance_every says so: the cuts move whatever the gain.
    [[nodiscard]] bool forced() const {
        return settings_.every > 0 && steps_since_cut_ >= settings_.every;
    }
    void clear_due() { due_ = BalanceDue::no; }

    // Cut points splitting `units` (the cells of every rank in key order, with their cost per
    // step) into runs of equal cost; none when the gain over `present` is too small to pay
    // for the move (below half the threshold) and the rebalance is not forced.
    [[nodiscard]] std::optional<BalancePlan> plan(const std::vector<CurveUnit>& units,
                                                  const RankLayout& present) const;
    // The cut points moved: the "sustained" rule and rebalance_every count from here.
    void cuts_moved();

    [[nodiscard]] const std::vector<BalanceSample>& history() const { return history_; }

private:
    BalanceSettings settings_;
    int ranks_ = 1;
    std::vector<double> window_busy_; // per rank, since the last judgement
    std::vector<double> cut_busy_;    // per rank, since the cut points last moved
    long window_steps_ = 0, steps_since_cut_ = 0;
    BalanceDue due_ = BalanceDue::no;
    double measured_ = 0;
    std::vector<BalanceSample> history_;
};

// A cell's cost per step and particle: its group's measured busy seconds per step shared out
// by particle count (`by_time`, once `steps` > 0), or 1 (cost = particle count).
[[nodiscard]] double cost_per_particle(bool by_time, double group_busy, long steps,
                                       double particles);

} // namespace sluice::tasks
