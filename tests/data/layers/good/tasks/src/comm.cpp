// Fixture for the layer check: tasks includes core and tasks.
#include "sluice/core/cell_grid.hpp"
#include "sluice/tasks/comm.hpp"
