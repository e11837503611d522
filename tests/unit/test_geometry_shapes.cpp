// The geometry module: meshes and vertex files read through CGAL, their queries, and the wall
// layers laid behind them (shape_particles.hpp): the innermost layer within 0.05 dx of dx/2
// behind the surface for spacings that divide nothing, on a sphere and a tilted box.
#include "sluice/geometry/shape_particles.hpp"
#include "sluice/geometry/shape_report.hpp"
#include "sluice/geometry/surface_index.hpp"

#include "shape_files.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <set>

using namespace sluice;
using sluice::test::box_shape;
using sluice::test::sphere_shape;
using sluice::test::temp_path;
using sluice::test::write_ascii_stl;

namespace {

SurfaceIndex read_back(const SurfaceGeometry& g, const std::string& name) {
    const std::string path = temp_path(name);
    write_ascii_stl(g, path);
    SurfaceGeometry read = read_triangle_mesh(path, {});
    std::filesystem::remove(path);
    return SurfaceIndex(std::move(read));
}

struct LayerStats {
    std::size_t sites = 0, innermost = 0;
    double worst_innermost = 0; // max | distance to the mesh - dx/2 | over layer 0 [dx]
};

LayerStats layer_stats(const SurfaceIndex& s, ShapeRole role, double dx, int layers) {
    LayerStats st;
    LatticeSpec l{dx, s.lo(), 3};
    visit_wall_sites(s, role, l, layers, [&](const WallSite& w) {
        ++st.sites;
        if (w.layer != 0)
            return;
        ++st.innermost;
        const double d = s.closest(w.x).distance;
        st.worst_innermost = std::max(st.worst_innermost, std::abs(d - 0.5 * dx) / dx);
    });
    return st;
}

} // namespace

TEST_CASE("a box read from an STL file is closed and outward, with its volume and area") {
    const SurfaceIndex s = read_back(box_shape({0, 0, 0}, {0.3, 0.2, 0.1}), "box.stl");
    CHECK(s.geometry().vertices.size() == 8); // the STL's repeated corners merged
    CHECK(s.closed());
    CHECK(s.outward());
    CHECK(s.enclosed_volume() == doctest::Approx(0.006).epsilon(1e-12));
    CHECK(s.surface_size() == doctest::Approx(2 * (0.06 + 0.03 + 0.02)).epsilon(1e-12));
    CHECK(s.inside({0.1, 0.1, 0.05}));
    CHECK_FALSE(s.inside({0.31, 0.1, 0.05}));
    const ClosestPoint c = s.closest({0.35, 0.1, 0.05});
    CHECK(c.distance == doctest::Approx(0.05));
    CHECK(c.normal[0] == doctest::Approx(1));
    CHECK(c.side == doctest::Approx(1));
    const auto hit = s.first_crossing({-0.1, 0.1, 0.05}, {0.1, 0.1, 0.05});
    REQUIRE(hit);
    CHECK(hit->fraction == doctest::Approx(0.5));
    CHECK(hit->normal[0] == doctest::Approx(-1));
    const ShapeReport r = report_shape(s, 1e-12);
    CHECK(r.thinnest == doctest::Approx(0.1));
    CHECK(r.degenerate == 0);
}

TEST_CASE("flipped normals are seen: a closed mesh pointing inwards is not outward") {
    Placement flip;
    flip.flip = true;
    const SurfaceIndex s(placed(box_shape({0, 0, 0}, {1, 1, 1}), flip));
    CHECK(s.closed());
    CHECK_FALSE(s.outward());
    CHECK(s.enclosed_volume() == doctest::Approx(-1));
}

TEST_CASE("an open mesh is not closed and has no inside") {
    SurfaceGeometry g = box_shape({0, 0, 0}, {1, 1, 1});
    g.triangles.pop_back();
    const SurfaceIndex s(std::move(g));
    CHECK_FALSE(s.closed());
    CHECK_THROWS_AS((void)s.inside({0.5, 0.5, 0.5}), GeometryError);
}

TEST_CASE("a box as a solid gets the lattice shell of the same box, site for site") {
    const double dx = 0.01;
    const SurfaceIndex s = read_back(box_shape({0.1, 0.2, 0.3}, {0.2, 0.26, 0.38}), "shell.stl");
    std::set<std::array<long, 3>> mesh_sites, lattice_sites;
    visit_wall_sites(s, ShapeRole::solid, {dx, s.lo(), 3}, 3, [&](const WallSite& w) {
        mesh_sites.insert({std::lround(w.x[0] / dx * 2), std::lround(w.x[1] / dx * 2),
                           std::lround(w.x[2] / dx * 2)});
    });
    const int n[3] = {10, 6, 8};
    for (int i = 0; i < n[0]; ++i)
        for (int j = 0; j < n[1]; ++j)
            for (int k = 0; k < n[2]; ++k) {
                const bool shell =
                    i < 3 || j < 3 || k < 3 || i >= n[0] - 3 || j >= n[1] - 3 || k >= n[2] - 3;
                if (shell)
                    lattice_sites.insert({std::lround((0.1 + (i + 0.5) * dx) / dx * 2),
                                          std::lround((0.2 + (j + 0.5) * dx) / dx * 2),
                                          std::lround((0.3 + (k + 0.5) * dx) / dx * 2)});
            }
    CHECK(mesh_sites == lattice_sites);
}

TEST_CASE("the innermost wall layer lies dx/2 behind a sphere and a tilted box within 0.05 dx") {
    const SurfaceIndex sphere = read_back(sphere_shape({0.5, 0.5, 0.5}, 0.1, 24, 48), "sphere.stl");
    REQUIRE(sphere.closed());
    REQUIRE(sphere.outward());
    Placement tilt;
    tilt.rotation_deg = {20, 30, 10};
    tilt.translation = {0.5, 0.5, 0.5};
    SurfaceIndex tilted(placed(box_shape({-0.1, -0.05, -0.075}, {0.1, 0.05, 0.075}), tilt));
    REQUIRE(tilted.outward());
    for (const double dx : {0.00937, 0.0131, 0.0173}) {
        CAPTURE(dx);
        // The area of the surface dx/2 inside: the sphere's and the box's shrunk by dx.
        const double r = 0.1 - dx / 2, a = 0.2 - dx, b = 0.1 - dx, c = 0.15 - dx;
        const double inner_area[2] = {4 * std::numbers::pi * r * r, 2 * (a * b + b * c + a * c)};
        const SurfaceIndex* shapes[2] = {&sphere, &tilted};
        for (int k = 0; k < 2; ++k) {
            const SurfaceIndex* s = shapes[k];
            CAPTURE(k);
            // Inside the solid and, for the same shape as a container's surface, outside it.
            const LayerStats solid = layer_stats(*s, ShapeRole::solid, dx, 3);
            CHECK(solid.worst_innermost < 0.05);
            // One site per dx^2 of the layer's own surface on average: within 12 % (the sphere at 6
            // dx radius reads 10 % low).
            CHECK(double(solid.innermost) ==
                  doctest::Approx(inner_area[k] / (dx * dx)).epsilon(0.12));
            const LayerStats shell = layer_stats(*s, ShapeRole::surface, dx, 3);
            CHECK(shell.worst_innermost < 0.05);
        }
    }
}

TEST_CASE("a 2-D polygon from a vertex file: closed, its area, and its wall layers") {
    const std::string path = temp_path("triangle.csv");
    {
        std::ofstream f(path);
        f << "# a triangle, counter-clockwise\n0, 0\n1, 0\n0.5 0.4\n0, 0\n";
    }
    const SurfaceIndex s(read_vertex_file(path, {}));
    std::filesystem::remove(path);
    CHECK(s.dimension() == 2);
    CHECK(s.closed());
    CHECK(s.outward());
    CHECK(s.enclosed_volume() == doctest::Approx(0.2));
    CHECK(s.inside({0.5, 0.1, 0}));
    CHECK_FALSE(s.inside({0.9, 0.3, 0}));
    const double dx = 0.0123;
    double worst = 0;
    std::size_t innermost = 0;
    visit_wall_sites(s, ShapeRole::solid, {dx, s.lo(), 2}, 3, [&](const WallSite& w) {
        CHECK(w.x[2] == 0);
        if (w.layer == 0) {
            ++innermost;
            worst = std::max(worst, std::abs(s.closest(w.x).distance - dx / 2) / dx);
        }
    });
    CHECK(worst < 0.05);
    CHECK(double(innermost) == doctest::Approx(s.surface_size() / dx).epsilon(0.15));
}

TEST_CASE("an open 2-D bed lays its walls below it only") {
    const std::string path = temp_path("bed.csv");
    {
        std::ofstream f(path);
        f << "1, 0.2\n0.5, 0\n0, 0\n"; // traced right to left: normals point up
    }
    const SurfaceIndex s(read_vertex_file(path, {}));
    std::filesystem::remove(path);
    CHECK_FALSE(s.closed());
    const double dx = 0.01;
    std::size_t count = 0;
    visit_wall_sites(s, ShapeRole::surface, {dx, s.lo(), 2}, 2, [&](const WallSite& w) {
        ++count;
        CHECK(w.normal[1] > 0);
        CHECK(s.closest(w.x).side < 0);
    });
    // Two layers under about 1.04 m of bed, and the wedge under the kink.
    CHECK(double(count) == doctest::Approx(2 * 1.039 / dx).epsilon(0.05));
}

TEST_CASE("behind a corner the side is the corner's, not the nearest face's") {
    // A container: right wall down, a bed rising to the right, left wall up (normals inwards).
    // Below its lower-left corner (0, 0.05) a point is nearer the left wall's end than the
    // bed, and in front of the left wall's plane: only the corner's pseudo-normal (the sum of
    // the two faces' normals) puts it behind.
    SurfaceGeometry g;
    g.dimension = 2;
    g.vertices = {{0.4, 0.6, 0}, {0.4, 0.12, 0}, {0, 0.05, 0}, {0, 0.6, 0}};
    g.segments = {{0, 1}, {1, 2}, {2, 3}};
    const SurfaceIndex s(g);
    const ClosestPoint below = s.closest({0.005, 0.005, 0});
    CHECK(below.point[0] == doctest::Approx(0));
    CHECK(below.point[1] == doctest::Approx(0.05));
    CHECK(below.side < 0);
    CHECK(s.closest({0.005, 0.06, 0}).side > 0); // inside the container
    CHECK(s.closest({-0.005, 0.3, 0}).side < 0); // behind the left wall

    // 3-D: a unit cube, outward. Outside beyond an edge and a corner: in front; inside near
    // them: behind (the nearest feature is a face there).
    const SurfaceIndex cube(box_shape({0, 0, 0}, {1, 1, 1}));
    CHECK(cube.closest({1.1, 1.1, 0.5}).side > 0.99); // edge: (1, 1, 0) / sqrt 2 pseudo-normal
    CHECK(cube.closest({1.1, 1.1, 1.1}).side > 0.99); // corner
    CHECK(cube.closest({0.95, 0.97, 0.5}).side < -0.99);
    CHECK(cube.within({1.05, 0.5, 0.5}, 0.06)); // the sphere query of the fluid's cut
    CHECK_FALSE(cube.within({1.05, 0.5, 0.5}, 0.04));
    CHECK_FALSE(cube.within({0.5, 0.5, 0.5}, 0.4)); // inside, far from every face
    // Open: a single square (two triangles, normal +z). Beyond its edge, level with it, the
    // side is 0 (the edge's pseudo-normal is the face's); above it, positive.
    SurfaceGeometry sq;
    sq.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    sq.triangles = {{0, 1, 2}, {0, 2, 3}};
    const SurfaceIndex plate(sq);
    CHECK(plate.closest({1.5, 0.5, 0}).side == doctest::Approx(0).epsilon(1e-12));
    CHECK(plate.closest({1.5, 0.5, 0.5}).side > 0);
    CHECK(plate.closest({0.5, 0.5, -0.1}).side < -0.99);
}

TEST_CASE("the section of a box by a plane is its rectangle, oriented outwards") {
    const SurfaceGeometry cut = section_by_plane(box_shape({0, 0, -1}, {2, 1, 1}), 0.25);
    const SurfaceIndex s(cut);
    CHECK(s.closed());
    CHECK(s.outward());
    CHECK(s.enclosed_volume() == doctest::Approx(2));
    CHECK_THROWS_AS(section_by_plane(box_shape({0, 0, -1}, {2, 1, 1}), 5), GeometryError);
}

TEST_CASE("hostile mesh files are refused with a message") {
    const auto refused = [](const std::string& name, const std::string& content,
                            const std::string& words) {
        const std::string path = temp_path(name);
        {
            std::ofstream f(path, std::ios::binary);
            f << content;
        }
        std::string message;
        try {
            (void)read_triangle_mesh(path, {});
        } catch (const GeometryError& e) {
            message = e.what();
        }
        std::filesystem::remove(path);
        CAPTURE(name);
        CAPTURE(message);
        CHECK_FALSE(message.empty());
        CHECK(message.find(words) != std::string::npos);
    };
    refused("empty.stl", "", "empty");
    refused("garbage.stl", "solid x\nfacet normal a b c\n", "");
    refused("mesh.xyz", "1 2 3\n", "unknown mesh format");
    refused("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", "");
    refused("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "");
    std::string message;
    try {
        (void)read_triangle_mesh(temp_path("missing.stl"), {});
    } catch (const GeometryError& e) {
        message = e.what();
    }
    CHECK(message.find("no file") != std::string::npos);
    GeometryLimits tiny;
    tiny.max_elements = 5;
    const std::string path = temp_path("big.stl");
    write_ascii_stl(box_shape({0, 0, 0}, {1, 1, 1}), path);
    CHECK_THROWS_WITH_AS((void)read_triangle_mesh(path, tiny), doctest::Contains("above the limit"),
                         GeometryError);
    std::filesystem::remove(path);
}
