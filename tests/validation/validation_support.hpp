#pragma once
// Shared helpers of the validation tests: locating cases and reference data, reading the
// reference CSV files (comment lines start with '#'), running a case the command line's way.
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/run.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h> // getpid: a folder of its own when suites run side by side

namespace sluice::testing {

inline std::string case_path(const std::string& name) {
    return std::string(SLUICE_SOURCE_DIR) + "/cases/" + name;
}
inline std::string data_path(const std::string& name) {
    return std::string(SLUICE_SOURCE_DIR) + "/tests/data/" + name;
}

// A case run through run_case (case reader output, run loop, probe CSV files: what `sluice run`
// does) into a results folder of its own under the temporary directory, emptied first. The
// caller reads the files and removes the folder.
struct FolderRun {
    std::string folder;
    RunResult result;
};
inline FolderRun run_in_temp_folder(const CaseConfig& cfg, const std::string& tag, int threads) {
    FolderRun run;
    run.folder = (std::filesystem::temp_directory_path() /
                  ("sluice_test_" + tag + "_" + std::to_string(::getpid())))
                     .string();
    std::filesystem::remove_all(run.folder);
    RunOptions opts;
    opts.out_dir = run.folder;
    opts.threads = threads;
    opts.quiet = true;
    run.result = run_case(cfg, opts);
    return run;
}

// Rows of a CSV file with a header line, '#' comment lines skipped; fields as strings.
inline std::vector<std::vector<std::string>> read_csv(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        if (header) {
            header = false;
            continue;
        }
        std::vector<std::string> fields;
        std::stringstream ss(line);
        std::string f;
        while (std::getline(ss, f, ','))
            fields.push_back(f);
        rows.push_back(fields);
    }
    return rows;
}

// Linear interpolation of y(x) on increasing xs.
inline double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (x <= xs.front())
        return ys.front();
    for (std::size_t k = 1; k < xs.size(); ++k)
        if (x <= xs[k]) {
            const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
            return ys[k - 1] + w * (ys[k] - ys[k - 1]);
        }
    return ys.back();
}

// RMS relative deviation (Z_sim - Z) / Z of a simulated surge front Z_sim(T), sampled as
// (Ts, Zs), from the rows (label, T, Z) of a reference CSV with T_lo < T <= T_hi and, unless
// `label` is empty, that label. `print` lists every point compared.
struct FrontDeviation {
    double rms = 0;
    int points = 0;
};
inline FrontDeviation front_deviation(const std::vector<double>& Ts, const std::vector<double>& Zs,
                                      const std::string& csv, double T_lo, double T_hi,
                                      const std::string& label = "", bool print = false) {
    double sum2 = 0;
    int n = 0;
    for (const auto& row : read_csv(csv)) {
        const double T = std::stod(row[1]), Z = std::stod(row[2]);
        if ((!label.empty() && row[0] != label) || T <= T_lo || T > T_hi)
            continue;
        const double Zsim = interpolate(Ts, Zs, T);
        const double rel = (Zsim - Z) / Z;
        if (print)
            std::printf("  %-6s T = %.3f  Z_exp = %.3f  Z_sim = %.3f  (%+.1f %%)\n", row[0].c_str(),
                        T, Z, Zsim, 100 * rel);
        sum2 += rel * rel;
        ++n;
    }
    return {n > 0 ? std::sqrt(sum2 / n) : 0.0, n};
}

} // namespace sluice::testing
