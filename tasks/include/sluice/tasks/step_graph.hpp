#pragma once
// One step as a dependency graph: a node per (stage, cell group). A stage that reads its
// neighbours' results of the previous stage ("neighbourhood" reach) waits for the previous
// stage of the group and of every adjacent group; a "self" stage waits for its own group only.
// There is no barrier between stages beyond these edges. The graph is built once per
// decomposition and replayed every step (tbb::flow continue_nodes re-arm after each run).
//
// On more than one rank, halo exchanges are nodes of the same graph. For exchange e (the
// results of stage s_e, or the state at the start of the step when s_e = -1) and peer rank p:
//   send(e,p)   waits for (s_e, g) of every boundary group g facing p, packs, and posts
//               MPI_Isend itself (with MPI_THREAD_MULTIPLE; otherwise it hands the buffer to
//               the main thread, which posts it at its next poll, up to 1 ms later);
//   recv(e,p)   is released by the main thread when MPI_Testsome reports the message (the
//               MPI_Irecv was posted before any task of the step ran) and, so that it never
//               overwrites halo data a local task still reads, by (s_e, g) of those groups;
//               it unpacks, and (s_e + 1, g) waits for it;
//   (s_e + 1, g) also waits for send(e,p): it may overwrite particles of g that the pack reads
//               (ThreadSanitizer found the walls stage writing a wall particle's pressure
//               while the pressure exchange packed it).
// Interior groups depend on no message and run while messages are in flight. Everything else
// in MPI (receives, completion tests) is the main thread's; no TBB worker ever waits in MPI.
#include "sluice/tasks/comm.hpp"
#include "sluice/tasks/decomposition.hpp"

#include <tbb/task_arena.h>

#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace sluice::tasks {

enum class Reach { self, neighbourhood };

struct StageSpec {
    std::string name;
    Reach reach = Reach::neighbourhood; // what the stage needs of the previous stage
    // Its nodes also wait for the main thread's gate (at most one gated stage per graph):
    // what runs before it may start while the main thread still waits for something else
    // (StepGraph::run's `gate`).
    bool gated = false;
};

struct ExchangeSpec {
    std::string name;
    int after_stage = -1; // whose results it carries; -1: the state at the start of the step
};

// What the solver supplies for halo exchanges: message sizes, packing and unpacking. pack and
// unpack run as tasks of the graph; recv_bytes is called by the main thread before the step.
class HaloData {
public:
    virtual ~HaloData() = default;
    [[nodiscard]] virtual std::size_t recv_bytes(int exchange, int peer) const = 0;
    virtual void pack(int exchange, int peer, Bytes& out) = 0;
    virtual void unpack(int exchange, int peer, std::span<const std::byte> in) = 0;
};

struct HaloWiring {
    std::vector<int> peers;                 // peer ranks, sorted
    std::vector<std::vector<int>> boundary; // per peer: local groups that face it
    std::vector<ExchangeSpec> exchanges;
    HaloData* data = nullptr;
    [[nodiscard]] bool active() const { return !peers.empty() && !exchanges.empty(); }
};

// Seconds on a clock shared by every rank of a node (steady clock, origin set once).
double clock_seconds();
void reset_clock_origin();
// Every rank takes rank 0's origin (collective): on one node, where the steady clock is the
// same for every process, the ranks' times are then directly comparable, so a message's
// completion on its receiver is never before its post on the sender. Across nodes each
// node's steady clock has its own origin and the times stay comparable only to the skew.
void share_clock_origin(const Comm& comm);
// CPU seconds the calling thread has used (CLOCK_THREAD_CPUTIME_ID): a task's work, which its
// wall interval overstates when more ranks and threads run than there are cores.
double thread_cpu_seconds();

// One task of the last run. stage >= 0: compute node of (stage, group); stage = -1: pack of
// exchange `exchange` for peer `group`; stage = -2: unpack of it.
struct TaskRecord {
    int stage = 0, group = 0, exchange = -1, thread = 0;
    double start = 0, end = 0;
    double cpu = 0; // thread CPU seconds the task used (thread_cpu_seconds)
};

// One message of the last run (post to detected completion).
struct MessageRecord {
    std::string name;
    int peer = 0;
    bool send = false;
    std::size_t bytes = 0;
    double post = 0, done = 0;
    // A halo message of a step graph: its (exchange, peer index) slot k = exchange * peers +
    // peer index, so its pack task is record n + k and its unpack n + m + k (task_records).
    // -1 for messages outside the graphs.
    int slot = -1;
};

class StepGraph {
public:
    // body(stage, group) does the work of one node. It must touch only the group's own
    // particles for writing.
    using Body = std::function<void(int stage, int group)>;

    // `arena` (optional) is where the tasks run; with halo exchanges it must leave the main
    // thread free to drive MPI.
    StepGraph(std::vector<StageSpec> stages, const std::vector<std::vector<int>>& neighbours,
              Body body, HaloWiring halo = {}, tbb::task_arena* arena = nullptr);
    ~StepGraph();
    StepGraph(const StepGraph&) = delete;
    StepGraph& operator=(const StepGraph&) = delete;

    // What the main thread's gate poll answers: keep the gated stage waiting, open it, or open
    // it with every body from the gated stage on skipped (their nodes still complete, and
    // their exchanges still send and receive a message, an empty one, so that the peers
    // finish the run as usual; the receives of those exchanges are not unpacked).
    enum class Gate { wait, open, skip };
    using GatePoll = std::function<Gate()>;

    // Runs every node once, in dependency order, and returns when all have finished and every
    // message of the step is complete. An exception thrown by a node body is rethrown here,
    // after the step's messages have all completed (so no peer is left waiting).
    // With a gated stage, `gate` is called by the main thread (between its polls of the
    // messages) until it answers open or skip; without `gate` the gate opens at once.
    void run(const GatePoll& gate = {});
    // The gated stage, or -1.
    [[nodiscard]] int gate_stage() const { return gate_stage_; }
    // Whether its pack tasks post their own messages (Comm::workers_may_post when it was built).
    [[nodiscard]] bool workers_post() const;

    [[nodiscard]] int stage_count() const { return static_cast<int>(stages_.size()); }
    [[nodiscard]] int group_count() const { return groups_; }
    [[nodiscard]] const std::vector<StageSpec>& stages() const { return stages_; }
    [[nodiscard]] const std::vector<std::vector<int>>& neighbours() const { return neighbours_; }
    [[nodiscard]] const HaloWiring& halo() const { return halo_; }

    // Busy seconds of each (stage, group) node in the last run.
    [[nodiscard]] double node_seconds(int stage, int group) const {
        const auto& r = records_[static_cast<std::size_t>(stage * groups_ + group)];
        return r.end - r.start;
    }
    // Every task (compute, pack, unpack) and message of the last run, and its time span.
    [[nodiscard]] const std::vector<TaskRecord>& task_records() const { return records_; }
    [[nodiscard]] const std::vector<MessageRecord>& message_records() const { return messages_; }
    // The graph's edges, by record slot (as task_records): the slots each task waits for
    // (the start of the run and a receive's arrival are not tasks and are not listed). Built
    // with the graph, so reading them costs a step nothing.
    [[nodiscard]] const std::vector<std::vector<int>>& task_predecessors() const {
        return predecessors_;
    }
    // MPI tag of exchange e's halo messages.
    [[nodiscard]] static int exchange_tag(int exchange);
    [[nodiscard]] double run_begin() const { return run_begin_; }
    [[nodiscard]] double run_end() const { return run_end_; }

    // Test hook: the main thread reports a completed receive only `seconds` after MPI does,
    // as if the network were that slow.
    void inject_receive_delay(double seconds) { receive_delay_ = seconds; }

private:
    void run_local();
    void run_with_messages(const GatePoll& gate);
    void open_gate(bool skip);
    [[nodiscard]] bool skipped(int stage) const;
    void record(std::size_t slot, int stage, int group, int exchange, double t0, double cpu0);
    void guard(const std::function<void()>& f);

    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<StageSpec> stages_;
    std::vector<std::vector<int>> neighbours_;
    int groups_ = 0;
    Body body_;
    HaloWiring halo_;
    std::vector<TaskRecord> records_; // compute nodes, then per (exchange, peer) pack, unpack
    std::vector<std::vector<int>> predecessors_; // by slot, as records_
    std::vector<MessageRecord> messages_;
    std::vector<Bytes> send_buf_, recv_buf_; // per (exchange, peer)
    double run_begin_ = 0, run_end_ = 0;
    double receive_delay_ = 0;
    int gate_stage_ = -1;
    std::mutex error_mutex_;
    std::exception_ptr error_;
};

} // namespace sluice::tasks
