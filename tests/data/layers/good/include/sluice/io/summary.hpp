#pragma once
// Fixture for the layer check: io includes core, physics, io and the version header.
#include "sluice/core/types.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/physics/options.hpp"
#include "sluice/version.hpp"
