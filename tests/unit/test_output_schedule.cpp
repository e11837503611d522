// The output schedule (solver/output_schedule.hpp): which probes and snapshots are due at a
// sequence of step times, the start and end of a run, and a resumed run.
#include "sluice/solver/output_schedule.hpp"

#include <doctest/doctest.h>

using namespace sluice;

namespace {

CaseConfig three_probes(bool snapshots) {
    CaseConfig cfg;
    cfg.end_time = 1.0;
    cfg.output_interval = 0.25;
    cfg.snapshots = snapshots;
    ProbeConfig p;
    p.name = "fine";
    p.interval = 0.1;
    cfg.probes.push_back(p);
    p.name = "every";
    p.interval = 0;
    p.every_step = true;
    cfg.probes.push_back(p);
    p.name = "outputs"; // interval 0: at the output interval
    p.every_step = false;
    cfg.probes.push_back(p);
    return cfg;
}

using Probes = std::vector<std::size_t>;

} // namespace

TEST_CASE("output schedule: a run from start to end") {
    const CaseConfig cfg = three_probes(true);
    OutputSchedule s(cfg);
    // Start (forced): everything, with a snapshot.
    auto d = s.due(0.0, true);
    CHECK(d.probes == Probes{0, 1, 2});
    CHECK(d.output);
    CHECK(d.snapshot);
    s.done(d, 0.0);
    CHECK(s.out_next() == 0.25);
    CHECK(s.probe_next() == std::vector<double>{0.1, 0.25, 0.25}); // every-step: unused
    // A step at 0.06: only the every-step probe.
    d = s.due(0.06, false);
    CHECK(d.probes == Probes{1});
    CHECK_FALSE(d.output);
    s.done(d, 0.06);
    // 0.1 minus a rounding error (within 1e-12 end_time) counts as 0.1.
    d = s.due(0.1 - 1e-14, false);
    CHECK(d.probes == Probes{0, 1});
    s.done(d, 0.1 - 1e-14);
    CHECK(s.probe_next()[0] == doctest::Approx(0.2));
    // A long step past two of the fine probe's times and an output time: one row each, and the
    // next times move past it (0.3 for the fine probe, 0.5 for the outputs).
    d = s.due(0.27, false);
    CHECK(d.probes == Probes{0, 1, 2});
    CHECK(d.output);
    CHECK(d.snapshot);
    s.done(d, 0.27);
    CHECK(s.probe_next()[0] == doctest::Approx(0.3));
    CHECK(s.out_next() == doctest::Approx(0.5));
    CHECK(s.last_output_time() == 0.27);
    // The last step lands on the end, the regular sample takes what is due, and the final
    // forced sample writes only what was not written at that time.
    d = s.due(1.0, false);
    s.done(d, 1.0);
    CHECK(d.probes == Probes{0, 1, 2});
    d = s.due(1.0, true);
    CHECK(d.probes.empty());
    CHECK(d.output);
    CHECK_FALSE(d.snapshot); // already written at 1.0
}

TEST_CASE("output schedule: without snapshots, output times still advance") {
    const CaseConfig cfg = three_probes(false);
    OutputSchedule s(cfg);
    const auto d = s.due(0.0, true);
    CHECK(d.output);
    CHECK_FALSE(d.snapshot);
    s.done(d, 0.0);
    CHECK(s.out_next() == 0.25);
}

TEST_CASE("output schedule: a resumed run continues the checkpoint's schedule") {
    const CaseConfig cfg = three_probes(true);
    OutputState state;
    state.out_next = 0.75;
    state.last_output_time = 0.5;
    state.probe_next = {0.6, 0.0, 0.75};
    OutputSchedule s(cfg);
    s.resume(state, 0.55); // the checkpoint was written after the sample at 0.55
    // The run's first (forced) sample at the checkpoint's time writes nothing again.
    auto d = s.due(0.55, true);
    CHECK(d.probes.empty());
    s.done(d, 0.55);
    // The next step: the every-step probe, and the fine probe once 0.6 is reached.
    d = s.due(0.58, false);
    CHECK(d.probes == Probes{1});
    d = s.due(0.6, false);
    CHECK(d.probes == Probes{0, 1});
}
