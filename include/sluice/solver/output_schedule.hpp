#pragma once
// When a run writes: which probes are due at a time and whether it is an output time (a
// snapshot when snapshots are on), and how the next times advance. Pure bookkeeping, the same
// on every rank (every rank calls it with the same times); the driver (run.cpp) samples and
// writes what it says. Its state goes into a checkpoint (OutputState) and comes back from one.
#include "sluice/io/case_config.hpp"
#include "sluice/io/checkpoint.hpp"

#include <cstddef>
#include <vector>

namespace sluice {

class OutputSchedule {
public:
    explicit OutputSchedule(const CaseConfig& cfg);

    // Continues the schedule of a checkpoint written at time t: the checkpoint follows the
    // sample at its time, so nothing is due again at t.
    void resume(const OutputState& state, double t);

    struct Due {
        std::vector<std::size_t> probes; // indices into cfg.probes
        bool output = false;             // an output time (its bookkeeping advances)
        bool snapshot = false;           // ... at which a snapshot is written
    };
    // What is due at time t; `force` makes everything due (start and end of a run), except
    // what was already written at t (an every-step probe before the final forced sample).
    // An every-step probe is due at every call.
    [[nodiscard]] Due due(double t, bool force) const;
    // Records that `d` was written at time t and moves the next times past t.
    void done(const Due& d, double t);

    [[nodiscard]] double out_next() const { return out_next_; }
    [[nodiscard]] double last_output_time() const { return last_output_time_; }
    [[nodiscard]] const std::vector<double>& probe_next() const { return probe_next_; }

private:
    const CaseConfig& cfg_;
    double eps_;       // time tolerance: 1e-12 end_time
    double out_every_; // output interval (end_time when 0)
    std::vector<double> probe_every_, probe_next_;
    std::vector<double> probe_last_; // time of each probe's last row
    double out_next_ = 0, last_output_time_ = -1;
};

} // namespace sluice
