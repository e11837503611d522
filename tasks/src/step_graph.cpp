#include "sluice/tasks/step_graph.hpp"

#include "tsan_sync.hpp"

#include <mpi.h>
#include <tbb/concurrent_queue.h>
#include <tbb/flow_graph.h>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <stdexcept>
#include <thread>

namespace sluice::tasks {

using tbb::flow::continue_msg;
using Node = tbb::flow::continue_node<continue_msg>;

namespace {
std::chrono::steady_clock::time_point& clock_origin() {
    static std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    return t0;
}
constexpr int kTagBase = 1000; // tags kTagBase + exchange index
// ThreadSanitizer's start-of-run token (tsan_sync.hpp): released by the main thread before a
// run, acquired by every task before it reads anything, even its own captures (which the main
// thread wrote when it built the graph). The edges from the start node order every task after
// the start of the run anyway; TSan needs to know it before a task has read its slot.
char run_start_token;
// The gate's token: released by the main thread when it opens the gate, acquired by the gated
// stage's nodes (their extra predecessor is the main thread's put).
char gate_token;

// Posts a halo message (from the main thread or from the pack task); returns the post time.
double post(const Bytes& buffer, int peer, int exchange, MPI_Request* request) {
    MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), MPI_BYTE, peer, kTagBase + exchange,
              MPI_COMM_WORLD, request);
    return clock_seconds();
}
} // namespace

int StepGraph::exchange_tag(int exchange) {
    return kTagBase + exchange;
}

double clock_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_origin()).count();
}

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
void reset_clock_origin() {
    clock_origin() = std::chrono::steady_clock::now();
}

void share_clock_origin(const Comm& comm) {
    reset_clock_origin();
    const auto ticks = comm.broadcast(std::to_string(clock_origin().time_since_epoch().count()), 0);
    clock_origin() = std::chrono::steady_clock::time_point(
        std::chrono::steady_clock::duration(std::stoll(ticks)));
}

struct StepGraph::Impl {
    tbb::task_arena* arena = nullptr;
    std::unique_ptr<tbb::flow::graph> graph;
    std::unique_ptr<tbb::flow::broadcast_node<continue_msg>> start;
    std::vector<std::unique_ptr<Node>> nodes; // stage * groups + group
    std::vector<std::unique_ptr<Node>> sends; // exchange * peers + peer
    std::vector<std::unique_ptr<Node>> recvs; // exchange * peers + peer
    tbb::concurrent_queue<int> ready;         // packed sends, by (exchange * peers + peer)
    // With workers_post, the pack task posts its message itself: its request and post time,
    // by slot, written before the slot is pushed to `ready` and read by the main thread after
    // it pops it (the queue orders the two).
    bool workers_post = false;
    std::vector<MPI_Request> worker_request;
    std::vector<double> worker_post_time;
    // Both counters are relaxed: what orders the tasks is the graph's edges and, for the main
    // thread, wait_for_all(). A stronger order here would also hide a missing edge from
    // ThreadSanitizer (tasks that happen to run one after the other would look ordered).
    std::atomic<int> running{0};          // tasks executing right now (sets the poll rate)
    std::atomic<std::size_t> finished{0}; // nodes of this run that have completed
    // Set by the main thread before it opens the gate; read by the nodes after it (the gate's
    // edges order them), relaxed like the counters.
    std::atomic<bool> skip{false};
    std::size_t total = 0; // nodes in the graph

    // ThreadSanitizer's view of the edges (tsan_sync.hpp), by task slot (as records_): a
    // task's own token is &waits_for[slot], and waits_for[slot] lists its predecessors'.
    std::vector<std::vector<const void*>> waits_for;
    [[nodiscard]] const void* token(std::size_t slot) const { return &waits_for[slot]; }
    void begin_task(std::size_t slot) const {
        for (const void* t : waits_for[slot])
            tsan::acquire(t);
    }
    void end_task(std::size_t slot) const { tsan::release(token(slot)); }
    // The main thread, after wait_for_all(): every task of the run happened before. So did
    // what oneTBB's header code did after a body (forwarding to successors, recycling the
    // task), up to the task's decrement of the graph's reference count, which wait_for_all()
    // waits on inside libtbb.so; an increment and decrement of it here let TSan see that too.
    void join_tasks() const {
        for (std::size_t slot = 0; slot < waits_for.size(); ++slot)
            tsan::acquire(token(slot));
        if constexpr (tsan::active) {
            graph->reserve_wait();
            graph->release_wait();
        }
    }

    void node_done() {
        if (finished.fetch_add(1, std::memory_order_relaxed) + 1 == total)
            finished.notify_one();
    }
};

void StepGraph::guard(const std::function<void()>& f) {
    // A failing body must not cancel the graph: its sends would never leave and the peers
    // would wait forever. The error is kept and rethrown once the step's messages are done.
    impl_->running.fetch_add(1, std::memory_order_relaxed);
    try {
        f();
    } catch (...) {
        std::lock_guard lock(error_mutex_);
        if (!error_)
            error_ = std::current_exception();
    }
    impl_->running.fetch_sub(1, std::memory_order_relaxed);
    impl_->node_done();
}

bool StepGraph::skipped(int stage) const {
    return gate_stage_ >= 0 && stage >= gate_stage_ && impl_->skip.load(std::memory_order_relaxed);
}

void StepGraph::open_gate(bool skip) {
    impl_->skip.store(skip, std::memory_order_relaxed);
    tsan::release(&gate_token);
    for (int grp = 0; grp < groups_; ++grp)
        impl_->nodes[static_cast<std::size_t>(gate_stage_ * groups_ + grp)]->try_put(
            continue_msg());
}

void StepGraph::record(std::size_t slot, int stage, int group, int exchange, double t0,
                       double cpu0) {
    TaskRecord& r = records_[slot];
    r.stage = stage;
    r.group = group;
    r.exchange = exchange;
    r.thread = tbb::this_task_arena::current_thread_index();
    r.start = t0;
    r.end = clock_seconds();
    r.cpu = thread_cpu_seconds() - cpu0;
}

StepGraph::StepGraph(std::vector<StageSpec> stages, const std::vector<std::vector<int>>& neighbours,
                     Body body, HaloWiring halo, tbb::task_arena* arena)
    : impl_(std::make_unique<Impl>()), stages_(std::move(stages)), neighbours_(neighbours),
      groups_(static_cast<int>(neighbours.size())), body_(std::move(body)), halo_(std::move(halo)) {
    impl_->arena = arena;
    const int P = static_cast<int>(halo_.peers.size());
    const int E = halo_.active() ? static_cast<int>(halo_.exchanges.size()) : 0;
    const std::size_t n = stages_.size() * static_cast<std::size_t>(groups_);
    const std::size_t m = static_cast<std::size_t>(E * P);
    for (int s = 0; s < stage_count(); ++s)
        if (stages_[static_cast<std::size_t>(s)].gated) {
            if (gate_stage_ >= 0)
                throw std::logic_error("a step graph has at most one gated stage");
            gate_stage_ = s;
        }
    records_.assign(n + 2 * m, {});
    impl_->workers_post = E > 0 && Comm::workers_may_post();
    impl_->worker_request.assign(m, MPI_REQUEST_NULL);
    impl_->worker_post_time.assign(m, 0.0);
    send_buf_.assign(m, {});
    recv_buf_.assign(m, {});
    impl_->waits_for.assign(n + 2 * m, {});
    predecessors_.assign(n + 2 * m, {});

    // Boundary work is the critical path between ranks: a peer waits for what these tasks
    // produce. Their tasks (and packing, unpacking) go before interior ones whenever both are
    // ready, so interior work fills the time messages are in flight.
    std::vector<bool> facing_any(static_cast<std::size_t>(groups_), false);
    if (E > 0)
        for (const auto& b : halo_.boundary)
            for (int grp : b)
                facing_any[static_cast<std::size_t>(grp)] = true;
    const tbb::flow::node_priority_t urgent = 2, boundary = 1, interior = tbb::flow::no_priority;

    auto build = [&] {
        auto& g = impl_->graph;
        g = std::make_unique<tbb::flow::graph>();
        impl_->start = std::make_unique<tbb::flow::broadcast_node<continue_msg>>(*g);
        impl_->nodes.reserve(n);
        for (int s = 0; s < stage_count(); ++s)
            for (int grp = 0; grp < groups_; ++grp) {
                const std::size_t slot = static_cast<std::size_t>(s * groups_ + grp);
                // A gated node has one predecessor more than its edges: the main thread's put.
                const bool gated = s == gate_stage_;
                if (gated)
                    impl_->waits_for[slot].push_back(&gate_token);
                impl_->nodes.push_back(std::make_unique<Node>(
                    *g, gated ? 1 : 0,
                    [this, s, grp, slot](const continue_msg&) {
                        tsan::acquire(&run_start_token);
                        impl_->begin_task(slot);
                        const double t0 = clock_seconds();
                        const double cpu0 = thread_cpu_seconds();
                        guard([&] {
                            if (!skipped(s))
                                body_(s, grp);
                        });
                        record(slot, s, grp, -1, t0, cpu0);
                        impl_->end_task(slot);
                    },
                    facing_any[static_cast<std::size_t>(grp)] ? boundary : interior));
            }
        auto slot_of = [&](int s, int grp) { return static_cast<std::size_t>(s * groups_ + grp); };
        auto node = [&](int s, int grp) -> Node& { return *impl_->nodes[slot_of(s, grp)]; };
        // Every edge goes through here, so that ThreadSanitizer and the trace learn the same
        // edges. from_slot: the predecessor's record slot, -1 for the start of the run.
        auto edge = [&](auto& from, const void* from_token, int from_slot, Node& to,
                        std::size_t to_slot) {
            tbb::flow::make_edge(from, to);
            impl_->waits_for[to_slot].push_back(from_token);
            if (from_slot >= 0)
                predecessors_[to_slot].push_back(from_slot);
        };
        const void* start_token = &run_start_token;
        for (int grp = 0; grp < groups_; ++grp)
            edge(*impl_->start, start_token, -1, node(0, grp), slot_of(0, grp));
        auto after_node = [&](int s, int grp, Node& to, std::size_t to_slot) {
            edge(node(s, grp), impl_->token(slot_of(s, grp)), static_cast<int>(slot_of(s, grp)), to,
                 to_slot);
        };
        for (int s = 1; s < stage_count(); ++s)
            for (int grp = 0; grp < groups_; ++grp) {
                after_node(s - 1, grp, node(s, grp), slot_of(s, grp));
                if (stages_[static_cast<std::size_t>(s)].reach == Reach::neighbourhood)
                    for (int nb : neighbours_[static_cast<std::size_t>(grp)])
                        after_node(s - 1, nb, node(s, grp), slot_of(s, grp));
            }
        for (int e = 0; e < E; ++e)
            for (int p = 0; p < P; ++p) {
                const auto k = static_cast<std::size_t>(e * P + p);
                const int after = halo_.exchanges[static_cast<std::size_t>(e)].after_stage;
                const auto& facing = halo_.boundary[static_cast<std::size_t>(p)];
                impl_->sends.push_back(std::make_unique<Node>(
                    *g,
                    [this, e, p, k, n, after](const continue_msg&) {
                        tsan::acquire(&run_start_token);
                        impl_->begin_task(n + k);
                        if (after < 0) {
                            impl_->node_done(); // packed and sent by the main thread
                            impl_->end_task(n + k);
                            return;
                        }
                        const double t0 = clock_seconds();
                        const double cpu0 = thread_cpu_seconds();
                        guard([&] {
                            send_buf_[k].clear(); // skipped: an empty message
                            if (!skipped(after))
                                halo_.data->pack(e, p, send_buf_[k]);
                        });
                        record(n + k, -1, p, e, t0, cpu0);
                        // Posted here, not at the main thread's next poll (up to 1 ms later
                        // while tasks run): the peer may be waiting for it.
                        if (impl_->workers_post)
                            impl_->worker_post_time[k] =
                                post(send_buf_[k], halo_.peers[static_cast<std::size_t>(p)], e,
                                     &impl_->worker_request[k]);
                        tsan::release(&send_buf_[k]); // the main thread posts or records it
                        impl_->ready.push(static_cast<int>(k));
                        impl_->end_task(n + k);
                    },
                    urgent));
                // One predecessor more than the edges: the main thread's "message arrived".
                impl_->recvs.push_back(std::make_unique<Node>(
                    *g, 1,
                    [this, e, p, k, n, m, after](const continue_msg&) {
                        tsan::acquire(&run_start_token);
                        impl_->begin_task(n + m + k);
                        const double t0 = clock_seconds();
                        const double cpu0 = thread_cpu_seconds();
                        guard([&] {
                            if (after < 0 || !skipped(after))
                                halo_.data->unpack(e, p, recv_buf_[k]);
                        });
                        record(n + m + k, -2, p, e, t0, cpu0);
                        impl_->end_task(n + m + k);
                    },
                    urgent));
                Node& send = *impl_->sends.back();
                Node& recv = *impl_->recvs.back();
                // The main thread's "message arrived" (the receive buffer is filled) is the
                // release of &recv_buf_[k] just before it puts to the receive node.
                impl_->waits_for[n + m + k].push_back(&recv_buf_[k]);
                if (after < 0 || facing.empty()) {
                    edge(*impl_->start, start_token, -1, send, n + k);
                } else {
                    for (int grp : facing)
                        after_node(after, grp, send, n + k);
                }
                if (after >= 0)
                    for (int grp : facing)
                        after_node(after, grp, recv, n + m + k);
                // The facing groups' next stage waits for the message and, because it may
                // overwrite their particles that the pack reads, for the pack too.
                if (after + 1 < stage_count())
                    for (int grp : facing) {
                        edge(recv, impl_->token(n + m + k), static_cast<int>(n + m + k),
                             node(after + 1, grp), slot_of(after + 1, grp));
                        if (after >= 0)
                            edge(send, impl_->token(n + k), static_cast<int>(n + k),
                                 node(after + 1, grp), slot_of(after + 1, grp));
                    }
            }
    };
    if (arena != nullptr)
        arena->execute(build);
    else
        build();
    impl_->total = impl_->nodes.size() + impl_->sends.size() + impl_->recvs.size();
}

bool StepGraph::workers_post() const {
    return impl_->workers_post;
}

StepGraph::~StepGraph() {
    if (impl_->arena != nullptr) {
        // Nodes and graph are destroyed inside their arena.
        impl_->arena->execute([&] {
            impl_->recvs.clear();
            impl_->sends.clear();
            impl_->nodes.clear();
            impl_->start.reset();
            impl_->graph.reset();
        });
    }
}

void StepGraph::run(const GatePoll& gate) {
    run_begin_ = clock_seconds();
    impl_->finished = 0;
    impl_->skip.store(false, std::memory_order_relaxed);
    messages_.clear();
    if (halo_.active()) {
        run_with_messages(gate);
    } else {
        // No message to drive: the main thread waits for the gate first.
        bool skip = false;
        if (gate_stage_ >= 0 && gate) {
            Gate answer = gate();
            for (; answer == Gate::wait; answer = gate())
                std::this_thread::sleep_for(std::chrono::microseconds(20));
            skip = answer == Gate::skip;
        }
        if (gate_stage_ >= 0) {
            auto open = [&] { open_gate(skip); };
            if (impl_->arena != nullptr)
                impl_->arena->execute(open);
            else
                open();
        }
        run_local();
    }
    run_end_ = clock_seconds();
    if (error_) {
        std::exception_ptr e;
        std::swap(e, error_);
        std::rethrow_exception(e);
    }
}

void StepGraph::run_local() {
    auto go = [&] {
        tsan::release(&run_start_token);
        impl_->start->try_put(continue_msg());
        impl_->graph->wait_for_all();
        impl_->join_tasks();
    };
    if (impl_->arena != nullptr)
        impl_->arena->execute(go);
    else
        go();
}

void StepGraph::run_with_messages(const GatePoll& gate) {
    const int P = static_cast<int>(halo_.peers.size());
    const int E = static_cast<int>(halo_.exchanges.size());
    const std::size_t m = static_cast<std::size_t>(E * P);
    std::vector<MPI_Request> rreq(m, MPI_REQUEST_NULL), sreq(m, MPI_REQUEST_NULL);
    std::vector<std::size_t> rmsg(m), smsg(m);
    // Receives first, before any task can produce data.
    for (int e = 0; e < E; ++e)
        for (int p = 0; p < P; ++p) {
            const auto k = static_cast<std::size_t>(e * P + p);
            recv_buf_[k].resize(halo_.data->recv_bytes(e, p));
            MPI_Irecv(recv_buf_[k].data(), static_cast<int>(recv_buf_[k].size()), MPI_BYTE,
                      halo_.peers[static_cast<std::size_t>(p)], kTagBase + e, MPI_COMM_WORLD,
                      &rreq[k]);
            rmsg[k] = messages_.size();
            messages_.push_back({halo_.exchanges[static_cast<std::size_t>(e)].name,
                                 halo_.peers[static_cast<std::size_t>(p)], false,
                                 recv_buf_[k].size(), clock_seconds(), 0, static_cast<int>(k)});
        }
    std::size_t received = 0, sent = 0;
    // Posts the packed buffer of (exchange, peer) slot k, or takes over the request of the
    // pack task that posted it.
    auto post_send = [&](std::size_t k, bool by_worker) {
        const int e = static_cast<int>(k) / P;
        const auto p = k % static_cast<std::size_t>(P);
        double posted = 0;
        if (by_worker) {
            sreq[k] = impl_->worker_request[k];
            posted = impl_->worker_post_time[k];
        } else {
            posted = post(send_buf_[k], halo_.peers[p], e, &sreq[k]);
        }
        Comm::count_sent(send_buf_[k].size());
        smsg[k] = messages_.size();
        messages_.push_back({halo_.exchanges[static_cast<std::size_t>(e)].name, halo_.peers[p],
                             true, send_buf_[k].size(), posted, 0, static_cast<int>(k)});
        ++sent;
    };
    // The state at the start of the step is ready now: it leaves before any task runs, so
    // the peers' boundary groups can start as early as possible.
    for (int e = 0; e < E; ++e) {
        if (halo_.exchanges[static_cast<std::size_t>(e)].after_stage >= 0)
            continue;
        for (int p = 0; p < P; ++p) {
            const auto k = static_cast<std::size_t>(e * P + p);
            const double t0 = clock_seconds();
            const double cpu0 = thread_cpu_seconds();
            send_buf_[k].clear();
            halo_.data->pack(e, p, send_buf_[k]);
            record(static_cast<std::size_t>(stage_count() * groups_) + k, -1, p, e, t0, cpu0);
            post_send(k, false);
        }
    }
    tsan::release(&run_start_token);
    impl_->start->try_put(continue_msg()); // from outside the arena: the workers take it
    bool gate_open = gate_stage_ < 0;
    if (!gate_open && !gate) {
        open_gate(false);
        gate_open = true;
    }

    std::vector<int> idx(m);
    std::vector<double> arrived(m, -1);
    std::size_t delayed = 0; // arrived but not yet reported (injected delay)
    auto backoff = std::chrono::microseconds(50);
    while (received < m || sent < m || delayed > 0 || !gate_open) {
        bool progress = false;
        if (!gate_open) {
            const Gate answer = gate();
            if (answer != Gate::wait) {
                open_gate(answer == Gate::skip);
                gate_open = true;
                progress = true;
            }
        }
        int k = 0;
        while (impl_->ready.try_pop(k)) {
            tsan::acquire(&send_buf_[static_cast<std::size_t>(k)]);
            // Only pack tasks queue slots (the start-of-step state is posted above).
            post_send(static_cast<std::size_t>(k), impl_->workers_post);
            progress = true;
        }
        if (received < m) {
            int count = 0;
            MPI_Testsome(static_cast<int>(m), rreq.data(), &count, idx.data(), MPI_STATUSES_IGNORE);
            for (int c = 0; c < count && count != MPI_UNDEFINED; ++c) {
                arrived[static_cast<std::size_t>(idx[static_cast<std::size_t>(c)])] =
                    clock_seconds();
                ++received;
                ++delayed;
                progress = true;
            }
        }
        if (delayed > 0) {
            const double now = clock_seconds();
            for (std::size_t q = 0; q < m; ++q)
                if (arrived[q] >= 0 && now - arrived[q] >= receive_delay_) {
                    messages_[rmsg[q]].done = now;
                    arrived[q] = -1;
                    --delayed;
                    tsan::release(&recv_buf_[q]);
                    impl_->recvs[q]->try_put(continue_msg());
                }
        }
        if (sent > 0) {
            int count = 0;
            MPI_Testsome(static_cast<int>(m), sreq.data(), &count, idx.data(), MPI_STATUSES_IGNORE);
            for (int c = 0; c < count && count != MPI_UNDEFINED; ++c)
                messages_[smsg[static_cast<std::size_t>(idx[static_cast<std::size_t>(c)])]].done =
                    clock_seconds();
        }
        // How fast to poll: a message matters at once when no task is running (the rank is
        // waiting for it), so then the poll interval is short; while the workers compute,
        // polling often only takes their core, so it backs off to 1 ms. Never a busy spin: a
        // rank may share its cores with another rank's workers.
        if (progress) {
            backoff = std::chrono::microseconds(50);
        } else if (impl_->running.load(std::memory_order_relaxed) == 0) {
            std::this_thread::sleep_for(std::chrono::microseconds(10));
        } else {
            std::this_thread::sleep_for(backoff);
            backoff = std::min(2 * backoff, std::chrono::microseconds(1000));
        }
    }
    // Wait for the last tasks without joining the arena: the main thread taking tasks would
    // make T + 1 compute threads, more than the cores this rank was given.
    for (std::size_t c = impl_->finished.load(); c < impl_->total; c = impl_->finished.load())
        impl_->finished.wait(c);
    if (impl_->arena != nullptr)
        impl_->arena->execute([&] { impl_->graph->wait_for_all(); });
    else
        impl_->graph->wait_for_all();
    impl_->join_tasks();
    for (std::size_t q = 0; q < m; ++q)
        if (sreq[q] != MPI_REQUEST_NULL) {
            MPI_Wait(&sreq[q], MPI_STATUS_IGNORE);
            messages_[smsg[q]].done = clock_seconds();
        }
}

} // namespace sluice::tasks
