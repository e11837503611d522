// Reflective mesh walls (physics/reflection.hpp, solver/reflective_walls.hpp): a move into a
// triangle or segment is mirrored across that element's plane exactly as across a plane wall,
// with the normal velocity reversed times the restitution; a move out of an element from
// behind passes; a concave corner reflects on both faces; no move ends inside a solid.
#include "shape_files.hpp"
#include "sluice/geometry/surface_index.hpp"
#include "sluice/solver/reflective_walls.hpp"

#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <random>

using namespace sluice;

namespace {

CaseConfig reflective_case(int dim, SurfaceGeometry g, double restitution) {
    CaseConfig c;
    c.dimension = dim;
    c.walls = WallModel::reflective;
    c.tank_faces.clear();
    c.restitution = restitution;
    WallMesh m;
    m.role = MeshRole::surface;
    m.shape = std::make_shared<SurfaceIndex>(std::move(g));
    c.meshes.push_back(std::move(m));
    return c;
}

Vec<3> v3(const Point3& p) {
    return {p[0], p[1], p[2]};
}

} // namespace

TEST_CASE("A move into a tilted triangle is mirrored as across its plane") {
    Placement p;
    p.rotation_deg = {20, 30, 10};
    p.translation = {0.5, 0.5, 0.5};
    const SurfaceGeometry g = placed(test::box_shape({-0.1, -0.05, -0.075}, {0.1, 0.05, 0.075}), p);
    const CaseConfig cfg = reflective_case(3, g, 0.5);
    const Reflector<3> r = reflective_walls<3>(cfg);
    REQUIRE(r.surfaces.size() == 1);
    REQUIRE(r.planes.empty());
    // Face 0's centroid, approached along the normal from 0.01 m in front, 0.012 m deep.
    const auto& t = g.triangles[0];
    const Vec<3> a = v3(g.vertices[t[0]]), b = v3(g.vertices[t[1]]), c = v3(g.vertices[t[2]]);
    const Vec<3> n = (b - a).cross(c - a).normalized();
    const Vec<3> centre = (a + b + c) / 3;
    const Vec<3> tangent = (b - a).normalized();
    const Vec<3> from = centre + 0.01 * n + 0.002 * tangent;
    Vec<3> x = centre - 0.002 * n + 0.004 * tangent;
    Vec<3> v_half = -2.0 * n + 0.5 * tangent, v = v_half;
    Vec<3> x_plane = x, vh_plane = v_half, v_plane = v;
    mirror_behind(Plane<3>{a, n}, Real(0.5), x_plane, vh_plane, v_plane);
    r.apply(from, x, v_half, v);
    CHECK((x - x_plane).norm() < 1e-15);
    CHECK((x - centre).dot(n) == doctest::Approx(0.002).epsilon(1e-9));
    CHECK(v_half.dot(n) == doctest::Approx(1.0).epsilon(1e-12)); // -(-2) x 0.5
    CHECK(v_half.dot(tangent) == doctest::Approx(0.5).epsilon(1e-12));
    CHECK((v - vh_plane).norm() < 1e-15);

    SUBCASE("a move out of the solid from behind is not reflected") {
        Vec<3> y = centre + 0.003 * n, vh = 2.0 * n, vv = vh;
        r.apply(centre - 0.003 * n, y, vh, vv);
        CHECK(y == centre + 0.003 * n);
        CHECK(vh == 2.0 * n);
    }
    SUBCASE("a move that misses the solid is untouched") {
        Vec<3> y = centre + 0.01 * n + 0.3 * tangent, vh = tangent, vv = vh;
        r.apply(centre + 0.01 * n, y, vh, vv);
        CHECK(y == centre + 0.01 * n + 0.3 * tangent);
    }
}

TEST_CASE("A tank of inward triangles reflects a move into its corner on both faces") {
    Placement inward;
    inward.flip = true;
    const CaseConfig cfg =
        reflective_case(3, placed(test::box_shape({0, 0, 0}, {1, 1, 1}), inward), 0.0);
    const Reflector<3> r = reflective_walls<3>(cfg);
    const Vec<3> from{0.004, 0.5, 0.003};
    Vec<3> x{-0.002, 0.5, -0.001}, v_half{-3, 1, -2}, v = v_half;
    r.apply(from, x, v_half, v);
    CHECK(x[0] == doctest::Approx(0.002));
    CHECK(x[2] == doctest::Approx(0.001));
    CHECK(x[1] == 0.5);
    CHECK(v_half == Vec<3>(0, 1, 0)); // restitution 0: only the tangential part is left
    // The same as the tank's six planes.
    CaseConfig tank = cfg;
    tank.meshes.clear();
    tank.tank_lo = {0, 0, 0};
    tank.tank_hi = {1, 1, 1};
    tank.tank_faces = {"x-", "x+", "y-", "y+", "z-", "z+"};
    const Reflector<3> planes = reflective_walls<3>(tank);
    REQUIRE(planes.planes.size() == 6);
    Vec<3> y{-0.002, 0.5, -0.001}, vh{-3, 1, -2}, vv = vh;
    planes.apply(from, y, vh, vv);
    CHECK(y == x);
    CHECK(vh == v_half);
}

TEST_CASE("No move from outside a faceted sphere ends inside it") {
    const SurfaceGeometry g = test::sphere_shape({0.5, 0.5, 0.5}, 0.1, 24, 48);
    const CaseConfig cfg = reflective_case(3, g, 0.3);
    const Reflector<3> r = reflective_walls<3>(cfg);
    const SurfaceIndex& shape = *cfg.meshes[0].shape;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int reflected = 0, inside = 0;
    for (int k = 0; k < 20000; ++k) {
        const Vec<3> dir = Vec<3>(u(rng), u(rng), u(rng)).normalized();
        const Vec<3> from = Vec<3>(0.5, 0.5, 0.5) + (0.1 + 0.01 * (u(rng) + 1)) * dir;
        const Vec<3> step = 0.03 * Vec<3>(u(rng), u(rng), u(rng));
        Vec<3> x = from + step, vh = step / 1e-3, v = vh;
        const Vec<3> before = x;
        r.apply(from, x, vh, v);
        reflected += x != before ? 1 : 0;
        const ClosestPoint c = shape.closest({x[0], x[1], x[2]});
        inside += shape.inside({x[0], x[1], x[2]}) && c.distance > 1e-12 ? 1 : 0;
    }
    CHECK(reflected > 2000);
    CHECK(inside == 0);
}

TEST_CASE("2-D: a particle falling on a sloped segment bounces off its line") {
    // A bed from (1, 0.2) down to (0, 0): listed right to left, its normal points up.
    SurfaceGeometry g;
    g.dimension = 2;
    g.vertices = {{1, 0.2, 0}, {0, 0, 0}};
    g.segments = {{0, 1}};
    const CaseConfig cfg = reflective_case(2, g, 1.0);
    const Reflector<2> r = reflective_walls<2>(cfg);
    const Vec<2> n = Vec<2>(-0.2, 1).normalized();
    const Vec<2> on{0.5, 0.1};
    Vec<2> x = on - 0.001 * n, vh{0.3, -1}, v = vh;
    r.apply(on + 0.002 * n, x, vh, v);
    CHECK((x - on).dot(n) == doctest::Approx(0.001).epsilon(1e-9));
    const Vec<2> vin{0.3, -1};
    CHECK(vh.dot(n) == doctest::Approx(-vin.dot(n)).epsilon(1e-12)); // elastic
    CHECK((vh - vh.dot(n) * n).norm() == doctest::Approx((vin - vin.dot(n) * n).norm()));
}
