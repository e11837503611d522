#pragma once
// Progress report on stderr while a case runs.
//   terminal:     one line rewritten in place (\r), at most 5 times per second;
//   not terminal: a plain line at most every 10 s of wall time (log files stay short);
//   quiet:        nothing.
// finish() always prints the final state (and ends the line on a terminal).
// A line: "step 1200  t 0.1235/2 s  6.2%  dt 1.03e-04 s  2.41e+06 pstep/s  ETA 3m12s", where
// pstep/s is particles x steps per wall-clock second.
#include <chrono>
#include <cstddef>
#include <cstdio>

namespace sluice {

class Progress {
public:
    Progress(double end_time, bool quiet);
    // For tests and redirection: explicit stream and terminal mode.
    Progress(double end_time, bool quiet, std::FILE* out, bool terminal);

    // Call every step; it decides itself whether to print.
    void update(long step, double t, double dt, double particle_steps_per_second);
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    void print(bool final_line);

    double end_time_;
    bool quiet_, terminal_;
    std::FILE* out_;
    Clock::time_point start_, last_print_;
    bool printed_ = false, have_state_ = false, finished_ = false;
    double t_start_ = 0;
    long step_ = 0;
    double t_ = 0, dt_ = 0, rate_ = 0;
    std::size_t line_width_ = 0;
};

} // namespace sluice
