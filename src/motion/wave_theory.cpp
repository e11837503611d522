#include "sluice/motion/wave_theory.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace sluice {

namespace {

constexpr double two_pi = 2 * std::numbers::pi;

void require_positive(double v, const char* what) {
    if (!(v > 0) || !std::isfinite(v))
        throw std::invalid_argument(std::string("wave theory: ") + what +
                                    " must be positive and finite");
}

// 2x / sinh 2x without overflow (0 for large x) and with its limit 1 at x = 0.
double x_over_sinh(double two_x) {
    if (two_x < 1e-8)
        return 1 - two_x * two_x / 6;
    return two_x / std::sinh(two_x); // sinh overflows to inf for 2x > ~710: the ratio is 0
}

} // namespace

double wave_number(double omega, double depth, double g) {
    require_positive(omega, "the angular frequency");
    require_positive(depth, "the depth");
    require_positive(g, "gravity");
    // Solve x tanh x = y for x = kh, y = omega^2 h / g (the deep-water kh). Start from Fenton &
    // McKee (1990, Coastal Eng. 14:499-513), kh = y coth(y^(3/4))^(2/3), within 1.5 %:
    // Newton converges quadratically from there in a few steps.
    const double y = omega * omega * depth / g;
    double x = y * std::pow(1 / std::tanh(std::pow(y, 0.75)), 2.0 / 3.0);
    for (int it = 0; it < 50; ++it) {
        const double th = std::tanh(x);
        const double f = x * th - y;
        const double df = th + x * (1 - th * th);
        const double dx = f / df;
        x -= dx;
        if (std::abs(dx) <= 4 * std::numeric_limits<double>::epsilon() * x)
            break;
    }
    return x / depth;
}

double piston_height_to_stroke(double kh) {
    require_positive(kh, "kh");
    // 2 (cosh 2kh - 1) / (sinh 2kh + 2kh) with numerator and denominator divided by sinh 2kh
    // ((cosh 2x - 1) / sinh 2x = tanh x): finite for any kh.
    return 2 * std::tanh(kh) / (1 + x_over_sinh(2 * kh));
}

double flap_height_to_stroke(double kh) {
    require_positive(kh, "kh");
    // 4 sinh x (1 - cosh x + x sinh x) / (x (sinh 2x + 2x)) divided through by sinh 2x =
    // 2 sinh x cosh x: 2 (x tanh x + sech x - 1) / (x (1 + 2x / sinh 2x)). For small x the
    // bracket cancels to x^2/2; written as 2 sinh(x/2) (x cosh(x/2) - sinh(x/2)) / cosh x it
    // does not (x cosh(x/2) - sinh(x/2) ~ x/2).
    const double x = kh;
    double bracket = 0;
    if (x < 1) {
        const double s = std::sinh(x / 2), c = std::cosh(x / 2);
        bracket = 2 * s * (x * c - s) / std::cosh(x);
    } else {
        bracket = x * std::tanh(x) + 1 / std::cosh(x) - 1; // 1/cosh -> 0 past overflow
    }
    return 2 * bracket / (x * (1 + x_over_sinh(2 * x)));
}

namespace {

struct WaveParameters {
    double omega, k, kh;
};

WaveParameters parameters(const RegularWave& wave) {
    require_positive(wave.height, "the wave height");
    require_positive(wave.period, "the wave period");
    const double omega = two_pi / wave.period;
    const double k = wave_number(omega, wave.depth, wave.g);
    return {omega, k, k * wave.depth};
}

// f(tau) = a1 sin(tau) + a2 sin(2 tau), tau = omega (t - start) + phase, with its time
// derivatives, ramped in after `start`.
SignalValue two_harmonics(double t, double a1, double a2, double omega, double phase, double start,
                          double ramp) {
    if (t <= start)
        return {};
    const double tau = omega * (t - start) + phase;
    const double s1 = std::sin(tau), c1 = std::cos(tau);
    const double s2 = std::sin(2 * tau), c2 = std::cos(2 * tau);
    const SignalValue f{a1 * s1 + a2 * s2, omega * (a1 * c1 + 2 * a2 * c2),
                        -omega * omega * (a1 * s1 + 4 * a2 * s2)};
    return ramped(f, smooth_ramp(t, start, ramp));
}

} // namespace

double piston_stroke(const RegularWave& wave) {
    const WaveParameters p = parameters(wave);
    return wave.height / piston_height_to_stroke(p.kh);
}

double piston_second_order_amplitude(const RegularWave& wave) {
    const WaveParameters p = parameters(wave);
    const double m1 = piston_height_to_stroke(p.kh);
    // 3 cosh x / sinh^3 x written as 3 / (tanh x sinh^2 x): 0, not inf/inf, in deep water.
    const double sh = std::sinh(p.kh);
    const double bound = 3 / (std::tanh(p.kh) * sh * sh);
    return wave.height * wave.height / (32 * wave.depth) * (bound - 2 / m1);
}

bool piston_second_order_valid(const RegularWave& wave) {
    const WaveParameters p = parameters(wave);
    const double L = two_pi / p.k;
    const double ursell = wave.height * L * L / (wave.depth * wave.depth * wave.depth);
    return ursell < 8 * std::numbers::pi * std::numbers::pi / 3;
}

Signal piston_displacement(const RegularWave& wave, double phase, double start, double ramp,
                           bool second_order) {
    const WaveParameters p = parameters(wave);
    const double a1 = piston_stroke(wave) / 2;
    const double a2 = second_order ? piston_second_order_amplitude(wave) : 0.0;
    const double omega = p.omega;
    return [=](double t) { return two_harmonics(t, a1, a2, omega, phase, start, ramp); };
}

Signal flap_angle(const RegularWave& wave, double phase, double start, double ramp) {
    const WaveParameters p = parameters(wave);
    const double a1 = wave.height / flap_height_to_stroke(p.kh) / 2;
    const double omega = p.omega, h = wave.depth;
    return [=](double t) {
        // theta = atan(u), u = X / h: theta' = u' / (1 + u^2),
        // theta'' = u'' / (1 + u^2) - 2 u u'^2 / (1 + u^2)^2.
        const SignalValue x = two_harmonics(t, a1, 0.0, omega, phase, start, ramp);
        const double u = x.value / h, du = x.rate / h, ddu = x.accel / h;
        const double q = 1 / (1 + u * u);
        return SignalValue{std::atan(u), du * q, ddu * q - 2 * u * du * du * q * q};
    };
}

double breaking_steepness_limit(double k, double depth) {
    require_positive(k, "the wave number");
    require_positive(depth, "the depth");
    return 0.142 * (two_pi / k) * std::tanh(k * depth);
}

std::vector<WaveComponent> jonswap_components(const JonswapSea& sea) {
    require_positive(sea.hs, "Hs");
    require_positive(sea.tp, "Tp");
    require_positive(sea.depth, "the depth");
    require_positive(sea.gamma, "gamma");
    require_positive(sea.f_min_factor, "f_min_factor");
    if (sea.components < 1)
        throw std::invalid_argument("wave theory: a JONSWAP sea needs at least one component");
    if (!(sea.f_max_factor > sea.f_min_factor) || !std::isfinite(sea.f_max_factor))
        throw std::invalid_argument("wave theory: f_max_factor must exceed f_min_factor");

    const double fp = 1 / sea.tp;
    const auto n = static_cast<std::size_t>(sea.components);
    const double df = (sea.f_max_factor - sea.f_min_factor) * fp / static_cast<double>(n);
    const double n0 = std::max(1.0, std::round(sea.f_min_factor * fp / df));

    std::vector<WaveComponent> c(n);
    double m0 = 0; // zeroth moment of the unscaled spectrum
    for (std::size_t i = 0; i < n; ++i) {
        const double f = (n0 + static_cast<double>(i)) * df;
        const double sigma = f <= fp ? 0.07 : 0.09;
        const double r = (f - fp) / (sigma * fp);
        const double s = std::pow(f / fp, -5.0) * std::exp(-1.25 * std::pow(f / fp, -4.0)) *
                         std::pow(sea.gamma, std::exp(-0.5 * r * r));
        c[i].frequency = f;
        c[i].amplitude = s; // the shape for now
        m0 += s * df;
    }
    // S = (Hs^2 / 16) shape / m0, so that sum S df = Hs^2 / 16; a_i = sqrt(2 S_i df).
    const double scale = sea.hs * sea.hs / (16 * m0);
    std::mt19937_64 engine(sea.seed);
    for (WaveComponent& w : c) {
        w.amplitude = std::sqrt(2 * scale * w.amplitude * df);
        // Top 53 bits of a 64-bit draw, exactly representable: uniform in [0, 1).
        const double u = static_cast<double>(engine() >> 11) * 0x1.0p-53;
        w.phase = two_pi * u;
    }
    return c;
}

Signal piston_irregular(const JonswapSea& sea, double start, double ramp) {
    struct Part {
        double amplitude, omega, phase;
    };
    std::vector<Part> parts;
    for (const WaveComponent& w : jonswap_components(sea)) {
        const double omega = two_pi * w.frequency;
        const double kh = wave_number(omega, sea.depth, sea.g) * sea.depth;
        // Height 2 a_i, stroke S_i = 2 a_i / m1, paddle amplitude S_i / 2.
        parts.push_back({w.amplitude / piston_height_to_stroke(kh), omega, w.phase});
    }
    return [parts = std::move(parts), start, ramp](double t) {
        if (t <= start)
            return SignalValue{};
        SignalValue f;
        for (const Part& p : parts) {
            const double tau = p.omega * (t - start) + p.phase;
            const double s = std::sin(tau), c = std::cos(tau);
            f.value += p.amplitude * s;
            f.rate += p.amplitude * p.omega * c;
            f.accel -= p.amplitude * p.omega * p.omega * s;
        }
        return ramped(f, smooth_ramp(t, start, ramp));
    };
}

} // namespace sluice
