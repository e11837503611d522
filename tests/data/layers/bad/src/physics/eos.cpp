// Fixture for the layer check: physics includes io (angle brackets).
#include "sluice/physics/eos.hpp"
#include <sluice/io/case_config.hpp>
