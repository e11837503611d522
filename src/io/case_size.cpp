// The size of a case: particle and micro-cell counts before anything is allocated
// (case_size.hpp).
#include "case_size.hpp"

#include "sluice/io/case_reader.hpp"
#include "sluice/io/wall_extent.hpp"
#include "sluice/physics/kernels.hpp"

#include "case_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace sluice::case_file {
namespace {

// Bounds of the case's size that come from types (the bounds of single keys are the schema's
// ranges; whether a case fits in memory is the memory estimate's, checked by the commands for
// their rank count): a 3-D Morton key has 21 bits per axis, and the balancer's peer search
// walks a rank's range of cell keys cell by cell (tasks::peers_of), which bounds the grid's
// cells (CellIndex itself is 64-bit; the cell ranges store occupied cells only).
constexpr double kMaxCells = 4294967295.0; // 2^32 - 1
constexpr double kMaxCellsPerAxis3d = 2097151;

// Lattice sites along an extent (the solver rounds the same way), in floating point so that a
// hostile extent cannot overflow an integer.
double sites(double extent, double dx) {
    return std::max(1.0, std::round(extent / dx));
}

} // namespace

// Refuses hostile sizes and sizes past the types, before anything is counted or allocated: the
// fluid lattice, the dummy-wall lattice around the tank, and the micro-cell grid.
void check_case_size(const Section& root, const CaseConfig& c) {
    const auto dim = static_cast<std::size_t>(c.dimension);
    const auto* dx_node = root.sub("particles").node("dx");
    double fluid = 0;
    for (const auto& b : c.blocks) {
        double n = 1;
        for (std::size_t a = 0; a < dim; ++a)
            n *= sites(b.hi[a] - b.lo[a], c.dx);
        fluid += n;
    }
    if (fluid > hostile_case_particles)
        root.reader().fail("particles.dx",
                           fmt::format("the fluid blocks would hold about {:.3g} particles "
                                       "(volume / dx^{}), beyond any machine (more than {:.0e}); "
                                       "increase dx",
                                       fluid, c.dimension, hostile_case_particles),
                           dx_node);

    const double support = kernel_support_factor(c.kernel) * c.h_over_dx * c.dx;
    const double layers = std::ceil(support / c.dx);
    if (c.walls == WallModel::dummy) {
        // Upper bound: the whole lattice of the tank grown by the wall layers on every side.
        double walls = 1;
        for (std::size_t a = 0; a < dim; ++a)
            walls *= sites(c.tank_hi[a] - c.tank_lo[a], c.dx) + 2 * layers;
        if (walls > hostile_case_particles)
            root.reader().fail(
                "particles.dx",
                fmt::format("the dummy walls around the tank would need up to {:.3g} particles "
                            "((tank / dx + wall layers)^{}), beyond any machine (more than "
                            "{:.0e}); increase dx or make the tank smaller",
                            walls, c.dimension, hostile_case_particles),
                dx_node);
    }

    // The solver's grid: the domain (and tank with its walls) plus one support on open axes,
    // in cells of one support.
    double cells = 1;
    for (std::size_t a = 0; a < dim; ++a) {
        double lo = c.domain_lo[a], hi = c.domain_hi[a];
        if (!c.periodic[a]) {
            const AxisExtent e = wall_extent(c, a);
            lo = e.lo - support;
            hi = e.hi + support;
        }
        const double n = std::max(1.0, std::floor((hi - lo) / support));
        if (dim == 3 && n > kMaxCellsPerAxis3d)
            root.reader().fail(
                "particles.dx",
                fmt::format("the domain is {:.3g} kernel supports long along {}; at most {:.0f} "
                            "in 3-D (Morton keys): increase dx or make the domain smaller",
                            n, kAxis[a], kMaxCellsPerAxis3d),
                dx_node);
        cells *= n;
    }
    if (cells > kMaxCells)
        root.reader().fail("particles.dx",
                           fmt::format("the domain would need {:.3g} micro-cells (one kernel "
                                       "support wide), more than the {:.0f} the balancer's "
                                       "peer search walks; increase dx or make the domain smaller",
                                       cells, kMaxCells),
                           dx_node);
}

} // namespace sluice::case_file
