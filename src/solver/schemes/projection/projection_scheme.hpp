#pragma once
// The incompressible projection scheme (docs/PROJECTION.md): three step graphs per step,
// their stage tables and bodies (projection_step.cpp) and the pressure solve between them
// (projection_solver.cpp, block_preconditioner.cpp).
#include "sluice/physics/projection.hpp"
#include "sluice/solver/halo_fields.hpp"

#include "../../step_scheme.hpp"
#include "projection_data.hpp"

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sluice {

template <int D>
class ProjectionScheme final : public StepScheme<D> {
public:
    ProjectionScheme(const CaseParams<D>& params, Particles<D>& P, const RankCells<D>& cells,
                     NeighbourLists<D>& neighbours, const StepClock& clock, GroupResults& results,
                     const RankLink& rank)
        : case_(params), P_(P), cells_(cells), neighbours_(neighbours), clock_(clock),
          results_(results), rank_(rank) {}

    // The projection step builds its own lists every step (its operators use another radius).
    [[nodiscard]] Real skin() const override { return 0; }
    [[nodiscard]] double cfl_speed() const override {
        return sluice::cfl_sound_speed(true, case_.cfg.sound_speed);
    }
    void start() override { init_projection(); }
    std::unique_ptr<tasks::StepGraph> build_graph(const GraphSite& site) override;
    // Its step graph has no gated stage (the predictor reads dt in the first stage).
    void run(tasks::StepGraph& graph, const tasks::StepGraph::GatePoll& /*gate*/) override {
        run_projection(graph);
    }
    [[nodiscard]] const PressureSolveRecord* last_pressure_solve() const override {
        return &proj_->last;
    }
    [[nodiscard]] const PressureSolveTotals* pressure_solve_totals() const override {
        return &proj_->totals;
    }
    [[nodiscard]] std::span<const WallContact<D>> wall_contacts() const override {
        return proj_->contacts;
    }
    // P7 applies max(p, 0) under a free surface; without one, every pressure.
    [[nodiscard]] Real applied_pressure_floor() const override {
        return sluice::applied_pressure_floor(proj_->free_level ? PressureLevel::free
                                                                : PressureLevel::surface);
    }

private:
    void init_projection();
    void run_projection(tasks::StepGraph& graph);
    template <class K>
    void projection_stage(const K& kernel, int stage, int group);
    void solver_stage(int stage, int group);
    void factor_block(int group); // block-Jacobi preconditioner of the group (after ppe_source)
    void correct_stage(int group);
    Vec<D> collide_with_walls(std::uint32_t i, const NeighbourList<D>& list, std::uint32_t b,
                              std::uint32_t e, Vec<D> v,
                              std::vector<WallContact<D>>& contacts) const;
    std::string solve_pressure(std::string& error); // non-empty: did not converge
    // The groups' partial sums, then the ranks'; with `coarse`, the ranks' restricted vectors
    // are summed into it as well (in rank order, in the same message).
    std::array<double, 7> reduce_partials(int count, bool failed_here,
                                          std::vector<double>* coarse = nullptr);
    // Two-level preconditioner (two_level.cpp): the aggregates, A P and A_c of this step (after
    // a coarse_mark run of the solver graph); false where A_c cannot be factorised.
    bool setup_coarse();
    // out = R v over this rank's rows (one entry per aggregate).
    void restrict_owned(const std::vector<Real>& v, std::vector<double>& out) const;

    // The units it is lent (step_scheme.hpp).
    const CaseParams<D> case_;
    Particles<D>& P_;
    const RankCells<D> cells_;
    NeighbourLists<D>& neighbours_;
    const StepClock& clock_;
    GroupResults& results_;
    const RankLink rank_;

    // Last member: its graphs live in the Simulation's arena and are destroyed first.
    std::unique_ptr<ProjectionData<D>> proj_;
};

} // namespace sluice
