#pragma once
// Particle shifting (Lind et al. 2012; in the delta+-SPH form of Sun et al. 2017, eq. 13):
//   dr_i = -A U h dt sum_j [1 + R (W_ij / W(dx))^n] grad_i W_ij V_j,   R = 0.2, n = 4,
// a small displacement each step that moves particles from crowded to sparse regions and so
// keeps the particle distribution regular where the flow stretches it (e.g. the hyperbolic
// points of a Taylor-Green vortex). A = 4 reproduces Sun's CFL Ma (2h)^2 prefactor with U the
// largest fluid speed. Near a free surface (kernel sum of volumes below 0.95) only the part
// tangential to the surface is kept, so surface particles are not pushed out of the fluid.
// The displacement is capped at 0.1 dx. No correction of the advected fields is applied
// (Sun et al. show it is of higher order for the flows considered).
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/physics/kernels.hpp"

namespace sluice {

struct ShiftingParams {
    Real coefficient = 0; // A U h dt [m^2]: the prefactor of the sum
    Real w_dx = 0;        // W(dx): kernel value at the lattice spacing
    Real max_shift = 0;   // cap on |dr| [m]
};

template <int D, class K>
SLUICE_FLATTEN void particle_shift(const Neighbourhood<D>& nb, const K& kernel,
                                   const ShiftingParams& prm, CellIndex c, const Particles<D>& P,
                                   std::span<Vec<D>> shift_out) {
    constexpr Real R = Real(0.2);
    const AdjacentCells<D> adj = nb.adjacent(c);
    for (std::uint32_t i = nb.begin(c), stop = nb.end(c); i < stop; ++i) {
        if (P.kind[i] != Kind::fluid)
            continue;
        Vec<D> s = Vec<D>::Zero();
        Vec<D> grad_c = Vec<D>::Zero();
        Real completeness = 0;
        nb.for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>& dx, Real r2) {
            const Real r = std::sqrt(r2);
            const Real Vj = P.mass[j] / P.rho[j];
            const Real W = kernel.W(r);
            completeness += Vj * W;
            if (r2 <= 0)
                return;
            const Vec<D> gradW = grad_W<D>(kernel, dx, r);
            const Real q = W / prm.w_dx;
            s += (1 + R * (q * q) * (q * q)) * Vj * gradW;
            grad_c += Vj * gradW;
        });
        Vec<D> dr = -prm.coefficient * s;
        if (completeness < Real(0.95) && grad_c.squaredNorm() > 0) {
            const Vec<D> n = grad_c.normalized(); // points into the fluid
            dr -= dr.dot(n) * n;
        }
        const Real len = dr.norm();
        if (len > prm.max_shift)
            dr *= prm.max_shift / len;
        shift_out[i] = dr;
    }
}

// Fickian particle shifting of the projection scheme (docs/PROJECTION.md, "Particle
// shifting"): Lind et al. (2012, J. Comput. Phys. 231, 1499), eqs. (21)-(24), after Xu et al.
// (2009):
//   dr_i = -D grad C_i,   grad C_i = sum_j V_j [1 + R (W_ij / W(dx))^n] grad_i W_ij,
//   R = 0.2, n = 4 (Monaghan's anti-clustering term, as Lind et al. add it).
// Lind's diffusion coefficient is D = A h |u| dt (WCSPH's particle_shift above uses
// the largest speed); the projection scheme passes D = A h^2 per step instead, independent of
// the velocity as in Skillen et al. (2013, Comput. Methods Appl. Mech. Eng. 265, 163), because
// in still water |u| ~ 0 and the speed-scaled shift did not lower the tank's pressure noise
// (docs/PROJECTION.md, "Particle shifting").
// Near a free surface (as Lind et al.) only the part tangential to the surface is kept,
// the normal being that of the plain concentration gradient sum_j V_j grad_i W_ij; the length
// is capped. Pure per-pair and per-particle pieces, so the scheme's own neighbour lists can
// drive them.
inline constexpr Real shift_anticlustering_R = Real(0.2);

// One pair's term V_j [1 + R (W_ij / W(dx))^4] grad_i W_ij of grad C_i.
template <int D>
Vec<D> shift_pair_term(const Vec<D>& grad_w, Real w, Real w_dx, Real volume) {
    const Real q = w / w_dx;
    return ((1 + shift_anticlustering_R * (q * q) * (q * q)) * volume) * grad_w;
}

// dr_i = -coefficient grad_c, without its component along surface_gradient (the plain
// concentration gradient, pointing into the fluid) when near_surface, capped at max_shift.
template <int D>
Vec<D> fickian_shift(Real coefficient, const Vec<D>& grad_c, bool near_surface,
                     const Vec<D>& surface_gradient, Real max_shift) {
    Vec<D> dr = -coefficient * grad_c;
    if (near_surface && surface_gradient.squaredNorm() > 0) {
        const Vec<D> n = surface_gradient.normalized();
        dr -= dr.dot(n) * n;
    }
    const Real len = dr.norm();
    if (len > max_shift)
        dr *= max_shift / len;
    return dr;
}

} // namespace sluice
