#pragma once
// Kick-drift-kick leap-frog (symplectic), with the closing kick of step n-1 and the opening
// kick of step n merged so that one force evaluation serves both:
//   kick:   v^{n+1/2} = v^{n-1/2} + (dt_{n-1} + dt_n)/2 a^n
//   drift:  x^{n+1}   = x^n   + dt_n v^{n+1/2}
//           rho^{n+1} = rho^n + dt_n D(x^n, v^{n+1/2})      (continuity scheme)
//           v^{n+1}*  = v^{n+1/2} + dt_n/2 a^n   (estimate used by the viscous terms of the
//                                                 next step and written to snapshots)
// Density is staggered like position: advancing it with a full-step velocity instead of
// v^{n+1/2} breaks the symplectic pairing of (rho, v) and makes acoustic modes grow.
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
inline Vec<D> kick(const Vec<D>& v_half, const Vec<D>& a, Real dt_prev, Real dt) {
    return v_half + Real(0.5) * (dt_prev + dt) * a;
}

template <int D>
inline Vec<D> drift(const Vec<D>& x, const Vec<D>& v_half, Real dt) {
    return x + dt * v_half;
}

template <int D>
inline Vec<D> velocity_estimate(const Vec<D>& v_half, const Vec<D>& a, Real dt) {
    return v_half + Real(0.5) * dt * a;
}

} // namespace sluice
