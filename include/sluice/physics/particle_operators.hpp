#pragma once
// One entry point for the three particle approximations of grad f and lap f at a particle
// (WMLS, MPS, SPH), so that they can be compared on the same particles and neighbour lists
// (tests/validation/test_wmls_benchmark.cpp, perf/wmls). Every one takes the neighbours'
// offsets x_j - x_i and differences f_j - f_i.
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/mps_operators.hpp"
#include "sluice/physics/sph_operators.hpp"
#include "sluice/physics/wmls.hpp"

#include <string_view>
#include <variant>

namespace sluice {

enum class Operator { wmls, mps, sph };

inline std::string_view operator_name(Operator op) {
    switch (op) {
    case Operator::wmls:
        return "WMLS";
    case Operator::mps:
        return "MPS";
    case Operator::sph:
        return "SPH";
    }
    return "?";
}

template <int D>
struct OperatorSettings {
    Operator op = Operator::wmls;
    Real re = 0;                                     // influence radius; SPH: the kernel support
    LsWeight weight = LsWeight::pnu_mps;             // WMLS and MPS
    MpsConstants mps;                                // MPS
    KernelType sph_kernel = KernelType::wendland_c2; // SPH, h = re / support factor
    Real volume = 0;                                 // SPH: particle volume
};

// Settings for particles of spacing l0: MPS constants from the regular lattice, SPH volume l0^D.
template <int D>
OperatorSettings<D> operator_settings(Operator op, Real l0, Real re,
                                      LsWeight weight = LsWeight::pnu_mps,
                                      KernelType sph_kernel = KernelType::wendland_c2) {
    OperatorSettings<D> s;
    s.op = op;
    s.re = re;
    s.weight = weight;
    s.mps = mps_lattice_constants<D>(l0, re, weight);
    s.sph_kernel = sph_kernel;
    s.volume = std::pow(l0, D);
    return s;
}

template <int D>
DiffResult<D> particle_derivatives(const OperatorSettings<D>& s, std::span<const Vec<D>> offsets,
                                   std::span<const Real> differences) {
    switch (s.op) {
    case Operator::wmls:
        return wmls_derivatives<D>(offsets, differences, s.re, s.weight);
    case Operator::mps:
        return mps_derivatives<D>(offsets, differences, s.re, s.weight, s.mps);
    case Operator::sph: {
        const AnyKernel<D> kernel =
            make_kernel<D>(s.sph_kernel, s.re / kernel_support_factor(s.sph_kernel));
        return std::visit(
            [&](const auto& k) { return sph_derivatives<D>(offsets, differences, k, s.volume); },
            kernel);
    }
    }
    return {};
}

} // namespace sluice
