#pragma once
// A time-integration scheme as Simulation drives it (docs/ARCHITECTURE.md, "Schemes"): the
// stages of its step graphs, each declared once as a row (name, reach, the halo field its
// results travel as), the body of each stage, what its step runs around the graphs, and its
// time-step and neighbour-list settings. WCSPH (schemes/wcsph/) and projection
// (schemes/projection/) are the two implementations. Private to src/solver.
#include "sluice/solver/pressure_solve.hpp"
#include "sluice/solver/simulation.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace sluice {

// One stage of a step graph: its name, how far it reads the previous stage, and the halo
// field (the scheme's own enumeration) that carries its results to the other ranks' next
// stages, if any.
template <class Field>
struct StageRow {
    const char* name;
    tasks::Reach reach;
    std::optional<Field> sends;
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
// sends a field (after `before`, the field sent before the first stage, if any). `fields`
// receives the exchanged fields in exchange order, for `data` to pack by.
template <class Field, class Name>
std::unique_ptr<tasks::StepGraph> graph_of_rows(const std::vector<StageRow<Field>>& rows,
                                                std::optional<Field> before, Name name,
                                                tasks::StepGraph::Body body, const GraphSite& site,
                                                tasks::HaloData* data, std::vector<Field>& fields) {
    std::vector<tasks::StageSpec> specs;
    for (const StageRow<Field>& row : rows)
        specs.push_back({row.name, row.reach});
    tasks::HaloWiring wiring;
    if (site.parallel) {
        fields.clear();
        if (before) {
            wiring.exchanges.push_back({name(*before), -1});
            fields.push_back(*before);
        }
        for (std::size_t stage = 0; stage < rows.size(); ++stage)
            if (rows[stage].sends) {
                wiring.exchanges.push_back({name(*rows[stage].sends), static_cast<int>(stage)});
                fields.push_back(*rows[stage].sends);
            }
        wiring.peers = site.peers;
        wiring.boundary = site.boundary;
        wiring.data = data;
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
    // One step: the step graph (graph_), and whatever the scheme runs around it. A throwing
    // task's error is rethrown after every message of the step has completed.
    virtual void run() = 0;

    // Projection: the last step's pressure solve and totals over the run (null otherwise).
    [[nodiscard]] virtual const PressureSolveRecord* last_pressure_solve() const { return nullptr; }
    [[nodiscard]] virtual const PressureSolveTotals* pressure_solve_totals() const {
        return nullptr;
    }
};

// The rank's state that stage bodies read and write, by reference into the Simulation. The
// names are the Simulation members' own, so that a stage body reads the same in a scheme as
// it did in Simulation.
template <int D>
struct SchemeContext {
    explicit SchemeContext(Simulation<D>& s)
        : cfg_(s.cfg_), opts_(s.opts_), comm_(s.comm_), P_(s.P_), grid_(s.grid_),
          ranges_(s.ranges_), plan_(s.ranks_.plan()), topo_(s.topo_), kernel_(s.kernel_),
          eos_(s.eos_), momentum_(s.momentum_), ts_params_(s.ts_params_), planes_(s.planes_),
          bounds_(s.bounds_), h_(s.h_), lists_(s.neighbours_.lists), wide_(s.neighbours_.wide),
          skin_(s.neighbours_.skin), rebuilt_(s.neighbours_.rebuilt),
          group_limits_(s.group_limits_), group_failure_(s.group_failure_),
          group_speed_(s.group_speed_), group_disp2_(s.group_disp2_), u_max_(s.u_max_),
          time_(s.time_), dt_(s.dt_), dt_prev_(s.dt_prev_), steps_(s.steps_), between_(s.between_),
          receive_delay_(s.receive_delay_), graph_(s.graph_) {}

    const CaseConfig& cfg_;
    const SimulationOptions& opts_;
    const tasks::Comm& comm_;
    Particles<D>& P_;
    const CellGrid<D>& grid_;
    CellRanges& ranges_;
    const HaloPlan& plan_;
    const tasks::GroupTopology& topo_;
    const AnyKernel<D>& kernel_;
    const Eos& eos_;
    const MomentumParams<D>& momentum_;
    const TimeStepParams& ts_params_;
    const std::vector<Plane<D>>& planes_;
    const StateBounds<D>& bounds_;
    const double& h_;
    std::vector<NeighbourList<D>>& lists_;
    std::vector<NeighbourList<D>>& wide_;
    const Real& skin_;
    const bool& rebuilt_;
    // Per-group results of the step, which the step's reduction agrees on.
    std::vector<TimeStepLimits>& group_limits_;
    std::vector<std::string>& group_failure_;
    std::vector<Real>& group_speed_;
    std::vector<Real>& group_disp2_;
    const Real& u_max_;
    const double& time_;
    const double& dt_;
    const double& dt_prev_;
    const long& steps_;
    std::vector<tasks::MessageRecord>& between_; // communication outside the step graph
    const double& receive_delay_;
    std::unique_ptr<tasks::StepGraph>& graph_;
};

} // namespace sluice
