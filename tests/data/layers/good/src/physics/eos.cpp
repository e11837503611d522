// Fixture for the layer check: physics includes core and physics.
#include "sluice/physics/eos.hpp"
#include "sluice/core/types.hpp"
// #include "sluice/io/case_config.hpp" in a comment is not an include
