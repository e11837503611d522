// The balancer's policy without MPI: hand-built busy times decide when a rebalance is due, and
// hand-computed cut points and imbalances of known cost arrays (tasks/balance_policy.hpp).
#include "sluice/tasks/balance_policy.hpp"

#include <doctest/doctest.h>

using namespace sluice::tasks;

namespace {

// `steps` steps in which every rank is busy for the given seconds.
void feed(BalancePolicy& p, long& step, int steps, const std::vector<double>& busy) {
    for (int k = 0; k < steps; ++k)
        p.add_step(++step, busy);
}

} // namespace

TEST_CASE("a balanced window triggers nothing and is recorded") {
    BalancePolicy p({3, 0.10, 0}, 2);
    long step = 0;
    feed(p, step, 2, {1.0, 1.0});
    CHECK(p.history().empty()); // the window is not full yet
    feed(p, step, 1, {1.0, 1.0});
    CHECK(p.due() == BalanceDue::no);
    REQUIRE(p.history().size() == 1);
    CHECK(p.history()[0].step == 3);
    CHECK(p.history()[0].imbalance == 1.0);
    // 1.05 (max 1.05 s against a mean of 1 s) is within the threshold of 0.10.
    feed(p, step, 3, {1.05, 0.95});
    CHECK(p.due() == BalanceDue::no);
    REQUIRE(p.history().size() == 2);
    CHECK(p.history()[1].step == 6);
    CHECK(p.history()[1].imbalance == doctest::Approx(1.05));
}

TEST_CASE("one window over the threshold waits for a rebuild; two at twice it are due now") {
    BalancePolicy p({3, 0.10, 0}, 2);
    long step = 0;
    // 1.3 s against a mean of 1 s: 1.3 > 1.1, but one window only.
    feed(p, step, 3, {1.3, 0.7});
    CHECK(p.due() == BalanceDue::at_rebuild);
    CHECK(p.measured() == doctest::Approx(1.3));
    // The second window: six steps since the cuts moved, 1.3 > 1 + 2 * 0.10 over all of them.
    feed(p, step, 3, {1.3, 0.7});
    CHECK(p.due() == BalanceDue::now);

    // After the cuts move, the sustained rule starts over.
    p.clear_due();
    p.cuts_moved();
    feed(p, step, 3, {1.3, 0.7});
    CHECK(p.due() == BalanceDue::at_rebuild);
}

TEST_CASE("an imbalance over the threshold but under twice it never becomes due now") {
    BalancePolicy p({3, 0.10, 0}, 2);
    long step = 0;
    feed(p, step, 9, {1.15, 0.85}); // three windows of 1.15: 1.1 < 1.15 < 1.2
    CHECK(p.due() == BalanceDue::at_rebuild);
    CHECK(p.measured() == doctest::Approx(1.15));
    // A balanced window after an unbalanced one leaves the decision for the rebuild standing,
    // and over the twelve steps since the cuts moved the imbalance is 1.1125 < 1.2.
    feed(p, step, 3, {1.0, 1.0});
    CHECK(p.due() == BalanceDue::at_rebuild);
}

TEST_CASE("rebalance_every forces a rebalance, however balanced and whatever the gain") {
    BalancePolicy p({10, 0.10, 4}, 2);
    long step = 0;
    feed(p, step, 3, {1.0, 1.0});
    CHECK(p.due() == BalanceDue::no);
    CHECK_FALSE(p.forced());
    feed(p, step, 1, {1.0, 1.0});
    CHECK(p.forced());
    CHECK(p.due() == BalanceDue::now);
    CHECK(p.measured() == 1.0);
    CHECK(p.history().empty()); // four steps of a ten-step window: no sample
    // Already at the best cuts: planned anyway.
    const std::vector<CurveUnit> units{{0, 1.0}, {8, 1.0}};
    RankLayout present;
    present.key_begin = {0, 8};
    const auto plan = p.plan(units, present);
    REQUIRE(plan);
    CHECK(plan->layout.key_begin == present.key_begin);
    CHECK(plan->predicted == 1.0);
    p.clear_due();
    p.cuts_moved();
    CHECK_FALSE(p.forced());
    CHECK_FALSE(p.plan(units, present));
}

TEST_CASE("planned cuts of a known cost array") {
    // Costs 3, 1, 2, 2, 1, 3, 0.5, 0.5 (total 13) on 3 ranks: ideal cuts at 13/3 and 26/3.
    // Cost prefixes 0, 3, 4, 6, 8, 9, 12, 12.5, 13: the first cut lands before unit 2 (4 is
    // 0.33 short of 4.33, 6 is 1.67 past it), the second before unit 5 (9 is 0.33 past 8.67,
    // 8 is 0.67 short). Ranks get 4, 5 and 4: 5 / (13/3) = 15/13.
    std::vector<CurveUnit> units;
    const double costs[] = {3, 1, 2, 2, 1, 3, 0.5, 0.5};
    for (int k = 0; k < 8; ++k)
        units.push_back({static_cast<sluice::MortonKey>(16 * k), costs[k]});
    BalancePolicy p({10, 0.10, 0}, 3);
    RankLayout present; // 3 | 1 2 2 1 3 0.5 | 0.5: 9.5 / (13/3) = 28.5/13
    present.key_begin = {0, 16, 112};
    const auto plan = p.plan(units, present);
    REQUIRE(plan);
    CHECK(plan->layout.key_begin == std::vector<sluice::MortonKey>{0, 32, 80});
    CHECK(plan->predicted == doctest::Approx(15.0 / 13.0));
    CHECK(plan->present == doctest::Approx(28.5 / 13.0));
    // The new cuts as the present ones: no gain, refused.
    CHECK_FALSE(p.plan(units, plan->layout));
}

TEST_CASE("a plan whose gain is below half the threshold is refused") {
    // Costs 48, 2, 50: the best cut (before unit 2) gives 50 | 50, imbalance 1; the present
    // cut (before unit 1) gives 48 | 52, imbalance 1.04. A gain of 0.04 is below 0.10 / 2 but
    // above 0.06 / 2.
    const std::vector<CurveUnit> units{{0, 48.0}, {8, 2.0}, {16, 50.0}};
    RankLayout present;
    present.key_begin = {0, 8};
    CHECK_FALSE(BalancePolicy({10, 0.10, 0}, 2).plan(units, present));
    const auto plan = BalancePolicy({10, 0.06, 0}, 2).plan(units, present);
    REQUIRE(plan);
    CHECK(plan->layout.key_begin == std::vector<sluice::MortonKey>{0, 16});
    CHECK(plan->predicted == 1.0);
    CHECK(plan->present == doctest::Approx(1.04));
}

TEST_CASE("a cell's cost per particle: measured time shared by particle count, or 1") {
    CHECK(cost_per_particle(true, 6.0, 3, 4.0) == 0.5);  // 6 s over 3 steps, 4 particles
    CHECK(cost_per_particle(true, 6.0, 0, 4.0) == 1.0);  // nothing measured yet
    CHECK(cost_per_particle(true, 6.0, 3, 0.0) == 1.0);  // an empty group
    CHECK(cost_per_particle(false, 6.0, 3, 4.0) == 1.0); // balance_cost = "particles"
}
