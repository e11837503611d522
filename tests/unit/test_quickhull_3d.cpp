// The exact 3-D orientation predicate against integer arithmetic, and the quickhull
// (convex_hull_3d) against Qhull (the old implementation, tests/reference): the same
// vertex set on random, lattice and degenerate sets, and the same answer for a point raised
// above a facet by any height outside Qhull's own rounding band.
#include "sluice/physics/convex_hull_3d.hpp"
#include "sluice/physics/exact_orientation.hpp"
#include "sluice/physics/quickhull_3d.hpp"
#include "tests/reference/hull_reference.hpp"

#include <Eigen/Geometry>
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

using namespace sluice;
using hull_reference::old_convex_hull_3d;

namespace {

__extension__ using Int128 = __int128; // GCC/Clang built-in; __extension__: not ISO C++

using Points = std::vector<Vec<3>>;
using IVec = std::array<std::int64_t, 3>;

// Exact ((b - a) x (c - a)) . (d - a) for integer coordinates below 2^40: fits in 127 bits.
int int128_sign(const IVec& a, const IVec& b, const IVec& c, const IVec& d) {
    Int128 u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        w[k] = d[k] - a[k];
    }
    const Int128 det = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) +
                       w[2] * (u[0] * v[1] - u[1] * v[0]);
    return (det > 0) - (det < 0);
}

Vec<3> scaled(const IVec& a, double s) {
    return {static_cast<double>(a[0]) * s, static_cast<double>(a[1]) * s,
            static_cast<double>(a[2]) * s};
}

void check_against_qhull(const Points& p, const std::string& what) {
    INFO(what);
    for (HullPoints which : {HullPoints::vertices, HullPoints::boundary}) {
        const ConvexHull3d old = old_convex_hull_3d(p, which);
        const ConvexHull3d now = convex_hull_3d(p, which);
        REQUIRE(now.dimension == old.dimension);
        REQUIRE(now.points == old.points);
    }
    // Every point is inside every facet (within rounding), every corner on three of them.
    const ConvexHull3d h = convex_hull_3d(p);
    Real size = 0;
    for (const auto& q : p)
        size = std::max(size, q.norm());
    for (const auto& f : h.facets)
        for (const auto& q : p)
            REQUIRE(f.head<3>().dot(q) + f[3] <= 1e-13 * size);
}

} // namespace

TEST_CASE("exact 3-D orientation agrees with integer arithmetic where doubles round") {
    std::mt19937_64 rng(777);
    const std::int64_t big = std::int64_t{1} << 38;
    std::uniform_int_distribution<std::int64_t> coord(-big, big);
    std::uniform_int_distribution<std::int64_t> small(-2, 2);
    const int n = 100000;
    int zero = 0;
    for (int t = 0; t < n; ++t) {
        // a, b, c random; d = a + (b - a) + (c - a) (+ a few units): coplanar or nearly.
        IVec a{}, b{}, c{}, d{};
        for (int k = 0; k < 3; ++k) {
            a[k] = coord(rng) / 4;
            b[k] = a[k] + coord(rng) / 8;
            c[k] = a[k] + coord(rng) / 8;
            d[k] = b[k] + c[k] - a[k] + (t % 2 == 0 ? small(rng) : 0);
        }
        const int exact = int128_sign(a, b, c, d);
        zero += exact == 0 ? 1 : 0;
        const double s = std::ldexp(1.0, -45); // exact scaling: not integers any more
        const Vec<3> A = scaled(a, s), B = scaled(b, s), C = scaled(c, s), D = scaled(d, s);
        REQUIRE(orientation_sign(A, B, C, D) == exact);
        REQUIRE(orientation_sign_expansion(A, B, C, D) == exact);
        REQUIRE(orientation_sign(B, C, A, D) == exact); // even permutation
        REQUIRE(orientation_sign(B, A, C, D) == -exact);
    }
    CHECK(zero > n / 4); // the coplanar cases were exercised
    // Random well-separated points: the filter and the expansion agree.
    std::uniform_real_distribution<double> u(-1, 1);
    for (int t = 0; t < 10000; ++t) {
        const Vec<3> A(u(rng), u(rng), u(rng)), B(u(rng), u(rng), u(rng)),
            C(u(rng), u(rng), u(rng)), D(u(rng), u(rng), u(rng));
        REQUIRE(orientation_sign(A, B, C, D) == orientation_sign_expansion(A, B, C, D));
    }
}

TEST_CASE("quickhull: the vertices (and boundary points) of Qhull on random and lattice sets") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int t = 0; t < 300; ++t) {
        const int n = 4 + t % 120;
        Points cube, ball, sphere;
        for (int i = 0; i < n; ++i) {
            const Vec<3> q(u(rng), u(rng), u(rng));
            cube.push_back(q);
            if (q.norm() <= 1)
                ball.push_back(q);
            sphere.push_back(q.normalized() * 3);
        }
        check_against_qhull(cube, "cube #" + std::to_string(t));
        if (ball.size() >= 4)
            check_against_qhull(ball, "ball #" + std::to_string(t));
        check_against_qhull(sphere, "sphere #" + std::to_string(t));
    }
    // Images of cubic lattices within 2 and 3 steps, offsets exact or rounded (x_j - x_i).
    for (double x0 : {0.0, 0.31, 7.7})
        for (int reach : {1, 2, 3}) {
            Points images;
            const double dx = 0.01;
            for (int x = -reach; x <= reach; ++x)
                for (int y = -reach; y <= reach; ++y)
                    for (int z = -reach; z <= reach; ++z) {
                        const auto pos = [&](int k) { return x0 + (k + 0.5) * dx; };
                        const Vec<3> r(pos(x) - pos(0), pos(y) - pos(0), pos(z) - pos(0));
                        if (r.squaredNorm() > 0)
                            images.push_back(r / r.squaredNorm());
                    }
            check_against_qhull(images, "lattice images, x0 " + std::to_string(x0) + ", reach " +
                                            std::to_string(reach));
        }
    // A cube's lattice points (corners, edge and face points: ties everywhere), duplicates.
    Points cube;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                cube.emplace_back(x, y, z);
    cube.push_back(cube[3]);
    cube.push_back(cube[0]);
    check_against_qhull(cube, "cube lattice with duplicates");
}

TEST_CASE("quickhull: a point raised above a facet is a vertex exactly when Qhull says so") {
    // An octahedron of radius s and a point in one face raised by h s: Qhull turns it into a
    // vertex from h = 4e-15 to 8e-15 (its rounding band, varies with the set); outside the
    // band the two must agree.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (double h : {0.0, 1e-16, 1e-15, 2e-15, 1.2e-14, 1e-13, 1e-12, 1e-9, 1e-6, 1e-3}) {
        for (int t = 0; t < 50; ++t) {
            const double s = std::pow(10.0, 4 * u(rng) - 2);
            Points p{{s, 0, 0}, {-s, 0, 0}, {0, s, 0}, {0, -s, 0}, {0, 0, s}, {0, 0, -s}};
            double a = u(rng), b = u(rng);
            if (a + b > 1) {
                a = 1 - a;
                b = 1 - b;
            }
            const double raise = h * s / std::sqrt(3.0);
            p.emplace_back(a * s + raise, b * s + raise, (1 - a - b) * s + raise);
            check_against_qhull(p, "raised by " + std::to_string(h) + " #" + std::to_string(t));
        }
    }
}

TEST_CASE("quickhull: too flat a first tetrahedron is refused, any solid set is built") {
    QuickhullWork work;
    std::vector<int> corners;
    std::vector<Eigen::Matrix<Real, 4, 1>> facets;
    const Points flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}};
    CHECK_FALSE(quickhull_3d(flat, 0, work, corners, facets));
    const Points tetra{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.1, 0.1, 0.1}};
    REQUIRE(quickhull_3d(tetra, 0, work, corners, facets));
    CHECK(corners == std::vector<int>{0, 1, 2, 3});
    CHECK(facets.size() == 4);
    CHECK_FALSE(quickhull_3d(tetra, 1.0, work, corners, facets)); // volume 1/6
}
