#pragma once
// Particle files written and read by every rank at once (private to src/io): MPI-IO under HDF5
// when the run has several ranks, HDF5's default (sec2) driver on one. Each rank writes or reads
// one contiguous slice of rows; the slices in rank order make up the dataset, so a file holds
// the same datasets for any rank layout.
//
// Byte-identical files for every layout, serial or MPI-IO: parallel HDF5 allocates a dataset's
// space when it is created (H5D_ALLOC_TIME_EARLY) and writes no fill values, so both drivers
// are told to do the same (sec2 would otherwise allocate late), and no object carries a
// modification time.
#include "hdf5_util.hpp"

#include <mpi.h>

#include <cstdint>
#include <optional>
#include <string>

namespace sluice::h5 {

// MPI_COMM_WORLD, or one rank when MPI is not running (unit tests, `sluice check`).
struct World {
    MPI_Comm comm = MPI_COMM_NULL;
    int rank = 0;
    int size = 1;
    [[nodiscard]] bool parallel() const { return size > 1; }
};
World world();

// This rank's rows of a dataset: [offset, offset + count) of total.
struct Slice {
    std::uint64_t offset = 0;
    std::uint64_t count = 0;
    std::uint64_t total = 0;
};
// Collective: slices of `count` rows per rank, placed in rank order (exclusive scan).
Slice slice_of_count(const World& w, std::uint64_t count);
// Rows [total * r / size, total * (r + 1) / size) for rank r: an even split for reading.
Slice even_slice(const World& w, std::uint64_t total);

// File access: MPI-IO on several ranks, the default driver on one.
Handle file_access(const World& w);
// Transfers: collective on several ranks.
Handle collective_transfer(const World& w);

// Creates dataset `name` of slice.total rows of `cols` values (rank 1 when cols == 1) and
// writes this rank's rows `data` (slice.count * cols values, row-major) into it. Collective.
// `checksummed`: chunks of at most 65536 rows with HDF5's Fletcher-32 checksum.
void write_rows(const World& w, hid_t file, const std::string& name, const void* data,
                const Slice& slice, std::size_t cols, hid_t mem_type, hid_t file_type,
                bool checksummed);

// Reads this rank's rows of a dataset whose dataspace has been checked by the caller.
// Independent (no collective): a rank whose read fails does not hold the others up.
// Returns false when HDF5 cannot read them (damaged: checksum or size).
bool read_rows(hid_t set, void* data, const Slice& slice, std::size_t cols, hid_t mem_type);

// Agreement after a step that may fail on some ranks only: every rank learns the error of the
// lowest-numbered rank that failed (its message), or nothing. Collective.
std::optional<std::string> first_error(const World& w, const std::optional<std::string>& mine);

// Rank 0's string on every rank. Collective.
std::string broadcast(const World& w, const std::string& s);

} // namespace sluice::h5
