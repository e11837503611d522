#pragma once
// A sum in particle-id order: the same bits however the particles were stored or gathered
// (Particles::total_mass sums the fluid masses this way; the run's totals sum the masses the
// ranks send rank 0 this way).
#include "sluice/core/types.hpp"

#include <utility>
#include <vector>

namespace sluice {

Real sum_in_id_order(std::vector<std::pair<ParticleId, Real>> values);

} // namespace sluice
