#include "sluice/tasks/profile.hpp"

#include <algorithm>

namespace sluice::tasks {

namespace {
std::vector<Interval> merged(std::vector<Interval> v) {
    std::sort(v.begin(), v.end(),
              [](const Interval& a, const Interval& b) { return a.begin < b.begin; });
    std::vector<Interval> out;
    for (const Interval& i : v) {
        if (i.end <= i.begin)
            continue;
        if (!out.empty() && i.begin <= out.back().end)
            out.back().end = std::max(out.back().end, i.end);
        else
            out.push_back(i);
    }
    return out;
}
} // namespace

double union_length(std::vector<Interval>& v) {
    double s = 0;
    for (const Interval& i : merged(v))
        s += i.end - i.begin;
    return s;
}

double uncovered_length(std::vector<Interval> a, std::vector<Interval> b) {
    const auto A = merged(std::move(a));
    const auto B = merged(std::move(b));
    double s = 0;
    std::size_t j = 0;
    for (const Interval& i : A) {
        double t = i.begin;
        while (j < B.size() && B[j].end <= t)
            ++j;
        std::size_t k = j;
        while (t < i.end) {
            if (k >= B.size() || B[k].begin >= i.end) {
                s += i.end - t;
                break;
            }
            if (B[k].begin > t)
                s += B[k].begin - t;
            t = std::max(t, B[k].end);
            ++k;
        }
    }
    return s;
}

double RankProfile::busy() const {
    double s = halo_pack_busy;
    for (double b : stage_busy)
        s += b;
    return s;
}

void RankProfile::add_step(const StepGraph& g, const std::vector<MessageRecord>& between) {
    stage_busy.resize(static_cast<std::size_t>(g.stage_count()), 0.0);
    stage_cpu.resize(stage_busy.size(), 0.0);
    std::vector<Interval> tasks, msgs;
    tasks.reserve(g.task_records().size());
    for (const TaskRecord& r : g.task_records()) {
        if (r.end <= r.start)
            continue;
        tasks.push_back({r.start, r.end});
        task_cpu += r.cpu;
        if (r.stage >= 0) {
            stage_busy[static_cast<std::size_t>(r.stage)] += r.end - r.start;
            stage_cpu[static_cast<std::size_t>(r.stage)] += r.cpu;
        } else {
            halo_pack_busy += r.end - r.start;
            halo_pack_cpu += r.cpu;
        }
    }
    for (const MessageRecord& m : g.message_records())
        msgs.push_back({m.post, m.done});
    for (const MessageRecord& m : between)
        msgs.push_back({m.post, m.done});
    comm += union_length(msgs);
    exposed += uncovered_length(msgs, tasks);
    graph_wall += g.run_end() - g.run_begin();
    ++steps;
}

} // namespace sluice::tasks
