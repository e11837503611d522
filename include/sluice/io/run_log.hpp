#pragma once
// The log of one run, through spdlog:
//   <out>/logs/rank_<N>.log  one file per MPI rank (rank_0.log on one rank): time-stamped
//                            lines, level info (debug with --verbose); always written;
//   stderr                   rank 0 only: nothing with --quiet, warnings and errors by default
//                            (the progress line says the rest), everything with --verbose.
#include <fmt/format.h>
#include <spdlog/logger.h>

#include <memory>
#include <string>
#include <utility>

namespace sluice {

struct LogOptions {
    std::string dir; // folder of the rank files (created); empty: no file
    int rank = 0;
    bool console = true; // this rank may write to stderr (rank 0)
    bool quiet = false, verbose = false;
};

class RunLog {
public:
    explicit RunLog(const LogOptions& opts);
    ~RunLog();
    RunLog(const RunLog&) = delete;
    RunLog& operator=(const RunLog&) = delete;

    template <class... A>
    void debug(fmt::format_string<A...> f, A&&... a) {
        logger_->debug(fmt::format(f, std::forward<A>(a)...));
    }
    template <class... A>
    void info(fmt::format_string<A...> f, A&&... a) {
        logger_->info(fmt::format(f, std::forward<A>(a)...));
    }
    template <class... A>
    void warn(fmt::format_string<A...> f, A&&... a) {
        logger_->warn(fmt::format(f, std::forward<A>(a)...));
    }
    template <class... A>
    void error(fmt::format_string<A...> f, A&&... a) {
        logger_->error(fmt::format(f, std::forward<A>(a)...));
    }
    // Only to the rank file (progress lines: the console has its own progress display).
    void file_only(const std::string& line);
    [[nodiscard]] const std::string& file() const { return file_; }

private:
    std::shared_ptr<spdlog::logger> logger_, file_logger_;
    std::string file_;
};

} // namespace sluice
