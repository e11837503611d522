#pragma once
// Fixture for the layer check: io includes the solver.
#include "sluice/io/case_config.hpp"
#include "sluice/solver/run.hpp"
