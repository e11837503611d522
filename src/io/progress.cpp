// Throttled progress line: cheap enough to call every step.
#include "sluice/io/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unistd.h>
#include <utility>

namespace sluice {
namespace {

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0)
        return "--";
    const auto s = static_cast<long long>(std::lround(seconds));
    if (s < 60)
        return fmt::format("{}s", s);
    if (s < 3600)
        return fmt::format("{}m{:02d}s", s / 60, s % 60);
    return fmt::format("{}h{:02d}m", s / 3600, (s % 3600) / 60);
}

double seconds(std::chrono::steady_clock::duration d) {
    return std::chrono::duration<double>(d).count();
}

} // namespace

Progress::Progress(double end_time, bool quiet, bool verbose)
    : Progress(end_time, quiet ? nullptr : stderr,
               !quiet && !verbose && ::isatty(::fileno(stderr)) != 0, verbose ? 1.0 : 10.0) {}

Progress::Progress(double end_time, std::FILE* out, bool terminal, double line_every)
    : end_time_(end_time), out_(out), terminal_(terminal), line_every_(line_every),
      start_(Clock::now()), last_print_(start_), last_sink_(start_) {}

void Progress::log_to(std::function<void(const std::string&)> sink, double every) {
    sink_ = std::move(sink);
    sink_every_ = every;
}

void Progress::update(long step, double t, double dt, double particle_steps_per_second) {
    if (out_ == nullptr && !sink_)
        return;
    const auto now = Clock::now();
    if (!have_state_) {
        // ETA is measured from the first report, so set-up time does not distort it.
        t_start_ = t;
        start_ = now;
        last_print_ = last_sink_ = now;
        have_state_ = true;
    }
    step_ = step;
    t_ = t;
    dt_ = dt;
    rate_ = particle_steps_per_second;
    // First report at once (the log shows the run started), then throttled.
    const bool console_due = out_ != nullptr && (!printed_ || seconds(now - last_print_) >=
                                                                  (terminal_ ? 0.2 : line_every_));
    const bool sink_due = sink_ && (!sunk_ || seconds(now - last_sink_) >= sink_every_);
    if (!console_due && !sink_due)
        return;
    const std::string text = line(false, now);
    if (console_due) {
        last_print_ = now;
        print(text, false);
    }
    if (sink_due) {
        last_sink_ = now;
        sunk_ = true;
        sink_(text);
    }
}

void Progress::finish() {
    if (finished_)
        return;
    finished_ = true;
    if (!have_state_)
        return;
    const std::string text = line(true, Clock::now());
    if (out_ != nullptr)
        print(text, true);
    if (sink_)
        sink_(text);
}

std::string Progress::line(bool final_line, Clock::time_point now) const {
    const double elapsed = seconds(now - start_);
    const double done = t_ - t_start_;
    const double eta = done > 0 ? elapsed * (end_time_ - t_) / done : -1;
    const double percent = end_time_ > 0 ? 100 * std::min(1.0, t_ / end_time_) : 0;
    // Kept under 80 columns: a wrapped line cannot be rewritten with \r.
    std::string text =
        fmt::format("step {}  t {:.4g}/{:.4g} s  {:.1f}%  dt {:.2e} s  {:.2e} pstep/s", step_, t_,
                    end_time_, percent, dt_, rate_);
    text += final_line ? fmt::format("  wall {}", format_duration(elapsed))
                       : fmt::format("  ETA {}", format_duration(eta));
    return text;
}

void Progress::print(const std::string& text, bool final_line) {
    if (terminal_) {
        // Pad over the remains of a longer previous line.
        std::string padded = text;
        if (text.size() < line_width_)
            padded.append(line_width_ - text.size(), ' ');
        line_width_ = text.size();
        fmt::print(out_, "\r{}{}", padded, final_line ? "\n" : "");
    } else {
        fmt::print(out_, "{}\n", text);
    }
    std::fflush(out_);
    printed_ = true;
}

} // namespace sluice
