#pragma once
// Wave-maker theory: the paddle motion that makes a wave of given height and period in water of
// given depth. Linear dispersion, the Biésel transfer functions of a piston and of a flap hinged
// at the bed (Dean & Dalrymple 1991, "Water wave mechanics for engineers and scientists", ch. 6,
// "Wavemaker theory"), Madsen's (1971) second-order correction for a piston, and a JONSWAP sea
// as a sum of linear components. The paddle motions are Signals (motion/signal.hpp), ramped in
// smoothly. Pure numerics, double throughout. k is the wave number [rad/m], h the still-water
// depth [m], omega the angular frequency [rad/s].
#include "sluice/motion/signal.hpp"

#include <cstdint>
#include <vector>

namespace sluice {

// k of the linear dispersion relation omega^2 = g k tanh(k h) (Dean & Dalrymple ch. 3), by
// Newton iteration on kh from Fenton & McKee's (1990) explicit approximation, to round-off.
double wave_number(double omega, double depth, double g);

// Wave height over stroke H/S of a piston (the whole depth moving as one), from the full linear
// wavemaker theory (Dean & Dalrymple §6.3; Biésel 1951):
//     H/S = 2 (cosh 2kh - 1) / (sinh 2kh + 2kh),
// kh in shallow water (the shallow-water theory of §6.2), 2 in deep water. kh > 0.
double piston_height_to_stroke(double kh);

// H/S of a flap hinged at the bed, S the stroke at the still water level (Dean & Dalrymple
// §6.3):
//     H/S = 4 sinh kh (1 - cosh kh + kh sinh kh) / (kh (sinh 2kh + 2kh)),
// kh/2 in shallow water, 2 (1 - 1/kh) -> 2 in deep water. kh > 0.
double flap_height_to_stroke(double kh);

// A regular (monochromatic) wave: height H [m], period T [s], still-water depth h [m].
struct RegularWave {
    double height = 0;
    double period = 0;
    double depth = 0;
    double g = 9.81;
};

// The stroke S (peak to peak) of a piston that makes `wave` to first order: H / (H/S)(kh).
double piston_stroke(const RegularWave& wave);

// Amplitude of Madsen's (1971) second-order piston motion, the term that suppresses the spurious
// free second harmonic a purely sinusoidal piston radiates:
//     X2 = H^2 / (32 h) (3 cosh kh / sinh^3 kh - 2 / m1),   m1 = (H/S)(kh) of the piston,
// the formula DualSPHysics implements (its libjwavegen, JWavePaddle::CalcCtePos2nd; described
// in Altomare et al. 2017, Coastal Eng. 127:37-54). Positive in shallow water, negative for
// kh > 1.157.
double piston_second_order_amplitude(const RegularWave& wave);

// Madsen's validity condition of that second-order theory, an Ursell number H L^2 / h^3 below
// 8 pi^2 / 3 (the criterion DualSPHysics checks; Madsen 1971). L = 2 pi / k.
bool piston_second_order_valid(const RegularWave& wave);

// The piston's displacement X(t) along the tank, ramped in by smooth_ramp over `ramp` seconds
// after `start` (0 before start); with tau = omega (t - start) + phase:
//     first order:  X = S/2 sin(tau),
//     second_order: X = S/2 sin(tau) + X2 sin(2 tau)  (Madsen 1971, X2 above).
Signal piston_displacement(const RegularWave& wave, double phase, double start, double ramp,
                           bool second_order);

// The angle theta(t) [rad] of a flap hinged at the bed, the hinge at depth h below the still
// water level. Where the flap crosses the still water level moves as X = S/2 sin(tau),
// S = H / (H/S)_flap(kh), ramped as piston_displacement, so theta = atan(X / h), positive when
// the flap leans towards +X (as a rotation about +z with y up, that is -theta). First order
// only: no second-order correction for a flap.
Signal flap_angle(const RegularWave& wave, double phase, double start, double ramp);

// Miche's (1944) breaking limit of a wave's height, H_max = 0.142 L tanh(kh), L = 2 pi / k
// (the steepness limit 1/7 in deep water): a wave-maker asked for more makes breaking waves.
double breaking_steepness_limit(double k, double depth);

// One linear component of an irregular sea: frequency [Hz], amplitude [m] of the surface
// elevation and phase [rad]. A piston moving as sin(2 pi f t + phase) makes the progressive
// wave amplitude cos(k x - 2 pi f t - phase) (Dean & Dalrymple §6.3), t from the start.
struct WaveComponent {
    double frequency = 0;
    double amplitude = 0;
    double phase = 0;
};

// A JONSWAP sea: significant wave height Hs [m], peak period Tp [s], depth h [m], peak
// enhancement gamma, `components` frequencies over [f_min_factor, f_max_factor] / Tp, random
// phases from `seed`.
struct JonswapSea {
    double hs = 0;
    double tp = 0;
    double depth = 0;
    double gamma = 3.3;
    double g = 9.81;
    int components = 64;
    double f_min_factor = 0.5;
    double f_max_factor = 3.0;
    std::uint64_t seed = 1;
};

// The components of `sea`. The JONSWAP shape (DNV-RP-C205 (2010) eq. 3.5.5; Goda 2000 §2.3),
//     S(f) ~ f^-5 exp(-5/4 (f/fp)^-4) gamma^exp(-(f - fp)^2 / (2 sigma^2 fp^2)),
// sigma = 0.07 below fp = 1/Tp and 0.09 above, is scaled so that the discrete spectrum's zeroth
// moment gives 4 sqrt(m0) = Hs exactly (in place of DNV's approximate 1 - 0.287 ln gamma);
// amplitude_i = sqrt(2 S(f_i) df). The frequencies are equally spaced integer multiples of
// df = (f_max - f_min) / components, f_i = (n0 + i) df with n0 df the multiple nearest f_min,
// so the record repeats after 1/df. The phases are uniform in [0, 2 pi), from std::mt19937_64
// (whose sequence the C++ standard fixes) mapped to [0, 1) by its top 53 bits: the same on
// every platform and compiler.
std::vector<WaveComponent> jonswap_components(const JonswapSea& sea);

// The piston displacement of `sea` to first order: each component a piston motion of amplitude
// S_i/2 = a_i / m1(k_i h) (the component's height 2 a_i over the piston's H/S, halved),
//     X(t) = sum_i a_i / m1(k_i h) sin(2 pi f_i (t - start) + phase_i),
// ramped in over `ramp` seconds after `start`. No second-order (Schäffer 1996) correction.
Signal piston_irregular(const JonswapSea& sea, double start, double ramp);

} // namespace sluice
