// A run's output files (run_outputs.hpp).
#include "run_outputs.hpp"

#include "probe_sampling.hpp"
#include "run_requests.hpp"
#include "spacing_census.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <vector>

namespace sluice {

template <int D>
RunOutputs<D>::RunOutputs(const CaseConfig& cfg, const std::string& out_dir,
                          const OutputState* resumed, double t, bool root, RunLog& log)
    : cfg_(cfg), out_dir_(out_dir), checkpoint_file_(checkpoint_path(out_dir)), root_(root),
      log_(log), schedule_(cfg) {
    namespace fs = std::filesystem;
    if (root) {
        fs::create_directories(out_dir);
        fs::remove(fs::path(out_dir) / "summary.json"); // an old summary would look complete
        fs::remove(stop_file_path(out_dir));            // it stopped an earlier run
        if (resumed == nullptr)
            fs::remove(checkpoint_file_); // an earlier run's: its snapshots are going
        discard_partial_checkpoint(checkpoint_file_);
    }
    // Every rank writes its slice of each snapshot (rank 0 alone touches the folder).
    if (cfg.snapshots) {
        if (resumed != nullptr) {
            std::vector<typename SnapshotWriter<D>::Earlier> earlier;
            for (std::size_t k = 0; k < resumed->snapshot_time.size(); ++k)
                earlier.push_back({resumed->snapshot_time[k], resumed->snapshot_particles[k]});
            snapshots_ = std::make_unique<SnapshotWriter<D>>(out_dir, cfg.fields, earlier);
        } else {
            snapshots_ = std::make_unique<SnapshotWriter<D>>(out_dir, cfg.fields);
        }
    }
    if (root)
        probe_files_ = resumed != nullptr ? std::make_unique<ProbeWriter>(out_dir, cfg.probes,
                                                                          resumed->probe_bytes)
                                          : std::make_unique<ProbeWriter>(out_dir, cfg.probes, D);
    if (resumed != nullptr)
        schedule_.resume(*resumed, t);
}

// Every rank takes the same decisions (same time). The probes are evaluated where the
// particles are (probe_sampling.hpp); each rank writes its own particles into a snapshot.
template <int D>
void RunOutputs<D>::sample(const Simulation<D>& sim, bool force) {
    const double t = sim.time();
    const OutputSchedule::Due due = schedule_.due(t, force);
    if (!due.probes.empty()) {
        const auto rows = sample_probes(sim, due.probes);
        if (root_)
            for (std::size_t n = 0; n < due.probes.size(); ++n)
                probe_files_->write(due.probes[n], t, rows[n]);
    }
    if (due.snapshot) {
        const std::string file = write_snapshot(sim);
        if (root_)
            log_.debug("snapshot {} at t = {:.6g} s (step {})", file, t, sim.steps());
    }
    schedule_.done(due, t);
}

template <int D>
bool RunOutputs<D>::quiet_at(double t) const {
    const OutputSchedule::Due due = schedule_.due(t, false);
    return due.probes.empty() && !due.output;
}

template <int D>
void RunOutputs<D>::finish(const Simulation<D>& sim) {
    if (sim.time() != schedule_.last_output_time())
        sample(sim, true);
}

template <int D>
std::string RunOutputs<D>::last_snapshot(const Simulation<D>& sim, const std::string& label) {
    if (!snapshots_) // snapshots are off: this one is written all the same
        snapshots_ = std::make_unique<SnapshotWriter<D>>(out_dir_, cfg_.fields);
    const std::string file = write_snapshot(sim);
    return root_ ? fmt::format(", {} in {}", label, file) : std::string();
}

// Every snapshot records the fluid's spacing (its attributes; the field when asked for): a
// census over the neighbours at each output, outside the step, that shows when and where a
// WCSPH fluid starts to crowd (docs/IMPACT_LOADS.md, "Particle spacing").
template <int D>
std::string RunOutputs<D>::write_snapshot(const Simulation<D>& sim) {
    const Real support = sim.kernel_support();
    const Real crowded = crowded_below(cfg_.dx);
    const bool field = snapshots_->writes_spacing();
    const SpacingCensus census = spacing_census<D>(sim, support, crowded, field);
    std::vector<Real> over_dx(census.nearest.size());
    for (std::size_t i = 0; i < over_dx.size(); ++i) {
        const Real r = census.nearest[i];
        over_dx[i] = std::isfinite(r) ? r / Real(cfg_.dx) : std::numeric_limits<Real>::quiet_NaN();
    }
    const SnapshotSpacing spacing{census.census, crowded, over_dx};
    last_spacing_ = census.census;
    spacing_step_ = sim.steps();
    return snapshots_->write(sim.particles(), sim.owned(), sim.time(), sim.steps(), &spacing);
}

// Collective: every rank writes its particles; the rest is rank 0's.
template <int D>
void RunOutputs<D>::write_checkpoint(const Simulation<D>& sim, double wall_seconds) {
    CheckpointHeader c;
    if (root_) {
        c.case_fingerprint = cfg_.fingerprint;
        c.ranks = sim.comm().size();
        c.solver = sim.solver_state();
        c.output.out_next = schedule_.out_next();
        c.output.last_output_time = schedule_.last_output_time();
        c.output.wall_seconds = wall_seconds;
        c.output.probe_next = schedule_.probe_next();
        c.output.probe_bytes = probe_files_->bytes();
        if (snapshots_)
            for (const auto& w : snapshots_->written()) {
                c.output.snapshot_time.push_back(w.time);
                c.output.snapshot_particles.push_back(w.particles);
            }
    }
    ::sluice::write_checkpoint<D>(checkpoint_file_, c, sim.particles(), sim.owned());
}

template class RunOutputs<2>;
template class RunOutputs<3>;

} // namespace sluice
