#pragma once
// Between the case's and the geometry's 3-component points (Triple, Point3: std::array<double,
// 3>) and the solver's Vec<D>: the first D components, the rest zero.
#include "sluice/core/types.hpp"
#include "sluice/io/case_config.hpp"

#include <cstddef>

namespace sluice {

template <int D>
Vec<D> to_vec(const Triple& t) {
    Vec<D> v;
    for (int d = 0; d < D; ++d)
        v[d] = Real(t[static_cast<std::size_t>(d)]);
    return v;
}

template <int D>
Triple to_triple(const Vec<D>& v) {
    Triple t{};
    for (int d = 0; d < D; ++d)
        t[static_cast<std::size_t>(d)] = double(v[d]);
    return t;
}

} // namespace sluice
