#pragma once
// What a rank spent its time on, step after step: busy time per stage, communication time,
// and how much of the communication was hidden behind computation.
//
// Definitions (docs/ARCHITECTURE.md, "Overlap"): a message is in flight from the moment it is
// posted until the main thread sees it complete. The rank's communication time C is the
// length of the union of its in-flight intervals (sends and receives, in-step halo exchanges
// and the between-step migration and reductions). The exposed time X is the part of C during
// which none of the rank's tasks was running: the rank was idle, waiting for messages.
// Hidden time is C - X, and the overlap efficiency is (C - X) / C.
#include "sluice/tasks/step_graph.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sluice::tasks {

struct Interval {
    double begin, end;
};

// Length of the union of the intervals (sorted in place).
double union_length(std::vector<Interval>& v);
// Length of the part of the union of `a` not covered by the union of `b`.
double uncovered_length(std::vector<Interval> a, std::vector<Interval> b);

struct RankProfile {
    std::vector<double> stage_busy; // seconds per stage, summed over groups and steps
    double halo_pack_busy = 0;      // packing and unpacking halo buffers
    double task_cpu = 0;            // thread CPU seconds of every task: the work done
    std::vector<double> stage_cpu;  // ... of the compute tasks, per stage
    double halo_pack_cpu = 0;       // ... of the packing and unpacking tasks
    double graph_wall = 0;          // wall time inside step graphs
    double between_wall = 0;        // wall time between graphs (rebin, migration, balance)
    double comm = 0;                // communication time C
    double exposed = 0;             // exposed communication time X
    long steps = 0;

    [[nodiscard]] double busy() const;
    [[nodiscard]] double hidden() const { return comm - exposed; }
    [[nodiscard]] double overlap_efficiency() const { return comm > 0 ? hidden() / comm : 1.0; }

    // Adds one step: the graph's tasks and messages, and messages that ran between graphs
    // (during which no task runs, so they are exposed).
    void add_step(const StepGraph& g, const std::vector<MessageRecord>& between);
};

} // namespace sluice::tasks
