// HDF5 snapshots (C API) and the XDMF index ParaView reads them through.
#include "sluice/io/snapshot_writer.hpp"

#include <fmt/format.h>

#include "hdf5_util.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace sluice {
namespace fs = std::filesystem;
using h5::check;
using h5::Handle;
using h5::write_attribute;

namespace {

const std::vector<std::string> kKnownFields = {"position",     "velocity", "density", "pressure",
                                               "acceleration", "mass",     "id",      "kind"};

bool is_vector_field(const std::string& f) {
    return f == "position" || f == "velocity" || f == "acceleration";
}

// Writes `data` (row-major, cols values per particle) as dataset `name` of
// shape N or N x 3.
template <class T>
void write_dataset(hid_t file, const std::string& name, const std::vector<T>& data, std::size_t n,
                   std::size_t cols, hid_t mem_type, hid_t file_type) {
    const std::array<hsize_t, 2> dims{n, cols};
    const Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims.data(), nullptr), H5Sclose,
                       "create the dataspace of " + name);
    // No modification times in the object headers: the same state gives the same file, byte
    // for byte (runs on different rank/thread counts are compared with cmp).
    const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create dataset properties");
    check(H5Pset_obj_track_times(dcpl.get(), false), "switch off time tracking");
    const Handle set(H5Dcreate2(file, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(),
                                H5P_DEFAULT),
                     H5Dclose, "create dataset " + name);
    if (n > 0)
        check(H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
              "write dataset " + name);
}

// N x 3 copy of a D-vector field; 2-D gets z = 0 so every viewer sees 3-D
// points.
template <int D>
std::vector<double> padded(const std::vector<Vec<D>>& v) {
    std::vector<double> out(3 * v.size(), 0.0);
    for (std::size_t i = 0; i < v.size(); ++i)
        for (int a = 0; a < D; ++a)
            out[3 * i + static_cast<std::size_t>(a)] = v[i][a];
    return out;
}

template <class T>
void require_size(const std::vector<T>& v, std::size_t n, const std::string& field) {
    if (v.size() != n)
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
    // An earlier run's files would otherwise sit beside this run's, or be listed
    // by the .xmf.
    remove_from(0);
    fs::remove(xmf_path_);
}

template <int D>
SnapshotWriter<D>::SnapshotWriter(std::string out_dir, std::vector<std::string> fields,
                                  const std::vector<Earlier>& earlier)
    : out_dir_(std::move(out_dir)), xmf_path_((fs::path(out_dir_) / "snapshots.xmf").string()) {
    init_fields(std::move(fields));
    for (std::size_t k = 0; k < earlier.size(); ++k) {
        const std::string rel = relative_path(k);
        if (!fs::exists(fs::path(out_dir_) / rel))
            throw std::runtime_error(
                fmt::format("cannot continue the snapshot series: {} is missing",
                            (fs::path(out_dir_) / rel).string()));
        written_.push_back({rel, earlier[k].time, earlier[k].particles});
    }
    remove_from(earlier.size());
    if (written_.empty())
        fs::remove(xmf_path_);
    else
        write_xmf();
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
    fs::create_directories(fs::path(out_dir_) / "snapshots");
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
void SnapshotWriter<D>::write_h5(const std::string& path, const Particles<D>& ps, double time,
                                 long step) const {
    const std::size_t n = ps.size();
    const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                      "create " + path);
    const hid_t f = file.get();
    const auto vec3 = [&](const std::string& name, const std::vector<Vec<D>>& v) {
        require_size(v, n, name);
        write_dataset(f, name, padded<D>(v), n, 3, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    };
    const auto scalar = [&](const std::string& name, const std::vector<Real>& v) {
        require_size(v, n, name);
        write_dataset(f, name, std::vector<double>(v.begin(), v.end()), n, 1, H5T_NATIVE_DOUBLE,
                      H5T_IEEE_F64LE);
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
            std::vector<std::uint64_t> ids(ps.id.begin(), ps.id.end());
            write_dataset(f, field, ids, n, 1, H5T_NATIVE_UINT64, H5T_STD_U64LE);
        } else if (field == "kind") {
            require_size(ps.kind, n, field);
            std::vector<std::uint8_t> kinds(n);
            for (std::size_t i = 0; i < n; ++i)
                kinds[i] = static_cast<std::uint8_t>(ps.kind[i]);
            write_dataset(f, field, kinds, n, 1, H5T_NATIVE_UINT8, H5T_STD_U8LE);
        }
    }
    write_attribute(f, "time", time, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    write_attribute(f, "step", static_cast<std::int64_t>(step), H5T_NATIVE_INT64, H5T_STD_I64LE);
    write_attribute(f, "dimension", static_cast<std::int32_t>(D), H5T_NATIVE_INT32, H5T_STD_I32LE);
    check(H5Fflush(f, H5F_SCOPE_LOCAL), "flush " + path);
}

template <int D>
std::string SnapshotWriter<D>::write(const Particles<D>& ps, double time, long step) {
    const std::string rel = relative_path(written_.size());
    const fs::path final_path = fs::path(out_dir_) / rel;
    const fs::path tmp =
        fs::path(out_dir_) / fmt::format("snapshots/.snap_{:06d}.h5.tmp", written_.size());
    try {
        write_h5(tmp.string(), ps, time, step);
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
    replace_file(tmp, final_path);
    written_.push_back({rel, time, ps.size()});
    write_xmf();
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
