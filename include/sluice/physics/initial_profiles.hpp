#pragma once
// The formulas of an initial state: how many wall layers a kernel support needs, which axis is
// up, the hydrostatic height of a settled column, and the pressure fields that keep a rotating
// or straining block's velocity gradient steady at t = 0. Pure functions of numbers; the
// particles of a case are built from them by solver/initial_state.hpp.
#include "sluice/physics/eos.hpp"

#include <cmath>

namespace sluice {

// Number of wall layers needed so that a fluid particle on the wall sees a full support.
inline int wall_layers(double support, double dx) {
    return static_cast<int>(std::ceil(support / dx - 1e-9));
}

// Vertical axis: y in 2-D, z in 3-D (gravity is not required to point along it).
template <int D>
constexpr int vertical_axis() {
    return D - 1;
}

// Height above the bottom of a column at rest of the particle below which a mass sigma_below
// per unit area lies, when the whole column holds sigma_total per unit area and its surface
// is at the background pressure: z = int_0^sigma_below dsigma / rho(p(sigma)), with
// p(sigma) = p_b + g (sigma_total - sigma) the weight above. Composite Simpson's rule; the
// integrand varies by ~1 % over a weakly compressible column, so 32 panels are exact to
// round-off for practical purposes.
double settled_height(const Eos& eos, double g, double sigma_total, double sigma_below);

// Pressure (above the background) of fluid in rigid rotation at angular velocity omega filling
// the rectangle [0, Lx] x [0, Ly] with p = 0 on its edges: the rotating square patch of
// Colagrossi (2005), solution of lap p = 2 rho omega^2 (the divergence of the Euler equation,
// lap p = -rho tr(grad v ^2), for v = omega x (x - c)). Written as the torsion-type single
// series p = -rho omega^2 [x (Lx - x) - sum_{m odd} 8 Lx^2/(m pi)^3 sin(m pi x/Lx)
// cosh(m pi (y - Ly/2)/Lx) / cosh(m pi Ly/(2 Lx))], which equals Colagrossi's double sine
// series and converges like 1/m^3. (x, y) measured from the lower-left corner.
double rotating_rectangle_pressure(double rho0, double omega, double Lx, double Ly, double x,
                                   double y);

// Pressure (above the background) of a uniform velocity gradient G inside the ellipse of
// semi-axes a, b with p = 0 on its edge: lap p = -rho tr(G^2) gives
// p = rho tr(G^2)/2 a^2 b^2/(a^2 + b^2) (1 - xi^2/a^2 - eta^2/b^2), (xi, eta) from the centre.
// Rigid rotation: tr(G^2) = -2 omega^2 (suction inside); Monaghan's (1994) elliptical drop
// v = (-A0 xi, A0 eta): tr(G^2) = 2 A0^2. Inline: the compiler may fuse its product into the
// caller's sum (as it did when this lived in the builder's translation unit).
inline double ellipse_pressure(double rho0, double trace_g2, double a, double b, double xi,
                               double eta) {
    const double p0 = 0.5 * rho0 * trace_g2 * a * a * b * b / (a * a + b * b);
    return p0 * (1 - xi * xi / (a * a) - eta * eta / (b * b));
}

} // namespace sluice
