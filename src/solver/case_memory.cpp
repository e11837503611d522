// The memory estimate of a case from its configuration (case_memory.hpp).
#include "sluice/solver/case_memory.hpp"

#include "sluice/core/particles.hpp"
#include "sluice/io/wall_extent.hpp"
#include "sluice/physics/kernels.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {
namespace {

double support_of(const CaseConfig& cfg) {
    return kernel_support_factor(cfg.kernel) * cfg.h_over_dx * cfg.dx;
}

} // namespace

double case_grid_cells(const CaseConfig& cfg) {
    const double support = support_of(cfg);
    double cells = 1;
    for (int d = 0; d < cfg.dimension; ++d) {
        const AxisExtent e = wall_extent(cfg, static_cast<std::size_t>(d));
        const double extent =
            cfg.periodic[d] ? cfg.domain_hi[d] - cfg.domain_lo[d] : e.hi - e.lo + 2 * support;
        cells *= std::max(1.0, std::floor(extent / support));
    }
    return cells;
}

MemoryEstimate case_memory(const CaseConfig& cfg, double fluid, double walls, int ranks) {
    MemoryInputs in;
    in.dimension = cfg.dimension;
    in.fluid = fluid;
    in.walls = walls;
    in.cells = case_grid_cells(cfg);
    in.support_over_dx = support_of(cfg) / cfg.dx;
    in.state_bytes = static_cast<double>(cfg.dimension == 2 ? Particles<2>::bytes_per_particle()
                                                            : Particles<3>::bytes_per_particle());
    in.periodic = std::any_of(cfg.periodic.begin(), cfg.periodic.begin() + cfg.dimension,
                              [](bool p) { return p; });
    in.ranks = ranks;
    return estimate_memory(in);
}

MemoryEstimate case_memory_before_counting(const CaseConfig& cfg, int ranks) {
    double fluid = 0;
    for (const FluidBlock& b : cfg.blocks) {
        double n = 1;
        for (std::size_t a = 0; a < static_cast<std::size_t>(cfg.dimension); ++a)
            n *= std::max(1.0, std::round((b.hi[a] - b.lo[a]) / cfg.dx));
        fluid += n;
    }
    return case_memory(cfg, fluid, 0, ranks);
}

} // namespace sluice
