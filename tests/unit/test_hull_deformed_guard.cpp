// Where convex-hull neighbours must help the projection scheme's operators, with
// the solver's settings (candidates = the particles within re = 3.1 dx; the function its
// stencil stage calls): on a jittered block carried by a shear flow (strain 2) or stretched
// 4:1, the WMLS gradient over the hull neighbours (the nearest particle in each direction)
// has a third to a half of the radius set's error (perf/convex_hull/README.md measures 0.31x
// and 0.57x), and the hull + radius union is exactly the radius set. The Laplacian over the
// hull alone is worse (about 6 neighbours for 5 unknowns): that is measured, not guarded.
#include "../validation/hull_deformed_sets.hpp"

#include <doctest/doctest.h>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("deformed blocks: the hull gradient beats the radius gradient") {
    const DeformedSet sheared = deformed_block("sheared", shear_map(2), 40, 0.01, 21);
    const DeformedSet stretched = deformed_block("stretched", stretch_map(4), 40, 0.01, 22);
    for (const auto* s : {&sheared, &stretched}) {
        CAPTURE(s->name);
        const DeformedErrors radius = deformed_errors(*s, DeformedSelection::radius);
        const DeformedErrors hull = deformed_errors(*s, DeformedSelection::hull);
        const DeformedErrors both = deformed_errors(*s, DeformedSelection::hull_union);
        REQUIRE(radius.scored > 200);
        CHECK(radius.not_ok == 0);
        CHECK(hull.gradient < (s == &sheared ? 0.5 : 0.75) * radius.gradient);
        // Within re the union adds back every candidate: the radius set, the same numbers.
        CHECK(both.gradient == radius.gradient);
        CHECK(both.laplacian == radius.laplacian);
        CHECK(hull.mean_neighbours < 0.3 * radius.mean_neighbours);
    }
}
