#include "sluice/tasks/trace.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sluice::tasks {

namespace {
constexpr int kMpiTrack = 10000; // thread id of the main (MPI) thread's track
}

TraceRecorder::TraceRecorder(int rank, std::vector<std::string> stage_names, std::size_t max_events)
    : rank_(rank), stages_(std::move(stage_names)), max_events_(max_events) {}

void TraceRecorder::slice(const std::string& name, int tid, double begin, double end,
                          const std::string& args) {
    if (events_ >= max_events_) {
        truncated_ = true;
        return;
    }
    if (!json_.empty())
        json_ += ",\n";
    // Timestamps in microseconds.
    json_ += fmt::format(
        R"({{"name":"{}","ph":"X","pid":{},"tid":{},"ts":{:.3f},"dur":{:.3f},"args":{{{}}}}})",
        name, rank_, tid, begin * 1e6, std::max(0.0, end - begin) * 1e6, args);
    ++events_;
}

void TraceRecorder::add_step(long step, const StepGraph& g,
                             const std::vector<MessageRecord>& between) {
    for (const TaskRecord& r : g.task_records()) {
        if (r.end <= 0)
            continue;
        const int tid = r.thread < 0 ? kMpiTrack + 1 : r.thread;
        if (r.stage >= 0) {
            const std::string& stage = r.stage < static_cast<int>(stages_.size())
                                           ? stages_[static_cast<std::size_t>(r.stage)]
                                           : std::string("stage");
            slice(
                stage, tid, r.start, r.end,
                fmt::format(R"("group":{},"step":{},"cpu_us":{:.3f})", r.group, step, r.cpu * 1e6));
        } else {
            const std::string& ex = g.halo().exchanges[static_cast<std::size_t>(r.exchange)].name;
            slice(fmt::format("{} {}", r.stage == -1 ? "pack" : "unpack", ex), tid, r.start, r.end,
                  fmt::format(R"("peer":{},"step":{},"cpu_us":{:.3f})",
                              g.halo().peers[static_cast<std::size_t>(r.group)], step,
                              r.cpu * 1e6));
        }
    }
    auto message = [&](const MessageRecord& m) {
        slice(fmt::format("{} {} {}", m.send ? "send" : "recv", m.name, m.send ? "to" : "from"),
              kMpiTrack, m.post, m.done,
              fmt::format(R"("peer":{},"bytes":{},"step":{})", m.peer, m.bytes, step));
    };
    for (const MessageRecord& m : g.message_records())
        message(m);
    for (const MessageRecord& m : between)
        message(m);
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
