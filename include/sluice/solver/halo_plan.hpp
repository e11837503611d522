#pragma once
// Who sends which particles to each peer rank this step (filled between steps by the rank's
// halo plan, RankExchange::plan_halo in src/solver/rank_exchange.cpp; packed by a scheme's
// halo fields).
#include "sluice/core/cell_grid.hpp"

#include <cstddef>
#include <vector>

namespace sluice {

struct HaloPlan {
    std::vector<std::vector<CellIndex>> send_cells;  // per peer, this rank's cells in key order
    std::vector<std::size_t> send_count, send_walls; // particles (and walls among them) sent
    std::vector<std::size_t> recv_count, recv_walls; // particles (and walls) received
    std::vector<std::size_t> recv_offset;            // where each peer's halo starts in P
};

} // namespace sluice
