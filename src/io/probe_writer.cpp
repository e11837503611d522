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

namespace {

std::string probe_path(const std::string& out_dir, const ProbeConfig& probe) {
    return (std::filesystem::path(out_dir) / "probes" / (probe.name + ".csv")).string();
}

} // namespace

ProbeWriter::ProbeWriter(const std::string& out_dir, const std::vector<ProbeConfig>& probes) {
    if (!probes.empty())
        std::filesystem::create_directories(std::filesystem::path(out_dir) / "probes");
    for (const auto& probe : probes) {
        const std::string path = probe_path(out_dir, probe);
        std::FILE* f = std::fopen(path.c_str(), "w");
        if (f == nullptr)
            throw std::runtime_error(
                fmt::format("cannot create {}: {}", path, std::strerror(errno)));
        files_.emplace_back(f);
        paths_.push_back(path);
        bytes_.push_back(0);
        append(files_.size() - 1, probe_csv_header(probe.type) + "\n");
    }
}

ProbeWriter::ProbeWriter(const std::string& out_dir, const std::vector<ProbeConfig>& probes,
                         const std::vector<std::uint64_t>& bytes) {
    if (bytes.size() != probes.size())
        throw std::runtime_error(
            fmt::format("cannot continue the probe files: {} lengths for {} probes", bytes.size(),
                        probes.size()));
    for (std::size_t k = 0; k < probes.size(); ++k) {
        const std::string path = probe_path(out_dir, probes[k]);
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (ec || size < bytes[k])
            throw std::runtime_error(fmt::format(
                "cannot continue {}: {}", path,
                ec ? ec.message()
                   : fmt::format("it has {} bytes, the checkpoint recorded {}", size, bytes[k])));
        std::filesystem::resize_file(path, bytes[k]); // rows written after the checkpoint
        std::FILE* f = std::fopen(path.c_str(), "a");
        if (f == nullptr)
            throw std::runtime_error(fmt::format("cannot open {}: {}", path, std::strerror(errno)));
        files_.emplace_back(f);
        paths_.push_back(path);
        bytes_.push_back(bytes[k]);
    }
}

void ProbeWriter::append(std::size_t index, const std::string& text) {
    std::FILE* f = files_.at(index).get();
    if (std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fflush(f) != 0 ||
        std::ferror(f) != 0)
        throw std::runtime_error(fmt::format("cannot write {}", paths_[index]));
    bytes_[index] += text.size();
}

void ProbeWriter::write(std::size_t index, double time, double value) {
    // fmt's "{}" is the shortest exact round-trip representation of a double.
    append(index, fmt::format("{},{}\n", time, value));
}

} // namespace sluice
