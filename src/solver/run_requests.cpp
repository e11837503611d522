// Stop and checkpoint requests from outside a run's steps (run_requests.hpp).
#include "run_requests.hpp"

#include "sluice/solver/simulation.hpp"

#include <csignal>

namespace sluice {

std::filesystem::path stop_file_path(const std::string& out_dir) {
    return std::filesystem::path(out_dir) / "stop";
}

RunRequests::RunRequests(const std::string& out_dir, double checkpoint_every_minutes, bool root)
    : stop_file_(stop_file_path(out_dir)), every_minutes_(checkpoint_every_minutes), root_(root) {}

std::string RunRequests::stop_reason() const {
    return StopSignals::received() == SIGTERM  ? "SIGTERM"
           : StopSignals::received() == SIGINT ? "SIGINT"
           : stop_file_seen_                   ? "the stop file"
                                               : "a signal to another rank";
}

unsigned RunRequests::pending() {
    unsigned flags = StopSignals::received() != 0 ? request_stop : 0u;
    if (!root_)
        return flags;
    const auto now = Clock::now();
    if (now - last_stop_check_ >= std::chrono::milliseconds(200)) { // few stat calls
        last_stop_check_ = now;
        stop_file_seen_ = std::filesystem::exists(stop_file_);
    }
    if (stop_file_seen_)
        flags |= request_stop;
    if (every_minutes_ > 0 &&
        std::chrono::duration<double>(now - last_checkpoint_).count() >= 60 * every_minutes_)
        flags |= request_checkpoint;
    return flags;
}

void RunRequests::remove_stop_file() const {
    std::filesystem::remove(stop_file_);
}

} // namespace sluice
