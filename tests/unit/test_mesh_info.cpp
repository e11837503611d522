// `sluice info` and `check` on [[walls.meshes]]: each mesh's line (elements, closed or open,
// normals, bounding box, area, enclosed volume, thinnest part, the wall particles laid and how
// closely their surface follows the mesh), and the warnings naming walls.meshes[i].file for a
// solid thinner than its wall layers and for a surface curved on the scale of dx; a closed mesh
// as a fluid block, and its refusals.
#include "shape_files.hpp"
#include "sluice/io/case_reader.hpp"
#include "sluice/solver/case_check.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

using namespace sluice;

namespace {

// A 0.6 m cube tank with dummy walls, dx = 0.01 m, Wendland C2 with h = 1.5 dx: 3 wall layers.
std::string case_with_mesh(const std::string& file) {
    return R"(
[case]
dimension = 3
[domain]
lo = [0, 0, 0]
hi = [0.6, 0.6, 0.6]
[fluid]
rho0 = 1000
viscosity = 1e-3
sound_speed = 40
[particles]
dx = 0.01
[[blocks]]
lo = [0, 0, 0]
hi = [0.2, 0.6, 0.2]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
[walls]
model = "dummy"
tank_lo = [0, 0, 0]
tank_hi = [0.6, 0.6, 0.6]
[[walls.meshes]]
file = ")" +
           file + R"("
role = "solid"
[time]
end_time = 1
)";
}

struct Checked {
    CaseInfo info;
    std::vector<CaseWarning> warnings;
};

Checked check_shape(const SurfaceGeometry& g, const std::string& name) {
    const std::string path = test::temp_path(name);
    test::write_ascii_stl(g, path);
    const CaseConfig cfg = read_case_text(case_with_mesh(path), "mesh.toml", {});
    Checked c{describe_case(cfg), {}};
    c.warnings = case_warnings(cfg, c.info);
    std::filesystem::remove(path);
    return c;
}

std::string mesh_line(const CaseInfo& info) {
    for (const auto& l : info.geometry)
        if (l.rfind("walls.meshes[0]", 0) == 0)
            return l;
    return {};
}

const CaseWarning* mesh_warning(const std::vector<CaseWarning>& w, const std::string& part) {
    for (const auto& x : w)
        if (x.key == "walls.meshes[0].file" && x.message.find(part) != std::string::npos)
            return &x;
    return nullptr;
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("a box obstacle as a mesh: its line in info, no warning") {
    const Checked c = check_shape(test::box_shape({0.3, 0.2, 0}, {0.4, 0.4, 0.3}), "box.stl");
    const std::string line = mesh_line(c.info);
    INFO(line);
    CHECK(contains(line, "(solid): 12 triangles, closed, normals out"));
    CHECK(contains(line, "[0.3, 0.2, 0] to [0.4, 0.4, 0.3] m"));
    CHECK(contains(line, "area 0.22 m^2"));      // 2 (0.02 + 0.03 + 0.06)
    CHECK(contains(line, "encloses 0.006 m^3")); // 0.1 x 0.2 x 0.3
    CHECK(contains(line, "thinnest 0.1 m (10 dx)"));
    CHECK(contains(line, "in 3 layers"));
    CHECK(mesh_warning(c.warnings, "") == nullptr);
}

TEST_CASE("a solid thinner than its wall layers is flagged with its thickness") {
    // 0.02 m thick: 2 dx, below the 3 layers (0.03 m) a fluid particle's kernel reaches.
    const Checked c = check_shape(test::box_shape({0.3, 0.1, 0}, {0.32, 0.5, 0.3}), "plate.stl");
    const CaseWarning* w = mesh_warning(c.warnings, "thick at its thinnest");
    REQUIRE(w != nullptr);
    CHECK(contains(w->message, "0.02 m (2 dx)"));
    CHECK(contains(w->message, "3 wall layers (0.03 m"));
    CHECK(contains(w->message, "dx <= 0.00667 m"));
}

TEST_CASE("a sphere of a few dx is flagged: its innermost layer has gaps") {
    // Radius 0.025 m = 2.5 dx: the innermost layer, dx/2 inside, has about (2/2.5)^2 = 0.64 of
    // the sites a flat face of that area would have.
    const Checked small = check_shape(test::sphere_shape({0.3, 0.3, 0.3}, 0.025, 24, 48), "s.stl");
    const CaseWarning* w = mesh_warning(small.warnings, "sites per dx^2");
    REQUIRE(w != nullptr);
    // Radius 0.15 m = 15 dx: (14.5/15)^2 = 0.93, no warning.
    const Checked large = check_shape(test::sphere_shape({0.3, 0.3, 0.3}, 0.15, 24, 48), "l.stl");
    CHECK(mesh_warning(large.warnings, "sites per dx^2") == nullptr);
    const std::string line = mesh_line(large.info);
    INFO(line);
    CHECK(contains(line, "its surface within"));
}

namespace {

// The tank above with a mesh fluid block instead of the box block and no wall mesh.
std::string case_with_mesh_block(const std::string& file, const std::string& extra) {
    std::string t = case_with_mesh(file);
    const auto block = t.find("[[blocks]]");
    const auto numerics = t.find("[numerics]");
    t.replace(block, numerics - block,
              "[[blocks]]\nshape = \"mesh\"\nfile = \"" + file + "\"\nhydrostatic = false\n" +
                  extra + "\n");
    const auto mesh = t.find("[[walls.meshes]]");
    const auto time = t.find("[time]");
    t.erase(mesh, time - mesh);
    return t;
}

} // namespace

TEST_CASE("a closed mesh as a fluid block fills its inside on the lattice") {
    const std::string path = test::temp_path("drop.stl");
    test::write_ascii_stl(test::sphere_shape({0.3, 0.3, 0.3}, 0.1, 24, 48), path);
    const CaseConfig cfg = read_case_text(case_with_mesh_block(path, ""), "drop.toml", {});
    REQUIRE(cfg.blocks.size() == 1);
    const FluidBlock& b = cfg.blocks[0];
    CHECK(b.shape == BlockShape::mesh);
    CHECK(b.lo[0] == doctest::Approx(0.2));
    CHECK(b.hi[2] == doctest::Approx(0.4));
    const double volume = b.mesh->shape->enclosed_volume(); // the faceted sphere's
    CHECK(volume == doctest::Approx(4.0 / 3 * 3.14159265 * 1e-3).epsilon(0.02));
    const CaseInfo info = describe_case(cfg);
    // One particle per dx^3 of the shape's volume: 4,224 sites against 4,159 dx^3 (+1.6 %) at
    // 10 dx radius, the lattice's count of points in a ball (its error falls as 1/r).
    CHECK(double(info.fluid_particles) == doctest::Approx(volume / 1e-6).epsilon(0.03));
    bool line = false;
    for (const auto& l : info.geometry)
        line = line || (l.rfind("blocks[0]", 0) == 0 && contains(l, "particles, volume"));
    CHECK(line);

    SUBCASE("hi cuts the shape: the ball filled up to its equator") {
        const CaseConfig half =
            read_case_text(case_with_mesh_block(path, "hi = [1, 1, 0.3]"), "drop.toml", {});
        CHECK(half.blocks[0].hi[2] == doctest::Approx(0.3));
        CHECK(half.blocks[0].lo[2] == doctest::Approx(0.2));
        CHECK(describe_case(half).fluid_particles == info.fluid_particles / 2);
    }
    SUBCASE("an open mesh cannot be filled") {
        const std::string open = test::temp_path("open.stl");
        SurfaceGeometry g = test::box_shape({0.2, 0.2, 0.2}, {0.4, 0.4, 0.4});
        g.triangles.pop_back();
        test::write_ascii_stl(g, open);
        CHECK_THROWS_WITH(read_case_text(case_with_mesh_block(open, ""), "open.toml", {}),
                          doctest::Contains("blocks[0].file"));
        std::filesystem::remove(open);
    }
    SUBCASE("the mesh keys belong to mesh blocks only") {
        std::string t = case_with_mesh(path);
        t.replace(t.find("hi = [0.2, 0.6, 0.2]"), 20, "hi = [0.2, 0.6, 0.2]\nscale = 2");
        CHECK_THROWS_WITH(read_case_text(t, "box.toml", {}), doctest::Contains("blocks[0].scale"));
    }
    std::filesystem::remove(path);
}

TEST_CASE("an area sensor on a mesh: centred on the surface, facing into the wall, or refused") {
    const std::string path = test::temp_path("sensor_box.stl");
    test::write_ascii_stl(test::box_shape({0.3, 0.2, 0}, {0.4, 0.4, 0.3}), path);
    const auto with_sensor = [&](const std::string& position, const std::string& extra) {
        return case_with_mesh(path) + "[[probes]]\nname = \"s\"\ntype = \"pressure\"\n" +
               "position = " + position + "\ndiameter = 0.05\nmesh = 0\n" + extra;
    };
    // 0.004 m in front of the box's x- face: centred on it, into the wall along +x.
    const CaseConfig cfg = read_case_text(with_sensor("[0.296, 0.3, 0.15]", ""), "s.toml", {});
    const ProbeConfig& p = cfg.probes.at(0);
    CHECK(p.wall.mesh == 0);
    CHECK(p.sensor_centre[0] == doctest::Approx(0.3));
    CHECK(p.sensor_centre[2] == doctest::Approx(0.15));
    CHECK(p.sensor_normal[0] == doctest::Approx(1));
    CHECK(p.sensor_normal[1] == doctest::Approx(0).epsilon(1e-12));
    CHECK_THROWS_WITH(read_case_text(with_sensor("[0.25, 0.3, 0.15]", ""), "s.toml", {}),
                      doctest::Contains("probes[0].position"));
    CHECK_THROWS_WITH(
        read_case_text(with_sensor("[0.296, 0.3, 0.15]", "reading = \"interpolated\"\n"), "s.toml",
                       {}),
        doctest::Contains("probes[0].reading"));
    std::filesystem::remove(path);
}
