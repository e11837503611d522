// The per-step agreement between ranks: the time-step limits, the largest speed and
// displacement, failures and requests of every cell group and rank reduced to one decision
// that every rank takes the same way. It is split in two so that the reports travel while the
// rank does its own bookkeeping: post_step_report() sends this rank's report as soon as the
// step's graph has finished (one non-blocking all-gather of a fixed-size record),
// agree_on_step() collects every rank's where the decision is first needed (before the
// step's buffers are swapped in) and reduces them.
#include "sluice/solver/simulation.hpp"

#include "sluice/io/errors.hpp"

#include <cstring>
#include <fmt/format.h>

namespace sluice {

template <int D>
void Simulation<D>::post_step_report(const std::string& task_error) {
    TimeStepLimits lim;
    for (const auto& l : results_.limits)
        lim = min(lim, l);
    Real speed = 0;
    for (Real s : results_.speed)
        speed = std::max(speed, s);
    Real disp2 = 0;
    for (Real d : results_.disp2)
        disp2 = std::max(disp2, d);
    PendingStepReport& rep = report_.emplace();
    // A task that threw comes first: the step's other results may be incomplete.
    std::int64_t failed = task_error.empty() ? failure_none : failure_internal;
    if (!task_error.empty())
        rep.failure = fmt::format("step {}: {}", clock_.steps + 1, task_error);
    for (const std::string& f : results_.failure)
        if (!f.empty() && failed == failure_none) {
            failed = failure_physical;
            rep.failure = f;
        }
    double busy = 0;
    for (const auto& r : graph_->task_records())
        busy += r.end - r.start;
    rep.mine = StepReport{
        lim.acoustic, lim.viscous, lim.force, speed,
        disp2,        busy,        failed,    static_cast<std::int64_t>(requests_local_)};
    requests_local_ = 0;
    rep.posted = tasks::clock_seconds();
    rep.gather = comm_.start_all_gather(std::span<const std::byte>(
        reinterpret_cast<const std::byte*>(&rep.mine), sizeof(rep.mine)));
}

template <int D>
void Simulation<D>::agree_on_step() {
    PendingStepReport rep = std::move(*report_);
    report_.reset();
    const auto all = rep.gather.wait();
    if (comm_.parallel())
        between_.push_back(
            {"reduce", -1, true, sizeof(rep.mine), rep.posted, tasks::clock_seconds()});
    // Every rank reduces the same list the same way (rank order).
    TimeStepLimits global;
    Real global_speed = 0, global_disp2 = 0;
    int failed_rank = -1;
    std::int64_t failed_kind = failure_none;
    std::int64_t agreed = 0;
    last_busy_.assign(all.size(), 0.0);
    for (std::size_t r = 0; r < all.size(); ++r) {
        StepReport o{};
        std::memcpy(&o, all[r].data(), sizeof(o));
        global = min(global, TimeStepLimits{o.acoustic, o.viscous, o.force});
        global_speed = std::max(global_speed, Real(o.speed));
        global_disp2 = std::max(global_disp2, Real(o.disp2));
        last_busy_[r] = o.busy;
        agreed |= o.requests;
        if (o.failed != failure_none && failed_rank < 0) {
            failed_rank = static_cast<int>(r);
            failed_kind = o.failed;
        }
    }
    if (failed_rank >= 0) {
        const std::string msg =
            comm_.parallel() ? fmt::format("{} (on rank {})",
                                           comm_.broadcast(rep.failure, failed_rank), failed_rank)
                             : rep.failure;
        if (failed_kind == failure_internal)
            throw InternalError(msg);
        throw RunError(msg);
    }
    limits_ = global;
    clock_.u_max = global_speed;
    disp2_max_ = global_disp2;
    requests_agreed_ = static_cast<unsigned>(agreed);
}

template void Simulation<2>::post_step_report(const std::string&);
template void Simulation<3>::post_step_report(const std::string&);
template void Simulation<2>::agree_on_step();
template void Simulation<3>::agree_on_step();

} // namespace sluice
