// [[walls.meshes]] (case_meshes.hpp).
#include "case_meshes.hpp"

#include "case_motions.hpp"

#include "sluice/geometry/shape_report.hpp"
#include "sluice/io/case_reader.hpp"
#include "sluice/physics/initial_profiles.hpp"
#include "sluice/physics/kernels.hpp"

#include "case_fingerprint.hpp"
#include "case_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace sluice::case_file {
namespace {

namespace fs = std::filesystem;

const std::vector<std::pair<std::string, MeshRole>> kRoles = {{"solid", MeshRole::solid},
                                                              {"surface", MeshRole::surface}};

bool is_vertex_file(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return ext == ".csv" || ext == ".txt" || ext == ".dat";
}

// The shape as the case places it; GeometryError becomes a refusal of `file`.
SurfaceGeometry load(const Section& s, const WallMesh& m, int dimension) {
    const GeometryLimits limits;
    try {
        SurfaceGeometry g;
        if (is_vertex_file(m.path)) {
            s.require(dimension == 2, "file",
                      "a vertex file describes a 2-D polyline; a 3-D case needs a triangle mesh "
                      "(.stl, .obj, .ply, .off)");
            g = read_vertex_file(m.path, limits);
        } else {
            g = read_triangle_mesh(m.path, limits);
            if (dimension == 2)
                g = section_by_plane(g, m.section_z);
        }
        Placement p;
        p.scale = m.scale;
        p.rotation_deg = m.rotation;
        p.translation = m.translation;
        p.flip = m.flip_normals;
        return placed(std::move(g), p);
    } catch (const GeometryError& e) {
        s.fail("file", e.what());
    }
}

} // namespace

ShapeReport read_shape_file(const Section& s, const CaseConfig& c, WallMesh& m) {
    // The placement's values first (their types and ranges), then the file.
    m.scale = s.number("scale", 1.0);
    if (const auto* r = s.node("rotation")) {
        if (c.dimension == 2) {
            m.rotation[2] = s.reader().as_number(*r, s.key("rotation"));
        } else {
            m.rotation = s.reader().as_triple(*r, s.key("rotation"));
        }
        for (double a : m.rotation)
            s.require(std::abs(a) <= 360, "rotation",
                      fmt::format("angles are in degrees, within [-360, 360]; got {}", a));
    }
    m.translation = s.triple("translation").value_or(Triple{});
    m.flip_normals = s.boolean("flip_normals").value_or(false);
    m.section_z = s.number("section_z", 0.0);
    const fs::path folder = fs::path(c.source_file).parent_path();
    const auto file = s.string("file");
    if (!file)
        s.fail("file", "missing required key: the shape's mesh or vertex file");
    m.file = *file;
    if (m.file.empty())
        s.fail("file", "must name a file");
    m.path = fs::path(m.file).is_absolute() ? m.file : (folder / m.file).string();
    if (s.node("section_z") != nullptr)
        s.require(c.dimension == 2 && !is_vertex_file(m.path), "section_z",
                  "only a 2-D case cut from a triangle mesh file has a section plane");

    SurfaceGeometry g = load(s, m, c.dimension);
    m.digest = file_sha256(m.path);
    // Degenerate: smaller than a millionth of dx (area: of dx^2).
    const double tiny = c.dimension == 3 ? 1e-12 * c.dx * c.dx : 1e-6 * c.dx;
    auto shape = std::make_shared<SurfaceIndex>(std::move(g));
    const ShapeReport r = report_shape(*shape, tiny, false); // thickness: info and check
    s.require(r.degenerate * 100 <= r.elements, "file",
              fmt::format("\"{}\": {} of its {} {} are degenerate (size below {:g}); repair "
                          "the mesh",
                          m.file, r.degenerate, r.elements,
                          c.dimension == 3 ? "triangles" : "segments", tiny));
    // The shape lies in the domain (a surface's wall layers may reach past it, as the tank's
    // do: the solver's grid covers them, wall_extent.hpp).
    const double eps = slack(c);
    for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a)
        s.require(r.lo[a] >= c.domain_lo[a] - eps && r.hi[a] <= c.domain_hi[a] + eps, "translation",
                  fmt::format("\"{}\" as placed spans {} = [{:g}, {:g}], outside the domain "
                              "[{:g}, {:g}]",
                              m.file, kAxis[a], r.lo[a], r.hi[a], c.domain_lo[a], c.domain_hi[a]));
    m.shape = std::move(shape);
    return r;
}

void require_closed_outward(const Section& s, const CaseConfig& c, const WallMesh& m,
                            const ShapeReport& r, const std::string& what,
                            const std::string& instead) {
    s.require(r.closed, instead.empty() ? "file" : "role",
              fmt::format("\"{}\" is not closed (some {} are not shared by exactly two {} "
                          "running opposite ways), so it has no inside{}: {}close the mesh",
                          m.file, c.dimension == 3 ? "edges" : "vertices",
                          c.dimension == 3 ? "triangles" : "segments", what,
                          instead.empty() ? "" : instead + ", or "));
    s.require(r.outward, "flip_normals",
              fmt::format("the normals of \"{}\" point inwards (its signed volume is {:g}); "
                          "set flip_normals = {}",
                          m.file, r.volume, m.flip_normals ? "false" : "true"));
}

void read_wall_meshes(const Section& walls, CaseConfig& c) {
    for (const auto& s : walls.entries("meshes")) {
        s.require(c.walls != WallModel::none, "file",
                  "a wall mesh is a wall: it needs walls.model = \"dummy\" (wall particles "
                  "laid behind it) or \"reflective\" (its faces reflect)");
        WallMesh m;
        if (!s.string("role"))
            s.fail("role", "missing required key: \"solid\" (a closed obstacle) or \"surface\" "
                           "(walls behind it, opposite its normals)");
        m.role = s.choice("role", m.role, kRoles);
        const ShapeReport r = read_shape_file(s, c, m);
        m.motion = motion_reference(s, "motion", c);
        if (m.role == MeshRole::solid)
            require_closed_outward(s, c, m, r, " as a solid", "use role = \"surface\"");
        c.meshes.push_back(std::move(m));
    }
}

} // namespace sluice::case_file
