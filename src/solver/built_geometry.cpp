#include "sluice/solver/built_geometry.hpp"

#include "initial_lattice.hpp"
#include "sluice/solver/initial_state.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace sluice {

using detail::AxisSites;
using detail::block_particles;
using detail::box_axis_sites;
using detail::box_particles;
using detail::face_walled;
using detail::lattice_count;
using detail::tank_axis_sites;

BuiltGeometry built_geometry(const CaseConfig& cfg, int layers) {
    BuiltGeometry g;
    const double dx = cfg.dx;
    const int dim = cfg.dimension;
    if (cfg.walls == WallModel::dummy) {
        std::array<AxisSites, 3> axes;
        for (int d = 0; d < dim; ++d)
            axes[static_cast<std::size_t>(d)] = tank_axis_sites(cfg, d, layers);
        for (int d = 0; d < dim; ++d)
            for (const bool upper : {false, true}) {
                if (!face_walled(cfg, d, upper))
                    continue;
                const AxisSites& s = axes[static_cast<std::size_t>(d)];
                BuiltFace f;
                f.axis = d;
                f.upper = upper;
                f.layers = layers;
                f.requested = upper ? cfg.tank_hi[d] : cfg.tank_lo[d];
                f.built = upper ? s.x[static_cast<std::size_t>(s.n_a + s.mid)] - 0.5 * dx
                                : s.x[static_cast<std::size_t>(s.n_a - 1)] + 0.5 * dx;
                f.particles = static_cast<std::size_t>(layers);
                for (int e = 0; e < dim; ++e)
                    if (e != d)
                        f.particles *= axes[static_cast<std::size_t>(e)].x.size();
                g.faces.push_back(f);
            }
        for (const WallBox& b : cfg.boxes) {
            BuiltBox bb;
            for (int d = 0; d < dim; ++d) {
                const AxisSites s = box_axis_sites(b, d, layers, dx);
                bb.lo[d] = s.x.front() - 0.5 * dx;
                bb.hi[d] = s.x.back() + 0.5 * dx;
                bb.thin[static_cast<std::size_t>(d)] = s.thin;
            }
            bb.particles = box_particles(cfg, b, layers, bb.sites);
            g.boxes.push_back(bb);
        }
    }
    for (const FluidBlock& b : cfg.blocks) {
        BuiltBlock bb;
        double requested = 1;
        for (int d = 0; d < dim; ++d) {
            const auto a = static_cast<std::size_t>(d);
            bb.sites[a] = block_lattice_count(cfg, b, d);
            bb.capped[a] = bb.sites[a] < lattice_count(b.lo[d], b.hi[d], dx);
            bb.hi[a] = b.lo[a] + bb.sites[a] * dx;
            requested *= b.hi[a] - b.lo[a];
        }
        if (b.shape == BlockShape::ellipse)
            requested *= dim == 2 ? std::numbers::pi / 4 : std::numbers::pi / 6;
        if (b.shape == BlockShape::mesh)
            requested = b.mesh->shape->enclosed_volume();
        bb.particles = block_particles(cfg, b);
        bb.volume = static_cast<double>(bb.particles) * std::pow(dx, dim);
        bb.requested_volume = requested;
        g.blocks.push_back(bb);
    }
    // Degenerate as the case reader counts them (case_meshes.cpp).
    const double tiny = dim == 3 ? 1e-12 * dx * dx : 1e-6 * dx;
    for (std::size_t i = 0; i < cfg.meshes.size(); ++i) {
        BuiltMesh bm;
        bm.shape = report_shape(*cfg.meshes[i].shape, tiny);
        if (cfg.walls == WallModel::dummy) {
            bm.walls = mesh_wall_census(cfg, i, layers);
            bm.coverage =
                static_cast<double>(bm.walls.first_layer) * std::pow(dx, dim - 1) / bm.shape.size;
        }
        g.meshes.push_back(bm);
    }
    return g;
}

} // namespace sluice
