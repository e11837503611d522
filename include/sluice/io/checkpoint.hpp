#pragma once
// Checkpoints: everything a run needs to go on bitwise as if it had never stopped, in one HDF5
// file <results>/checkpoint.h5 (layout below; docs/CASE_REFERENCE.md describes its use).
//
//   root attributes  format = "sluice-checkpoint" (string), format_version (int32),
//                    case_fingerprint (string, CaseConfig::fingerprint), dimension (int32),
//                    ranks (int32, information only), sluice_version (string),
//                    time, dt, dt_prev, u_max, limit_acoustic, limit_viscous, limit_force,
//                    out_next, last_output_time, wall_seconds (float64), step (int64)
//   datasets         particles: id (N uint64), kind (N uint8), x, x_ref, v, v_half, a
//                    (N x D float64; x_ref: positions at the last neighbour-list rebuild),
//                    rho, mass, p (N float64), in curve order;
//                    probe_next (K float64), probe_bytes (K uint64);
//                    snapshot_time (S float64), snapshot_particles (S uint64)
//
// Particle datasets are chunked with HDF5's Fletcher-32 checksum, so a damaged file is refused
// rather than read. The file is written under a temporary name, flushed to disk (fsync) and
// renamed over the previous checkpoint: at every moment the latest complete checkpoint is on
// disk under the final name.
//
// On several MPI ranks the particles are never gathered: every rank writes its slice of the
// particle datasets through MPI-IO (collectively, at the offset of the ranks before it in
// curve order) and reads back an even share of them; the file is the same for any rank
// layout, except for the attributes ranks and wall_seconds.
#include "sluice/core/particles.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sluice {

// Bumped whenever the layout above changes; other versions are refused.
inline constexpr int checkpoint_format_version = 3; // 2: x_ref added; 3: wall_seconds

// The solver's state between two steps, besides the particles.
struct SolverState {
    double time = 0;
    std::int64_t step = 0;
    double dt = 0;      // the next step's time step
    double dt_prev = 0; // the last step's: the leap-frog kick uses (dt_prev + dt) / 2
    double u_max = 0;   // largest fluid speed of the last step (scale of particle shifting)
    double limit_acoustic = 0, limit_viscous = 0, limit_force = 0; // last step's limits
    std::int64_t fluid_removed = 0; // fluid particles that left the domain and were removed
    // The free bodies' states and last loads (solver/wall_motion.hpp's body_state); empty
    // without free bodies.
    std::vector<double> bodies;
};

// The driver's output schedule and what it has written so far.
struct OutputState {
    double out_next = 0;                           // time of the next snapshot
    double last_output_time = -1;                  // time of the last snapshot / output
    std::vector<double> probe_next;                // per probe: time of the next sample
    std::vector<std::uint64_t> probe_bytes;        // per probe: length of its CSV at the checkpoint
    std::vector<double> snapshot_time;             // per snapshot written: its time ...
    std::vector<std::uint64_t> snapshot_particles; // ... and particle count
    // Wall time of the time loop up to the checkpoint, over every segment of the run.
    double wall_seconds = 0;
};

// Everything but the particles.
struct CheckpointHeader {
    std::string case_fingerprint;
    int ranks = 1; // the run that wrote it had this many ranks (any number may continue it)
    SolverState solver;
    OutputState output;
};

template <int D>
struct Checkpoint : CheckpointHeader {
    // This rank's share of the particles (fluid and wall) in curve order: rows
    // [first, first + particles.size()) of the file's total_particles. On one rank, all of them.
    Particles<D> particles;
    std::uint64_t first = 0;
    std::uint64_t total_particles = 0;
};

// The checkpoint file of a results folder.
std::string checkpoint_path(const std::string& results_dir);

// Removes the temporary file an interrupted write_checkpoint(path, ...) left (if any).
void discard_partial_checkpoint(const std::string& path);

// Writes `header` and this rank's first `count` particles to `path` atomically (see above).
// Collective on several MPI ranks: every rank passes its slice, ranks in curve order; the
// header is rank 0's. Throws std::runtime_error on failure (on every rank); the previous file
// at `path` is then untouched.
template <int D>
void write_checkpoint(const std::string& path, const CheckpointHeader& header,
                      const Particles<D>& particles, std::size_t count);
// One rank's convenience: `c` with all its particles.
template <int D>
void write_checkpoint(const std::string& path, const Checkpoint<D>& c) {
    write_checkpoint<D>(path, c, c.particles, c.particles.size());
}

// Reads a checkpoint for a case whose fingerprint is `case_fingerprint`: the header and this
// rank's even share of the particles (collective on several ranks, any number of them).
// Refuses (throws sluice::CaseError naming the file and the reason, on every rank) a missing,
// truncated or damaged file, a file that is no sluice checkpoint, another format version,
// another dimension, or a checkpoint written for another case.
template <int D>
Checkpoint<D> read_checkpoint(const std::string& path, const std::string& case_fingerprint);

extern template void write_checkpoint<2>(const std::string&, const CheckpointHeader&,
                                         const Particles<2>&, std::size_t);
extern template void write_checkpoint<3>(const std::string&, const CheckpointHeader&,
                                         const Particles<3>&, std::size_t);
extern template Checkpoint<2> read_checkpoint<2>(const std::string&, const std::string&);
extern template Checkpoint<3> read_checkpoint<3>(const std::string&, const std::string&);

} // namespace sluice
