#pragma once
// The memory estimate of a case (sluice/io/memory_estimate.hpp) from its configuration: the
// solver's bytes per particle and the grid the solver builds.
#include "sluice/io/case_config.hpp"
#include "sluice/io/memory_estimate.hpp"

#include <cstddef>

namespace sluice {

// Micro-cells of the solver's grid: the wall extent plus one support on open axes, the domain
// on periodic ones, in cells one support wide (`sluice info`'s "cells").
double case_grid_cells(const CaseConfig& cfg);

// The estimate for given particle counts on `ranks` ranks.
MemoryEstimate case_memory(const CaseConfig& cfg, double fluid, double walls, int ranks);

// Before anything is counted (counting a shaped block visits every lattice site of its box): the
// fluid blocks' lattice boxes (exact for boxes, more for shapes), no walls.
MemoryEstimate case_memory_before_counting(const CaseConfig& cfg, int ranks);

} // namespace sluice
