#pragma once
// The force the fluid exerts on one dummy wall particle during a step, from the pairs of the
// step's neighbour list: every fluid partner i accelerates by a_ij through the pair terms of
// momentum.hpp (pressure with both pressures clipped at p_floor, the laminar term on no-slip
// walls, the artificial viscosity where it acts on wall pairs), and the wall particle j
// receives -m_i a_ij (Newton's third law). Summed over a free body's particles this is the
// load that moves it (motion/rigid_body.hpp), and the momentum the fluid loses to the body is
// the momentum the body gains, to round-off. The same pair arithmetic as momentum.hpp's
// acceleration_cell; physics/wall_loads.hpp sums the same terms for the force probes.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/momentum.hpp"

#include <algorithm>

namespace sluice {

template <int D, class K>
Eigen::Matrix<double, D, 1>
fluid_force_on_wall_particle(const Neighbourhood<D>& nb, const K& kernel,
                             const MomentumParams<D>& prm, const AdjacentCells<D>& adj,
                             std::uint32_t j, const Particles<D>& P) {
    const Real eta2 = Real(0.01) * prm.h * prm.h;
    const Real two_mu = 2 * prm.mu;
    const Real av = prm.alpha * prm.h * prm.c0;
    const bool laminar = two_mu > 0 && prm.wall_viscous;
    const bool artificial = av > 0 && prm.wall_artificial;
    const Real rho_j = P.rho[j];
    const Real m_j = P.mass[j];
    const Real pj_over_rho2 = std::max(P.p[j], prm.p_floor) / (rho_j * rho_j);
    const Vec<D> v_bc = P.v_bc[j];
    using V = Eigen::Matrix<double, D, 1>;
    const auto F = [&kernel](Real r2) { return grad_factor(kernel, r2); };
    return nb.sum_over_pairs(
        adj, j, F, V(V::Zero()), [&](std::uint32_t i, const Vec<D>& dx_ji, Real r2, Real dWr) {
            if (r2 <= 0 || P.kind[i] != Kind::fluid)
                return V(V::Zero());
            const Vec<D> dx = -dx_ji; // x_i - x_j, as the momentum loop sees the pair
            const Real rho_i = P.rho[i];
            Real s = std::max(P.p[i], prm.p_floor) / (rho_i * rho_i) + pj_over_rho2;
            Vec<D> pair = Vec<D>::Zero();
            if (laminar || artificial) {
                const Vec<D> v_ij = P.v[i] - v_bc;
                if (laminar)
                    pair = laminar_viscosity(m_j, two_mu, rho_i, rho_j, dWr, r2, eta2) * v_ij;
                if (artificial) {
                    const Real vr = std::min(v_ij.dot(dx), Real(0));
                    s -= artificial_viscosity(av, vr, r2, eta2, rho_i, rho_j);
                }
            }
            const Vec<D> a_ij = pair - m_j * s * (dWr * dx);
            return V(-double(P.mass[i]) * a_ij.template cast<double>());
        });
}

} // namespace sluice
