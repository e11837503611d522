#pragma once
// Keeps the particle arrays sorted by (Morton key of their cell, id): the particles of a cell
// are then contiguous, cells follow the space-filling curve, and the order inside a cell is
// a property of the particles, not of the history of the run.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/cell_ranges.hpp"
#include "sluice/core/particles.hpp"

#include <array>
#include <vector>

namespace sluice {

struct CellOccupancy {
    CellIndex cell;
    MortonKey key;
    std::uint32_t count;
};

// Sorts P (if needed), sets `ranges` for the cells holding particles (clearing every other
// range, the halo's included) and lists the occupied cells in Morton order. Returns true when
// the order changed. Keeps its buffers between calls (the solver rebins at every Verlet-list
// rebuild); none of them is per cell of the grid, so its memory follows the particles.
template <int D>
class Rebinner {
public:
    bool operator()(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
                    std::vector<CellOccupancy>& occupied);

private:
    std::vector<MortonKey> key_, key_sorted_;
    std::vector<CellIndex> cell_, cell_sorted_;
    std::vector<MortonKey> distinct_;  // the particles' keys, sorted, once each
    std::vector<std::uint32_t> place_; // per particle: its key's position in distinct_
    std::vector<std::uint32_t> start_; // per distinct key: counting-sort offsets
    std::vector<std::size_t> perm_;
};

// One-off rebin (tests, tools).
template <int D>
bool rebin(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
           std::vector<CellOccupancy>& occupied);

extern template class Rebinner<2>;
extern template class Rebinner<3>;
extern template bool rebin<2>(const CellGrid<2>&, Particles<2>&, CellRanges&,
                              std::vector<CellOccupancy>&);
extern template bool rebin<3>(const CellGrid<3>&, Particles<3>&, CellRanges&,
                              std::vector<CellOccupancy>&);

} // namespace sluice
