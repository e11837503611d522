#pragma once
// Keeps the particle arrays sorted by (Morton key of their cell, id): the particles of a cell
// are then contiguous, cells follow the space-filling curve, and the order inside a cell is
// a property of the particles, not of the history of the run.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"

#include <array>
#include <vector>

namespace sluice {

struct CellOccupancy {
    CellIndex cell;
    MortonKey key;
    std::uint32_t count;
};

// Sorts P (if needed), fills `ranges` for every cell of the grid (clearing only the cells it
// and the halo unpacks listed there last time) and lists the occupied cells in Morton order.
// Returns true when the order changed. Keeps its buffers and the Morton order of the grid's
// cells between calls (the solver rebins at every Verlet-list rebuild).
template <int D>
class Rebinner {
public:
    bool operator()(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
                    std::vector<CellOccupancy>& occupied);

private:
    void prepare(const CellGrid<D>& grid);
    std::array<int, D> dims_{};
    std::vector<CellIndex> morton_order_; // every cell of the grid, in Morton order
    std::vector<MortonKey> morton_keys_;  // their keys (sorted)
    std::vector<std::uint32_t> start_;    // per cell: counting-sort offsets (zero between calls)
    std::vector<MortonKey> key_, key_sorted_;
    std::vector<CellIndex> cell_, cell_sorted_;
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
