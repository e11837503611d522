#pragma once
// Acoustic damper: a bulk viscosity that damps the compressional (acoustic) part of a weakly
// compressible flow and leaves its divergence-free part alone (after Sun, Pilloton, Antuono &
// Colagrossi 2023, "Inclusion of an acoustic damper term in weakly-compressible SPH models",
// J. Comput. Phys. 483, 112056). Its stress zeta (div u) I, zeta = rho nu_a, enters the momentum
// equation as a correction to the pressure,
//   p_i = p_EOS(rho_i) - rho_i nu_a (div u)_i,     nu_a = alpha h c0,
// so the pressure term that already pushes fluid and walls apart carries it: a compressing
// particle (div u < 0) pushes harder, an expanding one less. The walls (Adami extrapolation),
// the pressure probes and the wall loads read this pressure, the normal stress a wall carries.
// nu_a grows with c0 as the acoustic frequencies do, so the damping per acoustic period is the
// same at any c0: alpha h k for a wave of wave number k. In still water div u = 0 and nothing
// changes. The divergence is the plain SPH one with the difference form,
//   (div u)_i = sum_j V_j (v_j - v_i) . grad_i W_ij,
// over fluid and wall partners (walls are fixed: a wall partner's v_j = 0, as in the
// continuity rate of density.hpp), from the velocities at the start of the step.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/kernels.hpp"

#include <array>
#include <span>

namespace sluice {

// nu_a [m^2/s] of alpha (case key numerics.acoustic_damper), h and c0.
inline double acoustic_damper_viscosity(double alpha, double h, double c0) {
    return alpha * h * c0;
}

// (div u)_i of fluid particle i.
template <int D, class K>
SLUICE_FLATTEN Real velocity_divergence(const Neighbourhood<D>& nb, const K& kernel,
                                        const AdjacentCells<D>& adj, std::uint32_t i,
                                        const Particles<D>& P) {
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    const Real* const rho = P.rho.data();
    const Real* const mass = P.mass.data();
    const Kind* const kind = P.kind.data();
    const Real* const v = P.v.data()->data();
    std::array<Real, D> vi;
    for (int d = 0; d < D; ++d)
        vi[d] = P.v[i][d];
    const auto sum = nb.template lane_sum_over_pairs<1>(
        adj, i, F,
        [&](std::uint32_t j, const typename Neighbourhood<D>::Dx& dx, Real r2,
            Real Fij) -> std::array<Real, 1> {
            // grad_i W_ij = F dx with dx = x_i - x_j; the self pair adds nothing.
            const Real w = r2 > 0 ? mass[j] / rho[j] * Fij : Real(0);
            const bool wall = kind[j] == Kind::wall;
            Real dv_dx = 0;
            for (int d = 0; d < D; ++d)
                dv_dx += ((wall ? Real(0) : v[D * j + d]) - vi[d]) * dx[d];
            return {w * dv_dx};
        });
    return sum[0];
}

// Adds the damper's part -rho nu_a (div u) to the pressure of every fluid particle of cell c
// (after the equation of state) and sets p/rho^2 from the sum.
template <int D, class K>
void apply_acoustic_damper(const Neighbourhood<D>& nb, const K& kernel, Real nu_a, CellIndex c,
                           const Particles<D>& P, std::span<Real> p, std::span<Real> p_over_rho2) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const Real rho = P.rho[i];
        p[i] -= rho * nu_a * velocity_divergence(nb, kernel, adj, i, P);
        p_over_rho2[i] = p[i] / (rho * rho);
    }
}

} // namespace sluice
