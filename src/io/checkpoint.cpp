// Checkpoint files (HDF5 C API): layout and guarantees in include/sluice/io/checkpoint.hpp.
#include "sluice/io/checkpoint.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/version.hpp"

#include "hdf5_util.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace sluice {
namespace fs = std::filesystem;
using h5::check;
using h5::Handle;
using h5::write_attribute;

namespace {

constexpr const char* kFormat = "sluice-checkpoint";

// A reason to refuse a file; turned into a CaseError naming the file.
struct Refused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// ----- writing -----------------------------------------------------------------------------

void write_string_attribute(hid_t obj, const char* name, const std::string& value) {
    const Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
    check(H5Tset_size(type.get(), std::max<std::size_t>(1, value.size())), "size a string type");
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
    const Handle attr(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      H5Aclose, std::string("create attribute ") + name);
    std::string padded = value.empty() ? std::string(1, '\0') : value;
    check(H5Awrite(attr.get(), type.get(), padded.data()), std::string("write attribute ") + name);
}

// n rows of `cols` values; chunked with a Fletcher-32 checksum when not empty.
template <class T>
void write_column(hid_t file, const char* name, const std::vector<T>& data, std::size_t cols,
                  hid_t mem_type, hid_t file_type) {
    const std::size_t n = cols > 0 ? data.size() / cols : 0;
    const std::array<hsize_t, 2> dims{n, cols};
    const int rank = cols == 1 ? 1 : 2;
    const Handle space(H5Screate_simple(rank, dims.data(), nullptr), H5Sclose,
                       std::string("create the dataspace of ") + name);
    const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create dataset properties");
    if (n > 0) {
        const std::array<hsize_t, 2> chunk{std::min<hsize_t>(n, 65536), cols};
        check(H5Pset_chunk(dcpl.get(), rank, chunk.data()), "set a chunk size");
        check(H5Pset_fletcher32(dcpl.get()), "switch on checksums");
    }
    const Handle set(
        H5Dcreate2(file, name, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
        H5Dclose, std::string("create dataset ") + name);
    if (n > 0)
        check(H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
              std::string("write dataset ") + name);
}

// Particle columns are stored as 64-bit floats whatever sluice::Real is; HDF5 converts from and
// to the in-memory type (exact both ways for a float build).
hid_t native_real() {
    return single_precision ? H5T_NATIVE_FLOAT : H5T_NATIVE_DOUBLE;
}

template <int D>
std::vector<Real> flat(const std::vector<Vec<D>>& v) {
    std::vector<Real> out(D * v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        for (int a = 0; a < D; ++a)
            out[D * i + static_cast<std::size_t>(a)] = v[i][a];
    return out;
}

template <int D>
void write_h5(const std::string& path, const Checkpoint<D>& c) {
    const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                      "create " + path);
    const hid_t f = file.get();
    write_string_attribute(f, "format", kFormat);
    write_attribute(f, "format_version", static_cast<std::int32_t>(checkpoint_format_version),
                    H5T_NATIVE_INT32, H5T_STD_I32LE);
    write_string_attribute(f, "case_fingerprint", c.case_fingerprint);
    write_attribute(f, "dimension", static_cast<std::int32_t>(D), H5T_NATIVE_INT32, H5T_STD_I32LE);
    write_attribute(f, "ranks", static_cast<std::int32_t>(c.ranks), H5T_NATIVE_INT32,
                    H5T_STD_I32LE);
    write_string_attribute(f, "sluice_version",
                           fmt::format("{} ({})", sluice::version, sluice::git_revision));
    const auto real = [&](const char* name, double v) {
        write_attribute(f, name, v, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    };
    const SolverState& s = c.solver;
    real("time", s.time);
    write_attribute(f, "step", s.step, H5T_NATIVE_INT64, H5T_STD_I64LE);
    real("dt", s.dt);
    real("dt_prev", s.dt_prev);
    real("u_max", s.u_max);
    real("limit_acoustic", s.limit_acoustic);
    real("limit_viscous", s.limit_viscous);
    real("limit_force", s.limit_force);
    real("out_next", c.output.out_next);
    real("last_output_time", c.output.last_output_time);
    real("wall_seconds", c.output.wall_seconds);

    const Particles<D>& P = c.particles;
    std::vector<std::uint64_t> ids(P.id.begin(), P.id.end());
    std::vector<std::uint8_t> kinds(P.size());
    for (std::size_t i = 0; i < P.size(); ++i)
        kinds[i] = static_cast<std::uint8_t>(P.kind[i]);
    write_column(f, "id", ids, 1, H5T_NATIVE_UINT64, H5T_STD_U64LE);
    write_column(f, "kind", kinds, 1, H5T_NATIVE_UINT8, H5T_STD_U8LE);
    write_column(f, "x", flat<D>(P.x), D, native_real(), H5T_IEEE_F64LE);
    write_column(f, "x_ref", flat<D>(P.x_ref), D, native_real(), H5T_IEEE_F64LE);
    write_column(f, "v", flat<D>(P.v), D, native_real(), H5T_IEEE_F64LE);
    write_column(f, "v_half", flat<D>(P.v_half), D, native_real(), H5T_IEEE_F64LE);
    write_column(f, "a", flat<D>(P.a), D, native_real(), H5T_IEEE_F64LE);
    write_column(f, "rho", P.rho, 1, native_real(), H5T_IEEE_F64LE);
    write_column(f, "mass", P.mass, 1, native_real(), H5T_IEEE_F64LE);
    write_column(f, "p", P.p, 1, native_real(), H5T_IEEE_F64LE);
    const OutputState& o = c.output;
    write_column(f, "probe_next", o.probe_next, 1, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    write_column(f, "probe_bytes", o.probe_bytes, 1, H5T_NATIVE_UINT64, H5T_STD_U64LE);
    write_column(f, "snapshot_time", o.snapshot_time, 1, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    write_column(f, "snapshot_particles", o.snapshot_particles, 1, H5T_NATIVE_UINT64,
                 H5T_STD_U64LE);
    check(H5Fflush(f, H5F_SCOPE_LOCAL), "flush " + path);
}

// Forces the file (or folder) at `path` to disk, so a rename after it never exposes a file
// whose contents are still only in memory (a crash of the machine, not only of the process).
void sync_to_disk(const fs::path& path, bool directory) {
    const int fd = ::open(path.c_str(), directory ? O_RDONLY | O_DIRECTORY : O_RDONLY);
    if (fd < 0)
        throw std::runtime_error(
            fmt::format("cannot open {} to flush it: {}", path.string(), std::strerror(errno)));
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0 && !directory)
        throw std::runtime_error(
            fmt::format("cannot flush {} to disk: {}", path.string(), std::strerror(err)));
}

// ----- reading -----------------------------------------------------------------------------

bool has_attribute(hid_t obj, const char* name) {
    return H5Aexists(obj, name) > 0;
}

std::string read_string_attribute(hid_t obj, const char* name) {
    if (!has_attribute(obj, name))
        throw Refused(fmt::format("attribute '{}' is missing", name));
    const Handle attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, std::string("open ") + name);
    const Handle type(H5Aget_type(attr.get()), H5Tclose, "read a type");
    if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) != 0)
        throw Refused(fmt::format("attribute '{}' is not a fixed-length string", name));
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0 || size > 4096)
        throw Refused(fmt::format("attribute '{}' has an implausible length", name));
    std::string value(size, '\0');
    if (H5Aread(attr.get(), type.get(), value.data()) < 0)
        throw Refused(fmt::format("attribute '{}' cannot be read", name));
    value.resize(std::strlen(value.c_str()));
    return value;
}

template <class T>
T read_attribute(hid_t obj, const char* name, hid_t mem_type) {
    if (!has_attribute(obj, name))
        throw Refused(fmt::format("attribute '{}' is missing", name));
    const Handle attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, std::string("open ") + name);
    const Handle space(H5Aget_space(attr.get()), H5Sclose, "read a dataspace");
    if (H5Sget_simple_extent_type(space.get()) != H5S_SCALAR)
        throw Refused(fmt::format("attribute '{}' is not a single value", name));
    T v{};
    if (H5Aread(attr.get(), mem_type, &v) < 0)
        throw Refused(fmt::format("attribute '{}' cannot be read as a number", name));
    return v;
}

// A dataset of `cols` values per row; `rows` (if not npos) is the row count it must have.
template <class T>
std::vector<T> read_column(hid_t file, const char* name, std::size_t cols, hid_t mem_type,
                           std::size_t rows = std::string::npos) {
    if (H5Lexists(file, name, H5P_DEFAULT) <= 0)
        throw Refused(fmt::format("dataset '{}' is missing", name));
    const Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, std::string("open ") + name);
    const Handle space(H5Dget_space(set.get()), H5Sclose, "read a dataspace");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    std::array<hsize_t, 2> dims{0, 0};
    if (rank != (cols == 1 ? 1 : 2) ||
        H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0 ||
        (rank == 2 && dims[1] != cols))
        throw Refused(fmt::format("dataset '{}' does not have {} value(s) per row", name, cols));
    const auto n = static_cast<std::size_t>(dims[0]);
    if (rows != std::string::npos && n != rows)
        throw Refused(fmt::format("dataset '{}' has {} rows, expected {}", name, n, rows));
    std::vector<T> data(n * cols);
    if (n > 0 && H5Dread(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
        throw Refused(fmt::format("dataset '{}' cannot be read (damaged: checksum or size)", name));
    return data;
}

template <int D>
std::vector<Vec<D>> vectors(const std::vector<Real>& flat_values) {
    std::vector<Vec<D>> out(flat_values.size() / D);
    for (std::size_t i = 0; i < out.size(); ++i)
        for (int a = 0; a < D; ++a)
            out[i][a] = flat_values[D * i + static_cast<std::size_t>(a)];
    return out;
}

template <int D>
Checkpoint<D> read_h5(const std::string& path, const std::string& case_fingerprint) {
    const h5::QuietErrors quiet;
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0)
        throw Refused("not a readable HDF5 file (truncated, damaged or of another format)");
    const Handle file(id, H5Fclose, "open " + path);
    const hid_t f = file.get();

    if (!has_attribute(f, "format") || read_string_attribute(f, "format") != kFormat)
        throw Refused("not a sluice checkpoint (no format = \"sluice-checkpoint\")");
    const auto version = read_attribute<std::int32_t>(f, "format_version", H5T_NATIVE_INT32);
    if (version != checkpoint_format_version)
        throw Refused(fmt::format("checkpoint format version {}, but this sluice reads version {}",
                                  version, checkpoint_format_version));
    const auto dim = read_attribute<std::int32_t>(f, "dimension", H5T_NATIVE_INT32);
    if (dim != D)
        throw Refused(fmt::format("written by a {}-D case, this case is {}-D", dim, D));
    Checkpoint<D> c;
    c.case_fingerprint = read_string_attribute(f, "case_fingerprint");
    if (c.case_fingerprint != case_fingerprint)
        throw Refused(fmt::format(
            "written by another case (case fingerprint {} here {}): a checkpoint continues "
            "only the case it was written by; time.end_time and the [checkpoint], [limits] and "
            "[runtime] tables may change, nothing else",
            c.case_fingerprint.substr(0, 12), case_fingerprint.substr(0, 12)));
    c.ranks = read_attribute<std::int32_t>(f, "ranks", H5T_NATIVE_INT32);
    const auto real = [&](const char* name) {
        return read_attribute<double>(f, name, H5T_NATIVE_DOUBLE);
    };
    SolverState& s = c.solver;
    s.time = real("time");
    s.step = read_attribute<std::int64_t>(f, "step", H5T_NATIVE_INT64);
    s.dt = real("dt");
    s.dt_prev = real("dt_prev");
    s.u_max = real("u_max");
    s.limit_acoustic = real("limit_acoustic");
    s.limit_viscous = real("limit_viscous");
    s.limit_force = real("limit_force");
    c.output.out_next = real("out_next");
    c.output.last_output_time = real("last_output_time");
    c.output.wall_seconds = real("wall_seconds");
    if (!(s.dt > 0) || !std::isfinite(s.time) || s.step < 0)
        throw Refused(
            fmt::format("implausible state: step {}, t = {}, dt = {}", s.step, s.time, s.dt));

    const auto ids = read_column<std::uint64_t>(f, "id", 1, H5T_NATIVE_UINT64);
    const std::size_t n = ids.size();
    const auto kinds = read_column<std::uint8_t>(f, "kind", 1, H5T_NATIVE_UINT8, n);
    Particles<D>& P = c.particles;
    P.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (kinds[i] > static_cast<std::uint8_t>(Kind::wall))
            throw Refused(fmt::format("particle {} has an unknown kind {}", ids[i], kinds[i]));
        P.id[i] = ids[i];
        P.kind[i] = static_cast<Kind>(kinds[i]);
    }
    const auto vec = [&](const char* name) {
        return vectors<D>(read_column<Real>(f, name, D, native_real(), n));
    };
    P.x = vec("x");
    P.x_ref = vec("x_ref");
    P.v = vec("v");
    P.v_half = vec("v_half");
    P.a = vec("a");
    P.rho = read_column<Real>(f, "rho", 1, native_real(), n);
    P.mass = read_column<Real>(f, "mass", 1, native_real(), n);
    P.p = read_column<Real>(f, "p", 1, native_real(), n);
    OutputState& o = c.output;
    o.probe_next = read_column<double>(f, "probe_next", 1, H5T_NATIVE_DOUBLE);
    o.probe_bytes =
        read_column<std::uint64_t>(f, "probe_bytes", 1, H5T_NATIVE_UINT64, o.probe_next.size());
    o.snapshot_time = read_column<double>(f, "snapshot_time", 1, H5T_NATIVE_DOUBLE);
    o.snapshot_particles = read_column<std::uint64_t>(f, "snapshot_particles", 1, H5T_NATIVE_UINT64,
                                                      o.snapshot_time.size());
    return c;
}

} // namespace

std::string checkpoint_path(const std::string& results_dir) {
    return (fs::path(results_dir) / "checkpoint.h5").string();
}

namespace {

fs::path temporary_path(const fs::path& final_path) {
    const fs::path dir =
        final_path.parent_path().empty() ? fs::path(".") : final_path.parent_path();
    return dir / fmt::format(".{}.tmp", final_path.filename().string());
}

} // namespace

void discard_partial_checkpoint(const std::string& path) {
    std::error_code ec;
    fs::remove(temporary_path(path), ec);
}

template <int D>
void write_checkpoint(const std::string& path, const Checkpoint<D>& c) {
    const fs::path final_path(path);
    const fs::path tmp = temporary_path(final_path);
    const fs::path dir = tmp.parent_path();
    try {
        write_h5<D>(tmp.string(), c); // closed when it returns
        sync_to_disk(tmp, false);
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
    std::error_code ec;
    fs::rename(tmp, final_path, ec); // atomic: the old checkpoint or the new, never neither
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error(fmt::format("cannot move {} to {}: {}", tmp.string(),
                                             final_path.string(), ec.message()));
    }
    sync_to_disk(dir, true);
}

template <int D>
Checkpoint<D> read_checkpoint(const std::string& path, const std::string& case_fingerprint) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw CaseError(path, "", "refused as a checkpoint: no such file");
    try {
        return read_h5<D>(path, case_fingerprint);
    } catch (const Refused& e) {
        throw CaseError(path, "", std::string("refused as a checkpoint: ") + e.what());
    } catch (const std::runtime_error& e) {
        throw CaseError(path, "", std::string("refused as a checkpoint: ") + e.what());
    }
}

template void write_checkpoint<2>(const std::string&, const Checkpoint<2>&);
template void write_checkpoint<3>(const std::string&, const Checkpoint<3>&);
template Checkpoint<2> read_checkpoint<2>(const std::string&, const std::string&);
template Checkpoint<3> read_checkpoint<3>(const std::string&, const std::string&);

} // namespace sluice
