#pragma once
// A run's output files: the results folder made ready, the snapshots, the probe files and the
// output schedule that says when each is due, and the checkpoint that records them. Every
// rank writes its slice of a snapshot and of a checkpoint (collective); the probe files and
// the folder are rank 0's. Private to the driver (run.cpp).
#include "sluice/io/case_config.hpp"
#include "sluice/io/checkpoint.hpp"
#include "sluice/io/probe_writer.hpp"
#include "sluice/io/run_log.hpp"
#include "sluice/io/snapshot_writer.hpp"
#include "sluice/solver/output_schedule.hpp"
#include "sluice/solver/simulation.hpp"

#include <memory>
#include <string>

namespace sluice {

template <int D>
class RunOutputs {
public:
    // Makes the folder ready (rank 0: an old summary.json, stop file, partial checkpoint and,
    // on a fresh start, the old checkpoint removed) and opens the writers; on a restart
    // (`resumed` = the checkpoint's record) continues the files it records at time `t`.
    RunOutputs(const CaseConfig& cfg, const std::string& out_dir, const OutputState* resumed,
               double t, bool root, RunLog& log);

    // The probes and the snapshot due at the simulation's time (every one when `force`).
    void sample(const Simulation<D>& sim, bool force);
    // Whether sample() at time t would read nothing of the state (no probe or output due).
    [[nodiscard]] bool quiet_at(double t) const;
    // The end time's sample, unless the last sample was taken there.
    void finish(const Simulation<D>& sim);
    // After a failed step: the state every rank holds (the last good one) as a snapshot, even
    // with snapshots off; returns ", <label> in <file>" on rank 0 (empty on the others).
    std::string last_snapshot(const Simulation<D>& sim, const std::string& label);
    // The fluid's spacing census of the last snapshot written (every rank's counts together).
    [[nodiscard]] const NeighbourCensus& last_spacing() const { return last_spacing_; }
    // That census if the last snapshot was written at `step` (the state the caller holds:
    // every step changes it), so the run's totals need not take it again; otherwise null.
    // Its support and threshold are the run's: the kernel's support, crowded_below(dx).
    [[nodiscard]] const NeighbourCensus* spacing_at(long step) const {
        return spacing_step_ == step ? &last_spacing_ : nullptr;
    }
    // Collective: the particles, the solver's state and this record of the outputs;
    // `wall_seconds` is every segment's time loop so far.
    void write_checkpoint(const Simulation<D>& sim, double wall_seconds);

    [[nodiscard]] const std::string& checkpoint_file() const { return checkpoint_file_; }

private:
    const CaseConfig& cfg_;
    std::string out_dir_;
    std::string checkpoint_file_;
    bool root_;
    RunLog& log_;
    OutputSchedule schedule_;
    std::unique_ptr<SnapshotWriter<D>> snapshots_;
    std::unique_ptr<ProbeWriter> probe_files_;
    NeighbourCensus last_spacing_;
    long spacing_step_ = -1; // the step of the state last_spacing_ counted
    // Collective: the next snapshot, with the fluid's spacing (spacing_census.hpp).
    std::string write_snapshot(const Simulation<D>& sim);
};

extern template class RunOutputs<2>;
extern template class RunOutputs<3>;

} // namespace sluice
