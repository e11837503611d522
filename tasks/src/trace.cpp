#include "sluice/tasks/trace.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace sluice::tasks {

namespace {
constexpr int kMpiTrack = 10000; // thread id of the main (MPI) thread's track
}

TraceRecorder::TraceRecorder(int rank, std::vector<std::string> stage_names, std::size_t max_events)
    : rank_(rank), stages_(std::move(stage_names)), max_events_(max_events) {}

// Room for one more event (else the trace is marked truncated), and its separator written.
bool TraceRecorder::open_event() {
    if (events_ >= max_events_) {
        truncated_ = true;
        return false;
    }
    if (!json_.empty())
        json_ += ",\n";
    ++events_;
    return true;
}

void TraceRecorder::slice(const std::string& name, int tid, double begin, double end,
                          const std::string& args) {
    if (!open_event())
        return;
    // Timestamps in microseconds.
    fmt::format_to(
        std::back_inserter(json_),
        R"({{"name":"{}","ph":"X","pid":{},"tid":{},"ts":{:.3f},"dur":{:.3f},"args":{{{}}}}})",
        name, rank_, tid, begin * 1e6, std::max(0.0, end - begin) * 1e6, args);
}

void TraceRecorder::add_step(long step, const StepGraph& g,
                             const std::vector<MessageRecord>& between) {
    // Task ids are unique within the rank's trace: this run's record slot plus a base that
    // grows by the record count with every run.
    const auto& records = g.task_records();
    const auto& preds = g.task_predecessors();
    const long base = next_id_;
    next_id_ += static_cast<long>(records.size());
    const std::size_t n = static_cast<std::size_t>(g.stage_count() * g.group_count());
    const std::size_t m = (records.size() - n) / 2;
    auto thread_of = [](const TaskRecord& r) { return r.thread < 0 ? kMpiTrack + 1 : r.thread; };
    std::string waited; // one buffer for every task's list
    for (std::size_t slot = 0; slot < records.size(); ++slot) {
        const TaskRecord& r = records[slot];
        if (r.end <= 0)
            continue;
        // The tasks it waited for (graph edges), as ids of this run.
        waited.clear();
        for (int q : preds[slot]) {
            if (records[static_cast<std::size_t>(q)].end <= 0)
                continue;
            if (!waited.empty())
                waited += ',';
            fmt::format_to(std::back_inserter(waited), "{}", base + q);
        }
        if (r.stage >= 0) {
            const std::string& stage = r.stage < static_cast<int>(stages_.size())
                                           ? stages_[static_cast<std::size_t>(r.stage)]
                                           : std::string("stage");
            slice(stage, thread_of(r), r.start, r.end,
                  fmt::format(R"("group":{},"step":{},"cpu_us":{:.3f},"id":{},"preds":[{}])",
                              r.group, step, r.cpu * 1e6, base + static_cast<long>(slot), waited));
        } else {
            const std::string& ex = g.halo().exchanges[static_cast<std::size_t>(r.exchange)].name;
            slice(fmt::format("{} {}", r.stage == -1 ? "pack" : "unpack", ex), thread_of(r),
                  r.start, r.end,
                  fmt::format(R"("peer":{},"step":{},"cpu_us":{:.3f},"id":{},"preds":[{}])",
                              g.halo().peers[static_cast<std::size_t>(r.group)], step, r.cpu * 1e6,
                              base + static_cast<long>(slot), waited));
        }
    }
    auto message = [&](const MessageRecord& m_rec, std::string links) {
        const int src = m_rec.send ? rank_ : m_rec.peer;
        const int dst = m_rec.send ? m_rec.peer : rank_;
        slice(fmt::format("{} {} {}", m_rec.send ? "send" : "recv", m_rec.name,
                          m_rec.send ? "to" : "from"),
              kMpiTrack, m_rec.post, m_rec.done,
              fmt::format(R"("peer":{},"bytes":{},"step":{},"src":{},"dst":{},"kind":"{}"{})",
                          m_rec.peer, m_rec.bytes, step, src, dst, m_rec.name, links));
    };
    const int P = static_cast<int>(g.halo().peers.size());
    for (const MessageRecord& m_rec : g.message_records()) {
        if (m_rec.slot < 0 || P == 0) {
            message(m_rec, "");
            continue;
        }
        const int e = m_rec.slot / P;
        // The pack task that produced it (sender) or the unpack task that consumed it
        // (receiver), and a flow event from the one to the other: its id is the same on both
        // ranks (step, exchange, sender, receiver).
        const std::size_t task = static_cast<std::size_t>(m_rec.slot) + (m_rec.send ? n : n + m);
        const int src = m_rec.send ? rank_ : m_rec.peer;
        const int dst = m_rec.send ? m_rec.peer : rank_;
        const long flow = ((step * 64 + e) * 1024 + src) * 1024 + dst;
        message(m_rec, fmt::format(R"(,"tag":{},"{}":{},"flow":{})", StepGraph::exchange_tag(e),
                                   m_rec.send ? "producer" : "consumer",
                                   base + static_cast<long>(task), flow));
        const TaskRecord& r = records[task];
        if (r.end > 0 && e < 64 && src < 1024 && dst < 1024)
            flow_event(m_rec.name, m_rec.send, flow, thread_of(r), r.start);
    }
    for (const MessageRecord& m_rec : between)
        message(m_rec, "");
}

void TraceRecorder::flow_event(const std::string& name, bool start, long id, int tid, double at) {
    if (!open_event())
        return;
    // "s" binds to the slice enclosing `at` on its thread (the pack), "f" with "bp":"e" to the
    // one enclosing it at the other end (the unpack).
    fmt::format_to(
        std::back_inserter(json_),
        R"({{"name":"{}","cat":"halo","ph":"{}","id":{},"pid":{},"tid":{},"ts":{:.3f}{}}})", name,
        start ? "s" : "f", id, rank_, tid, at * 1e6, start ? "" : R"(,"bp":"e")");
}

void TraceRecorder::add_event(const std::string& name, double begin, double end) {
    slice(name, kMpiTrack, begin, end, "");
}

void TraceRecorder::add_work(long step, const std::string& name, double begin, double end) {
    slice(name, kMpiTrack, begin, end, fmt::format(R"("step":{})", step));
}

void TraceRecorder::write(const Comm& comm, const std::string& path) const {
    std::string mine = json_;
    // Track names: "rank r" processes, "worker k" and "MPI, main thread" threads.
    std::string meta = fmt::format(
        R"({{"name":"process_name","ph":"M","pid":{0},"args":{{"name":"rank {0}"}}}},)"
        R"({{"name":"thread_name","ph":"M","pid":{0},"tid":{1},"args":{{"name":"MPI, main thread"}}}})",
        rank_, kMpiTrack);
    mine = mine.empty() ? meta : meta + ",\n" + mine;
    const auto all = comm.gather(
        std::span<const std::byte>(reinterpret_cast<const std::byte*>(mine.data()), mine.size()));
    if (comm.rank() != 0)
        return;
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out)
            throw std::runtime_error("cannot write trace file " + path);
        out << "{\"displayTimeUnit\":\"ms\",\"traceEvents\":[\n";
        bool first = true;
        for (const Bytes& b : all) {
            if (b.empty())
                continue;
            if (!first)
                out << ",\n";
            out.write(reinterpret_cast<const char*>(b.data()),
                      static_cast<std::streamsize>(b.size()));
            first = false;
        }
        out << "\n]}\n";
    }
    std::filesystem::rename(tmp, path);
}

} // namespace sluice::tasks
