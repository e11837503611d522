#pragma once
// A time-integration scheme as Simulation drives it (docs/ARCHITECTURE.md, "Schemes"): the
// stages of its step graphs, each declared once as a row (name, reach, the halo field its
// results travel as), the body of each stage, what its step runs around the graphs, and its
// time-step and neighbour-list settings; and the units of the rank's state it is lent. WCSPH
// (schemes/wcsph/) and projection (schemes/projection/) are the two implementations. Private to
// src/solver.
#include "sluice/solver/halo_fields.hpp"
#include "sluice/solver/neighbour_lists.hpp"
#include "sluice/solver/pressure_solve.hpp"
#include "sluice/solver/simulation.hpp"
#include "sluice/solver/step_units.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace sluice {

// One stage of a step graph, declared once: its name, how far it reads the previous stage,
// and the halo field (halo_fields.hpp: the particles it carries, the arrays it copies) that
// carries its results to the other ranks' next stages, if any.
struct StageRow {
    const char* name;
    tasks::Reach reach;
    std::optional<HaloField> sends;
    // The first stage that reads what the previous step's agreement decides (dt, the largest
    // speed): it waits for the main thread's gate, and the stages before it may run ahead
    // (docs/ARCHITECTURE.md, "Time step").
    bool gated = false;
};

// What a scheme needs of the rank to wire a graph's halo exchanges.
struct GraphSite {
    const std::vector<std::vector<int>>* neighbours = nullptr; // group adjacency
    bool parallel = false;
    std::vector<int> peers;
    std::vector<std::vector<int>> boundary; // per peer: local groups that face it
    tbb::task_arena* arena = nullptr;
};

// The step graph that `rows` declare: one stage per row and one halo exchange per row that
// sends a field (after `before`, the field sent before the first stage, if any). `halo`
// receives the exchanged fields in exchange order and packs them.
template <int D>
std::unique_ptr<tasks::StepGraph>
graph_of_rows(const std::vector<StageRow>& rows, std::optional<HaloField> before,
              tasks::StepGraph::Body body, const GraphSite& site, HaloFields<D>& halo) {
    std::vector<tasks::StageSpec> specs;
    for (const StageRow& row : rows)
        specs.push_back({row.name, row.reach, row.gated});
    tasks::HaloWiring wiring;
    if (site.parallel) {
        halo.exchanges.clear();
        if (before) {
            wiring.exchanges.push_back({before->name, -1});
            halo.exchanges.push_back(*before);
        }
        for (std::size_t stage = 0; stage < rows.size(); ++stage)
            if (rows[stage].sends) {
                wiring.exchanges.push_back({rows[stage].sends->name, static_cast<int>(stage)});
                halo.exchanges.push_back(*rows[stage].sends);
            }
        wiring.peers = site.peers;
        wiring.boundary = site.boundary;
        wiring.data = &halo;
    }
    return std::make_unique<tasks::StepGraph>(std::move(specs), *site.neighbours, std::move(body),
                                              std::move(wiring), site.arena);
}

template <int D>
class StepScheme {
public:
    virtual ~StepScheme() = default;

    // Neighbour-list skin [m] (numerics.neighbour_skin, or 0 where the scheme builds its
    // lists every step).
    [[nodiscard]] virtual Real skin() const = 0;
    // The sound speed of the CFL limit.
    [[nodiscard]] virtual double cfl_speed() const = 0;
    // Once, after the particles are generated (or read from a checkpoint) and before they are
    // distributed: the scheme's own per-particle state.
    virtual void start() {}
    // The step graph over the current cell groups (and the scheme's other graphs). The
    // previous graphs are already destroyed or are destroyed here before the new ones.
    virtual std::unique_ptr<tasks::StepGraph> build_graph(const GraphSite& site) = 0;
    // One step: the step graph (the last build_graph's), and whatever the scheme runs around
    // it. A throwing task's error is rethrown after every message of the step has completed.
    // `gate` opens the step graph's gated stage (StepGraph::run), if it has one.
    virtual void run(tasks::StepGraph& graph, const tasks::StepGraph::GatePoll& gate) = 0;
    // Running ahead: the stages before the gated one may run while the previous step's
    // agreement is in flight. keep_ahead() saves, for the owned particles, every array those
    // stages write; restore_ahead() puts it back when the step that ran ahead is discarded.
    virtual void keep_ahead(std::size_t /*owned*/) {}
    virtual void restore_ahead(std::size_t /*owned*/) {}

    // Projection: the last step's pressure solve and totals over the run (null otherwise).
    [[nodiscard]] virtual const PressureSolveRecord* last_pressure_solve() const { return nullptr; }
    [[nodiscard]] virtual const PressureSolveTotals* pressure_solve_totals() const {
        return nullptr;
    }
    // Projection: the last step's wall collisions of this rank's fluid particles (none
    // otherwise: WCSPH's walls act through pair forces only).
    [[nodiscard]] virtual std::span<const WallContact<D>> wall_contacts() const { return {}; }
    // The lowest pressure the scheme applies to the fluid, below which probes do not read
    // (-infinity: WCSPH's fluid pairs apply every pressure, tension included).
    [[nodiscard]] virtual Real applied_pressure_floor() const {
        return -std::numeric_limits<Real>::infinity();
    }
};

// What a Simulation lends its scheme, in units (docs/ARCHITECTURE.md, "Schemes"): a scheme's
// constructor takes the units it uses, besides the particles (Particles<D>&), the neighbour
// lists (NeighbourLists<D>&, which its first stage fills), the step clock (const StepClock&)
// and the per-group results that its last stage writes (GroupResults&). Nothing else of the
// Simulation is reachable from a scheme.

// Read-only for the whole run: the case and the physics parameters derived from it.
template <int D>
struct CaseParams {
    const CaseConfig& cfg;
    const AnyKernel<D>& kernel;
    const Eos& eos;
    const MomentumParams<D>& momentum;
    const TimeStepParams& time_step; // CFL, viscous and force limits
    const Reflector<D>& walls;       // reflective walls (none under dummy walls)
    const WallMotion<D>& motion;     // moving wall objects (empty when every wall is fixed)
    const StateBounds<D>& bounds;    // healthy range of a fluid particle's state
    double h;                        // smoothing length [m]
};

// The rank's cells: the grid, each cell's particle range (the state exchange records the halo
// cells'), and the cell groups whose (stage, group) nodes run the stage bodies.
template <int D>
struct RankCells {
    const CellGrid<D>& grid;
    CellRanges& ranges;
    const tasks::GroupTopology& topo;
};

// What a scheme may use of the rank's communication besides its graphs' halo exchanges.
struct RankLink {
    const tasks::Comm& comm;                    // the scheme's own reductions
    const HaloPlan& plan;                       // the particles each halo message carries
    std::vector<tasks::MessageRecord>& between; // its messages outside the step graphs
    const double& receive_delay; // test hook: the delay of every halo message's arrival
};

} // namespace sluice
