#pragma once
// A WCSPH simulation: the scene (particles, grid, walls) plus the step graph that advances it.
// This is where physics stages are bound to the runtime's (stage, group) nodes; the physics
// itself lives in include/sluice/physics/, the scheduling in tasks/.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/core/rebin.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/momentum.hpp"
#include "sluice/physics/timestep.hpp"
#include "sluice/physics/walls.hpp"
#include "sluice/tasks/decomposition.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sluice {

template <int D>
class Simulation {
public:
    explicit Simulation(const CaseConfig& cfg);

    // Advances one time step.
    void step();

    [[nodiscard]] double time() const { return time_; }
    [[nodiscard]] long steps() const { return steps_; }
    [[nodiscard]] double dt() const { return dt_; }
    [[nodiscard]] const Particles<D>& particles() const { return P_; }
    [[nodiscard]] Particles<D>& particles() { return P_; }
    [[nodiscard]] const CellGrid<D>& grid() const { return grid_; }
    [[nodiscard]] const AnyKernel<D>& kernel() const { return kernel_; }
    [[nodiscard]] const Eos& eos() const { return eos_; }
    [[nodiscard]] const CaseConfig& config() const { return cfg_; }
    [[nodiscard]] const tasks::StepGraph& graph() const { return *graph_; }
    [[nodiscard]] int decompositions() const { return decompositions_; }
    [[nodiscard]] double h() const { return h_; }

    // Stability limits of the initial state at rest (gravity as the only force).
    [[nodiscard]] TimeStepLimits limits_at_rest() const;
    // Limits measured on the last step.
    [[nodiscard]] const TimeStepLimits& last_limits() const { return limits_; }

    // Busy seconds per stage summed over all steps (across re-decompositions), and the
    // stage names in graph order.
    [[nodiscard]] const std::vector<double>& stage_busy_seconds() const { return stage_busy_; }
    [[nodiscard]] std::vector<std::string> stage_names() const;

    // Seconds spent in rebinning and re-decomposition between steps, summed over the run.
    [[nodiscard]] double rebin_seconds_total() const { return rebin_seconds_; }

private:
    void rebin_and_decompose();
    void build_graph();
    void run_stage(int stage, int group);
    template <class K>
    void run_stage_with(const K& kernel, int stage, int group);

    enum class StageKind { density, walls, accel, kick, drift };

    CaseConfig cfg_;
    Particles<D> P_;
    CellGrid<D> grid_;
    CellRanges ranges_;
    std::vector<CellOccupancy> occupied_;
    AnyKernel<D> kernel_;
    Eos eos_;
    MomentumParams<D> momentum_;
    TimeStepParams ts_params_;
    std::vector<Plane<D>> planes_;
    Vec<D> domain_lo_, domain_hi_;
    double escape_margin_ = 0;
    double h_ = 0;
    bool continuity_ = false;
    double delta_h_c0_ = 0; // delta-SPH coefficient times h c0

    tasks::GroupTopology topo_;
    std::unique_ptr<tasks::StepGraph> graph_;
    std::vector<StageKind> stage_kinds_;
    int decompositions_ = 0;
    int target_groups_ = 1;

    // Per-group results of the drift stage.
    std::vector<TimeStepLimits> group_limits_;
    std::vector<std::string> group_failure_;
    std::vector<NeighbourList<D>> lists_; // per group, rebuilt by its first stage each step
    std::vector<Real> group_speed_;       // largest fluid speed per group (shifting velocity scale)
    Real u_max_ = 0;

    double time_ = 0, dt_ = 0, dt_prev_ = 0;
    long steps_ = 0;
    TimeStepLimits limits_;
    double rebin_seconds_ = 0;
    std::vector<double> stage_busy_;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

} // namespace sluice
