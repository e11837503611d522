#pragma once
// Probe time series: one CSV per probe at <out>/probes/<name>.csv, e.g.
//   time_s,pressure_Pa
//   0.01,4905.1234
// Values are written in the shortest form that reads back to the same double; a dry probe
// writes "nan". Each row is flushed, so the file is usable while the run goes on.
#include "sluice/io/case_config.hpp"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace sluice {

// Header of a probe's CSV: "time_s,pressure_Pa", "time_s,water_level_m", "time_s,front_x_m"
// (front_y_m, front_z_m for a front along y or z); a force probe:
// "time_s,Fx_N,Fy_N[,Fz_N]" and, with moment_about, ",Mz_Nm" (2-D) or ",Mx_Nm,My_Nm,Mz_Nm".
// In 2-D forces and moments are per metre of width (N/m, N m/m) though the names say N, Nm.
std::string probe_csv_header(const ProbeConfig& probe, int dimension);
// Number of value columns after time_s.
std::size_t probe_columns(const ProbeConfig& probe, int dimension);

class ProbeWriter {
public:
    // Creates <out_dir>/probes/ and one file per probe (truncating earlier ones), header first.
    // Throws std::runtime_error when a file cannot be created.
    ProbeWriter(const std::string& out_dir, const std::vector<ProbeConfig>& probes,
                int dimension = 2);

    // Continues the files of an interrupted run: each is cut back to its length at the
    // checkpoint (`bytes[k]`, rows written after it are dropped) and appended to.
    // Throws std::runtime_error when a file is missing or shorter than that.
    ProbeWriter(const std::string& out_dir, const std::vector<ProbeConfig>& probes,
                const std::vector<std::uint64_t>& bytes);

    // Appends one row to probe number `index` (in the order given to the constructor).
    void write(std::size_t index, double time, double value);
    // A row of several values (a force probe's components).
    void write(std::size_t index, double time, const std::vector<double>& values);

    [[nodiscard]] std::size_t size() const { return files_.size(); }
    [[nodiscard]] const std::string& path(std::size_t index) const { return paths_.at(index); }
    // Length of each file so far, in bytes (recorded by checkpoints).
    [[nodiscard]] const std::vector<std::uint64_t>& bytes() const { return bytes_; }

private:
    void append(std::size_t index, const std::string& text);

    struct Close {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    std::vector<std::unique_ptr<std::FILE, Close>> files_;
    std::vector<std::string> paths_;
    std::vector<std::uint64_t> bytes_;
};

} // namespace sluice
