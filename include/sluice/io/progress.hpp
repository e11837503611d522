#pragma once
// Progress report of a running case.
//   console, terminal:     one line rewritten in place (\r), at most 5 times per second
//                          (plain lines every second with --verbose, so that log lines
//                          between them stay readable);
//   console, not terminal: a plain line every 10 s of wall time (batch jobs: logs stay short);
//   quiet:                 nothing on the console;
//   log sink (optional):   a plain line every 10 s and at the end (the per-rank log file).
// finish() always reports the final state (and ends the line on a terminal).
// A line: "step 1200  t 0.1235/2 s  6.2%  dt 1.03e-04 s  2.41e+06 pstep/s  ETA 3m12s", where
// pstep/s is particles x steps per wall-clock second.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>

namespace sluice {

class Progress {
public:
    // On stderr, in the mode its being a terminal and the flags select.
    Progress(double end_time, bool quiet, bool verbose = false);
    // Explicit stream (nullptr: no console output), mode and interval of plain lines [s].
    Progress(double end_time, std::FILE* out, bool terminal, double line_every);

    // Also give a plain line to `sink` every `every` seconds of wall time and at the end.
    void log_to(std::function<void(const std::string&)> sink, double every = 10.0);

    // Call every step; it decides itself whether to print.
    void update(long step, double t, double dt, double particle_steps_per_second);
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    [[nodiscard]] std::string line(bool final_line, Clock::time_point now) const;
    void print(const std::string& text, bool final_line);

    double end_time_;
    std::FILE* out_;
    bool terminal_;
    double line_every_;
    std::function<void(const std::string&)> sink_;
    double sink_every_ = 10.0;
    Clock::time_point start_, last_print_, last_sink_;
    bool printed_ = false, sunk_ = false, have_state_ = false, finished_ = false;
    double t_start_ = 0;
    long step_ = 0;
    double t_ = 0, dt_ = 0, rate_ = 0;
    std::size_t line_width_ = 0;
};

} // namespace sluice
