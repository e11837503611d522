#pragma once
// Probes sampled where the particles are: each rank sends rank 0 only the particles a due
// probe reads (its footprint), or, for a surge front, its binned columns. Private to the driver
// (run.cpp).
#include "sluice/solver/simulation.hpp"

#include <cstddef>
#include <vector>

namespace sluice {

// Collective (every rank calls it with the same `due`, indices into config().probes). Returns,
// on rank 0, one CSV row (after the time) per due probe, in `due`'s order; nothing elsewhere.
// The values are those of the probe functions over all particles, bit for bit, for any number
// of ranks: each probe reads only particles inside its footprint, and the footprint's
// particles reach rank 0 in the order a gather of all particles would give them. The wall
// collisions an interpolated force probe adds (projection scheme) reach rank 0 from the rank
// of each colliding fluid particle and are summed in particle-id order.
template <int D>
std::vector<std::vector<double>> sample_probes(const Simulation<D>& sim,
                                               const std::vector<std::size_t>& due);

extern template std::vector<std::vector<double>> sample_probes<2>(const Simulation<2>&,
                                                                  const std::vector<std::size_t>&);
extern template std::vector<std::vector<double>> sample_probes<3>(const Simulation<3>&,
                                                                  const std::vector<std::size_t>&);

} // namespace sluice
