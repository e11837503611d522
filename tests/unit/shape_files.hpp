#pragma once
// Shapes the geometry tests build in code and write as files: boxes, UV spheres, tilted boxes,
// in ASCII STL, so that the tests read them through the same reader as a case does.
#include "sluice/geometry/surface_geometry.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

namespace sluice::test {

// An axis-aligned box, 12 triangles, outward normals.
inline SurfaceGeometry box_shape(const Point3& lo, const Point3& hi) {
    SurfaceGeometry g;
    for (int k = 0; k < 8; ++k)
        g.vertices.push_back(
            {(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]});
    // Each face as two triangles, counter-clockwise seen from outside.
    const std::uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : q) {
        g.triangles.push_back({f[0], f[1], f[2]});
        g.triangles.push_back({f[0], f[2], f[3]});
    }
    return g;
}

// A UV sphere of `stacks` x `slices`, outward normals, poles as single vertices.
inline SurfaceGeometry sphere_shape(const Point3& c, double r, int stacks, int slices) {
    SurfaceGeometry g;
    const double pi = std::numbers::pi;
    g.vertices.push_back({c[0], c[1], c[2] - r});
    for (int i = 1; i < stacks; ++i) {
        const double th = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double ph = 2 * pi * j / slices;
            g.vertices.push_back({c[0] + r * std::sin(th) * std::cos(ph),
                                  c[1] + r * std::sin(th) * std::sin(ph), c[2] - r * std::cos(th)});
        }
    }
    g.vertices.push_back({c[0], c[1], c[2] + r});
    const auto ring = [&](int i, int j) {
        return static_cast<std::uint32_t>(1 + (i - 1) * slices + (j % slices));
    };
    const auto top = static_cast<std::uint32_t>(g.vertices.size() - 1);
    for (int j = 0; j < slices; ++j) {
        g.triangles.push_back({0, ring(1, j + 1), ring(1, j)});
        for (int i = 1; i + 1 < stacks; ++i) {
            g.triangles.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
            g.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
        }
        g.triangles.push_back({ring(stacks - 1, j), ring(stacks - 1, j + 1), top});
    }
    return g;
}

inline void write_ascii_stl(const SurfaceGeometry& g, const std::string& path) {
    std::ofstream out(path);
    out.precision(17);
    out << "solid test\n";
    for (std::size_t e = 0; e < g.triangles.size(); ++e) {
        const Point3 n = element_normal(g, e);
        out << "facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\nouter loop\n";
        for (auto v : g.triangles[e])
            out << "vertex " << g.vertices[v][0] << ' ' << g.vertices[v][1] << ' '
                << g.vertices[v][2] << '\n';
        out << "endloop\nendfacet\n";
    }
    out << "endsolid test\n";
}

// A fresh file path under the system's temporary folder.
inline std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("sluice_test_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

} // namespace sluice::test
