// Reading, cutting and placing shapes (surface_geometry.hpp): CGAL's polygon soup readers for
// mesh files, CGAL's Polygon_mesh_slicer for sections; vertex files are read here (two numbers
// a line).
#include "sluice/geometry/surface_geometry.hpp"

#include "point_math.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

namespace sluice {

using detail::cross;
using detail::minus;
using detail::norm;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<P3>;

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return ext;
}

// The file exists, is a regular readable file, and is within the byte limit.
void check_file(const std::string& path, const GeometryLimits& limits) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status))
        throw GeometryError("no file \"" + path + "\"");
    if (!std::filesystem::is_regular_file(status))
        throw GeometryError("\"" + path + "\" is not a regular file");
    const auto bytes = std::filesystem::file_size(path, ec);
    if (ec)
        throw GeometryError("cannot read \"" + path + "\": " + ec.message());
    if (bytes > limits.max_bytes)
        throw GeometryError("\"" + path + "\" has " + std::to_string(bytes) +
                            " bytes, above the limit of " + std::to_string(limits.max_bytes));
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
        throw GeometryError("cannot open \"" + path + "\" for reading");
    if (bytes == 0)
        throw GeometryError("\"" + path + "\" is empty");
}

bool finite(const Point3& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

} // namespace

SurfaceGeometry read_triangle_mesh(const std::string& path, const GeometryLimits& limits) {
    check_file(path, limits);
    const std::string ext = lower_extension(path);
    if (ext != ".stl" && ext != ".obj" && ext != ".ply" && ext != ".off")
        throw GeometryError("unknown mesh format \"" + ext + "\" of \"" + path +
                            "\"; sluice reads .stl (ASCII or binary), .obj, .ply and .off");
    std::vector<P3> points;
    std::vector<std::vector<std::size_t>> polygons;
    bool ok = false;
    try {
        ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
    } catch (const std::exception& e) {
        throw GeometryError("cannot read \"" + path + "\" as " + ext + ": " + e.what());
    }
    if (!ok)
        throw GeometryError("cannot read \"" + path + "\" as a " + ext + " mesh (malformed file)");
    if (polygons.empty())
        throw GeometryError("\"" + path + "\" holds no triangles");
    SurfaceGeometry g;
    g.dimension = 3;
    std::size_t triangles = 0;
    for (const auto& poly : polygons) {
        if (poly.size() < 3)
            throw GeometryError("\"" + path + "\" has a face with " + std::to_string(poly.size()) +
                                " vertices");
        for (std::size_t v : poly)
            if (v >= points.size())
                throw GeometryError("\"" + path + "\" has a face with vertex index " +
                                    std::to_string(v) + " beyond its " +
                                    std::to_string(points.size()) + " vertices");
        triangles += poly.size() - 2;
    }
    if (triangles > limits.max_elements)
        throw GeometryError("\"" + path + "\" has " + std::to_string(triangles) +
                            " triangles, above the limit of " +
                            std::to_string(limits.max_elements));
    for (const auto& p : points)
        if (!finite({p.x(), p.y(), p.z()}))
            throw GeometryError("\"" + path + "\" has a vertex that is not a finite number");
    // STL repeats each vertex per facet; OBJ and PLY may too: shared corners must be one vertex
    // for the shape's edges to pair up (closedness, the inside test).
    CGAL::Polygon_mesh_processing::merge_duplicate_points_in_polygon_soup(points, polygons);
    g.vertices.reserve(points.size());
    for (const auto& p : points)
        g.vertices.push_back({p.x(), p.y(), p.z()});
    g.triangles.reserve(triangles);
    for (const auto& poly : polygons)
        for (std::size_t k = 1; k + 1 < poly.size(); ++k) // a fan from the first vertex
            g.triangles.push_back({static_cast<std::uint32_t>(poly[0]),
                                   static_cast<std::uint32_t>(poly[k]),
                                   static_cast<std::uint32_t>(poly[k + 1])});
    return g;
}

SurfaceGeometry read_vertex_file(const std::string& path, const GeometryLimits& limits) {
    check_file(path, limits);
    std::ifstream in(path);
    SurfaceGeometry g;
    g.dimension = 2;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream ss(line);
        std::string first;
        if (!(ss >> first) || first[0] == '#')
            continue;
        ss.clear();
        ss.str(line);
        double x = 0, y = 0;
        std::string rest;
        if (!(ss >> x >> y) || (ss >> rest))
            throw GeometryError("\"" + path + "\" line " + std::to_string(number) +
                                ": expected two numbers \"x, y\"");
        if (!std::isfinite(x) || !std::isfinite(y))
            throw GeometryError("\"" + path + "\" line " + std::to_string(number) +
                                ": a vertex that is not a finite number");
        g.vertices.push_back({x, y, 0});
        if (g.vertices.size() > limits.max_elements + 1)
            throw GeometryError("\"" + path + "\" has more than " +
                                std::to_string(limits.max_elements) + " segments");
    }
    if (g.vertices.size() < 2)
        throw GeometryError("\"" + path + "\" holds fewer than two vertices");
    const bool closes = g.vertices.size() > 3 && g.vertices.front() == g.vertices.back();
    if (closes)
        g.vertices.pop_back();
    const auto n = static_cast<std::uint32_t>(g.vertices.size());
    for (std::uint32_t k = 0; k + 1 < n; ++k)
        g.segments.push_back({k, k + 1});
    if (closes)
        g.segments.push_back({n - 1, 0});
    return g;
}

SurfaceGeometry section_by_plane(const SurfaceGeometry& mesh, double z0) {
    if (mesh.dimension != 3)
        throw GeometryError("only a 3-D mesh has a section");
    std::vector<P3> points;
    for (const auto& v : mesh.vertices)
        points.emplace_back(v[0], v[1], v[2]);
    std::vector<std::vector<std::size_t>> faces;
    for (const auto& t : mesh.triangles)
        faces.push_back({t[0], t[1], t[2]});
    if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces))
        throw GeometryError("the mesh is not a manifold surface, so it cannot be cut");
    Mesh m;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, m);
    using Tree =
        CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
    Tree tree(CGAL::faces(m).first, CGAL::faces(m).second, m);
    tree.accelerate_distance_queries();
    CGAL::Polygon_mesh_slicer<Mesh, K> slicer(m);
    std::vector<std::vector<P3>> polylines;
    slicer(K::Plane_3(0, 0, 1, -z0), std::back_inserter(polylines));
    SurfaceGeometry g;
    g.dimension = 2;
    std::map<std::pair<double, double>, std::uint32_t> index;
    const auto vertex = [&](const P3& p) {
        const auto key = std::make_pair(p.x(), p.y());
        const auto [it, added] = index.emplace(key, static_cast<std::uint32_t>(g.vertices.size()));
        if (added)
            g.vertices.push_back({p.x(), p.y(), 0});
        return it->second;
    };
    for (const auto& line : polylines) {
        if (line.size() < 2)
            continue;
        // Orient the polyline by the cut triangles: its segments' normals (dy, -dx) should
        // agree with the mesh's normals projected on the plane (a length-weighted vote).
        double agree = 0;
        for (std::size_t k = 0; k + 1 < line.size(); ++k) {
            const P3 mid = CGAL::midpoint(line[k], line[k + 1]);
            const auto face = tree.closest_point_and_primitive(mid).second;
            const auto n = CGAL::Polygon_mesh_processing::compute_face_normal(face, m);
            const double dx = line[k + 1].x() - line[k].x(), dy = line[k + 1].y() - line[k].y();
            agree += dy * n.x() - dx * n.y();
        }
        std::vector<std::uint32_t> ids;
        for (const auto& p : line)
            ids.push_back(vertex(p));
        if (agree < 0)
            std::reverse(ids.begin(), ids.end());
        for (std::size_t k = 0; k + 1 < ids.size(); ++k)
            if (ids[k] != ids[k + 1])
                g.segments.push_back({ids[k], ids[k + 1]});
    }
    if (g.segments.empty())
        throw GeometryError("the plane z = " + std::to_string(z0) + " does not cut the mesh");
    return g;
}

SurfaceGeometry placed(SurfaceGeometry g, const Placement& p) {
    if (!std::isfinite(p.scale) || p.scale <= 0)
        throw GeometryError("the scale must be a positive finite number");
    constexpr double deg = std::numbers::pi / 180;
    const double ax = p.rotation_deg[0] * deg, ay = p.rotation_deg[1] * deg,
                 az = p.rotation_deg[2] * deg;
    const bool rotate = ax != 0 || ay != 0 || az != 0;
    for (auto& v : g.vertices) {
        Point3 x{v[0] * p.scale, v[1] * p.scale, v[2] * p.scale};
        if (rotate) {
            if (g.dimension == 3) {
                x = {x[0], std::cos(ax) * x[1] - std::sin(ax) * x[2],
                     std::sin(ax) * x[1] + std::cos(ax) * x[2]};
                x = {std::cos(ay) * x[0] + std::sin(ay) * x[2], x[1],
                     -std::sin(ay) * x[0] + std::cos(ay) * x[2]};
            }
            x = {std::cos(az) * x[0] - std::sin(az) * x[1],
                 std::sin(az) * x[0] + std::cos(az) * x[1], x[2]};
        }
        for (std::size_t a = 0; a < 3; ++a)
            v[a] = x[a] + p.translation[a];
        if (g.dimension == 2)
            v[2] = 0;
    }
    if (p.flip) {
        for (auto& t : g.triangles)
            std::swap(t[1], t[2]);
        for (auto& s : g.segments)
            std::swap(s[0], s[1]);
    }
    return g;
}

Point3 element_normal(const SurfaceGeometry& g, std::size_t e) {
    Point3 n{};
    if (g.dimension == 3) {
        const auto& t = g.triangles[e];
        n = cross(minus(g.vertices[t[1]], g.vertices[t[0]]),
                  minus(g.vertices[t[2]], g.vertices[t[0]]));
    } else {
        const auto& s = g.segments[e];
        const Point3 d = minus(g.vertices[s[1]], g.vertices[s[0]]);
        n = {d[1], -d[0], 0};
    }
    const double len = norm(n);
    if (len > 0)
        for (double& c : n)
            c /= len;
    return n;
}

double element_size(const SurfaceGeometry& g, std::size_t e) {
    if (g.dimension == 3) {
        const auto& t = g.triangles[e];
        return 0.5 * norm(cross(minus(g.vertices[t[1]], g.vertices[t[0]]),
                                minus(g.vertices[t[2]], g.vertices[t[0]])));
    }
    const auto& s = g.segments[e];
    return norm(minus(g.vertices[s[1]], g.vertices[s[0]]));
}

} // namespace sluice
