#pragma once
// Scalar and small-vector types shared by every layer.
#include <Eigen/Core>
#include <cstdint>
#include <type_traits>

// On a per-cell neighbour loop: inline every call inside it (the per-pair lambda included).
// Without it GCC 12 keeps the pair lambda an out-of-line call, since the neighbour walks invoke
// it from several places, and a call per pair costs a third of a stage (perf/NOTES.md).
// Only in optimised builds without sanitizers: with ASan's instrumentation, flattening makes
// GCC spend over 7 minutes and 2.7 GB on simulation.cpp.
#if defined(__OPTIMIZE__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
#define SLUICE_FLATTEN [[gnu::flatten]]
#else
#define SLUICE_FLATTEN
#endif

namespace sluice {

// Floating-point type of the particle state and of the pair arithmetic: double unless the build
// sets SLUICE_PRECISION=float (CMakeLists.txt). Simulated time, reductions over all particles
// (mass, energy, diagnostics) and every file format stay double (docs/ARCHITECTURE.md).
#ifdef SLUICE_SINGLE_PRECISION
using Real = float;
#else
using Real = double;
#endif
// Whether this build is the single-precision one: what summary.json, --version, checkpoints and
// the case checks ask of it.
inline constexpr bool single_precision = std::is_same_v<Real, float>;

// Small fixed-size vector of dimension D (2 or 3). Eigen does this well; no hand-rolled type.
template <int D>
using Vec = Eigen::Matrix<Real, D, 1>;

template <int D>
using Mat = Eigen::Matrix<Real, D, D>;

using ParticleId = std::uint64_t;

// What a particle is. Wall (dummy) particles take part in sums but are not integrated.
enum class Kind : std::uint8_t { fluid = 0, wall = 1 };

} // namespace sluice
