#pragma once
// Fixture for the layer check: core includes only core.
#include "sluice/core/types.hpp"
