#pragma once
// The end of a step for one fluid particle, for both schemes: its new position, velocity and
// density from the step's rates, kept on the fluid side of the reflective walls. (The
// periodic wrap belongs to the cell grid and is the caller's.)
#include "sluice/physics/integrator.hpp"
#include "sluice/physics/reflection.hpp"

namespace sluice {

template <int D>
struct DriftedState {
    Vec<D> x;
    Vec<D> v;
    Real rho;
};

// WCSPH leap-frog (integrator.hpp): x^{n+1} = x^n + dt v^{n+1/2}, plus the shifting
// displacement when `shift` is given; v^{n+1}* = v^{n+1/2} + dt/2 a^n; rho^{n+1} = rho^n +
// dt D when `drho` is given (continuity), else unchanged (summation recomputes it). A
// reflection turns v_half too, which the next kick starts from.
template <int D>
DriftedState<D> leapfrog_drift(const Vec<D>& x, Vec<D>& v_half, const Vec<D>& a, Real rho,
                               const Real* drho, const Vec<D>* shift, Real dt,
                               const Reflector<D>& walls) {
    DriftedState<D> s{drift<D>(x, v_half, dt), velocity_estimate<D>(v_half, a, dt), rho};
    if (shift != nullptr)
        s.x += *shift;
    if (drho != nullptr)
        s.rho = rho + dt * *drho;
    if (!walls.empty())
        walls.apply(x, s.x, v_half, s.v);
    return s;
}

// Projection scheme (docs/PROJECTION.md, P8): x^{n+1} = x^n + dt v^{n+1} with the corrected
// velocity v, plus the shifting displacement when `shift` is given, which a reflection turns;
// the density is not advanced (the scheme keeps rho0).
template <int D>
Vec<D> projection_drift(const Vec<D>& x, Vec<D>& v, Real dt, const Reflector<D>& walls,
                        const Vec<D>* shift = nullptr) {
    Vec<D> moved = x + dt * v;
    if (shift != nullptr)
        moved += *shift;
    if (!walls.empty()) {
        Vec<D> unused = v;
        walls.apply(x, moved, unused, v);
    }
    return moved;
}

} // namespace sluice
