// spdlog sinks of a run: one file per rank, stderr on rank 0 at the level the flags ask for.
#include "sluice/io/run_log.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_sinks.h>

#include <filesystem>
#include <vector>

namespace sluice {

RunLog::RunLog(const LogOptions& opts) {
    std::vector<spdlog::sink_ptr> sinks;
    spdlog::sink_ptr file_sink;
    if (!opts.dir.empty()) {
        std::filesystem::create_directories(opts.dir);
        file_ = (std::filesystem::path(opts.dir) / fmt::format("rank_{}.log", opts.rank)).string();
        file_sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>(file_, /*truncate=*/true);
        file_sink->set_pattern(fmt::format("[%Y-%m-%d %H:%M:%S.%e] [rank {}] [%l] %v", opts.rank));
        file_sink->set_level(opts.verbose ? spdlog::level::debug : spdlog::level::info);
        sinks.push_back(file_sink);
    }
    if (opts.console && !opts.quiet) {
        auto console = std::make_shared<spdlog::sinks::stderr_sink_mt>();
        console->set_pattern("sluice: %v");
        console->set_level(opts.verbose ? spdlog::level::debug : spdlog::level::warn);
        sinks.push_back(console);
    }
    logger_ = std::make_shared<spdlog::logger>("sluice", sinks.begin(), sinks.end());
    logger_->set_level(spdlog::level::debug);
    // A run that dies must not lose its last lines.
    logger_->flush_on(spdlog::level::debug);
    if (file_sink) {
        file_logger_ = std::make_shared<spdlog::logger>("sluice-file", file_sink);
        file_logger_->set_level(spdlog::level::info);
        file_logger_->flush_on(spdlog::level::info);
    }
}

RunLog::~RunLog() {
    if (logger_)
        logger_->flush();
}

void RunLog::file_only(const std::string& line) {
    if (file_logger_)
        file_logger_->info(line);
}

} // namespace sluice
