#pragma once
// The acceleration of momentum.hpp (pressure, laminar and artificial viscosity, gravity) in
// 2-D over a neighbour list, four pairs per instruction: each pair's neighbour is one packed
// MomentumNeighbour record, and four records transpose into four lanes (x, y, v_x, v_y and
// rho, m, p/rho^2, wall). The scalar loop is bound by moving each neighbour's fields from six
// arrays, not by its arithmetic; gathering them per field lane by lane cost more than it
// saved (perf/NOTES.md, 2026-11-22 to 2026-11-27), a packed record does not.
//
// Same terms as detail::acceleration_cell<2, K, Viscous, Artificial>; the pairs of a row are
// dealt to the lanes in list order (pair b + 4k + l to lane l) and the lanes added in a fixed
// order at the end, so the result depends only on the list, which is the same for any threads,
// groups and ranks: bitwise invariant across them, as before, but not bitwise the scalar
// loop's (the last bits of the sum differ).
#include "sluice/core/lanes.hpp"
#include "sluice/physics/momentum.hpp"

#include <stdexcept>

namespace sluice {

#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)

namespace detail {

template <bool Viscous, bool Artificial>
SLUICE_FLATTEN void
acceleration_lanes_cell(const Neighbourhood<2>& nb, const MomentumParams<2>& prm, CellIndex c,
                        const Particles<2>& P, const MomentumNeighbour<2>* records,
                        std::span<Vec<2>> a_out) {
    static_assert(sizeof(MomentumNeighbour<2>) == 64 && alignof(MomentumNeighbour<2>) >= 32);
    const Real eta2 = Real(0.01) * prm.h * prm.h;
    const Real two_mu = 2 * prm.mu;
    const Real av = prm.alpha * prm.h * prm.c0;
    const Mask4 all{-1, -1, -1, -1}, none{0, 0, 0, 0};
    const Mask4 viscous_on_walls = prm.wall_viscous ? all : none;
    const Mask4 artificial_on_walls = prm.wall_artificial ? all : none;
    const Real4 zero{0, 0, 0, 0};
    const NeighbourList<2>& list = *nb.list;
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        const MomentumNeighbour<2>& self = records[i];
        const Real rho_i = self.rho;
        const Real4 p_over_rho2_i = zero + self.p_over_rho2;
        // A fluid-wall pair acts with the fluid pressure clipped at the background pressure.
        const Real4 p_clipped_over_rho2_i = zero + std::max(P.p[i], prm.p_floor) / (rho_i * rho_i);
        Real4 sum_x = zero, sum_y = zero;
        // The pair terms of acceleration_cell (momentum.hpp) for the four pairs to neighbours
        // js (lanes past the row's end: i itself with a zero factor, dropped by `live`).
        for_pairs_in_fours(
            list, i, self.x, [&](const std::uint32_t(&js)[4], Real4 factor, Real4 xi, Real4 yi) {
                const MomentumNeighbour<2>* const n[4] = {records + js[0], records + js[1],
                                                          records + js[2], records + js[3]};
                Real4 xj = load_lanes(n[0]->x.data()), yj = load_lanes(n[1]->x.data());
                Real4 vxj = load_lanes(n[2]->x.data()), vyj = load_lanes(n[3]->x.data());
                transpose_lanes(xj, yj, vxj, vyj);
                Real4 rho_j = load_lanes(&n[0]->rho), m_j = load_lanes(&n[1]->rho);
                Real4 p_over_rho2_j = load_lanes(&n[2]->rho), wall_j = load_lanes(&n[3]->rho);
                transpose_lanes(rho_j, m_j, p_over_rho2_j, wall_j);
                const Real4 dx = xi - xj, dy = yi - yj;
                const Real4 r2 = dx * dx + dy * dy;
                const Mask4 wall = wall_j != zero;
                const Real4 vx = self.v[0] - vxj, vy = self.v[1] - vyj; // v_ij (v_bc for a wall)
                Real4 s = (wall ? p_clipped_over_rho2_i : p_over_rho2_i) + p_over_rho2_j;
                Real4 pair_x = zero, pair_y = zero;
                if constexpr (Viscous) {
                    const Real4 k = laminar_viscosity(m_j, two_mu, rho_i, rho_j, factor, r2, eta2);
                    const Mask4 laminar = (~wall) | viscous_on_walls;
                    pair_x = laminar ? k * vx : zero;
                    pair_y = laminar ? k * vy : zero;
                }
                if constexpr (Artificial) {
                    const Real4 vr_raw = vx * dx + vy * dy;
                    const Real4 vr = vr_raw < zero ? vr_raw : zero;
                    const Real4 pi = artificial_viscosity(av, vr, r2, eta2, rho_i, rho_j);
                    s -= ((~wall) | artificial_on_walls) ? pi : zero;
                }
                const Real4 coefficient = m_j * s;
                const Mask4 live = r2 > zero;
                sum_x += live ? pair_x - coefficient * (factor * dx) : zero;
                sum_y += live ? pair_y - coefficient * (factor * dy) : zero;
            });
        a_out[i] = Vec<2>(sum_lanes(sum_x), sum_lanes(sum_y)) + prm.gravity;
    }
}

} // namespace detail

#endif

// The acceleration of the fluid particles of cell c from the records of their neighbours
// (write_momentum_neighbour, for every particle the list names), over a list that covers c.
// Only where acceleration_uses_lanes<D>(): elsewhere calling it is a logic error.
template <int D>
void acceleration_lanes([[maybe_unused]] const Neighbourhood<D>& nb,
                        [[maybe_unused]] const MomentumParams<D>& prm, [[maybe_unused]] CellIndex c,
                        [[maybe_unused]] const Particles<D>& P,
                        [[maybe_unused]] const MomentumNeighbour<D>* records,
                        [[maybe_unused]] std::span<Vec<D>> a_out) {
#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)
    if constexpr (D == 2) {
        with_viscosity_switches(prm, [&]<bool Viscous, bool Artificial>() {
            detail::acceleration_lanes_cell<Viscous, Artificial>(nb, prm, c, P, records, a_out);
        });
        return;
    }
#endif
    throw std::logic_error("acceleration_lanes: this build or dimension has no lanes");
}

// Whether acceleration_lanes computes the acceleration: in 2-D, in a build with four double
// lanes.
template <int D>
constexpr bool acceleration_uses_lanes() {
    return D == 2 && lanes_available;
}

} // namespace sluice
