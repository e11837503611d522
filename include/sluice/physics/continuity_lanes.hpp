#pragma once
// The continuity rate of density.hpp (velocity divergence and delta-SPH density diffusion) in
// 2-D over a neighbour list, four pairs per instruction. A neighbour's position, density, mass
// and wall flag come from the packed MomentumNeighbour record the acceleration reads
// (momentum_lanes.hpp): within a step they are the values the continuity rate reads too, so
// no record is written for it. Its velocity v^{n+1/2} (and, with Antuono's diffusion, its
// density gradient) comes from its own array, two values per particle.
//
// Same terms as continuity_rate; the pairs of a row go to the lanes in list order (pair
// b + 4k + l to lane l) and the lanes are added in a fixed order, so the rate depends only on
// the list: bitwise invariant across threads, groups and ranks, not bitwise the scalar loop's.
// V_j = m_j / rho_j is read from the EOS's array (four scalar loads); dividing per pair measured
// the same. A row's full groups of four pairs load their indices and factors directly; only
// its last one to three pairs take the padded path.
#include "sluice/core/lanes.hpp"
#include "sluice/physics/density.hpp"
#include "sluice/physics/momentum_lanes.hpp"

#include <stdexcept>

namespace sluice {

#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)

namespace detail {

template <bool Diffuse, DensityDiffusion Form, bool MovingWalls>
SLUICE_FLATTEN void
continuity_lanes_cell(const Neighbourhood<2>& nb, const DensityDiffusionParams<2>& diff,
                      CellIndex c, const Particles<2>& P, const MomentumNeighbour<2>* records,
                      std::span<const Vec<2>> vel, std::span<Real> drho_out) {
    constexpr bool antuono = Diffuse && Form == DensityDiffusion::antuono;
    constexpr bool fourtakas = Diffuse && Form == DensityDiffusion::fourtakas;
    const Real4 zero{0, 0, 0, 0}, minus_two = zero - 2;
    const Real gh_x = diff.hydrostatic_gradient[0], gh_y = diff.hydrostatic_gradient[1];
    const NeighbourList<2>& list = *nb.list;
    // Two values per particle (static_assert'ed by Neighbourhood::lane_sum_over_pairs).
    const Real* v = reinterpret_cast<const Real*>(vel.data());
    const Real* g = reinterpret_cast<const Real*>(P.grad_rho.data());
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const MomentumNeighbour<2>& self = records[i];
        const Real rho_i = self.rho;
        const Real vx_i = vel[i][0], vy_i = vel[i][1];
        const Real gx_i = antuono ? P.grad_rho[i][0] : 0, gy_i = antuono ? P.grad_rho[i][1] : 0;
        Real4 sum_div = zero, sum_diffusion = zero;
        // The pair terms of continuity_rate (density.hpp) for the four pairs to neighbours n
        // (lanes past the row's end: i itself with a zero factor, so every term is zero).
        for_pairs_in_fours(
            list, i, self.x, [&](const std::uint32_t(&n)[4], Real4 factor, Real4 xi, Real4 yi) {
                const MomentumNeighbour<2>* r[4] = {records + n[0], records + n[1], records + n[2],
                                                    records + n[3]};
                Real4 xj, yj, vxj, vyj;
                load_pair_lanes(r[0]->x.data(), r[1]->x.data(), r[2]->x.data(), r[3]->x.data(), xj,
                                yj);
                load_pair_lanes(v + 2 * n[0], v + 2 * n[1], v + 2 * n[2], v + 2 * n[3], vxj, vyj);
                Real4 rho_j = load_lanes(&r[0]->rho), m_j = load_lanes(&r[1]->rho);
                Real4 unused = load_lanes(&r[2]->rho), wall_j = load_lanes(&r[3]->rho);
                transpose_lanes(rho_j, m_j, unused, wall_j);
                const Mask4 wall = wall_j != zero;
                const Real4 dx = xi - xj, dy = yi - yj;
                if constexpr (!MovingWalls) { // fixed walls: v_j = 0 (v_half not exchanged)
                    vxj = wall ? zero : vxj;
                    vyj = wall ? zero : vyj;
                }
                const Real4 dv_dx = (vx_i - vxj) * dx + (vy_i - vyj) * dy;
                sum_div += m_j * factor * dv_dx;
                if constexpr (Diffuse) {
                    const Real4 volume_j{P.volume[n[0]], P.volume[n[1]], P.volume[n[2]],
                                         P.volume[n[3]]};
                    Real4 diffusion;
                    if constexpr (antuono) {
                        Real4 gxj, gyj;
                        load_pair_lanes(g + 2 * n[0], g + 2 * n[1], g + 2 * n[2], g + 2 * n[3], gxj,
                                        gyj);
                        const Real4 g_dx = (gx_i + gxj) * dx + (gy_i + gyj) * dy;
                        diffusion =
                            volume_j * (minus_two * (rho_j - rho_i) * factor - g_dx * factor);
                    }
                    if constexpr (fourtakas) {
                        const Real4 rho_h = (zero - gh_x * dx) - gh_y * dy; // dx = x_i - x_j
                        diffusion = volume_j * (minus_two * (rho_j - rho_i - rho_h) * factor);
                    }
                    sum_diffusion += wall ? zero : diffusion; // diffusion over fluid pairs only
                }
            });
        drho_out[i] = sum_lanes(sum_div) + diff.delta_h_c0 * sum_lanes(sum_diffusion);
    }
}

} // namespace detail

#endif

// The continuity rate of the fluid particles of cell c from the records of their neighbours
// (write_momentum_neighbour, for every particle the list names) and their velocities `vel`,
// over a list that covers c. Only where continuity_uses_lanes<D>(): elsewhere calling it is a
// logic error.
template <int D>
void continuity_rate_lanes([[maybe_unused]] const Neighbourhood<D>& nb,
                           [[maybe_unused]] const DensityDiffusionParams<D>& diff,
                           [[maybe_unused]] CellIndex c, [[maybe_unused]] const Particles<D>& P,
                           [[maybe_unused]] const MomentumNeighbour<D>* records,
                           [[maybe_unused]] std::span<const Vec<D>> vel,
                           [[maybe_unused]] std::span<Real> drho_out,
                           [[maybe_unused]] bool moving_walls = false) {
#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)
    if constexpr (D == 2) {
        // Fixed walls compile to the loop without moving walls' arithmetic.
        const auto cell = [&]<bool Diffuse, DensityDiffusion Form>() {
            if (moving_walls)
                detail::continuity_lanes_cell<Diffuse, Form, true>(nb, diff, c, P, records, vel,
                                                                   drho_out);
            else
                detail::continuity_lanes_cell<Diffuse, Form, false>(nb, diff, c, P, records, vel,
                                                                    drho_out);
        };
        if (diff.delta_h_c0 <= 0)
            cell.template operator()<false, DensityDiffusion::antuono>();
        else if (diff.form == DensityDiffusion::antuono)
            cell.template operator()<true, DensityDiffusion::antuono>();
        else
            cell.template operator()<true, DensityDiffusion::fourtakas>();
        return;
    }
#endif
    throw std::logic_error("continuity_rate_lanes: this build or dimension has no lanes");
}

// Whether continuity_rate_lanes computes the continuity rate: where the acceleration reads
// the records (acceleration_uses_lanes), which the continuity rate then reads too.
template <int D>
constexpr bool continuity_uses_lanes() {
    return acceleration_uses_lanes<D>();
}

} // namespace sluice
