// Fixture for the layer check: tasks includes physics (spaces after the #).
#include "sluice/tasks/comm.hpp"
#include "sluice/core/cell_grid.hpp"
#include "sluice/physics/eos.hpp"
namespace sluice::tasks::tsan {} // namespace sluice::tasks::tsan
