#pragma once
// The rank's neighbour lists (docs/ARCHITECTURE.md, "Neighbour lists" and "Verlet lists"): per
// cell group, the pairs that a step's stages walk and, with a skin > 0, the wider lists they
// are selected from, kept until some particle has moved more than skin/2 since they were
// built. The first stage of each group fills them (a scheme's stage body); this unit sizes
// them, counts the rebuilds and decides when the lists expire.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/types.hpp"

#include <cstddef>
#include <vector>

namespace sluice {

template <int D>
struct NeighbourLists {
    std::vector<NeighbourList<D>> lists; // per group, this step's pairs within the support
    // Per group (skin > 0), the pairs within support + skin at the last rebuild.
    std::vector<NeighbourList<D>> wide;
    Real skin = 0;       // numerics.neighbour_skin [m]; 0: lists every step
    bool rebuilt = true; // the coming (or running) step starts from a rebuild
    long rebuilds = 0;   // steps that began with a rebuild

    // One list per cell group (buffers keep their capacity).
    void resize(std::size_t groups) {
        lists.resize(groups);
        wide.resize(skin > 0 ? groups : 0);
    }
    // At the start of a step.
    void count_step() {
        if (rebuilt)
            ++rebuilds;
    }
    // After a step, given the largest squared displacement of any particle (all ranks) from
    // the positions of the last rebuild and whether particles are to be removed (all ranks):
    // whether the lists are rebuilt before the next step. They stay valid while every particle
    // is within skin/2 of where they were built and none leaves the set.
    bool expire(Real disp2_max, bool removals) {
        rebuilt = expired(disp2_max, removals);
        return rebuilt;
    }
    [[nodiscard]] bool expired(Real disp2_max, bool removals) const {
        return removals || skin <= 0 || disp2_max > 0.25 * skin * skin;
    }
};

} // namespace sluice
