// Wave-maker theory: the dispersion relation to round-off and its deep- and shallow-water
// limits, the piston and flap transfer functions (limits, and values computed independently to
// 40 digits with mpmath from Dean & Dalrymple's formulas), Madsen's second-order piston term by
// hand, the paddle Signals' derivatives against finite differences, and the JONSWAP components
// (Hs from the discrete spectrum, peak at Tp, reproducible phases, a record that repeats).
#include "sluice/motion/wave_theory.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

using namespace sluice;

namespace {

constexpr double pi = std::numbers::pi;

// rate and accel of `s` at t against central differences of value and rate.
void check_derivatives(const Signal& s, double t, double rate_scale, double accel_scale) {
    const double e = 1e-5;
    const SignalValue v = s(t), a = s(t - e), b = s(t + e);
    CHECK(v.rate == doctest::Approx((b.value - a.value) / (2 * e)).scale(rate_scale).epsilon(1e-8));
    CHECK(v.accel == doctest::Approx((b.rate - a.rate) / (2 * e)).scale(accel_scale).epsilon(1e-8));
}

} // namespace

TEST_CASE("Dispersion relation: residual to round-off for kh in [0.05, 10]") {
    for (double h : {0.1, 1.0, 30.0}) {
        for (double kh = 0.05; kh <= 10.0001; kh *= 1.1) {
            const double g = 9.81, k = kh / h;
            const double omega = std::sqrt(g * k * std::tanh(kh));
            const double k_solved = wave_number(omega, h, g);
            CHECK(k_solved == doctest::Approx(k).epsilon(1e-12));
            const double residual = omega * omega - g * k_solved * std::tanh(k_solved * h);
            CHECK(std::abs(residual) <= 1e-12 * omega * omega);
        }
    }
}

TEST_CASE("Dispersion relation: deep- and shallow-water limits") {
    const double g = 9.81;
    // Deep water (kh = 102): k = omega^2 / g; tanh 102 = 1 - 5e-89.
    const double omega_deep = 10.0;
    CHECK(wave_number(omega_deep, 10.0, g) ==
          doctest::Approx(omega_deep * omega_deep / g).epsilon(1e-14));
    // Shallow water: k = omega / sqrt(g h) (1 + (kh)^2 / 6 + ...); at kh ~ 1e-4 the correction
    // is 2e-9.
    const double h = 1.0, omega = 1e-4 * std::sqrt(g * h);
    const double k = wave_number(omega, h, g);
    CHECK(k == doctest::Approx(omega / std::sqrt(g * h)).epsilon(1e-8));
    CHECK(k * h == doctest::Approx(1e-4).epsilon(1e-8));
    // Very deep and very shallow water stay finite.
    CHECK(std::isfinite(wave_number(100.0, 1000.0, g)));
    CHECK(std::isfinite(wave_number(1e-8, 1e-3, g)));
    CHECK_THROWS_AS(wave_number(0.0, 1.0, g), std::invalid_argument);
    CHECK_THROWS_AS(wave_number(1.0, -1.0, g), std::invalid_argument);
}

TEST_CASE("Piston transfer function: limits and values") {
    // Shallow water: H/S = kh (Dean & Dalrymple §6.2) to O((kh)^3).
    for (double kh : {1e-9, 1e-6, 1e-4})
        CHECK(piston_height_to_stroke(kh) == doctest::Approx(kh).epsilon(1e-7));
    // Deep water: H/S -> 2, finite far past sinh's overflow.
    CHECK(piston_height_to_stroke(30.0) == doctest::Approx(2.0).epsilon(1e-14));
    CHECK(piston_height_to_stroke(1e4) == 2.0);
    // 2 (cosh 2kh - 1) / (sinh 2kh + 2kh), evaluated to 40 digits (mpmath).
    CHECK(piston_height_to_stroke(0.05) == doctest::Approx(0.049999993058862158).epsilon(1e-14));
    CHECK(piston_height_to_stroke(0.5) == doctest::Approx(0.49933830158073696).epsilon(1e-14));
    CHECK(piston_height_to_stroke(1.0) == doctest::Approx(0.98178930731303442).epsilon(1e-14));
    CHECK(piston_height_to_stroke(2.0) == doctest::Approx(1.6815789361329113).epsilon(1e-14));
    CHECK(piston_height_to_stroke(10.0) == doctest::Approx(1.99999982686311).epsilon(1e-14));
    // The formula as written, where it does not overflow.
    for (double kh = 0.05; kh < 10; kh *= 1.3) {
        const double direct = 2 * (std::cosh(2 * kh) - 1) / (std::sinh(2 * kh) + 2 * kh);
        CHECK(piston_height_to_stroke(kh) == doctest::Approx(direct).epsilon(1e-13));
    }
    CHECK_THROWS_AS(piston_height_to_stroke(0.0), std::invalid_argument);
}

TEST_CASE("Flap transfer function: limits and values") {
    // Shallow water: H/S = kh / 2 (Dean & Dalrymple §6.2); no cancellation at small kh.
    for (double kh : {1e-9, 1e-6, 1e-4})
        CHECK(flap_height_to_stroke(kh) == doctest::Approx(kh / 2).epsilon(1e-7));
    // Deep water: H/S = 2 (1 - 1/kh) up to exponentially small terms, -> 2.
    for (double kh : {40.0, 1e3, 1e6})
        CHECK(flap_height_to_stroke(kh) == doctest::Approx(2 * (1 - 1 / kh)).epsilon(1e-14));
    CHECK(flap_height_to_stroke(1e9) == doctest::Approx(2.0).epsilon(1e-8));
    // 4 sinh kh (1 - cosh kh + kh sinh kh) / (kh (sinh 2kh + 2kh)) to 40 digits (mpmath).
    CHECK(flap_height_to_stroke(0.05) == doctest::Approx(0.025005203560287537).epsilon(1e-13));
    CHECK(flap_height_to_stroke(0.5) == doctest::Approx(0.25474376376054894).epsilon(1e-14));
    CHECK(flap_height_to_stroke(1.0) == doctest::Approx(0.52808762358926085).epsilon(1e-14));
    CHECK(flap_height_to_stroke(2.0) == doctest::Approx(1.0412385908643425).epsilon(1e-14));
    CHECK(flap_height_to_stroke(10.0) == doctest::Approx(1.800018003322708).epsilon(1e-14));
    for (double kh = 0.3; kh < 10; kh *= 1.3) {
        const double direct = 4 * std::sinh(kh) * (1 - std::cosh(kh) + kh * std::sinh(kh)) /
                              (kh * (std::sinh(2 * kh) + 2 * kh));
        CHECK(flap_height_to_stroke(kh) == doctest::Approx(direct).epsilon(1e-12));
    }
    // A flap moves less water than a piston of the same stroke at the surface.
    for (double kh = 0.05; kh < 10; kh *= 1.3)
        CHECK(flap_height_to_stroke(kh) < piston_height_to_stroke(kh));
}

TEST_CASE("Madsen's second-order piston term, by hand at kh = 1") {
    // h = 0.5 m, k = 2 rad/m (kh = 1): omega^2 = g k tanh(kh), T = 1.6254311014483264 s.
    RegularWave w{0.1, 2 * pi / std::sqrt(9.81 * 2 * std::tanh(1.0)), 0.5};
    CHECK(wave_number(2 * pi / w.period, w.depth, w.g) == doctest::Approx(2.0).epsilon(1e-13));
    // m1 = 0.981789307313034, S = H / m1 = 0.101854847323282 m.
    CHECK(piston_stroke(w) == doctest::Approx(0.10185484732328209).epsilon(1e-13));
    // 3 cosh 1 / sinh^3 1 = 3 (1.5430806348) / 1.6230592 = 2.8521431; 2 / m1 = 2.0371005;
    // difference 0.8150426 times H^2 / (32 h) = 0.000625: X2 = 5.0940e-4 m.
    CHECK(piston_second_order_amplitude(w) ==
          doctest::Approx(0.00050941161419526044).epsilon(1e-12));
    CHECK(piston_second_order_valid(w));
    // In the displacement: X(t) - X1(t) = X2 sin(2 tau) after the ramp; at tau = pi/4 (mod 2
    // pi) the first-order term is S/2 sin(pi/4) and the second-order one is X2.
    const double start = 0.5, ramp = 2 * w.period, phase = 0.3;
    const Signal x1 = piston_displacement(w, phase, start, ramp, false);
    const Signal x2 = piston_displacement(w, phase, start, ramp, true);
    const double omega = 2 * pi / w.period;
    const double t = start + 3 * w.period + (pi / 4 - phase) / omega;
    CHECK(x1(t).value == doctest::Approx(piston_stroke(w) / 2 * std::sin(pi / 4)).epsilon(1e-12));
    CHECK(x2(t).value - x1(t).value ==
          doctest::Approx(piston_second_order_amplitude(w)).epsilon(1e-9));
    // Deep water: the term tends to -H^2 / (32 h) (the bound part vanishes, 2 / m1 -> 1).
    RegularWave deep{0.01, 0.5, 5.0}; // kh ~ 80
    CHECK(piston_second_order_amplitude(deep) ==
          doctest::Approx(-0.01 * 0.01 / (32 * 5.0)).epsilon(1e-12));
    // Shallow water: H L^2 / h^3 past 8 pi^2 / 3 is outside Madsen's theory.
    CHECK_FALSE(piston_second_order_valid(RegularWave{0.05, 10.0, 0.3}));
}

TEST_CASE("Piston and flap signals: zero before start, rate and accel are derivatives") {
    const RegularWave w{0.08, 1.4, 0.6};
    const double start = 0.25, ramp = 3.0;
    const Signal piston1 = piston_displacement(w, 0.0, start, ramp, false);
    const Signal piston2 = piston_displacement(w, 1.1, start, ramp, true);
    const Signal flap = flap_angle(w, 0.4, start, ramp);
    for (const Signal* s : {&piston1, &piston2, &flap}) {
        const SignalValue before = (*s)(start - 0.1), at = (*s)(start);
        CHECK(before.value == 0);
        CHECK(before.rate == 0);
        CHECK(at.accel == 0);
    }
    const double omega = 2 * pi / w.period;
    const double a = piston_stroke(w) / 2;
    // The flap's stroke at the still water level, S/2 = H / (H/S)_flap / 2, and its angle.
    const double kh = wave_number(omega, w.depth, w.g) * w.depth;
    const double half_stroke = w.height / flap_height_to_stroke(kh) / 2;
    const double theta = std::atan(half_stroke / w.depth);
    // During the ramp and after it.
    for (double t = start + 0.05; t < start + ramp + 2 * w.period; t += 0.173) {
        check_derivatives(piston1, t, a * omega, a * omega * omega);
        check_derivatives(piston2, t, a * omega, a * omega * omega);
        check_derivatives(flap, t, theta * omega, theta * omega * omega);
    }
    // After the ramp, at sin(tau) = 1: the full first-order stroke, and the flap's angle that
    // puts its still-water crossing at S/2.
    const double t_peak = start + 5 * w.period + w.period / 4;
    CHECK(piston1(t_peak).value == doctest::Approx(a).epsilon(1e-12));
    const Signal flap0 = flap_angle(w, 0.0, start, ramp);
    CHECK(flap0(t_peak).value == doctest::Approx(theta).epsilon(1e-12));
    CHECK(std::tan(flap0(t_peak).value) * w.depth == doctest::Approx(half_stroke).epsilon(1e-12));
}

TEST_CASE("Miche's breaking limit") {
    // Deep water: H_max / L = 0.142 (about 1/7).
    const double k = 2 * pi / 3.0;
    CHECK(breaking_steepness_limit(k, 100.0) == doctest::Approx(0.142 * 3.0).epsilon(1e-14));
    // Shallow water: 0.142 L kh = 0.142 * 2 pi h = 0.892 h, close to McCowan's 0.78 h.
    CHECK(breaking_steepness_limit(1e-3, 1.0) == doctest::Approx(0.142 * 2 * pi).epsilon(1e-6));
}

TEST_CASE("JONSWAP components: Hs, the peak, frequencies, phases") {
    JonswapSea sea;
    sea.hs = 0.12;
    sea.tp = 1.6;
    sea.depth = 0.7;
    const std::vector<WaveComponent> c = jonswap_components(sea);
    REQUIRE(c.size() == 64);
    // 4 sqrt(m0) = Hs, m0 = sum a_i^2 / 2.
    double m0 = 0;
    for (const WaveComponent& w : c)
        m0 += w.amplitude * w.amplitude / 2;
    CHECK(4 * std::sqrt(m0) == doctest::Approx(sea.hs).epsilon(1e-10));
    // Equally spaced integer multiples of df, over [f_min, f_max] to within df / 2.
    const double fp = 1 / sea.tp, df = 2.5 * fp / 64;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const double n = c[i].frequency / df;
        CHECK(std::abs(n - std::round(n)) < 1e-9);
        if (i > 0)
            CHECK(c[i].frequency - c[i - 1].frequency == doctest::Approx(df).epsilon(1e-12));
    }
    CHECK(std::abs(c.front().frequency - 0.5 * fp) <= df / 2 + 1e-12);
    CHECK(std::abs(c.back().frequency - 3.0 * fp) <= 1.5 * df + 1e-12);
    // The largest component is the one nearest the peak frequency 1/Tp.
    const auto peak = std::max_element(
        c.begin(), c.end(), [](const auto& a, const auto& b) { return a.amplitude < b.amplitude; });
    CHECK(std::abs(peak->frequency - fp) <= df / 2 + 1e-12);
    // Phases in [0, 2 pi), the same for the same seed, different for another.
    const std::vector<WaveComponent> again = jonswap_components(sea);
    JonswapSea other = sea;
    other.seed = 2;
    const std::vector<WaveComponent> d = jonswap_components(other);
    int differ = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        CHECK(c[i].phase >= 0);
        CHECK(c[i].phase < 2 * pi);
        CHECK(c[i].phase == again[i].phase);
        CHECK(c[i].amplitude == d[i].amplitude);
        differ += c[i].phase != d[i].phase;
    }
    CHECK(differ == 64);
    // The standard's mt19937_64 sequence (first draw for seed 1), top 53 bits to [0, 1).
    const std::uint64_t first = 2469588189546311528ULL;
    CHECK(c[0].phase == 2 * pi * (static_cast<double>(first >> 11) * 0x1.0p-53));
    // gamma = 1 is Pierson-Moskowitz: the same Hs, a lower peak.
    JonswapSea pm = sea;
    pm.gamma = 1;
    const std::vector<WaveComponent> p = jonswap_components(pm);
    double m0_pm = 0, a_max = 0;
    for (const WaveComponent& w : p) {
        m0_pm += w.amplitude * w.amplitude / 2;
        a_max = std::max(a_max, w.amplitude);
    }
    CHECK(4 * std::sqrt(m0_pm) == doctest::Approx(sea.hs).epsilon(1e-10));
    CHECK(a_max < peak->amplitude);
}

TEST_CASE("Irregular piston signal: per-component amplitudes, derivatives, period 1/df") {
    JonswapSea sea;
    sea.hs = 0.1;
    sea.tp = 1.5;
    sea.depth = 0.8;
    sea.components = 16;
    const double start = 1.0, ramp = 4.0;
    const Signal x = piston_irregular(sea, start, ramp);
    CHECK(x(start).value == 0);
    // After the ramp: the sum of a_i / m1(k_i h) sin(2 pi f_i (t - start) + phase_i).
    const double t = start + ramp + 3.3;
    double expected = 0;
    for (const WaveComponent& w : jonswap_components(sea)) {
        const double omega = 2 * pi * w.frequency;
        const double kh = wave_number(omega, sea.depth, sea.g) * sea.depth;
        expected +=
            w.amplitude / piston_height_to_stroke(kh) * std::sin(omega * (t - start) + w.phase);
    }
    CHECK(x(t).value == doctest::Approx(expected).epsilon(1e-12));
    const double omega_p = 2 * pi / sea.tp;
    for (double s = start + 0.1; s < start + ramp + 5; s += 0.37)
        check_derivatives(x, s, sea.hs * omega_p, sea.hs * omega_p * omega_p);
    // The record repeats after 1/df.
    const double repeat = 1 / (2.5 / sea.tp / 16);
    for (double s = start + ramp; s < start + ramp + 3; s += 0.41)
        CHECK(x(s + repeat).value == doctest::Approx(x(s).value).scale(sea.hs).epsilon(1e-10));
}
