// Warnings about the scheme's numerics (numerics_advice.hpp).
#include "sluice/solver/numerics_advice.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include <fmt/format.h>

namespace sluice {

std::vector<CaseWarning> numerics_warnings(const CaseConfig& cfg) {
    std::vector<CaseWarning> out;
    // The projection scheme has no artificial viscosity and uses the kernel for its operator
    // radius only; the Riemann solver replaces the artificial viscosity.
    if (cfg.scheme != Scheme::wcsph)
        return out;
    const double nu = cfg.viscosity / cfg.rho0;
    const double re_dx =
        nu > 0 ? 0.1 * cfg.sound_speed * cfg.dx / nu : std::numeric_limits<double>::infinity();
    const bool viscous = re_dx < max_viscous_cell_reynolds;
    const bool artificial = cfg.dissipation == Dissipation::artificial;
    if (viscous && cfg.kernel != KernelType::quintic)
        out.push_back(
            {"numerics.kernel",
             fmt::format("the laminar viscosity acts on the particle scale (cell Reynolds number "
                         "0.1 c0 dx / nu = {:.3g}, below {:.0f}): the quintic kernel with "
                         "h_over_dx = 1.0 gives 2-3x smaller errors than this kernel in such "
                         "flows (Poiseuille, Taylor-Green; inaccurate)",
                         re_dx, max_viscous_cell_reynolds)});
    if (viscous && artificial && cfg.artificial_viscosity > 0) {
        // Monaghan (2005): the artificial viscosity acts as nu = alpha h c0 / (2 (D + 2)).
        const double nu_art = cfg.artificial_viscosity * cfg.h_over_dx * cfg.dx * cfg.sound_speed /
                              (2.0 * (cfg.dimension + 2));
        out.push_back(
            {"numerics.artificial_viscosity",
             fmt::format("alpha = {:g} adds a viscosity alpha h c0 / {} = {:.3g} m^2/s, {:.3g} % "
                         "of the laminar nu = {:.3g} m^2/s, in a flow whose answer is its "
                         "laminar viscosity (cell Reynolds number {:.3g}): 0 leaves it to nu "
                         "(inaccurate)",
                         cfg.artificial_viscosity, 2 * (cfg.dimension + 2), nu_art,
                         100 * nu_art / nu, nu, re_dx)});
    }
    double g2 = 0;
    for (std::size_t a = 0; a < static_cast<std::size_t>(cfg.dimension); ++a)
        if (!cfg.periodic[a])
            g2 += cfg.gravity[a] * cfg.gravity[a];
    if (!viscous && artificial && cfg.artificial_viscosity == 0 && g2 > 0 && !cfg.blocks.empty())
        out.push_back({"numerics.artificial_viscosity",
                       "alpha = 0 in a free-surface flow: still water keeps a kinetic-energy "
                       "floor about 100x higher than with 0.02, and first-impact peaks rise by "
                       "30-60 % and keep growing with c0 (inaccurate; "
                       "docs/RECOMMENDED_PRACTICE.md)"});
    return out;
}

} // namespace sluice
