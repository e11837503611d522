#pragma once
// The weakly compressible scheme (docs/ARCHITECTURE.md, "The step as a graph"): its stage
// table, the halo fields its stages send, and the stage bodies (wcsph_stages.cpp).
#include "sluice/physics/damping_zone.hpp"
#include "sluice/physics/density.hpp"
#include "sluice/physics/momentum_lanes.hpp"
#include "sluice/physics/riemann.hpp"
#include "sluice/solver/halo_fields.hpp"

#include "../../step_scheme.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace sluice {

// What a stage computes: defined with the stage table (wcsph_stages.cpp), so that a new stage
// touches that file only.
enum class WcsphStage : std::uint8_t;

template <int D>
class WcsphScheme final : public StepScheme<D> {
public:
    // fail_step: the step in which this rank's drift throws (--debug-fail-*), or -1.
    WcsphScheme(const CaseParams<D>& params, Particles<D>& P, const RankCells<D>& cells,
                NeighbourLists<D>& neighbours, const StepClock& clock, GroupResults& results,
                const RankLink& rank, long fail_step);

    [[nodiscard]] Real skin() const override {
        return Real(case_.cfg.neighbour_skin * case_.cfg.dx);
    }
    [[nodiscard]] double cfl_speed() const override {
        return sluice::cfl_sound_speed(false, case_.cfg.sound_speed);
    }
    std::unique_ptr<tasks::StepGraph> build_graph(const GraphSite& site) override;
    void run(tasks::StepGraph& graph, const tasks::StepGraph::GatePoll& gate) override;
    void keep_ahead(std::size_t owned) override;
    void restore_ahead(std::size_t owned) override;

private:
    using StageKind = WcsphStage;
    struct Stage {
        StageRow row;
        StageKind kind;
    };
    // The step's stages, one row each (wcsph_stages.cpp).
    [[nodiscard]] std::vector<Stage> stage_table();
    void run_stage(int stage, int group);
    template <class K>
    void run_stage_with(const K& kernel, int stage, int group);
    // The fluid's load on the free bodies' wall particles of a group (acceleration stage).
    template <class K>
    void sum_body_loads(const Neighbourhood<D>& nb, const K& kernel,
                        const std::vector<CellIndex>& cells, BodyLoadSums& sums) const;

    // The units it is lent (step_scheme.hpp).
    const CaseParams<D> case_;
    Particles<D>& P_;
    const RankCells<D> cells_;
    NeighbourLists<D>& neighbours_;
    const StepClock& clock_;
    GroupResults& results_;
    const RankLink rank_;
    long fail_step_;

    RiemannParams<D> riemann_; // numerics.dissipation = "riemann"
    bool riemann_dissipation_ = false;
    Real damper_nu_ = 0;                  // acoustic damper nu_a = alpha h c0 [m^2/s]; 0 = off
    std::vector<DampingZone<D>> damping_; // [[damping_zones]], applied by the kick
    bool continuity_ = false;
    double delta_h_c0_ = 0; // delta-SPH coefficient times h c0
    DensityDiffusionParams<D> diffusion_;
    bool density_gradient_ = false; // the density stage computes the renormalised gradient
    std::vector<StageKind> stage_kinds_;
    // f(live, kept) for each array the stages before the gated one write.
    template <class F>
    void each_ahead_array(F&& f);
    // What the stages before the gated one write (keep_ahead), owned particles only.
    Particles<D> kept_;
    std::unique_ptr<HaloFields<D>> halo_;
    // In 2-D the acceleration reads its neighbours as packed records, four pairs per
    // instruction (momentum_lanes.hpp). Owned, then halo, like the particle arrays: fluid
    // particles' written by the density stage (with their pressure), wall particles' by the
    // walls stage, each sent to the other ranks with that stage's halo field.
    bool momentum_lanes_ = false;
    std::vector<MomentumNeighbour<D>> momentum_records_, kept_momentum_records_;
};

} // namespace sluice
