#pragma once
// Shared helpers of the validation tests: locating cases and reference data, reading the
// reference CSV files (comment lines start with '#').
#include "sluice/io/case_reader.hpp"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sluice::testing {

inline std::string case_path(const std::string& name) {
    return std::string(SLUICE_SOURCE_DIR) + "/cases/" + name;
}
inline std::string data_path(const std::string& name) {
    return std::string(SLUICE_SOURCE_DIR) + "/tests/data/" + name;
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

} // namespace sluice::testing
