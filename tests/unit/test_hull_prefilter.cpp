// The prefilter of the mapped hull (mapped_hull.hpp: HullPrefilter): the ball it
// finds lies inside the hull of the images, and dropping the images inside it changes neither
// the corners nor the boundary points, on exact and jittered lattices, deformed lattices and
// one-sided (free-surface) sets, in 2-D and 3-D.
#include "sluice/physics/mapped_hull.hpp"
#include "sluice/physics/neighbour_selection.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace sluice;

namespace {

// Offsets x_j - x_i of a lattice of spacing 1 within `reach` steps, mapped by `deform` (a
// matrix), every coordinate jittered by up to `jitter`, and kept when `keep` holds.
template <int D, class Keep>
std::vector<Vec<D>> deformed_lattice(const Mat<D>& deform, double jitter, int reach,
                                     std::mt19937_64& rng, Keep keep) {
    std::uniform_real_distribution<double> u(-jitter, jitter);
    std::vector<Vec<D>> r;
    const int n = 2 * reach + 1;
    const int total = D == 2 ? n * n : n * n * n;
    for (int idx = 0; idx < total; ++idx) {
        Vec<D> o;
        int rest = idx;
        for (int d = 0; d < D; ++d) {
            o[d] = rest % n - reach;
            rest /= n;
        }
        if (o.squaredNorm() == 0 || o.norm() > reach + 0.1)
            continue;
        Vec<D> p = deform * o;
        for (int d = 0; d < D; ++d)
            p[d] += u(rng);
        if (p.squaredNorm() > 0 && keep(p))
            r.push_back(p);
    }
    return r;
}

std::vector<int> sorted(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
}

// Both forms of the hull agree; returns whether the prefilter dropped anything.
template <int D>
bool same_hull(const std::vector<Vec<D>>& r) {
    const MappedHull<D> fast = mapped_hull<D>(r, HullPrefilter::inscribed_ball);
    const MappedHull<D> full = mapped_hull<D>(r, HullPrefilter::none);
    CHECK(fast.vertices == full.vertices);
    CHECK(sorted(fast.boundary) == sorted(full.boundary));
    CHECK(hull_surrounds_origin(fast) == hull_surrounds_origin(full));
    const Real rho = inscribed_ball_radius<D>(fast.images);
    int inside = 0;
    for (const auto& q : fast.images)
        inside += q.norm() < 0.99 * rho ? 1 : 0;
    // The ball lies inside the hull: every facet is at least rho from the origin.
    if (rho > 0)
        for (const auto& f : full.facets)
            CHECK(-f[D] >= rho * (1 - 1e-12));
    return inside > 0;
}

template <int D>
void check_family(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    Mat<D> shear = Mat<D>::Identity();
    shear(0, 1) = 1.3;
    Mat<D> stretch = Mat<D>::Identity();
    stretch(0, 0) = 4;
    const auto all = [](const Vec<D>&) { return true; };
    const auto lower = [](const Vec<D>& p) { return p[D - 1] < 0.3; }; // a free surface above
    int dropped = 0, sets = 0;
    for (const Mat<D>& m : {Mat<D>(Mat<D>::Identity()), shear, stretch})
        for (double jitter : {0.0, 0.1, 0.2, 0.4})
            for (int rep = 0; rep < (jitter > 0 ? 20 : 1); ++rep) {
                dropped += same_hull<D>(deformed_lattice<D>(m, jitter, 3, rng, all)) ? 1 : 0;
                same_hull<D>(deformed_lattice<D>(m, jitter, 3, rng, lower));
                ++sets;
            }
    // The filter must act on most full stencils (else it buys nothing).
    CHECK(dropped > sets / 2);
}

} // namespace

TEST_CASE("prefilter ball: the inradius of the nearest images on a lattice") {
    // The four (six) nearest images of a unit lattice span a diamond (octahedron) of inradius
    // 1/sqrt(2) (1/sqrt(3)).
    std::mt19937_64 rng(1);
    const auto all2 = [](const Vec<2>&) { return true; };
    const auto all3 = [](const Vec<3>&) { return true; };
    const auto r2 = deformed_lattice<2>(Mat<2>::Identity(), 0, 3, rng, all2);
    const auto r3 = deformed_lattice<3>(Mat<3>::Identity(), 0, 3, rng, all3);
    CHECK(inscribed_ball_radius<2>(mapped_hull<2>(r2).images) ==
          doctest::Approx(1 / std::sqrt(2.0)).epsilon(1e-12));
    CHECK(inscribed_ball_radius<3>(mapped_hull<3>(r3).images) ==
          doctest::Approx(1 / std::sqrt(3.0)).epsilon(1e-12));
    // One-sided: nothing along +y (+z), no ball.
    const auto half2 = deformed_lattice<2>(Mat<2>::Identity(), 0, 3, rng,
                                           [](const Vec<2>& p) { return p.y() <= 0; });
    CHECK(inscribed_ball_radius<2>(mapped_hull<2>(half2).images) == 0);
}

TEST_CASE("prefilter: same corners and boundary points as the full hull, 2-D") {
    check_family<2>(7);
}

TEST_CASE("prefilter: same corners and boundary points as the full hull, 3-D") {
    check_family<3>(8);
}

TEST_CASE("prefilter: select_neighbours unchanged on the lattice ties") {
    // Exact lattice: the diagonal images lie exactly on the diamond's edges (boundary points)
    // and on the prefilter's ball; they must stay.
    NeighbourSelection hull;
    hull.policy = NeighbourPolicy::convex_hull;
    std::mt19937_64 rng(3);
    const auto r = deformed_lattice<2>(Mat<2>::Identity() * 0.01, 0, 3, rng,
                                       [](const Vec<2>&) { return true; });
    CHECK(select_neighbours<2>(r, 0.031, 0.01, hull).size() == 8);
}
