#pragma once
// What asks a run to stop or checkpoint from outside its steps: SIGTERM/SIGINT, the stop file
// in the results folder, and the checkpoint timer (checkpoint.every_minutes). Each request is
// posted into the next step's reduction, so every rank acts on it together. Private to the
// driver (run.cpp).
#include "sluice/solver/simulation.hpp"

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

    // Before a step: posts what was asked since the last call.
    template <int D>
    void post(Simulation<D>& sim) {
        post_to([&sim](unsigned flags) { sim.post_request(flags); });
    }
    // A checkpoint was written: the timer starts again.
    void checkpoint_written() { last_checkpoint_ = Clock::now(); }
    // Rank 0, after a stop: what asked for it; the stop file is removed.
    [[nodiscard]] std::string stop_reason() const;
    void remove_stop_file() const;

private:
    using Clock = std::chrono::steady_clock;
    template <class Post>
    void post_to(Post post);

    StopSignals signals_;
    std::filesystem::path stop_file_;
    double every_minutes_;
    bool root_;
    Clock::time_point last_checkpoint_ = Clock::now();
    Clock::time_point last_stop_check_ = Clock::now();
    bool stop_file_seen_ = false;
};

template <class Post>
void RunRequests::post_to(Post post) {
    if (StopSignals::received() != 0)
        post(request_stop);
    if (!root_)
        return;
    const auto now = Clock::now();
    if (now - last_stop_check_ >= std::chrono::milliseconds(200)) { // few stat calls
        last_stop_check_ = now;
        stop_file_seen_ = std::filesystem::exists(stop_file_);
    }
    if (stop_file_seen_)
        post(request_stop);
    if (every_minutes_ > 0 &&
        std::chrono::duration<double>(now - last_checkpoint_).count() >= 60 * every_minutes_)
        post(request_checkpoint);
}

} // namespace sluice
