#pragma once
// The lattice arithmetic shared by the particle builders (initial_state.cpp) and the report of
// the geometry as built (built_geometry.cpp), so that the report counts exactly the sites the
// builders fill. Private to src/solver.
#include "sluice/io/case_config.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace sluice::detail {

// The wall sites along one axis (see axis_sites in initial_state.cpp): their coordinates, and
// how many belong to the stack laid from the low end, the span between, the stack from the
// high end.
struct AxisSites {
    std::vector<double> x;
    int n_a = 0, mid = 0, n_b = 0; // sites in each part (thin: all in mid)
    bool thin = false;
};

// Lattice points of spacing dx centred in [lo, hi): lo + (k + 1/2) dx.
int lattice_count(double lo, double hi, double dx);

// Whether the tank face (axis, upper) is named in walls.tank_faces.
bool face_walled(const CaseConfig& cfg, int axis, bool upper);

// The tank's wall sites along axis d: the walled faces' layers laid outwards from tank_lo and
// tank_hi, the span between them covered as axis_sites does.
AxisSites tank_axis_sites(const CaseConfig& cfg, int d, int layers);

// A box's sites along axis d: `layers` laid inwards from each face.
AxisSites box_axis_sites(const WallBox& b, int d, int layers, double dx);

// Particles of block b (the lattice of add_fluid_blocks, the shape's test).
std::size_t block_particles(const CaseConfig& cfg, const FluidBlock& b);

// Wall particles of box b: its sites less those deeper than `layers` from every face; n is set
// to its sites along each axis.
std::size_t box_particles(const CaseConfig& cfg, const WallBox& b, int layers,
                          std::array<int, 3>& n);

} // namespace sluice::detail
