#pragma once
// Where a case's particles may lie along an axis: the domain, the tank grown by its dummy wall
// layers, and each mesh (a surface's bounding box grown by its wall layers: they may reach
// past the domain as the tank's do). The solver's cell grid covers it plus one kernel support
// on open axes; the case checks size that grid and `sluice info` reports it.
#include "sluice/io/case_config.hpp"

#include <cstddef>

namespace sluice {

struct AxisExtent {
    double lo = 0, hi = 0;
};

AxisExtent wall_extent(const CaseConfig& c, std::size_t axis);

} // namespace sluice
