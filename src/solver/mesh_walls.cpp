// Mesh walls and the fluid sites they take (mesh_walls.hpp).
#include "sluice/solver/mesh_walls.hpp"

#include "sluice/geometry/shape_particles.hpp"

#include "vec_triple.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

namespace {

ShapeRole role_of(const WallMesh& m) {
    return m.role == MeshRole::solid ? ShapeRole::solid : ShapeRole::surface;
}

LatticeSpec lattice_of(const CaseConfig& cfg, const WallMesh& m) {
    return {cfg.dx, m.shape->lo(), cfg.dimension};
}

} // namespace

template <int D>
ParticleId visit_mesh_wall_particles(const CaseConfig& cfg, int layers, ParticleId first_id,
                                     const InitialSink<D>& sink) {
    ParticleId next_id = first_id;
    const double mass = cfg.rho0 * std::pow(cfg.dx, D);
    for (std::size_t im = 0; im < cfg.meshes.size(); ++im) {
        const WallMesh& m = cfg.meshes[im];
        const int object = wall_object_index_of_mesh(cfg, im);
        visit_wall_sites(*m.shape, role_of(m), lattice_of(cfg, m), layers, [&](const WallSite& w) {
            sink({next_id++, Kind::wall, to_vec<D>(w.x), Vec<D>::Zero(), Real(cfg.rho0), Real(mass),
                  object});
        });
    }
    return next_id;
}

std::vector<std::size_t> count_mesh_wall_particles(const CaseConfig& cfg, int layers) {
    std::vector<std::size_t> counts;
    for (const WallMesh& m : cfg.meshes) {
        std::size_t n = 0;
        visit_wall_sites(*m.shape, role_of(m), lattice_of(cfg, m), layers,
                         [&](const WallSite&) { ++n; });
        counts.push_back(n);
    }
    return counts;
}

MeshWallCensus mesh_wall_census(const CaseConfig& cfg, std::size_t mesh, int layers) {
    const WallMesh& m = cfg.meshes.at(mesh);
    MeshWallCensus c;
    const double dx = cfg.dx;
    visit_wall_sites(*m.shape, role_of(m), lattice_of(cfg, m), layers, [&](const WallSite& w) {
        ++c.particles;
        c.first_layer += w.layer == 0 ? 1 : 0;
        const double d = std::sqrt(m.shape->squared_distance(w.x));
        c.surface_deviation = std::max(c.surface_deviation, std::abs(d - (w.layer + 0.5) * dx));
    });
    return c;
}

bool wall_particle_of_mesh(const CaseConfig& cfg, std::size_t mesh, int layers, const Triple& x) {
    const WallMesh& m = cfg.meshes.at(mesh);
    const ClosestPoint c = m.shape->closest(x);
    if (c.distance < 0.01 * cfg.dx)
        return true;
    if (m.role == MeshRole::solid)
        return m.shape->inside(x);
    return c.side < 0 && c.distance < layers * cfg.dx;
}

bool fluid_site_taken_by_mesh(const CaseConfig& cfg, const Triple& x) {
    const double keep = 0.5 * cfg.dx * (1 - 1e-9);
    for (const WallMesh& m : cfg.meshes) {
        // A solid takes nothing beyond dx/2 of its bounding box (most sites of a block): no
        // query. (Behind a surface is anywhere below a bed, so a surface is always asked.)
        if (m.role == MeshRole::solid) {
            bool near = true;
            for (std::size_t a = 0; a < static_cast<std::size_t>(cfg.dimension); ++a)
                near = near && x[a] > m.shape->lo()[a] - keep && x[a] < m.shape->hi()[a] + keep;
            if (!near)
                continue;
        }
        if (m.role == MeshRole::solid) {
            if (m.shape->inside(x) || m.shape->within(x, keep))
                return true;
            continue;
        }
        const ClosestPoint c = m.shape->closest(x);
        if (c.distance < keep || c.side < 0)
            return true;
    }
    return false;
}

template ParticleId visit_mesh_wall_particles<2>(const CaseConfig&, int, ParticleId,
                                                 const InitialSink<2>&);
template ParticleId visit_mesh_wall_particles<3>(const CaseConfig&, int, ParticleId,
                                                 const InitialSink<3>&);

} // namespace sluice
