#pragma once
// Fixture for the layer check (tests/layers/check_layers.sh): core includes physics.
#include "sluice/core/types.hpp"
#include "sluice/physics/kernels.hpp"
