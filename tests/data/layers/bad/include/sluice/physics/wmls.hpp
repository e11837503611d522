// Fixture for the layer check: physics declares a namespace of its own (the convention is
// `sluice`), and names a nested one on the same line as a comment: namespace physics {
#include "sluice/core/types.hpp"
namespace sluice::physics {
namespace fs = std::filesystem;
} // namespace sluice::physics
