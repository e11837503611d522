// libFuzzer target for the shape readers (geometry/surface_geometry.hpp) and the shape queries
// built on what they accept: any file must either give a shape whose index, report and wall
// sites are computed without a crash, or a GeometryError. Any other exception, a crash, a
// sanitizer report or a hang is a bug. Build and run: scripts/fuzz.sh (preset `fuzz`).
//
// Input: one byte choosing the format (STL, OBJ, PLY, OFF, or a 2-D vertex file), then the
// file's bytes, written to a temporary file of that extension (CGAL's readers take a path).
#include "sluice/geometry/shape_particles.hpp"
#include "sluice/geometry/shape_report.hpp"
#include "sluice/geometry/surface_geometry.hpp"
#include "sluice/geometry/surface_index.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1)
        return 0;
    static const char* const kExt[] = {".stl", ".obj", ".ply", ".off", ".csv"};
    const char* ext = kExt[data[0] % 5];
    const std::string path = "/tmp/sluice_fuzz_mesh_" + std::to_string(::getpid()) + ext;
    {
        std::ofstream out(path, std::ios::binary);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    sluice::GeometryLimits limits;
    limits.max_bytes = 1 << 20;
    limits.max_elements = 5000;
    try {
        const bool vertex_file = data[0] % 5 == 4;
        sluice::SurfaceGeometry g = vertex_file ? sluice::read_vertex_file(path, limits)
                                                : sluice::read_triangle_mesh(path, limits);
        if (!vertex_file && (data[0] & 0x80) != 0)
            g = sluice::section_by_plane(g, 0.0);
        const sluice::SurfaceIndex shape(std::move(g));
        const sluice::ShapeReport r = sluice::report_shape(shape, 1e-12);
        const sluice::Point3 far{r.hi[0] + 1, r.hi[1] + 1, r.hi[2] + 1};
        (void)shape.closest(far);
        (void)shape.within(far, 0.5);
        (void)shape.first_crossing(r.lo, far);
        if (shape.closed())
            (void)shape.inside(far);
        // Wall sites on a coarse lattice: at most about 4,000 sites per axis pair.
        double extent = 0;
        for (int a = 0; a < 3; ++a)
            extent = std::max(extent, r.hi[a] - r.lo[a]);
        if (extent > 0 && extent < 1e6) {
            const sluice::LatticeSpec lattice{extent / 16, r.lo, shape.dimension()};
            std::size_t sites = 0;
            sluice::visit_wall_sites(shape, sluice::ShapeRole::surface, lattice, 2,
                                     [&](const sluice::WallSite&) { ++sites; });
        }
    } catch (const sluice::GeometryError&) {
    }
    std::remove(path.c_str());
    return 0;
}
