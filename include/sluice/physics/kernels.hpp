#pragma once
// Smoothing kernels W(r, h) and their radial derivative dW/dr, for D = 1, 2, 3.
// Each kernel is a small value type; `support()` is the radius where W vanishes.
// Normalisations are checked numerically in tests/unit/test_kernels.cpp (integral = 1,
// gradient against finite differences).
#include "sluice/core/types.hpp"
#include "sluice/physics/options.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <variant>

namespace sluice {

// Morris (1996) quintic spline, support 3h (Tak 2024, eq. 4):
//   W = s [(3-q)^5 - 6(2-q)^5 + 15(1-q)^5], terms dropped where their base is negative.
// s = 1/(120h) in 1-D (Tak (2024) prints 120/h), 7/(478 pi h^2) in 2-D, 1/(120 pi h^3) in 3-D.
// Tak (2024) (after Morris 1996) prints 3/(359 pi h^3) in 3-D, which integrates to 1.0028: the
// exact value is 1/(120 pi h^3) (checked in tests/unit/test_kernels.cpp).
template <int D>
struct QuinticKernel {
    Real h, inv_h, sigma;
    explicit QuinticKernel(Real h_) : h(h_), inv_h(1 / h_), sigma(norm(h_)) {}
    static Real norm(Real h_) {
        if constexpr (D == 1)
            return 1 / (120 * h_);
        else if constexpr (D == 2)
            return 7 / (478 * std::numbers::pi_v<Real> * h_ * h_);
        else
            return 1 / (120 * std::numbers::pi_v<Real> * h_ * h_ * h_);
    }
    [[nodiscard]] Real support() const { return 3 * h; }
    [[nodiscard]] Real W(Real r) const {
        const Real q = r * inv_h;
        Real w = 0;
        if (q < 3)
            w += p5(3 - q);
        if (q < 2)
            w -= 6 * p5(2 - q);
        if (q < 1)
            w += 15 * p5(1 - q);
        return sigma * w;
    }
    [[nodiscard]] Real dW(Real r) const {
        const Real q = r * inv_h;
        Real w = 0;
        if (q < 3)
            w -= 5 * p4(3 - q);
        if (q < 2)
            w += 30 * p4(2 - q);
        if (q < 1)
            w -= 75 * p4(1 - q);
        return sigma * inv_h * w;
    }

private:
    static Real p4(Real t) { return (t * t) * (t * t); }
    static Real p5(Real t) { return p4(t) * t; }
};

// Wendland C2, support 2h: W = s (1 - q/2)^4 (2q + 1)  (2-D, 3-D); 1-D uses the C2 form
// s (1 - q/2)^3 (1.5q + 1).  s = 5/(8h), 7/(4 pi h^2), 21/(16 pi h^3).
template <int D>
struct WendlandC2Kernel {
    Real h, inv_h, sigma;
    explicit WendlandC2Kernel(Real h_) : h(h_), inv_h(1 / h_), sigma(norm(h_)) {}
    static Real norm(Real h_) {
        if constexpr (D == 1)
            return 5 / (8 * h_);
        else if constexpr (D == 2)
            return 7 / (4 * std::numbers::pi_v<Real> * h_ * h_);
        else
            return 21 / (16 * std::numbers::pi_v<Real> * h_ * h_ * h_);
    }
    [[nodiscard]] Real support() const { return 2 * h; }
    [[nodiscard]] Real W(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2)
            return 0;
        const Real t = 1 - q / 2;
        if constexpr (D == 1)
            return sigma * t * t * t * (Real(1.5) * q + 1);
        else
            return sigma * (t * t) * (t * t) * (2 * q + 1);
    }
    [[nodiscard]] Real dW(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2)
            return 0;
        const Real t = 1 - q / 2;
        if constexpr (D == 1)
            return sigma * inv_h * (-3 * q) * t * t; // d/dq[(1-q/2)^3(1.5q+1)] = -3q(1-q/2)^2
        else
            return sigma * inv_h * (-5 * q) * t * t * t;
    }
    // (dW/dr)/r without the division: q/r = 1/h. Finite at r = 0 (the self pair, whose
    // gradient F dx is zero anyway).
    [[nodiscard]] Real dW_over_r(Real r) const {
        const Real q = r * inv_h;
        const Real t = std::max(1 - q / 2, Real(0));
        if constexpr (D == 1)
            return sigma * inv_h * inv_h * (-3) * t * t;
        else
            return sigma * inv_h * inv_h * (-5) * t * t * t;
    }
};

// Monaghan & Lattanzio (1985) cubic B-spline, support 2h:
//   W = s (1 - 1.5q^2 + 0.75q^3) for q < 1, s 0.25 (2 - q)^3 for 1 <= q < 2.
// s = 2/(3h), 10/(7 pi h^2), 1/(pi h^3).
template <int D>
struct CubicSplineKernel {
    Real h, inv_h, sigma;
    explicit CubicSplineKernel(Real h_) : h(h_), inv_h(1 / h_), sigma(norm(h_)) {}
    static Real norm(Real h_) {
        if constexpr (D == 1)
            return 2 / (3 * h_);
        else if constexpr (D == 2)
            return 10 / (7 * std::numbers::pi_v<Real> * h_ * h_);
        else
            return 1 / (std::numbers::pi_v<Real> * h_ * h_ * h_);
    }
    [[nodiscard]] Real support() const { return 2 * h; }
    [[nodiscard]] Real W(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2)
            return 0;
        if (q < 1)
            return sigma * (1 - Real(1.5) * q * q + Real(0.75) * q * q * q);
        const Real t = 2 - q;
        return sigma * Real(0.25) * t * t * t;
    }
    [[nodiscard]] Real dW(Real r) const {
        const Real q = r * inv_h;
        if (q >= 2)
            return 0;
        if (q < 1)
            return sigma * inv_h * (-3 * q + Real(2.25) * q * q);
        const Real t = 2 - q;
        return sigma * inv_h * (-Real(0.75) * t * t);
    }
    // (dW/dr)/r with q/r = 1/h: s/h^2 (-3 + 2.25 q) for q < 1, s/h^2 (-0.75 (2 - q)^2 / q) for
    // 1 <= q < 2. Both pieces are computed and one is selected, so the factor loop of a
    // neighbour list vectorises (a branch on q < 1 mispredicts about every other pair). The
    // inner piece is finite at r = 0 (the self pair, whose gradient F dx is zero anyway).
    [[nodiscard]] Real dW_over_r(Real r) const {
        const Real q = r * inv_h;
        const Real t = std::max(2 - q, Real(0));
        const Real inner = -3 + Real(2.25) * q;
        const Real outer = -Real(0.75) * t * t / q;
        return sigma * inv_h * inv_h * (q < 1 ? inner : outer);
    }
};

template <int D>
using AnyKernel = std::variant<QuinticKernel<D>, WendlandC2Kernel<D>, CubicSplineKernel<D>>;

template <int D>
AnyKernel<D> make_kernel(KernelType type, Real h) {
    switch (type) {
    case KernelType::quintic:
        return QuinticKernel<D>(h);
    case KernelType::wendland_c2:
        return WendlandC2Kernel<D>(h);
    case KernelType::cubic_spline:
        return CubicSplineKernel<D>(h);
    }
    return QuinticKernel<D>(h);
}

// Support radius as a multiple of h.
inline double kernel_support_factor(KernelType type) {
    return type == KernelType::quintic ? 3.0 : 2.0;
}

// The radial factor F(r) = (dW/dr)/r of the pair at squared distance r2, so that
// grad_i W_ij = F dx with dx = x_i - x_j. Kernels with a closed form of dW/dr / r (Wendland, cubic
// spline) give it without a division; for the particle itself F dx is zero whatever F is. Neighbour
// lists store F once per step (Neighbourhood::sum_over_pairs).
template <class K>
inline Real grad_factor(const K& kernel, Real r2) {
    if constexpr (requires { kernel.dW_over_r(r2); }) {
        return kernel.dW_over_r(std::sqrt(r2));
    } else {
        if (r2 <= 0)
            return 0;
        const Real r = std::sqrt(r2);
        return kernel.dW(r) / r;
    }
}

// Gradient of W with respect to x_i for the pair displacement dx = x_i - x_j at distance r.
template <int D, class K>
inline Vec<D> grad_W(const K& kernel, const Vec<D>& dx, Real r) {
    if (r <= 0)
        return Vec<D>::Zero();
    return (kernel.dW(r) / r) * dx;
}

} // namespace sluice
