// The output schedule (output_schedule.hpp).
#include "sluice/solver/output_schedule.hpp"

namespace sluice {

OutputSchedule::OutputSchedule(const CaseConfig& cfg)
    : cfg_(cfg), eps_(1e-12 * cfg.end_time),
      out_every_(cfg.output_interval > 0 ? cfg.output_interval : cfg.end_time),
      probe_last_(cfg.probes.size(), -1.0) {
    for (const auto& p : cfg.probes) {
        probe_every_.push_back(p.interval > 0 ? p.interval : out_every_);
        probe_next_.push_back(0.0);
    }
}

void OutputSchedule::resume(const OutputState& state, double t) {
    probe_next_ = state.probe_next;
    probe_last_.assign(cfg_.probes.size(), t);
    out_next_ = state.out_next;
    last_output_time_ = state.last_output_time;
}

OutputSchedule::Due OutputSchedule::due(double t, bool force) const {
    Due d;
    for (std::size_t k = 0; k < cfg_.probes.size(); ++k)
        if ((force || cfg_.probes[k].every_step || t >= probe_next_[k] - eps_) &&
            t != probe_last_[k])
            d.probes.push_back(k);
    d.output = force || t >= out_next_ - eps_;
    d.snapshot = d.output && cfg_.snapshots && t != last_output_time_;
    return d;
}

void OutputSchedule::done(const Due& d, double t) {
    for (std::size_t k : d.probes) {
        probe_last_[k] = t;
        while (probe_next_[k] <= t + eps_)
            probe_next_[k] += probe_every_[k];
    }
    if (d.output) {
        last_output_time_ = t;
        while (out_next_ <= t + eps_)
            out_next_ += out_every_;
    }
}

} // namespace sluice
