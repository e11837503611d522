// Fixture for the layer check: physics declares its names in `sluice`, internals in `detail`.
#include "sluice/core/types.hpp"
namespace sluice {
namespace detail {} // namespace detail
} // namespace sluice
