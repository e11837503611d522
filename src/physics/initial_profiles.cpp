#include "sluice/physics/initial_profiles.hpp"

#include <cmath>
#include <numbers>

namespace sluice {

double settled_height(const Eos& eos, double g, double sigma_total, double sigma_below) {
    constexpr int panels = 32;
    const double step = sigma_below / panels;
    const auto f = [&](double s) {
        return 1.0 / eos.density(Real(eos.p_background + g * (sigma_total - s)));
    };
    double sum = f(0) + f(sigma_below);
    for (int k = 1; k < panels; ++k)
        sum += (k % 2 ? 4 : 2) * f(k * step);
    return sum * step / 3;
}

double rotating_rectangle_pressure(double rho0, double omega, double Lx, double Ly, double x,
                                   double y) {
    // The particular solution x (x - Lx) vanishes on the x edges; the harmonic series cancels
    // it on the y edges. cosh(k s)/cosh(k Ly/2) with |s| <= Ly/2 is evaluated as
    // exp(k (|s| - Ly/2)) (1 + exp(-2 k |s|)) / (1 + exp(-k Ly)) so that large k cannot
    // overflow. 400 odd terms: truncation below 1e-6 of the centre value.
    const double pi = std::numbers::pi;
    const double s = std::abs(y - 0.5 * Ly);
    double series = 0;
    for (int m = 1; m < 800; m += 2) {
        const double k = m * pi / Lx;
        const double ratio =
            std::exp(k * (s - 0.5 * Ly)) * (1 + std::exp(-2 * k * s)) / (1 + std::exp(-k * Ly));
        series += 8 * Lx * Lx / std::pow(m * pi, 3) * std::sin(k * x) * ratio;
    }
    return -rho0 * omega * omega * (x * (Lx - x) - series);
}

} // namespace sluice
