#pragma once
// Scalar and small-vector types shared by every layer.
#include <Eigen/Core>
#include <cstdint>

namespace sluice {

// Floating-point type of all particle state. Double by default (see docs/ARCHITECTURE.md).
using Real = double;

// Small fixed-size vector of dimension D (2 or 3). Eigen does this well; no hand-rolled type.
template <int D>
using Vec = Eigen::Matrix<Real, D, 1>;

template <int D>
using Mat = Eigen::Matrix<Real, D, D>;

using ParticleId = std::uint64_t;

// What a particle is. Wall (dummy) particles take part in sums but are not integrated.
enum class Kind : std::uint8_t { fluid = 0, wall = 1 };

} // namespace sluice
