// The 3-D hull (convex_hull_3d: the exact quickhull) against a brute-force
// facet search: every plane through three points with all points on one side is a supporting
// plane, and the 2-D hull corners of the points on it are hull vertices (O(n^4)). Degenerate inputs
// (fewer than 4 points, duplicates, coplanar and collinear sets) must give their lower-dimensional
// hull, not fail.
#include "sluice/physics/convex_hull_3d.hpp"
#include "sluice/physics/mapped_hull.hpp"

#include <Eigen/Geometry>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>

using namespace sluice;

namespace {

using Points = std::vector<Vec<3>>;

// Lowest index of each distinct point.
std::vector<int> distinct(const Points& p) {
    std::vector<int> out;
    for (std::size_t i = 0; i < p.size(); ++i) {
        bool seen = false;
        for (std::size_t j = 0; j < i; ++j)
            seen = seen || p[j] == p[i];
        if (!seen)
            out.push_back(static_cast<int>(i));
    }
    return out;
}

// Brute force: vertices (or all points on a facet) of the hull of p.
std::vector<int> brute_force_hull(const Points& p, HullPoints which) {
    const std::vector<int> d = distinct(p);
    const auto at = [&](int i) { return p[static_cast<std::size_t>(i)]; };
    Real scale = 0;
    for (int i : d)
        scale = std::max(scale, at(i).cwiseAbs().maxCoeff());
    std::set<int> out;
    bool any_plane = false;
    for (std::size_t a = 0; a < d.size(); ++a)
        for (std::size_t b = a + 1; b < d.size(); ++b)
            for (std::size_t c = b + 1; c < d.size(); ++c) {
                const Vec<3> n = (at(d[b]) - at(d[a])).cross(at(d[c]) - at(d[a]));
                if (n.norm() <= 1e-12 * scale * scale)
                    continue; // collinear triple
                any_plane = true;
                const Real tol = 1e-12 * n.norm() * scale;
                int above = 0, below = 0;
                std::vector<int> on;
                for (int l : d) {
                    const Real s = n.dot(at(l) - at(d[a]));
                    if (s > tol)
                        ++above;
                    else if (s < -tol)
                        ++below;
                    else
                        on.push_back(l);
                }
                if (above > 0 && below > 0)
                    continue;                        // not a supporting plane
                if (which == HullPoints::boundary) { // every point of the face
                    out.insert(on.begin(), on.end());
                    continue;
                }
                // The face's corners: 2-D hull of its points, projected along n's largest axis.
                int drop = 0;
                n.cwiseAbs().maxCoeff(&drop);
                std::vector<Vec<2>> flat;
                for (int l : on)
                    flat.emplace_back(at(l)[(drop + 1) % 3], at(l)[(drop + 2) % 3]);
                for (int k : monotone_chain_hull_2d(flat, which))
                    out.insert(on[static_cast<std::size_t>(k)]);
            }
    if (!any_plane) { // fewer than 3 distinct points, or all on a line
        if (d.size() <= 2 || which == HullPoints::boundary)
            return d;
        const Vec<3> u = at(d[1]) - at(d[0]);
        const auto [lo, hi] = std::minmax_element(
            d.begin(), d.end(), [&](int i, int j) { return u.dot(at(i)) < u.dot(at(j)); });
        std::vector<int> ends = {*lo, *hi};
        std::sort(ends.begin(), ends.end());
        return ends;
    }
    return {out.begin(), out.end()};
}

void check_against_brute_force(const Points& p, const std::string& what) {
    INFO(what);
    for (HullPoints which : {HullPoints::vertices, HullPoints::boundary}) {
        INFO((which == HullPoints::vertices ? "vertices" : "boundary"));
        CHECK(convex_hull_3d(p, which).points == brute_force_hull(p, which));
    }
}

Vec<3> random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    Vec<3> v(g(rng), g(rng), g(rng));
    return v.normalized();
}

} // namespace

TEST_CASE("random sets: Qhull vertices equal the brute-force facet search") {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> size(4, 14);
    for (int t = 0; t < 300; ++t) {
        Points cube, sphere, lattice_images;
        const int n = size(rng);
        for (int i = 0; i < n; ++i) {
            cube.emplace_back(u(rng), u(rng), u(rng));
            sphere.push_back(random_unit(rng)); // every point a vertex
        }
        check_against_brute_force(cube, "cube #" + std::to_string(t));
        check_against_brute_force(sphere, "sphere #" + std::to_string(t));
        CHECK(convex_hull_3d(sphere).points.size() == static_cast<std::size_t>(n));
        CHECK(convex_hull_3d(cube).dimension == 3);
    }
}

TEST_CASE("integer sets with coplanar faces and duplicates") {
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> c(-2, 2);
    for (int t = 0; t < 200; ++t) {
        Points p;
        const int n = 4 + t % 11;
        for (int i = 0; i < n; ++i)
            p.emplace_back(c(rng), c(rng), c(rng));
        check_against_brute_force(p, "small-integer set #" + std::to_string(t));
    }
    // The 3x3x3 lattice cube: 8 corners; every point but the centre on the boundary.
    Points cube;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                cube.emplace_back(x, y, z);
    CHECK(convex_hull_3d(cube).points.size() == 8);
    CHECK(convex_hull_3d(cube, HullPoints::boundary).points.size() == 26);
    check_against_brute_force(cube, "3x3x3 lattice");
}

TEST_CASE("degenerate sets: fewer than 4 points, coplanar, collinear, all equal") {
    CHECK(convex_hull_3d(Points{}).points.empty());
    CHECK(convex_hull_3d(Points{}).dimension == -1);
    const Points one = {{1, 2, 3}, {1, 2, 3}};
    CHECK(convex_hull_3d(one).points == std::vector<int>{0});
    CHECK(convex_hull_3d(one).dimension == 0);
    const Points two = {{0, 0, 0}, {1, 1, 1}};
    CHECK(convex_hull_3d(two).points == std::vector<int>{0, 1});
    CHECK(convex_hull_3d(two).dimension == 1);
    const Points line = {{2, 2, 2}, {0, 0, 0}, {1, 1, 1}, {3, 3, 3}, {1, 1, 1}};
    CHECK(convex_hull_3d(line).points == std::vector<int>{1, 3});
    CHECK(convex_hull_3d(line, HullPoints::boundary).points == std::vector<int>{0, 1, 2, 3});
    const Points triangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(convex_hull_3d(triangle).points == std::vector<int>{0, 1, 2});
    CHECK(convex_hull_3d(triangle).dimension == 2);
    // A tilted plane x + y + z = 3 with a grid on it, plus duplicates: a flat hexagon-like set.
    Points plane;
    for (int x = 0; x <= 3; ++x)
        for (int y = 0; x + y <= 3; ++y)
            plane.emplace_back(x, y, 3 - x - y);
    plane.push_back(plane[4]);
    const auto flat = convex_hull_3d(plane);
    CHECK(flat.dimension == 2);
    CHECK(flat.facets.empty());
    CHECK(flat.points.size() == 3); // the triangle's corners (0,0,3), (0,3,0), (3,0,0)
    check_against_brute_force(plane, "tilted plane");
    check_against_brute_force(triangle, "triangle");
    check_against_brute_force(line, "line");
    // Random coplanar sets on an axis plane and a tilted one (coordinates exact).
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int> c(-3, 3);
    for (int t = 0; t < 100; ++t) {
        Points axis, tilted;
        for (int i = 0; i < 8; ++i) {
            const int x = c(rng), y = c(rng);
            axis.emplace_back(x, y, 1);
            tilted.emplace_back(x, y, 2 * x - y);
        }
        check_against_brute_force(axis, "z = 1 plane #" + std::to_string(t));
        check_against_brute_force(tilted, "z = 2x - y plane #" + std::to_string(t));
    }
}

TEST_CASE("inverse-square images of a cubic lattice: the octahedron of the 6 face neighbours") {
    Points r;
    for (int x = -2; x <= 2; ++x)
        for (int y = -2; y <= 2; ++y)
            for (int z = -2; z <= 2; ++z)
                if (x != 0 || y != 0 || z != 0)
                    r.emplace_back(0.1 * x, 0.1 * y, 0.1 * z);
    const MappedHull<3> h = mapped_hull<3>(r);
    REQUIRE(h.vertices.size() == 6);
    for (int i : h.vertices)
        CHECK(r[static_cast<std::size_t>(i)].norm() == doctest::Approx(0.1));
    // Edge neighbours map onto the octahedron's edges, corner neighbours onto its faces.
    CHECK(h.boundary.size() == 26);
    for (int i : h.boundary)
        CHECK(r[static_cast<std::size_t>(i)].cwiseAbs().maxCoeff() == doctest::Approx(0.1));
    // Its faces are 1/sqrt(3) of the octahedron's size (10/dx) away from the origin.
    CHECK(h.facets.size() == 8);
    for (const auto& f : h.facets)
        CHECK(-f[3] == doctest::Approx(10 / std::sqrt(3.0)));
    CHECK(hull_surrounds_origin(h));
}
