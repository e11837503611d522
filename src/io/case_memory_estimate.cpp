// The memory estimate per rank and the limit it is checked against (memory_estimate.hpp). The
// coefficients are counted from the arrays the solver allocates and calibrated against the peak
// resident memory of runs: perf/memory/README.md, "Memory estimate", has the commands.
#include "sluice/io/memory_estimate.hpp"

#include "sluice/io/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include <unistd.h>

namespace sluice {
namespace {

// The coefficients below are the least-squares fit of the peak resident memory of eight 1-rank
// runs (2-D and 3-D dam breaks from 6,098 to 515,018 particles, the sparse tank at two sizes:
// perf/memory/README.md, "Memory estimate", lists them with the command), each run as
// perf/memory/peak_rss.py makes it: snapshots at the start and the end, a checkpoint every 2
// steps. They fit those eight within 5 %.
//
// The process without particles: the executable, the libraries and the MPI, TBB and HDF5
// runtimes (fitted: 31.7 MiB; the 2-D default case of 6,098 particles peaks at 39.2 MiB).
constexpr double kBaselineBytes = 31.7 * (1 << 20);
// Per particle besides Particles<D> (whose arrays are counted: MemoryInputs::state_bytes) and
// the neighbour lists: the rebin's keys, cells and permutation (8 + 8 + 4 + 4 + 8), the list
// offsets (4), the scheme's own arrays, the permutation's scratch, the snapshot's and the
// checkpoint's buffers (fitted: 334 B; counted: 36 B of it).
constexpr double kOtherBytesPerParticle = 334;
// Per pair of the full support ball (pi s^2 or 4/3 pi s^3 pairs, s = support / dx) of a fluid
// particle: its lists hold the index j (4) and the radial factor (8) of each pair, with the
// capacity of the longest fill kept and the pair stages' scratch (fitted: 36.3 B; counted: 12).
constexpr double kBytesPerFluidPair = 36.3;
// The same for a wall particle, which lists only its fluid neighbours (fitted: 4.0 B).
constexpr double kBytesPerWallPair = 4.0;
// A periodic case's lists also hold each pair's image shift (8 per axis; counted, not fitted).
constexpr double kShiftBytesPerAxis = 8;
// Per stored cell of a rank's grid: the hash table of cell ranges (CellRanges::bytes_for: 16 B
// slots, at most half full, and a table kept up to twice larger between rebins: 64 B) and the
// Rebinner's per-occupied-cell key and offset (12 B). A rank stores its occupied cells and one
// slot per halo particle (docs/ARCHITECTURE.md, "Cell storage"); empty space costs nothing.
constexpr double kGridBytesPerStoredCell = 76;
// Rank 0 of a parallel run: every fluid particle's id and mass gathered (16 B) and unpacked into
// a vector, for the fluid mass summed in id order (run_totals.cpp); measured 28 B per fluid
// particle: rank 0's peak after start-up was 27 MiB above rank 1's for 999,698 fluid particles on
// 4 ranks (perf/memory/README.md, "Distributed start").
constexpr double kTotalsBytesPerFluid = 28;

double pairs_per_particle(int dim, double support_over_dx) {
    const double s = support_over_dx;
    return dim == 2 ? std::numbers::pi * s * s : 4.0 / 3.0 * std::numbers::pi * s * s * s;
}

double mem_total_bytes() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    double kib = 0;
    std::string unit;
    while (in >> key >> kib >> unit)
        if (key == "MemTotal:")
            return kib * 1024;
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0;
}

} // namespace

double grid_bytes_per_rank(int dimension, double owned, double halo, double support_over_dx,
                           double domain_cells) {
    // A full cell is one support wide: (support / dx)^D lattice sites.
    const double per_cell = std::max(1.0, std::pow(support_over_dx, dimension));
    return kGridBytesPerStoredCell * std::min(domain_cells, owned / per_cell + halo);
}

double halo_particles_per_rank(int dimension, double particles_per_rank, double total_particles,
                               double support_over_dx, int ranks) {
    if (ranks <= 1)
        return 0;
    const double side = std::pow(particles_per_rank, 1.0 / dimension);
    const double layer = std::ceil(support_over_dx);
    const double grown = std::pow(side + 2 * layer, dimension);
    return std::min(grown - particles_per_rank, total_particles - particles_per_rank);
}

MemoryEstimate estimate_memory(const MemoryInputs& in) {
    MemoryEstimate e;
    e.ranks = std::max(1, in.ranks);
    const double all = in.fluid + in.walls;
    e.particles_per_rank = all / e.ranks;
    e.halo_particles = halo_particles_per_rank(in.dimension, e.particles_per_rank, all,
                                               in.support_over_dx, e.ranks);
    const double pairs = pairs_per_particle(in.dimension, in.support_over_dx);
    const double shift = in.periodic ? kShiftBytesPerAxis * in.dimension : 0;
    const double fluid =
        in.state_bytes + kOtherBytesPerParticle + (kBytesPerFluidPair + shift) * pairs;
    const double wall =
        in.state_bytes + kOtherBytesPerParticle + (kBytesPerWallPair + shift) * pairs;
    e.baseline = kBaselineBytes;
    // The ranks hold equal counts (the decomposition cuts the particles' curve into equal
    // shares), and a fluid particle costs some ten times a wall particle: the busiest rank is
    // one whose share is fluid first (a dam break's column lies in the first ranks' part).
    e.fluid_per_rank = std::min(e.particles_per_rank, in.fluid);
    e.particles = fluid * e.fluid_per_rank + wall * (e.particles_per_rank - e.fluid_per_rank);
    e.halo = in.state_bytes * e.halo_particles;
    e.grid = grid_bytes_per_rank(in.dimension, e.particles_per_rank, e.halo_particles,
                                 in.support_over_dx, in.cells);
    e.totals = e.ranks > 1 ? kTotalsBytesPerFluid * in.fluid : 0;
    return e;
}

MemoryLimit memory_limit(std::optional<double> max_memory, int ranks_here) {
    if (max_memory)
        return {*max_memory, fmt::format("--max-memory {}", human_bytes(*max_memory))};
    const int here = std::max(1, ranks_here);
    const double total = mem_total_bytes();
    return {total / here,
            here > 1 ? fmt::format("this machine's memory ({} MemTotal) shared by its {} ranks",
                                   human_bytes(total), here)
                     : fmt::format("this machine's memory ({} MemTotal)", human_bytes(total))};
}

std::optional<double> parse_memory_size(const std::string& text) {
    std::istringstream in(text);
    double v = 0;
    if (!(in >> v) || !std::isfinite(v) || v <= 0)
        return std::nullopt;
    std::string unit; // what follows the number and any blanks, with no blank inside
    in >> std::ws;
    for (char ch; in.get(ch);) {
        if (std::isspace(static_cast<unsigned char>(ch)))
            return std::nullopt;
        unit += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    }
    double scale = 0;
    if (unit.empty() || unit == "B")
        scale = 1;
    const std::string prefixes = "KMGT";
    for (std::size_t k = 0; k < prefixes.size(); ++k) {
        const std::string p(1, prefixes[k]);
        if (unit == p || unit == p + "I" || unit == p + "IB")
            scale = std::pow(1024.0, static_cast<double>(k + 1));
        else if (unit == p + "B")
            scale = std::pow(1000.0, static_cast<double>(k + 1));
    }
    if (scale == 0 || !std::isfinite(v * scale))
        return std::nullopt;
    return v * scale;
}

std::string human_bytes(double bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int u = 0;
    while (bytes >= 1024 && u < 6) {
        bytes /= 1024;
        ++u;
    }
    return fmt::format("{:.1f} {}", bytes, units[u]);
}

void check_memory(const CaseConfig& cfg, const MemoryEstimate& e, const MemoryLimit& limit) {
    if (e.total() <= limit.bytes)
        return;
    throw CaseError(
        cfg.source_file, "particles.dx",
        fmt::format("on {} rank{} the busiest rank would need about {} ({:.3g} particles of "
                    "its own, {} of grid), above {}; increase dx, make the domain smaller or "
                    "run on more ranks (sluice info --ranks R shows the estimate)",
                    e.ranks, e.ranks == 1 ? "" : "s", human_bytes(e.total()), e.particles_per_rank,
                    human_bytes(e.grid), limit.source));
}

} // namespace sluice
