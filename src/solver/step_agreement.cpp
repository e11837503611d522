// The per-step agreement between ranks (Simulation::reduce_step_results): the time-step
// limits, the largest speed and displacement, failures and requests of every cell group and
// rank reduced to one decision that every rank takes the same way.
#include "sluice/solver/simulation.hpp"

#include "sluice/io/errors.hpp"

#include <cstring>
#include <fmt/format.h>

namespace sluice {

template <int D>
void Simulation<D>::reduce_step_results(const std::string& task_error) {
    TimeStepLimits lim;
    for (const auto& l : group_limits_)
        lim = min(lim, l);
    Real speed = 0;
    for (Real s : group_speed_)
        speed = std::max(speed, s);
    Real disp2 = 0;
    for (Real d : group_disp2_)
        disp2 = std::max(disp2, d);
    // A task that threw comes first: the step's other results may be incomplete.
    enum : std::int64_t { none = 0, physical = 1, internal = 2 };
    std::int64_t failed = task_error.empty() ? none : internal;
    std::string failure =
        task_error.empty() ? std::string() : fmt::format("step {}: {}", steps_ + 1, task_error);
    for (const std::string& f : group_failure_)
        if (!f.empty() && failed == none) {
            failed = physical;
            failure = f;
        }
    double busy = 0;
    for (const auto& r : graph_->task_records())
        busy += r.end - r.start;
    const unsigned requests = requests_local_;
    requests_local_ = 0;
    if (!comm_.parallel()) {
        if (failed == internal)
            throw InternalError(failure);
        if (failed == physical)
            throw RunError(failure);
        limits_ = lim;
        u_max_ = speed;
        disp2_max_ = disp2;
        last_busy_.assign(1, busy);
        requests_agreed_ = requests;
        return;
    }
    // One small all-gather per step: the time-step limits, the largest speed, failures,
    // requests (stop, checkpoint) and the busy time the balancer needs. Every rank reduces the
    // same list the same way.
    struct Report {
        double acoustic, viscous, force, speed, disp2, busy;
        std::int64_t failed, requests;
    };
    const Report mine{lim.acoustic, lim.viscous, lim.force, speed,
                      disp2,        busy,        failed,    static_cast<std::int64_t>(requests)};
    const double t0 = tasks::clock_seconds();
    const auto all = comm_.all_gather(
        std::span<const std::byte>(reinterpret_cast<const std::byte*>(&mine), sizeof(mine)));
    between_.push_back({"reduce", -1, true, sizeof(mine), t0, tasks::clock_seconds()});
    TimeStepLimits global;
    Real global_speed = 0, global_disp2 = 0;
    int failed_rank = -1;
    std::int64_t failed_kind = none;
    std::int64_t agreed = 0;
    last_busy_.assign(all.size(), 0.0);
    for (std::size_t r = 0; r < all.size(); ++r) {
        Report rep{};
        std::memcpy(&rep, all[r].data(), sizeof(rep));
        global = min(global, TimeStepLimits{rep.acoustic, rep.viscous, rep.force});
        global_speed = std::max(global_speed, Real(rep.speed));
        global_disp2 = std::max(global_disp2, Real(rep.disp2));
        last_busy_[r] = rep.busy;
        agreed |= rep.requests;
        if (rep.failed != none && failed_rank < 0) {
            failed_rank = static_cast<int>(r);
            failed_kind = rep.failed;
        }
    }
    if (failed_rank >= 0) {
        const std::string msg =
            fmt::format("{} (on rank {})", comm_.broadcast(failure, failed_rank), failed_rank);
        if (failed_kind == internal)
            throw InternalError(msg);
        throw RunError(msg);
    }
    limits_ = global;
    u_max_ = global_speed;
    disp2_max_ = global_disp2;
    requests_agreed_ = static_cast<unsigned>(agreed);
}

template void Simulation<2>::reduce_step_results(const std::string&);
template void Simulation<3>::reduce_step_results(const std::string&);

} // namespace sluice
