// Stop and checkpoint requests from outside a run's steps (run_requests.hpp).
#include "run_requests.hpp"

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

void RunRequests::remove_stop_file() const {
    std::filesystem::remove(stop_file_);
}

} // namespace sluice
