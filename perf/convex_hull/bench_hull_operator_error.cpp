// WMLS gradient/Laplacian error with convex-hull neighbours against radius neighbours on
// strongly anisotropic particle sets (perf/convex_hull/README.md, "Operator error"). The sets
// and the three neighbour selections are described in tests/validation/hull_operator_error.hpp;
// the guard on these figures is tests/validation/test_hull_operator_error.cpp.
// Usage: bench_hull_operator_error
#include "hull_operator_error.hpp"

#include <cstdio>

using namespace sluice;
using namespace sluice::testing;

int main() {
    std::printf("WMLS (PNU-MPS weight) relative L2 errors, f = sin x cos y, l0 = %.2f\n",
                kHullErrorL0);
    std::printf("%-14s %-26s %8s %10s %10s %8s %8s\n", "set", "neighbours", "scored", "E_grad",
                "E_lap", "not ok", "mean n");
    for (const auto& s : anisotropic_sets())
        for (Selection sel : {Selection::radius, Selection::radius_wide, Selection::hull_union,
                              Selection::hull_union_adaptive}) {
            const SetErrors e = set_errors(s, sel);
            std::printf("%-14s %-26s %8d %10.3e %10.3e %8d %8.1f\n", s.name.c_str(),
                        selection_name(sel), e.scored, e.gradient, e.laplacian, e.not_ok,
                        e.mean_neighbours);
        }
    return 0;
}
