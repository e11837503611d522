#pragma once
// The peak resident memory of one rank of a run, estimated from the case's sizes before
// anything is allocated (`sluice info --ranks R`), and the limit `sluice check`/`info`/`run`
// refuse a case against (perf/memory/README.md, "Memory estimate", has the measurements each
// coefficient comes from). Pure: sizes in, bytes out; no solver types.
#include "sluice/io/case_config.hpp"

#include <cstddef>
#include <optional>
#include <string>

namespace sluice {

// What the estimate needs of a case (counts as doubles, so that hostile sizes cannot overflow).
struct MemoryInputs {
    int dimension = 2;
    double fluid = 0, walls = 0; // particles of the whole case
    double cells = 0;            // micro-cells of the whole domain's grid
    double support_over_dx = 0;  // kernel support in lattice spacings
    double state_bytes = 0;      // bytes of one element of every array of Particles<D>
    bool periodic = false;       // some axis is periodic (pairs carry an image shift)
    int ranks = 1;               // MPI ranks the case runs on
};

// The estimate for the rank that needs the most, by term, in bytes: an equal share of the
// particles, fluid first, with rank 0's run totals.
struct MemoryEstimate {
    int ranks = 1;
    double particles_per_rank = 0; // owned particles (fluid and walls), an even share
    double fluid_per_rank = 0;     // of which fluid: as many as the share holds
    double halo_particles = 0;     // copies of other ranks' particles within one support
    double baseline = 0;           // the process: libraries, MPI, TBB and HDF5 runtimes
    double particles = 0;          // owned particles: state, neighbour lists, sort buffers
    double halo = 0;               // halo copies' state
    double grid = 0;               // grid_bytes_per_rank
    double totals = 0;             // rank 0's run totals (every fluid particle's id and mass)
    [[nodiscard]] double total() const { return baseline + particles + halo + grid + totals; }
};

// The micro-cell grid's bytes on one rank: the cells its `owned` particles occupy (full cells
// one support wide) and one per halo copy, at most the domain's cells.
double grid_bytes_per_rank(int dimension, double owned, double halo, double support_over_dx,
                           double domain_cells);

// The halo copies one rank of `ranks` holds: the layer one support deep around a compact
// region of particles_per_rank particles (a cube or square of the lattice), at most every
// particle the rank does not own. 0 on one rank.
double halo_particles_per_rank(int dimension, double particles_per_rank, double total_particles,
                               double support_over_dx, int ranks);

MemoryEstimate estimate_memory(const MemoryInputs& in);

// The bytes one rank may use: --max-memory, else the machine's memory (MemTotal of
// /proc/meminfo, else sysconf) shared by the ranks on this machine (`ranks_here`).
struct MemoryLimit {
    double bytes = 0;
    std::string source; // "--max-memory 4GiB" or "MemTotal 23.4 GiB / 4 ranks on this machine"
};
MemoryLimit memory_limit(std::optional<double> max_memory, int ranks_here);

// "4GiB", "512 MiB", "2e9", "1.5G" (powers of 1024 for K/M/G/T with or without "iB", of 1000
// for KB/MB/GB/TB); nullopt for anything else or a size <= 0 or not finite.
std::optional<double> parse_memory_size(const std::string& text);

// "1.5 GiB": bytes in binary units with one decimal.
std::string human_bytes(double bytes);

// Refuses (CaseError naming cfg.source_file and particles.dx) a case whose estimate for the
// busiest rank exceeds the limit.
void check_memory(const CaseConfig& cfg, const MemoryEstimate& e, const MemoryLimit& limit);

} // namespace sluice
