// Checkpoint files (HDF5 C API): layout and guarantees in include/sluice/io/checkpoint.hpp.
#include "sluice/io/checkpoint.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/physics/timestep.hpp"
#include "sluice/version.hpp"

#include "h5_parallel.hpp"

#include <fmt/format.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <utility>

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

// The header travels from rank 0 to every rank as bytes (every rank must write the same
// attributes; wall_seconds, probe_bytes and the snapshot list are rank 0's).
template <class T>
void put(std::string& b, const T& v) {
    b.append(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void put_vector(std::string& b, const std::vector<T>& v) {
    put(b, static_cast<std::uint64_t>(v.size()));
    b.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}
template <class T>
T take(const std::string& b, std::size_t& pos) {
    T v{};
    std::memcpy(&v, b.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
}
template <class T>
std::vector<T> take_vector(const std::string& b, std::size_t& pos) {
    std::vector<T> v(take<std::uint64_t>(b, pos));
    std::memcpy(v.data(), b.data() + pos, v.size() * sizeof(T));
    pos += v.size() * sizeof(T);
    return v;
}

void put_solver(std::string& b, const SolverState& s) {
    put(b, s.time);
    put(b, s.step);
    put(b, s.dt);
    put(b, s.dt_prev);
    put(b, s.u_max);
    put(b, s.limit_acoustic);
    put(b, s.limit_viscous);
    put(b, s.limit_force);
    put(b, s.fluid_removed);
    put_vector(b, s.bodies);
}
SolverState take_solver(const std::string& b, std::size_t& pos) {
    SolverState s;
    s.time = take<double>(b, pos);
    s.step = take<std::int64_t>(b, pos);
    s.dt = take<double>(b, pos);
    s.dt_prev = take<double>(b, pos);
    s.u_max = take<double>(b, pos);
    s.limit_acoustic = take<double>(b, pos);
    s.limit_viscous = take<double>(b, pos);
    s.limit_force = take<double>(b, pos);
    s.fluid_removed = take<std::int64_t>(b, pos);
    s.bodies = take_vector<double>(b, pos);
    return s;
}

CheckpointHeader rank0_header(const h5::World& w, const CheckpointHeader& h) {
    if (!w.parallel())
        return h;
    std::string b;
    if (w.rank == 0) {
        put_vector(b, std::vector<char>(h.case_fingerprint.begin(), h.case_fingerprint.end()));
        put(b, h.ranks);
        put_solver(b, h.solver);
        const OutputState& o = h.output;
        put(b, o.out_next);
        put(b, o.last_output_time);
        put(b, o.wall_seconds);
        put_vector(b, o.probe_next);
        put_vector(b, o.probe_bytes);
        put_vector(b, o.snapshot_time);
        put_vector(b, o.snapshot_particles);
    }
    b = h5::broadcast(w, b);
    CheckpointHeader out;
    std::size_t pos = 0;
    const auto fp = take_vector<char>(b, pos);
    out.case_fingerprint.assign(fp.begin(), fp.end());
    out.ranks = take<int>(b, pos);
    out.solver = take_solver(b, pos);
    OutputState& o = out.output;
    o.out_next = take<double>(b, pos);
    o.last_output_time = take<double>(b, pos);
    o.wall_seconds = take<double>(b, pos);
    o.probe_next = take_vector<double>(b, pos);
    o.probe_bytes = take_vector<std::uint64_t>(b, pos);
    o.snapshot_time = take_vector<double>(b, pos);
    o.snapshot_particles = take_vector<std::uint64_t>(b, pos);
    return out;
}

// A small dataset every rank knows in full: rank 0 writes it.
template <class T>
void write_small(const h5::World& w, hid_t file, const char* name, const std::vector<T>& data,
                 hid_t mem_type, hid_t file_type) {
    const h5::Slice slice{0, w.rank == 0 ? data.size() : 0, data.size()};
    h5::write_rows(w, file, name, data.data(), slice, 1, mem_type, file_type, true);
}

// Particle columns are stored as 64-bit floats whatever sluice::Real is; HDF5 converts from and
// to the in-memory type (exact both ways for a float build).
hid_t native_real() {
    return single_precision ? H5T_NATIVE_FLOAT : H5T_NATIVE_DOUBLE;
}

template <int D>
std::vector<Real> flat(const std::vector<Vec<D>>& v, std::size_t n) {
    std::vector<Real> out(D * n);
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < D; ++a)
            out[D * i + static_cast<std::size_t>(a)] = v[i][a];
    return out;
}

template <int D>
void write_h5(const h5::World& w, const std::string& path, const CheckpointHeader& c,
              const Particles<D>& P, std::size_t n) {
    const Handle fapl = h5::file_access(w);
    const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
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
    write_attribute(f, "fluid_removed", s.fluid_removed, H5T_NATIVE_INT64, H5T_STD_I64LE);
    if (!s.bodies.empty()) {
        const hsize_t n_bodies = s.bodies.size();
        const Handle space(H5Screate_simple(1, &n_bodies, nullptr), H5Sclose,
                           "create the free bodies' dataspace");
        const Handle attr(
            H5Acreate2(f, "free_bodies", H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
            H5Aclose, "create attribute free_bodies");
        h5::check(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, s.bodies.data()),
                  "write attribute free_bodies");
    }
    real("out_next", c.output.out_next);
    real("last_output_time", c.output.last_output_time);
    real("wall_seconds", c.output.wall_seconds);

    if (P.size() < n)
        throw std::logic_error("checkpoint: fewer particles than the count to write");
    const h5::Slice slice = h5::slice_of_count(w, n);
    const auto rows = [&](const char* name, const void* data, std::size_t cols, hid_t mem_type,
                          hid_t file_type) {
        h5::write_rows(w, f, name, data, slice, cols, mem_type, file_type, true);
    };
    const std::vector<std::uint64_t> ids(P.id.begin(),
                                         P.id.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<std::uint8_t> kinds(n);
    for (std::size_t i = 0; i < n; ++i)
        kinds[i] = static_cast<std::uint8_t>(P.kind[i]);
    rows("id", ids.data(), 1, H5T_NATIVE_UINT64, H5T_STD_U64LE);
    rows("kind", kinds.data(), 1, H5T_NATIVE_UINT8, H5T_STD_U8LE);
    rows("x", flat<D>(P.x, n).data(), D, native_real(), H5T_IEEE_F64LE);
    rows("x_ref", flat<D>(P.x_ref, n).data(), D, native_real(), H5T_IEEE_F64LE);
    rows("v", flat<D>(P.v, n).data(), D, native_real(), H5T_IEEE_F64LE);
    rows("v_half", flat<D>(P.v_half, n).data(), D, native_real(), H5T_IEEE_F64LE);
    rows("a", flat<D>(P.a, n).data(), D, native_real(), H5T_IEEE_F64LE);
    rows("rho", P.rho.data(), 1, native_real(), H5T_IEEE_F64LE);
    rows("mass", P.mass.data(), 1, native_real(), H5T_IEEE_F64LE);
    rows("p", P.p.data(), 1, native_real(), H5T_IEEE_F64LE);
    const OutputState& o = c.output;
    write_small(w, f, "probe_next", o.probe_next, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    write_small(w, f, "probe_bytes", o.probe_bytes, H5T_NATIVE_UINT64, H5T_STD_U64LE);
    write_small(w, f, "snapshot_time", o.snapshot_time, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE);
    write_small(w, f, "snapshot_particles", o.snapshot_particles, H5T_NATIVE_UINT64, H5T_STD_U64LE);
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

// Opens a dataset of `cols` values per row and returns its row count; `rows` (if not npos) is
// the row count it must have.
std::pair<Handle, std::size_t> open_rows(hid_t file, const char* name, std::size_t cols,
                                         std::size_t rows) {
    if (H5Lexists(file, name, H5P_DEFAULT) <= 0)
        throw Refused(fmt::format("dataset '{}' is missing", name));
    Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, std::string("open ") + name);
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
    return {std::move(set), n};
}

// Rows `slice` of a dataset of slice.total rows of `cols` values.
template <class T>
std::vector<T> read_slice(hid_t file, const char* name, std::size_t cols, hid_t mem_type,
                          const h5::Slice& slice) {
    const auto [set, n] = open_rows(file, name, cols, slice.total);
    std::vector<T> data(slice.count * cols);
    if (!h5::read_rows(set.get(), data.data(), slice, cols, mem_type))
        throw Refused(fmt::format("dataset '{}' cannot be read (damaged: checksum or size)", name));
    return data;
}

// A whole dataset of `cols` values per row; `rows` (if not npos) is the row count it must have.
template <class T>
std::vector<T> read_column(hid_t file, const char* name, std::size_t cols, hid_t mem_type,
                           std::size_t rows = std::string::npos) {
    const std::size_t n = open_rows(file, name, cols, rows).second;
    return read_slice<T>(file, name, cols, mem_type, h5::Slice{0, n, n});
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
Checkpoint<D> read_h5(const h5::World& w, const std::string& path,
                      const std::string& case_fingerprint) {
    const h5::QuietErrors quiet;
    const Handle fapl = h5::file_access(w);
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
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
    // Absent in checkpoints written before domain.particle_exit: nothing was removed.
    s.fluid_removed = has_attribute(f, "fluid_removed")
                          ? read_attribute<std::int64_t>(f, "fluid_removed", H5T_NATIVE_INT64)
                          : 0;
    if (has_attribute(f, "free_bodies")) {
        const Handle attr(H5Aopen(f, "free_bodies", H5P_DEFAULT), H5Aclose, "open free_bodies");
        const Handle space(H5Aget_space(attr.get()), H5Sclose, "read a dataspace");
        const hssize_t n_bodies = H5Sget_simple_extent_npoints(space.get());
        if (n_bodies < 0)
            throw Refused("attribute 'free_bodies' cannot be read");
        s.bodies.resize(static_cast<std::size_t>(n_bodies));
        if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, s.bodies.data()) < 0)
            throw Refused("attribute 'free_bodies' cannot be read as numbers");
    }
    c.output.out_next = real("out_next");
    c.output.last_output_time = real("last_output_time");
    c.output.wall_seconds = real("wall_seconds");
    // The run goes on from this step with this dt: one that cannot move the clock (infinite,
    // zero, NaN, or lost in t's rounding) would make it spin or jump past its end.
    if (!std::isfinite(s.time) || !step_advances_clock(s.time, s.dt) || s.step < 0)
        throw Refused(
            fmt::format("implausible state: step {}, t = {}, dt = {}", s.step, s.time, s.dt));

    // This rank's even share of the rows.
    const h5::Slice slice = h5::even_slice(w, open_rows(f, "id", 1, std::string::npos).second);
    c.first = slice.offset;
    c.total_particles = slice.total;
    const auto ids = read_slice<std::uint64_t>(f, "id", 1, H5T_NATIVE_UINT64, slice);
    const std::size_t n = ids.size();
    const auto kinds = read_slice<std::uint8_t>(f, "kind", 1, H5T_NATIVE_UINT8, slice);
    Particles<D>& P = c.particles;
    P.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (kinds[i] > static_cast<std::uint8_t>(Kind::wall))
            throw Refused(fmt::format("particle {} has an unknown kind {}", ids[i], kinds[i]));
        P.id[i] = ids[i];
        P.kind[i] = static_cast<Kind>(kinds[i]);
    }
    const auto vec = [&](const char* name) {
        return vectors<D>(read_slice<Real>(f, name, D, native_real(), slice));
    };
    P.x = vec("x");
    P.x_ref = vec("x_ref");
    P.v = vec("v");
    P.v_half = vec("v_half");
    P.a = vec("a");
    P.rho = read_slice<Real>(f, "rho", 1, native_real(), slice);
    P.mass = read_slice<Real>(f, "mass", 1, native_real(), slice);
    P.p = read_slice<Real>(f, "p", 1, native_real(), slice);
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
void write_checkpoint(const std::string& path, const CheckpointHeader& header,
                      const Particles<D>& particles, std::size_t count) {
    const h5::World w = h5::world();
    const fs::path final_path(path);
    const fs::path tmp = temporary_path(final_path);
    const fs::path dir = tmp.parent_path();
    // Every rank writes its slice of the temporary file (closed collectively when write_h5
    // returns); rank 0 alone flushes it to disk and renames it.
    std::optional<std::string> error;
    try {
        write_h5<D>(w, tmp.string(), rank0_header(w, header), particles, count);
        if (w.rank == 0)
            sync_to_disk(tmp, false);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (const auto first = h5::first_error(w, error)) {
        std::error_code ec;
        if (w.rank == 0)
            fs::remove(tmp, ec);
        throw std::runtime_error(*first);
    }
    if (w.rank == 0) {
        std::error_code ec;
        fs::rename(tmp, final_path, ec); // atomic: the old checkpoint or the new, never neither
        if (ec) {
            error = fmt::format("cannot move {} to {}: {}", tmp.string(), final_path.string(),
                                ec.message());
            fs::remove(tmp, ec);
        } else {
            try {
                sync_to_disk(dir, true);
            } catch (const std::exception& e) {
                error = e.what();
            }
        }
    }
    if (const auto first = h5::first_error(w, error))
        throw std::runtime_error(*first);
}

template <int D>
Checkpoint<D> read_checkpoint(const std::string& path, const std::string& case_fingerprint) {
    const h5::World w = h5::world();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw CaseError(path, "", "refused as a checkpoint: no such file");
    // A damaged chunk may lie in one rank's share only: every rank refuses together.
    std::optional<std::string> error;
    Checkpoint<D> c;
    try {
        c = read_h5<D>(w, path, case_fingerprint);
    } catch (const std::runtime_error& e) { // Refused, or HDF5 failing
        error = e.what();
    }
    if (const auto first = h5::first_error(w, error))
        throw CaseError(path, "", std::string("refused as a checkpoint: ") + *first);
    return c;
}

template void write_checkpoint<2>(const std::string&, const CheckpointHeader&, const Particles<2>&,
                                  std::size_t);
template void write_checkpoint<3>(const std::string&, const CheckpointHeader&, const Particles<3>&,
                                  std::size_t);
template Checkpoint<2> read_checkpoint<2>(const std::string&, const std::string&);
template Checkpoint<3> read_checkpoint<3>(const std::string&, const std::string&);

} // namespace sluice
