// CSV time series of the probes.
#include "sluice/io/probe_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace sluice {
namespace {

// An area sensor on a moving wall, whose rows also say where it is.
bool moving_sensor(const ProbeConfig& probe) {
    return probe.type == ProbeType::pressure && probe.diameter > 0 && probe.frame >= 0;
}

} // namespace

std::string probe_csv_header(const ProbeConfig& probe, int dimension) {
    switch (probe.type) {
    case ProbeType::pressure:
        if (moving_sensor(probe)) // then where its centre is and its normal into the wall
            return dimension == 3 ? "time_s,pressure_Pa,x_m,y_m,z_m,nx,ny,nz"
                                  : "time_s,pressure_Pa,x_m,y_m,nx,ny";
        return "time_s,pressure_Pa";
    case ProbeType::water_level:
        return "time_s,water_level_m";
    case ProbeType::surge_front:
        return fmt::format("time_s,front_{}_m", "xyz"[probe.direction_axis]);
    case ProbeType::force: {
        std::string h = "time_s,Fx_N,Fy_N";
        if (dimension == 3)
            h += ",Fz_N";
        if (probe.moment_about)
            h += dimension == 3 ? ",Mx_Nm,My_Nm,Mz_Nm" : ",Mz_Nm";
        return h;
    }
    case ProbeType::motion: {
        std::string h = dimension == 3
                            ? "time_s,dx_m,dy_m,dz_m,angle_deg,vx_m_s,vy_m_s,vz_m_s,omega_deg_s"
                            : "time_s,dx_m,dy_m,angle_deg,vx_m_s,vy_m_s,omega_deg_s";
        if (probe.body)
            h += dimension == 3 ? ",qw,qx,qy,qz,wx_rad_s,wy_rad_s,wz_rad_s,Fx_N,Fy_N,Fz_N,Mx_Nm,"
                                  "My_Nm,Mz_Nm"
                                : ",Fx_N,Fy_N,Mz_Nm";
        return h;
    }
    }
    return "time_s,value";
}

std::size_t probe_columns(const ProbeConfig& probe, int dimension) {
    if (probe.type == ProbeType::motion)
        return 2 * static_cast<std::size_t>(dimension) + 2 +
               (probe.body ? (dimension == 3 ? 13u : 3u) : 0u);
    if (moving_sensor(probe))
        return 1 + 2 * static_cast<std::size_t>(dimension);
    if (probe.type != ProbeType::force)
        return 1;
    const auto d = static_cast<std::size_t>(dimension);
    return d + (probe.moment_about ? (d == 3 ? 3 : 1) : 0);
}

namespace {

std::string probe_path(const std::string& out_dir, const ProbeConfig& probe) {
    return (std::filesystem::path(out_dir) / "probes" / (probe.name + ".csv")).string();
}

} // namespace

ProbeWriter::ProbeWriter(const std::string& out_dir, const std::vector<ProbeConfig>& probes,
                         int dimension) {
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
        append(files_.size() - 1, probe_csv_header(probe, dimension) + "\n");
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

void ProbeWriter::write(std::size_t index, double time, const std::vector<double>& values) {
    std::string row = fmt::format("{}", time);
    for (double v : values)
        row += fmt::format(",{}", v);
    append(index, row + "\n");
}

} // namespace sluice
