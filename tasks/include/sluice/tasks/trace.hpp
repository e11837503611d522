#pragma once
// Chrome/Perfetto trace of a run (chrome://tracing, ui.perfetto.dev): every task as a slice on
// its rank's worker-thread track, every message as a slice on the rank's "MPI" track (the
// main thread, which drives all communication). Each rank records its own events; the root
// gathers them into one file.
//
// Edges (perf/strong_scaling/critical_path.py reads them): a task's args hold its `id`
// (unique within its rank) and `preds`, the ids of the tasks it waited for (the graph's
// edges). A halo message's args hold `src`, `dst`, `tag`, `kind` (the exchange) and
// `producer` (sender: its pack task) or `consumer` (receiver: its unpack task), and `flow`,
// the same on both ranks; a flow event pair (ph "s" at the pack, "f" at the unpack) draws
// the arrow. Every reader of complete slices (ph "X") is unaffected by the flow events.
#include "sluice/tasks/comm.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace sluice::tasks {

class TraceRecorder {
public:
    // At most `max_events` events are kept (a warning is added past that).
    TraceRecorder(int rank, std::vector<std::string> stage_names, std::size_t max_events);

    void add_step(long step, const StepGraph& g, const std::vector<MessageRecord>& between);
    void add_event(const std::string& name, double begin, double end); // e.g. a rebalance
    // The main thread's own work between two graphs, counted in the window of `step`.
    void add_work(long step, const std::string& name, double begin, double end);

    // Gathers every rank's events to rank 0, which writes `path`. Collective.
    void write(const Comm& comm, const std::string& path) const;

    [[nodiscard]] std::size_t events() const { return events_; }
    [[nodiscard]] bool truncated() const { return truncated_; }

private:
    bool open_event();
    void slice(const std::string& name, int tid, double begin, double end, const std::string& args);
    void flow_event(const std::string& name, bool start, long id, int tid, double at);
    int rank_;
    long next_id_ = 0; // the next run's first task id
    std::vector<std::string> stages_;
    std::size_t max_events_, events_ = 0;
    bool truncated_ = false;
    std::string json_; // comma-separated events
};

} // namespace sluice::tasks
