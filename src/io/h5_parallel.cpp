// Slices of particle datasets written and read by every rank (h5_parallel.hpp).
#include "h5_parallel.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace sluice::h5 {

World world() {
    World w;
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (initialised == 0 || finalised != 0)
        return w;
    w.comm = MPI_COMM_WORLD;
    MPI_Comm_rank(w.comm, &w.rank);
    MPI_Comm_size(w.comm, &w.size);
    return w;
}

Slice slice_of_count(const World& w, std::uint64_t count) {
    Slice s{0, count, count};
    if (!w.parallel())
        return s;
    MPI_Exscan(&count, &s.offset, 1, MPI_UINT64_T, MPI_SUM, w.comm);
    if (w.rank == 0)
        s.offset = 0; // MPI_Exscan leaves rank 0's result undefined
    MPI_Allreduce(&count, &s.total, 1, MPI_UINT64_T, MPI_SUM, w.comm);
    return s;
}

Slice even_slice(const World& w, std::uint64_t total) {
    const auto r = static_cast<std::uint64_t>(w.rank), n = static_cast<std::uint64_t>(w.size);
    // total * r / n without overflow for any particle count that fits in memory.
    const auto at = [&](std::uint64_t k) { return total / n * k + total % n * k / n; };
    return Slice{at(r), at(r + 1) - at(r), total};
}

Handle file_access(const World& w) {
    Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create file access properties");
    if (w.parallel())
        check(H5Pset_fapl_mpio(fapl.get(), w.comm, MPI_INFO_NULL), "select MPI-IO");
    return fapl;
}

Handle collective_transfer(const World& w) {
    Handle dxpl(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "create transfer properties");
    if (w.parallel())
        check(H5Pset_dxpl_mpio(dxpl.get(), H5FD_MPIO_COLLECTIVE), "select collective transfers");
    return dxpl;
}

namespace {

// This rank's rows in the file's dataspace and the matching memory dataspace (a selection of
// nothing for an empty slice: the rank still takes part in the collective write).
struct Selection {
    Handle file_space, mem_space;
};

Selection select(hid_t set, const Slice& s, std::size_t cols) {
    const int rank = cols == 1 ? 1 : 2;
    Handle file_space(H5Dget_space(set), H5Sclose, "read a dataspace");
    const std::array<hsize_t, 2> start{s.offset, 0}, count{s.count, cols};
    const std::array<hsize_t, 2> mem_dims{std::max<hsize_t>(s.count, 1), cols};
    Handle mem_space(H5Screate_simple(rank, mem_dims.data(), nullptr), H5Sclose,
                     "create a memory dataspace");
    if (s.count == 0) {
        check(H5Sselect_none(file_space.get()), "select no rows");
        check(H5Sselect_none(mem_space.get()), "select no rows");
    } else {
        check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                  count.data(), nullptr),
              "select this rank's rows");
    }
    return Selection{std::move(file_space), std::move(mem_space)};
}

} // namespace

void write_rows(const World& w, hid_t file, const std::string& name, const void* data,
                const Slice& slice, std::size_t cols, hid_t mem_type, hid_t file_type,
                bool checksummed) {
    const int rank = cols == 1 ? 1 : 2;
    const std::array<hsize_t, 2> dims{slice.total, cols};
    const Handle space(H5Screate_simple(rank, dims.data(), nullptr), H5Sclose,
                       "create the dataspace of " + name);
    const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create dataset properties");
    // No modification times in the object headers: the same state gives the same file, byte
    // for byte (runs on different rank/thread counts are compared with cmp).
    check(H5Pset_obj_track_times(dcpl.get(), false), "switch off time tracking");
    check(H5Pset_alloc_time(dcpl.get(), H5D_ALLOC_TIME_EARLY), "allocate at creation");
    check(H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER), "switch off fill values");
    if (checksummed && slice.total > 0) {
        const std::array<hsize_t, 2> chunk{std::min<hsize_t>(slice.total, 65536), cols};
        check(H5Pset_chunk(dcpl.get(), rank, chunk.data()), "set a chunk size");
        check(H5Pset_fletcher32(dcpl.get()), "switch on checksums");
    }
    const Handle set(H5Dcreate2(file, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(),
                                H5P_DEFAULT),
                     H5Dclose, "create dataset " + name);
    if (slice.total == 0)
        return; // every rank knows: nothing to write
    const Selection sel = select(set.get(), slice, cols);
    const Handle dxpl = collective_transfer(w);
    const unsigned char none = 0; // a valid address for a rank with no rows
    check(H5Dwrite(set.get(), mem_type, sel.mem_space.get(), sel.file_space.get(), dxpl.get(),
                   slice.count > 0 ? data : &none),
          "write dataset " + name);
}

bool read_rows(hid_t set, void* data, const Slice& slice, std::size_t cols, hid_t mem_type) {
    if (slice.count == 0)
        return true;
    const Selection sel = select(set, slice, cols);
    return H5Dread(set, mem_type, sel.mem_space.get(), sel.file_space.get(), H5P_DEFAULT, data) >=
           0;
}

std::optional<std::string> first_error(const World& w, const std::optional<std::string>& mine) {
    if (!w.parallel())
        return mine;
    // The lowest failing rank: the largest of (size - rank) among failing ranks.
    const int claim = mine ? w.size - w.rank : 0;
    int best = 0;
    MPI_Allreduce(&claim, &best, 1, MPI_INT, MPI_MAX, w.comm);
    if (best == 0)
        return std::nullopt;
    const int root = w.size - best;
    std::string message = w.rank == root ? *mine : std::string();
    auto length = static_cast<unsigned long long>(message.size());
    MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, root, w.comm);
    message.resize(static_cast<std::size_t>(length));
    MPI_Bcast(message.data(), static_cast<int>(length), MPI_CHAR, root, w.comm);
    if (root != w.rank)
        message += " (on rank " + std::to_string(root) + ")";
    return message;
}

std::string broadcast(const World& w, const std::string& s) {
    if (!w.parallel())
        return s;
    std::string out = s;
    auto length = static_cast<unsigned long long>(out.size());
    MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, 0, w.comm);
    out.resize(static_cast<std::size_t>(length));
    MPI_Bcast(out.data(), static_cast<int>(length), MPI_CHAR, 0, w.comm);
    return out;
}

} // namespace sluice::h5
