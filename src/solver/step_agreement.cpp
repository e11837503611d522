// The per-step agreement between ranks: the time-step limits, the largest speed and
// displacement, failures and requests of every cell group and rank reduced to one decision
// that every rank takes the same way. It is split in two so that the reports travel while the
// rank does its own bookkeeping: post_step_report() sends this rank's report as soon as the
// step's graph has finished (one non-blocking all-gather of a fixed-size record),
// agree_on_step() collects every rank's where the decision is first needed (before the
// step's buffers are swapped in) and reduces them.
#include "sluice/solver/simulation.hpp"

#include "step_scheme.hpp"

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
    std::int64_t leaving = 0;
    for (std::int64_t n : results_.leaving)
        leaving += n;
    leaving_local_ = leaving;
    double busy = 0;
    for (const auto& r : graph_->task_records())
        busy += r.end - r.start;
    rep.mine = StepReport{.acoustic = lim.acoustic,
                          .viscous = lim.viscous,
                          .force = lim.force,
                          .speed = speed,
                          .disp2 = disp2,
                          .busy = busy,
                          .failed = failed,
                          .requests = static_cast<std::int64_t>(requests_local_),
                          .leaving = leaving};
    requests_local_ = 0;
    rep.posted = tasks::clock_seconds();
    // The free bodies' load shares ride in the same message (no round of their own).
    std::vector<std::byte> bytes(sizeof(rep.mine));
    std::memcpy(bytes.data(), &rep.mine, sizeof(rep.mine));
    if (!motion_->bodies().empty())
        motion_->pack_loads(results_.body_loads, bytes);
    rep.gather = comm_.start_all_gather(bytes);
}

template <int D>
void Simulation<D>::agree_on_step() {
    PendingStepReport rep = std::move(*report_);
    report_.reset();
    const auto all = rep.gather.wait();
    if (comm_.parallel())
        between_.push_back(
            {"reduce", -1, true, sizeof(rep.mine), rep.posted, tasks::clock_seconds()});
    const StepFailed failed = reduce_reports(all);
    if (failed.rank >= 0)
        raise_failure(failed, rep.failure);
}

template <int D>
typename Simulation<D>::StepFailed
Simulation<D>::reduce_reports(const std::vector<tasks::Bytes>& all) {
    // Every rank reduces the same list the same way (rank order).
    TimeStepLimits global;
    Real global_speed = 0, global_disp2 = 0;
    StepFailed failed;
    std::int64_t agreed = 0, leaving = 0;
    last_busy_.assign(all.size(), 0.0);
    for (std::size_t r = 0; r < all.size(); ++r) {
        StepReport o{};
        std::memcpy(&o, all[r].data(), sizeof(o));
        global = min(global, TimeStepLimits{o.acoustic, o.viscous, o.force});
        global_speed = std::max(global_speed, Real(o.speed));
        global_disp2 = std::max(global_disp2, Real(o.disp2));
        last_busy_[r] = o.busy;
        agreed |= o.requests;
        leaving += o.leaving;
        if (o.failed != failure_none && failed.rank < 0)
            failed = {static_cast<int>(r), o.failed};
    }
    if (failed.rank >= 0)
        return failed;
    if (!motion_->bodies().empty()) {
        std::vector<std::span<const std::byte>> shares;
        for (const auto& b : all)
            shares.push_back(std::span<const std::byte>(b).subspan(sizeof(StepReport)));
        if (!motion_->agree_loads(shares))
            throw RunError(fmt::format("step {}: the fluid's load on a free body is beyond 1e18 "
                                       "(N or N m): the flow around it blew up",
                                       clock_.steps + 1));
    }
    limits_ = global;
    clock_.u_max = global_speed;
    disp2_max_ = global_disp2;
    requests_agreed_ = static_cast<unsigned>(agreed);
    leaving_agreed_ = leaving;
    return failed;
}

template <int D>
void Simulation<D>::raise_failure(const StepFailed& failed, const std::string& own_message) {
    const std::string msg =
        comm_.parallel()
            ? fmt::format("{} (on rank {})", comm_.broadcast(own_message, failed.rank), failed.rank)
            : own_message;
    if (failed.kind == failure_internal)
        throw InternalError(msg);
    throw RunError(msg);
}

template <int D>
void Simulation<D>::run_ahead(double t_graph) {
    // This step's report is in flight. Assume what it decides almost every step: no failure,
    // no rebuild of the lists, no rebalance, no request. Then the next step starts from the
    // state this step's graph left (its buffers swapped in) and on the same lists, groups and
    // halo plan, and only its gated stage (the first that reads dt or the agreed largest
    // speed) needs the agreement: the stages before it run while the reports travel. The
    // main thread completes the agreement between its polls of the graph's messages and
    // opens the gate; if the assumption was wrong, every rank knows it from the same
    // reports, lets the rest of the graph run with empty bodies (its messages still flow, so
    // no peer waits), puts back what the early stages overwrote, and goes on exactly as
    // agree_on_step, advance_time and between_steps would have.
    P_.swap_buffers();
    scheme_->keep_ahead(owned_); // of the state swapped in (rho is one of the buffers)
    const bool rebuilt = neighbours_.rebuilt;
    neighbours_.rebuilt = false; // the assumption: the lists stay
    enum class Outcome { pending, go, discard, failed };
    Outcome outcome = Outcome::pending;
    StepFailed failed;
    using Gate = tasks::StepGraph::Gate;
    const auto gate = [&]() -> Gate {
        if (!report_->gather.test())
            return Gate::wait;
        const auto all = report_->gather.wait();
        between_.push_back(
            {"reduce", -1, true, sizeof(report_->mine), report_->posted, tasks::clock_seconds()});
        failed = reduce_reports(all);
        if (failed.rank >= 0) {
            outcome = Outcome::failed;
            return Gate::skip;
        }
        advance_clock();
        balance_.add_step(clock_.steps, last_busy_);
        // Particles that left the domain are removed by a rebuild.
        const bool layout_changes = neighbours_.expired(disp2_max_, leaving_agreed_ > 0) ||
                                    balance_.due() == tasks::BalanceDue::now;
        outcome = requests_agreed_ != 0 || layout_changes ? Outcome::discard : Outcome::go;
        return outcome == Outcome::go ? Gate::open : Gate::skip;
    };
    const double t_ahead = tasks::clock_seconds();
    std::string error = run_graphs(gate);
    const double t_ahead_end = tasks::clock_seconds();
    profile_.between_wall += t_ahead - t_graph;
    if (outcome == Outcome::go) {
        ++ahead_steps_;
        ran_ahead_ = true;
        ahead_error_ = std::move(error);
        report_.reset();
        change_layout(); // nothing to change (that was the gate's condition)
        profile_.between_wall += tasks::clock_seconds() - t_ahead_end;
        return;
    }
    // Discarded: its stages before the gate wrote only the arrays keep_ahead kept (and the
    // halo copies and the lists, which the step run again writes afresh).
    ++ahead_discarded_;
    if (trace_)
        trace_->add_work(clock_.steps + 1, "run ahead, discarded", t_ahead, t_ahead_end);
    scheme_->restore_ahead(owned_);
    PendingStepReport rep = std::move(*report_);
    report_.reset();
    if (outcome == Outcome::failed) {
        P_.swap_buffers(); // the failing step's state never swapped in
        neighbours_.rebuilt = rebuilt;
        raise_failure(failed, rep.failure);
    }
    change_layout();
    profile_.between_wall += tasks::clock_seconds() - t_ahead_end;
}

template void Simulation<2>::post_step_report(const std::string&);
template void Simulation<3>::post_step_report(const std::string&);
template void Simulation<2>::agree_on_step();
template void Simulation<3>::agree_on_step();
template Simulation<2>::StepFailed Simulation<2>::reduce_reports(const std::vector<tasks::Bytes>&);
template Simulation<3>::StepFailed Simulation<3>::reduce_reports(const std::vector<tasks::Bytes>&);
template void Simulation<2>::raise_failure(const StepFailed&, const std::string&);
template void Simulation<3>::raise_failure(const StepFailed&, const std::string&);
template void Simulation<2>::run_ahead(double);
template void Simulation<3>::run_ahead(double);

} // namespace sluice
