#pragma once
// Density: summation (seed 000 eq. 6) or the continuity equation with delta-SPH density
// diffusion in the Antuono et al. (2010) / Marrone et al. (2011) form, whose renormalised
// density gradient removes the hydrostatic part so a still tank stays still.
// Each function handles the particles of one cell; it writes only those particles' fields.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"

#include <Eigen/LU>

namespace sluice {

// rho_i = sum_j m_j W_ij over fluid and wall particles, for the fluid particles of cell c.
template <int D, class K>
void summation_density(const Neighbourhood<D>& nb, const K& kernel, CellIndex c,
                       const Particles<D>& P, std::span<Real> rho_out) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t i = nb.begin(c); i < nb.end(c); ++i) {
        if (P.kind[i] != Kind::fluid) continue;
        Real rho = 0;
        nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>&, Real r2) {
            rho += P.mass[j] * kernel.W(std::sqrt(r2));
        });
        rho_out[i] = rho;
    }
}

// Renormalised density gradient <grad rho>^L_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,
// L_i = [sum_j V_j grad_i W_ij (x_j - x_i)^T]^{-1}, over fluid neighbours (Antuono 2010,
// eq. 9). Where L is singular (too few neighbours) the uncorrected sum is used.
template <int D, class K>
void renormalised_density_gradient(const Neighbourhood<D>& nb, const K& kernel, CellIndex c,
                                   const Particles<D>& P, std::span<Vec<D>> grad_out) {
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t i = nb.begin(c); i < nb.end(c); ++i) {
        if (P.kind[i] != Kind::fluid) continue;
        Mat<D> M = Mat<D>::Zero();
        Vec<D> g = Vec<D>::Zero();
        const Real rho_i = P.rho[i];
        nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>& dx, Real r2) {
            if (P.kind[j] != Kind::fluid || r2 <= 0) return;
            const Vec<D> gradW = grad_W<D>(kernel, dx, std::sqrt(r2));
            const Real Vj = P.mass[j] / P.rho[j];
            M -= Vj * gradW * dx.transpose(); // x_j - x_i = -dx
            g += (P.rho[j] - rho_i) * Vj * gradW;
        });
        // M is the identity for a full, regular support.
        grad_out[i] = std::abs(M.determinant()) > Real(1e-3) ? Vec<D>(M.inverse() * g) : g;
    }
}

// Pressure from the equation of state for the fluid particles of cell c.
template <int D>
void equation_of_state(const Neighbourhood<D>& nb, const Eos& eos, CellIndex c,
                       const Particles<D>& P, std::span<Real> p_out) {
    for (std::uint32_t i = nb.begin(c); i < nb.end(c); ++i)
        if (P.kind[i] == Kind::fluid) p_out[i] = eos.pressure(P.rho[i]);
}

} // namespace sluice
