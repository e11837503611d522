#pragma once
// Particle snapshots as HDF5 files plus one XDMF file that ParaView opens as a time series.
//
//   <out>/snapshots/snap_000000.h5, snap_000001.h5, ...   (numbered by snapshot, from 0)
//   <out>/snapshots.xmf                                    (references every snapshot so far)
//
// Each .h5 holds one dataset per field at the root: position, velocity, acceleration (N x 3
// float64; 2-D cases are padded with z = 0), density, pressure, mass (N float64), id (N
// uint64), kind (N uint8: 0 fluid, 1 wall), spacing (N float64: the distance from a fluid
// particle to its nearest fluid neighbour over dx; NaN for a wall particle and for a fluid
// particle with no fluid neighbour within the kernel support), and the root attributes time [s]
// (float64), step (int64) and dimension (int32). position is always written: it is the XDMF
// geometry. With the fluid's spacing given, every snapshot also gets the root attributes
// fluid_particles, fluid_crowded, fluid_isolated (uint64), crowded_below and
// closest_fluid_pair [m] (float64; infinity when there is no fluid pair).
// Files are written under a temporary name and renamed, so a snapshot or the .xmf is either
// complete or absent under its final name.
#include "sluice/core/neighbour_census.hpp"
#include "sluice/core/particles.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sluice {

// The fluid's spacing at a snapshot (computed by the solver over every rank): the census,
// every rank's counts together, and this rank's values of the "spacing" field, one per
// particle it writes.
struct SnapshotSpacing {
    NeighbourCensus census;
    Real crowded_below = 0;        // [m]
    std::span<const Real> over_dx; // nearest fluid neighbour / dx, NaN where there is none
};

template <int D>
class SnapshotWriter {
public:
    // Creates <out_dir>/snapshots/ and removes snapshots of an earlier run in the same folder
    // (snap_*.h5 and snapshots.xmf), so the series on disk is always this run's. Collective on
    // several MPI ranks (rank 0 touches the folder).
    // Throws std::invalid_argument for a field name outside the list above.
    SnapshotWriter(std::string out_dir, std::vector<std::string> fields);

    // One snapshot already on disk, as a restarted run continues the series.
    struct Earlier {
        double time;
        std::size_t particles;
    };
    // Continues the series of an interrupted run: snap_000000.h5 ... of `earlier` are kept
    // (they must exist), later ones (written after the checkpoint) are removed, and the .xmf is
    // rewritten to list exactly `earlier`.
    SnapshotWriter(std::string out_dir, std::vector<std::string> fields,
                   const std::vector<Earlier>& earlier);

    // Path of snapshot number `index`, relative to the results folder.
    [[nodiscard]] static std::string relative_path(std::size_t index);

    // Writes the next snapshot and rewrites the .xmf; returns the path of the .h5 written.
    // Throws std::runtime_error when a file cannot be written.
    std::string write(const Particles<D>& particles, double time, long step) {
        return write(particles, particles.size(), time, step);
    }
    // The same from this rank's first `count` particles. On several MPI ranks this is
    // collective (every rank constructs the writer and calls it with its slice, ranks in curve
    // order): each writes its slice of the file through MPI-IO at the offset of the ranks
    // before it, and rank 0 alone touches the folder (removals, renames, the .xmf). The file
    // is the same for any rank layout, byte for byte. Every rank throws if any rank failed.
    // `spacing` is required when the fields include "spacing".
    std::string write(const Particles<D>& particles, std::size_t count, double time, long step,
                      const SnapshotSpacing* spacing = nullptr);
    // Whether the fields include "spacing".
    [[nodiscard]] bool writes_spacing() const;

    [[nodiscard]] std::size_t count() const { return written_.size(); }
    [[nodiscard]] const std::string& xmf_path() const { return xmf_path_; }
    // The snapshots written so far (time and particle count), for a checkpoint.
    [[nodiscard]] std::vector<Earlier> written() const;

private:
    struct Written {
        std::string file; // relative to out_dir, e.g. snapshots/snap_000003.h5
        double time;
        std::size_t particles;
    };

    // Returns the particle count of the file (every rank's together).
    std::uint64_t write_h5(const std::string& path, const Particles<D>& particles,
                           std::size_t count, double time, long step,
                           const SnapshotSpacing* spacing) const;
    void write_xmf() const;
    void init_fields(std::vector<std::string> fields);
    // Removes snapshot files numbered `keep` and above, and temporary ones.
    void remove_from(std::size_t keep) const;

    std::string out_dir_, xmf_path_;
    std::vector<std::string> fields_; // position first, no duplicates
    std::vector<Written> written_;
};

extern template class SnapshotWriter<2>;
extern template class SnapshotWriter<3>;

} // namespace sluice
