// HDF5 snapshots (C API) and the XDMF index ParaView reads them through.
#include "sluice/io/snapshot_writer.hpp"

#include <fmt/format.h>

#include "h5_parallel.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace sluice {
namespace fs = std::filesystem;
using h5::check;
using h5::Handle;
using h5::write_attribute;

namespace {

const std::vector<std::string> kKnownFields = {
    "position", "velocity", "density", "pressure", "acceleration", "mass", "id", "kind", "spacing"};

bool is_vector_field(const std::string& f) {
    return f == "position" || f == "velocity" || f == "acceleration";
}

// N x 3 copy of the first n values of a D-vector field; 2-D gets z = 0 so every viewer sees
// 3-D points.
template <int D>
std::vector<double> padded(const std::vector<Vec<D>>& v, std::size_t n) {
    std::vector<double> out(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < D; ++a)
            out[3 * i + static_cast<std::size_t>(a)] = v[i][a];
    return out;
}

template <class T>
void require_size(const std::vector<T>& v, std::size_t n, const std::string& field) {
    if (v.size() < n)
        throw std::logic_error(
            fmt::format("snapshot: field {} has {} entries for {} particles", field, v.size(), n));
}

void replace_file(const fs::path& tmp, const fs::path& final_path) {
    std::error_code ec;
    fs::rename(tmp, final_path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(fmt::format("cannot move {} to {}: {}", tmp.string(),
                                             final_path.string(), ec.message()));
    }
}

} // namespace

template <int D>
SnapshotWriter<D>::SnapshotWriter(std::string out_dir, std::vector<std::string> fields)
    : out_dir_(std::move(out_dir)), xmf_path_((fs::path(out_dir_) / "snapshots.xmf").string()) {
    init_fields(std::move(fields));
    const h5::World w = h5::world();
    std::optional<std::string> error;
    if (w.rank == 0) {
        try {
            fs::create_directories(fs::path(out_dir_) / "snapshots");
            // An earlier run's files would otherwise sit beside this run's, or be listed
            // by the .xmf.
            remove_from(0);
            fs::remove(xmf_path_);
        } catch (const std::exception& e) {
            error = e.what();
        }
    }
    if (const auto first = h5::first_error(w, error))
        throw std::runtime_error(*first);
}

template <int D>
SnapshotWriter<D>::SnapshotWriter(std::string out_dir, std::vector<std::string> fields,
                                  const std::vector<Earlier>& earlier)
    : out_dir_(std::move(out_dir)), xmf_path_((fs::path(out_dir_) / "snapshots.xmf").string()) {
    init_fields(std::move(fields));
    const h5::World w = h5::world();
    std::optional<std::string> error;
    try {
        for (std::size_t k = 0; k < earlier.size(); ++k) {
            const std::string rel = relative_path(k);
            if (!fs::exists(fs::path(out_dir_) / rel))
                throw std::runtime_error(
                    fmt::format("cannot continue the snapshot series: {} is missing",
                                (fs::path(out_dir_) / rel).string()));
            written_.push_back({rel, earlier[k].time, earlier[k].particles});
        }
        if (w.rank == 0) {
            fs::create_directories(fs::path(out_dir_) / "snapshots");
            remove_from(earlier.size());
            if (written_.empty())
                fs::remove(xmf_path_);
            else
                write_xmf();
        }
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (const auto first = h5::first_error(w, error))
        throw std::runtime_error(*first);
}

template <int D>
void SnapshotWriter<D>::init_fields(std::vector<std::string> fields) {
    fields_.emplace_back("position");
    for (auto& f : fields) {
        if (std::find(kKnownFields.begin(), kKnownFields.end(), f) == kKnownFields.end())
            throw std::invalid_argument("snapshot: unknown field '" + f + "'");
        if (std::find(fields_.begin(), fields_.end(), f) == fields_.end())
            fields_.push_back(std::move(f));
    }
}

template <int D>
void SnapshotWriter<D>::remove_from(std::size_t keep) const {
    fs::remove(fs::path(out_dir_) / ".snapshots.xmf.tmp"); // from an interrupted write
    for (const auto& entry : fs::directory_iterator(fs::path(out_dir_) / "snapshots")) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with(".snap_")) {
            fs::remove(entry.path());
            continue;
        }
        // snap_NNNNNN.h5: numbered from 0 in the order written.
        if (!name.starts_with("snap_"))
            continue;
        std::size_t index = 0;
        const auto digits = name.substr(
            5, name.find('.') == std::string::npos ? std::string::npos : name.find('.') - 5);
        const bool numbered =
            !digits.empty() && digits.size() <= 18 &&
            std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (numbered)
            index = std::stoull(digits);
        if (!numbered || index >= keep)
            fs::remove(entry.path());
    }
}

template <int D>
std::string SnapshotWriter<D>::relative_path(std::size_t index) {
    return fmt::format("snapshots/snap_{:06d}.h5", index);
}

template <int D>
std::vector<typename SnapshotWriter<D>::Earlier> SnapshotWriter<D>::written() const {
    std::vector<Earlier> out;
    for (const auto& w : written_)
        out.push_back({w.time, w.particles});
    return out;
}

template <int D>
bool SnapshotWriter<D>::writes_spacing() const {
    return std::find(fields_.begin(), fields_.end(), "spacing") != fields_.end();
}

template <int D>
std::uint64_t SnapshotWriter<D>::write_h5(const std::string& path, const Particles<D>& ps,
                                          std::size_t n, double time, long step,
                                          const SnapshotSpacing* spacing) const {
    const h5::World w = h5::world();
    const h5::Slice slice = h5::slice_of_count(w, n);
    const Handle fapl = h5::file_access(w);
    const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
                      "create " + path);
    const hid_t f = file.get();
    const auto rows = [&](const std::string& name, const void* data, std::size_t cols,
                          hid_t mem_type, hid_t file_type) {
        h5::write_rows(w, f, name, data, slice, cols, mem_type, file_type, false);
    };
    const auto vec3 = [&](const std::string& name, const std::vector<Vec<D>>& v) {
        require_size(v, n, name);
        rows(name, padded<D>(v, n).data(), 3, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    };
    const auto scalar = [&](const std::string& name, const std::vector<Real>& v) {
        require_size(v, n, name);
        const std::vector<double> values(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n));
        rows(name, values.data(), 1, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    };
    for (const auto& field : fields_) {
        if (field == "position")
            vec3(field, ps.x);
        else if (field == "velocity")
            vec3(field, ps.v);
        else if (field == "acceleration")
            vec3(field, ps.a);
        else if (field == "density")
            scalar(field, ps.rho);
        else if (field == "pressure")
            scalar(field, ps.p);
        else if (field == "mass")
            scalar(field, ps.mass);
        else if (field == "id") {
            require_size(ps.id, n, field);
            const std::vector<std::uint64_t> ids(ps.id.begin(),
                                                 ps.id.begin() + static_cast<std::ptrdiff_t>(n));
            rows(field, ids.data(), 1, H5T_NATIVE_UINT64, H5T_STD_U64LE);
        } else if (field == "kind") {
            require_size(ps.kind, n, field);
            std::vector<std::uint8_t> kinds(n);
            for (std::size_t i = 0; i < n; ++i)
                kinds[i] = static_cast<std::uint8_t>(ps.kind[i]);
            rows(field, kinds.data(), 1, H5T_NATIVE_UINT8, H5T_STD_U8LE);
        } else if (field == "spacing") {
            if (spacing == nullptr || spacing->over_dx.size() != n)
                throw std::logic_error("snapshot: the spacing field needs a value per particle");
            const std::vector<double> values(spacing->over_dx.begin(), spacing->over_dx.end());
            rows(field, values.data(), 1, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
        }
    }
    if (spacing != nullptr) {
        const NeighbourCensus& c = spacing->census;
        const auto count = [&](const char* name, std::uint64_t v) {
            write_attribute(f, name, v, H5T_NATIVE_UINT64, H5T_STD_U64LE);
        };
        count("fluid_particles", c.fluid);
        count("fluid_crowded", c.fluid_crowded);
        count("fluid_isolated", c.fluid_isolated);
        write_attribute(f, "crowded_below", double(spacing->crowded_below), H5T_NATIVE_DOUBLE,
                        H5T_IEEE_F64LE);
        write_attribute(f, "closest_fluid_pair", double(c.closest_fluid_pair), H5T_NATIVE_DOUBLE,
                        H5T_IEEE_F64LE);
    }
    write_attribute(f, "time", time, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    write_attribute(f, "step", static_cast<std::int64_t>(step), H5T_NATIVE_INT64, H5T_STD_I64LE);
    write_attribute(f, "dimension", static_cast<std::int32_t>(D), H5T_NATIVE_INT32, H5T_STD_I32LE);
    check(H5Fflush(f, H5F_SCOPE_LOCAL), "flush " + path);
    return slice.total;
}

template <int D>
std::string SnapshotWriter<D>::write(const Particles<D>& ps, std::size_t count, double time,
                                     long step, const SnapshotSpacing* spacing) {
    const h5::World w = h5::world();
    const std::string rel = relative_path(written_.size());
    const fs::path final_path = fs::path(out_dir_) / rel;
    const fs::path tmp =
        fs::path(out_dir_) / fmt::format("snapshots/.snap_{:06d}.h5.tmp", written_.size());
    // Every rank writes its slice of the temporary file (closed collectively when write_h5
    // returns); rank 0 alone renames it and rewrites the .xmf.
    std::optional<std::string> error;
    std::uint64_t total = 0;
    try {
        total = write_h5(tmp.string(), ps, count, time, step, spacing);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (const auto first = h5::first_error(w, error)) {
        std::error_code ec;
        if (w.rank == 0)
            fs::remove(tmp, ec);
        throw std::runtime_error(*first);
    }
    written_.push_back({rel, time, static_cast<std::size_t>(total)});
    if (w.rank == 0) {
        try {
            replace_file(tmp, final_path);
            write_xmf();
        } catch (const std::exception& e) {
            error = e.what();
        }
    }
    if (const auto first = h5::first_error(w, error)) {
        written_.pop_back();
        throw std::runtime_error(*first);
    }
    return final_path.string();
}

template <int D>
void SnapshotWriter<D>::write_xmf() const {
    // XDMF 2/3 as read by ParaView's XDMF readers: a temporal collection of
    // Polyvertex grids. id is declared as signed 64-bit: the older XDMF reader
    // has no unsigned 64-bit type and HDF5 converts on read (ids stay far below
    // 2^63).
    std::string x = "<?xml version=\"1.0\" ?>\n"
                    "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                    "<Xdmf Version=\"3.0\">\n"
                    "  <Domain>\n"
                    "    <Grid Name=\"particles\" GridType=\"Collection\" "
                    "CollectionType=\"Temporal\">\n";
    for (const auto& w : written_) {
        const auto item = [&](const std::string& field) {
            const bool vec = is_vector_field(field);
            const char* type = field == "id"     ? "NumberType=\"Int\" Precision=\"8\""
                               : field == "kind" ? "NumberType=\"UChar\" Precision=\"1\""
                                                 : "NumberType=\"Float\" Precision=\"8\"";
            const std::string dims =
                vec ? fmt::format("{} 3", w.particles) : fmt::format("{}", w.particles);
            return fmt::format("<DataItem Dimensions=\"{}\" {} Format=\"HDF\">{}:/{}</DataItem>",
                               dims, type, w.file, field);
        };
        x += fmt::format("      <Grid Name=\"{}\" GridType=\"Uniform\">\n",
                         fs::path(w.file).stem().string());
        x += fmt::format("        <Time Value=\"{}\"/>\n", w.time);
        x += fmt::format("        <Topology TopologyType=\"Polyvertex\" "
                         "NumberOfElements=\"{}\"/>\n",
                         w.particles);
        x += fmt::format("        <Geometry GeometryType=\"XYZ\">\n          {}\n        "
                         "</Geometry>\n",
                         item("position"));
        for (const auto& field : fields_) {
            if (field == "position")
                continue;
            x += fmt::format("        <Attribute Name=\"{}\" AttributeType=\"{}\" "
                             "Center=\"Node\">\n          {}\n        </Attribute>\n",
                             field, is_vector_field(field) ? "Vector" : "Scalar", item(field));
        }
        x += "      </Grid>\n";
    }
    x += "    </Grid>\n  </Domain>\n</Xdmf>\n";

    const fs::path tmp = fs::path(out_dir_) / ".snapshots.xmf.tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << x;
        out.flush();
        if (!out)
            throw std::runtime_error("cannot write " + tmp.string());
    }
    replace_file(tmp, xmf_path_);
}

template class SnapshotWriter<2>;
template class SnapshotWriter<3>;

} // namespace sluice
