// Throttled progress line: cheap enough to call every step.
#include "sluice/io/progress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unistd.h>

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

} // namespace

Progress::Progress(double end_time, bool quiet)
    : Progress(end_time, quiet, stderr, ::isatty(::fileno(stderr)) != 0) {}

Progress::Progress(double end_time, bool quiet, std::FILE* out, bool terminal)
    : end_time_(end_time), quiet_(quiet), terminal_(terminal), out_(out), start_(Clock::now()),
      last_print_(start_) {}

void Progress::update(long step, double t, double dt, double particle_steps_per_second) {
    if (quiet_)
        return;
    if (!have_state_) {
        // ETA is measured from the first report, so set-up time does not distort it.
        t_start_ = t;
        start_ = Clock::now();
        last_print_ = start_;
        have_state_ = true;
    }
    step_ = step;
    t_ = t;
    dt_ = dt;
    rate_ = particle_steps_per_second;
    const double since = std::chrono::duration<double>(Clock::now() - last_print_).count();
    // First report at once (the log shows the run started), then throttled.
    if (!printed_ || since >= (terminal_ ? 0.2 : 10.0))
        print(false);
}

void Progress::finish() {
    if (quiet_ || finished_)
        return;
    finished_ = true;
    if (have_state_)
        print(true);
}

void Progress::print(bool final_line) {
    const auto now = Clock::now();
    last_print_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double done = t_ - t_start_;
    const double eta = done > 0 ? elapsed * (end_time_ - t_) / done : -1;
    const double percent = end_time_ > 0 ? 100 * std::min(1.0, t_ / end_time_) : 0;
    // Kept under 80 columns: a wrapped line cannot be rewritten with \r.
    std::string line =
        fmt::format("step {}  t {:.4g}/{:.4g} s  {:.1f}%  dt {:.2e} s  {:.2e} pstep/s", step_, t_,
                    end_time_, percent, dt_, rate_);
    line += final_line ? fmt::format("  wall {}", format_duration(elapsed))
                       : fmt::format("  ETA {}", format_duration(eta));
    if (terminal_) {
        // Pad over the remains of a longer previous line.
        const std::size_t width = line.size();
        if (width < line_width_)
            line.append(line_width_ - width, ' ');
        line_width_ = width;
        fmt::print(out_, "\r{}{}", line, final_line ? "\n" : "");
    } else {
        fmt::print(out_, "{}\n", line);
    }
    std::fflush(out_);
    printed_ = true;
}

} // namespace sluice
