#pragma once
// What asks a run to stop or checkpoint from outside its steps: SIGTERM/SIGINT, the stop file
// in the results folder, and the checkpoint timer (checkpoint.every_minutes). Each request is
// posted into the next step's reduction, so every rank acts on it together. Private to the
// driver (run.cpp).
#include "stop_signals.hpp"

#include <chrono>
#include <filesystem>
#include <string>

namespace sluice {

// `touch <out>/stop` asks a running case to checkpoint and stop.
[[nodiscard]] std::filesystem::path stop_file_path(const std::string& out_dir);

class RunRequests {
public:
    // Installs the signal handlers (StopSignals) for the object's lifetime; rank 0 (`root`)
    // alone watches the stop file and the checkpoint timer.
    RunRequests(const std::string& out_dir, double checkpoint_every_minutes, bool root);

    // Before a step: what was asked since the last call (request_stop, request_checkpoint),
    // for Simulation::post_request.
    [[nodiscard]] unsigned pending();
    // A checkpoint was written: the timer starts again.
    void checkpoint_written() { last_checkpoint_ = Clock::now(); }
    // Rank 0, after a stop: what asked for it; and the stop file removed (it would stop the
    // next run in this folder).
    [[nodiscard]] std::string stop_reason() const;
    void remove_stop_file() const;

private:
    using Clock = std::chrono::steady_clock;

    StopSignals signals_;
    std::filesystem::path stop_file_;
    double every_minutes_;
    bool root_;
    Clock::time_point last_checkpoint_ = Clock::now();
    Clock::time_point last_stop_check_ = Clock::now();
    bool stop_file_seen_ = false;
};

} // namespace sluice
