#pragma once
// The weakly compressible scheme (docs/ARCHITECTURE.md, "The step as a graph"): its stage
// table and stage bodies (wcsph_stages.cpp) and the halo fields they send (halo_fields.hpp).
#include "sluice/physics/density.hpp"
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
class WcsphScheme final : public StepScheme<D>, private SchemeContext<D> {
public:
    explicit WcsphScheme(Simulation<D>& sim);

    [[nodiscard]] Real skin() const override { return Real(cfg_.neighbour_skin * cfg_.dx); }
    [[nodiscard]] double cfl_speed() const override {
        return sluice::cfl_sound_speed(false, cfg_.sound_speed);
    }
    std::unique_ptr<tasks::StepGraph> build_graph(const GraphSite& site) override;
    void run() override;

private:
    using What = typename HaloFields<D>::What;
    using StageKind = WcsphStage;
    struct Stage {
        StageRow<What> row;
        StageKind kind;
    };
    // The step's stages, one row each (wcsph_stages.cpp).
    [[nodiscard]] std::vector<Stage> stage_table() const;
    void run_stage(int stage, int group);
    template <class K>
    void run_stage_with(const K& kernel, int stage, int group);

    using Ctx = SchemeContext<D>;
    using Ctx::between_;
    using Ctx::bounds_;
    using Ctx::cfg_;
    using Ctx::comm_;
    using Ctx::dt_;
    using Ctx::dt_prev_;
    using Ctx::eos_;
    using Ctx::graph_;
    using Ctx::grid_;
    using Ctx::group_disp2_;
    using Ctx::group_failure_;
    using Ctx::group_limits_;
    using Ctx::group_speed_;
    using Ctx::h_;
    using Ctx::kernel_;
    using Ctx::lists_;
    using Ctx::momentum_;
    using Ctx::opts_;
    using Ctx::P_;
    using Ctx::plan_;
    using Ctx::planes_;
    using Ctx::ranges_;
    using Ctx::rebuilt_;
    using Ctx::skin_;
    using Ctx::steps_;
    using Ctx::time_;
    using Ctx::topo_;
    using Ctx::ts_params_;
    using Ctx::u_max_;
    using Ctx::wide_;

    RiemannParams<D> riemann_; // numerics.dissipation = "riemann"
    bool riemann_dissipation_ = false;
    bool continuity_ = false;
    double delta_h_c0_ = 0; // delta-SPH coefficient times h c0
    DensityDiffusionParams<D> diffusion_;
    bool density_gradient_ = false; // the density stage computes the renormalised gradient
    std::vector<StageKind> stage_kinds_;
    std::unique_ptr<HaloFields<D>> halo_;
};

} // namespace sluice
