// Fixture for the layer check: tasks includes core and tasks.
#include "sluice/tasks/comm.hpp"
#include "sluice/core/cell_grid.hpp"
