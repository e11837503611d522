// Tak's (2024) debris box with its tank as the paper builds it, 12 reflective triangles
// (cases/debris_box_mesh_3d.toml, meshes/debris_tank_3d.stl), against the same tank as six
// reflective planes (cases/debris_box_3d.toml): the block falls, hits the floor and spreads to
// the walls, and the two runs agree particle for particle at every step. The mesh's vertices
// and normals are exact (0 and 1), so each mirror is the plane's to the last bit; the
// tolerance below (1e-12 m) is the guard. The plane run uses one thread and the mesh run two.
// Coarse (dx = 0.025 m, 1,000 particles) and 0.25 s: the block reaches the floor at about 0.1 s and
// its front the walls after 0.2 s.
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <unordered_map>

using namespace sluice;
using namespace sluice::testing;

namespace {

std::unordered_map<ParticleId, std::size_t> by_id(const Particles<3>& P) {
    std::unordered_map<ParticleId, std::size_t> m;
    for (std::size_t i = 0; i < P.size(); ++i)
        m[P.id[i]] = i;
    return m;
}

} // namespace

TEST_CASE("Debris box: a tank of 12 reflective triangles moves the fluid as its 6 planes do") {
    const std::vector<std::string> coarse = {"particles.dx=0.025", "time.end_time=0.25"};
    const CaseConfig planes_cfg = read_case(case_path("debris_box_3d.toml"), coarse);
    const CaseConfig mesh_cfg = read_case(case_path("debris_box_mesh_3d.toml"), coarse);
    REQUIRE(mesh_cfg.meshes.size() == 1);
    REQUIRE(mesh_cfg.tank_faces.empty());

    // One thread against two: the reflections of one group's particles must not reach another
    // group's rates within the step (a race would show here as a difference).
    SimulationOptions one, two;
    one.threads = 1;
    two.threads = 2;
    Simulation<3> planes(planes_cfg, one);
    Simulation<3> mesh(mesh_cfg, two);
    REQUIRE(planes.particles().size() == mesh.particles().size());
    double worst = 0, lowest = 1;
    long steps = 0, contacts = 0;
    while (planes.time() < planes_cfg.end_time) {
        planes.step();
        mesh.step();
        ++steps;
        REQUIRE(mesh.dt() == planes.dt());
        const auto& A = planes.particles();
        const auto& B = mesh.particles();
        const auto index = by_id(B);
        for (std::size_t i = 0; i < A.size(); ++i) {
            const std::size_t j = index.at(A.id[i]);
            worst = std::max(worst, (A.x[i] - B.x[j]).cwiseAbs().maxCoeff());
            worst = std::max(worst, (A.v[i] - B.v[j]).cwiseAbs().maxCoeff() * 1e-3);
            const double gap = std::min(B.x[j].minCoeff(), 1 - B.x[j].maxCoeff());
            lowest = std::min(lowest, gap);
            contacts += gap < 0.25 * mesh_cfg.dx ? 1 : 0;
        }
        if (worst > 1e-12) {
            std::printf("first disagreement at step %ld (t = %.6f s): %.3g\n", steps, planes.time(),
                        worst);
            break;
        }
    }
    std::printf("debris box, planes vs mesh: %ld steps, %ld particle-steps within dx/4 of a "
                "wall, largest difference %.3g m, nearest approach to a wall %.3g m\n",
                steps, contacts, worst, lowest);
    CHECK(contacts > 1000); // the walls were reached
    CHECK(worst <= 1e-12);
    CHECK(lowest >= 0); // every particle inside the tank
}
