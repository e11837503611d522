#pragma once
// Kick-drift-kick leap-frog (symplectic), with the closing kick of step n-1 and the opening
// kick of step n merged so that one force evaluation serves both:
//   v^n       = v^{n-1/2} + dt_{n-1}/2 a^n        (closing kick of the previous step)
//   v^{n+1/2} = v^n + dt_n/2 a^n                   (opening kick)
//   x^{n+1}   = x^n + dt_n v^{n+1/2}               (drift)
//   v^{n+1}*  = v^{n+1/2} + dt_n/2 a^n             (estimate used by the viscous terms and
//                                                   written to snapshots)
//   rho^{n+1} = rho^n + dt_n drho^n                (continuity scheme)
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
struct LeapfrogState {
    Vec<D> x, v_half, v;
    Real rho;
};

template <int D>
inline LeapfrogState<D> leapfrog(const Vec<D>& x, const Vec<D>& v_half, Real rho,
                                 const Vec<D>& a, Real drho, Real dt_prev, Real dt) {
    const Vec<D> v_n = v_half + Real(0.5) * dt_prev * a;
    const Vec<D> v_half_new = v_n + Real(0.5) * dt * a;
    return {x + dt * v_half_new, v_half_new, v_half_new + Real(0.5) * dt * a, rho + dt * drho};
}

} // namespace sluice
