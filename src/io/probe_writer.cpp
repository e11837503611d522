// CSV time series of the probes.
#include "sluice/io/probe_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace sluice {

std::string probe_csv_header(ProbeType type) {
    switch (type) {
    case ProbeType::pressure:
        return "time_s,pressure_Pa";
    case ProbeType::water_level:
        return "time_s,water_level_m";
    case ProbeType::surge_front:
        return "time_s,front_x_m";
    }
    return "time_s,value";
}

ProbeWriter::ProbeWriter(const std::string& out_dir, const std::vector<ProbeConfig>& probes) {
    const auto dir = std::filesystem::path(out_dir) / "probes";
    if (!probes.empty())
        std::filesystem::create_directories(dir);
    for (const auto& probe : probes) {
        const std::string path = (dir / (probe.name + ".csv")).string();
        std::FILE* f = std::fopen(path.c_str(), "w");
        if (f == nullptr)
            throw std::runtime_error(
                fmt::format("cannot create {}: {}", path, std::strerror(errno)));
        files_.emplace_back(f);
        paths_.push_back(path);
        fmt::print(f, "{}\n", probe_csv_header(probe.type));
        std::fflush(f);
    }
}

void ProbeWriter::write(std::size_t index, double time, double value) {
    std::FILE* f = files_.at(index).get();
    // fmt's "{}" is the shortest exact round-trip representation of a double.
    fmt::print(f, "{},{}\n", time, value);
    if (std::fflush(f) != 0 || std::ferror(f) != 0)
        throw std::runtime_error(fmt::format("cannot write {}", paths_[index]));
}

} // namespace sluice
