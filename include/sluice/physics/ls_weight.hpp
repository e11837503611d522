#pragma once
// Weight functions w(r) of the particle operators (docs/WMLS.md, section "Weights").
// Both vanish for r >= re, so a neighbour list longer than re is harmless.
//   pnu_mps: w = re / (0.85 r + 0.15 re) - 1   (Lee et al. 2011, the PNU-MPS kernel that
//            Park et al. (2014) takes for its WMLS fit and its MPS comparison). It is Koshizuka & Oka's
//            re/r - 1 with the singularity at r = 0 removed: w(0) = 1/0.15 - 1 = 17/3.
//   smooth:  w = (1 - q)^4 (1 + 4q), q = r/re   (Wendland C2 shape, unnormalised): smooth
//            (C2 at r = re), finite, so a neighbour crossing re changes the fit continuously.
#include "sluice/core/types.hpp"

namespace sluice {

enum class LsWeight { pnu_mps, smooth };

inline Real ls_weight(Real r, Real re, LsWeight weight) {
    if (r >= re)
        return 0;
    if (weight == LsWeight::pnu_mps)
        return re / (Real(0.85) * r + Real(0.15) * re) - 1;
    const Real q = r / re;
    const Real t = 1 - q;
    return (t * t) * (t * t) * (1 + 4 * q);
}

} // namespace sluice
