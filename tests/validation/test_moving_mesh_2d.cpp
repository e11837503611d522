// A wall object given as a mesh moves as its motion says: the 64-gon of radius 0.08 m of
// tests/data/mesh_loads/circle_2d.csv (a solid obstacle in still water 0.4 m deep) sways
// 2 cm to and fro along x with a period of 0.5 s. After 0.6 s every one of its wall
// particles is where the pose puts its t = 0 position (to round-off: the drift places them,
// nothing integrates them), the other walls have not moved, no water particle is inside the
// moving circle, and the mass is unchanged.
#include "sluice/motion/motion_law.hpp"
#include "sluice/solver/simulation.hpp"
#include "validation_support.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

using namespace sluice;
using namespace sluice::testing;

TEST_CASE("A swaying mesh obstacle: its particles on its pose, the water kept out") {
    const std::string text = R"(
[case]
dimension = 2
[domain]
lo = [0.0, 0.0]
hi = [0.4, 0.6]
[fluid]
rho0 = 1000.0
viscosity = 1.0e-3
sound_speed = 20.0
[particles]
dx = 0.01
[[blocks]]
lo = [0.0, 0.0]
hi = [0.4, 0.4]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
artificial_viscosity = 0.02
[walls]
model = "dummy"
tank_lo = [0.0, 0.0]
tank_hi = [0.4, 0.6]
tank_faces = ["x-", "x+", "y-"]
[[walls.meshes]]
file = "circle_2d.csv"
role = "solid"
motion = "sway"
[[motions]]
name = "sway"
kind = "sway"
amplitude = [0.02, 0.0]
period = 0.5
ramp = 0.25
[time]
end_time = 0.6
)";
    // Named in the mesh's folder: the case's `file` is relative to it.
    const CaseConfig cfg = read_case_text(text, data_path("mesh_loads/moving_circle_2d.toml"));
    Simulation<2> sim(cfg);
    const auto& P0 = sim.particles();
    const double mass0 = P0.total_mass();
    std::map<ParticleId, Eigen::Vector3d> x0;
    for (std::size_t i = 0; i < P0.size(); ++i)
        if (P0.kind[i] == Kind::wall)
            x0[P0.id[i]] = to_pose_point<2>(P0.x[i]);
    while (sim.time() < cfg.end_time)
        sim.step();

    const Pose pose = make_motion(cfg.motions[0]).pose(sim.time());
    const Eigen::Vector3d centre(0.2 + pose.d[0], 0.2, 0);
    const auto& P = sim.particles();
    int moved = 0, fixed = 0, inside = 0;
    double worst_moved = 0, worst_fixed = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        const Eigen::Vector3d x = to_pose_point<2>(P.x[i]);
        if (P.kind[i] == Kind::fluid) {
            // Water inside the circle (its surface, less half a spacing).
            inside += (x - centre).norm() < 0.08 - 0.005 ? 1 : 0;
            continue;
        }
        const Eigen::Vector3d& start = x0.at(P.id[i]);
        // The circle's particles lie within its radius of its centre at t = 0.
        if ((start - Eigen::Vector3d(0.2, 0.2, 0)).norm() < 0.081) {
            worst_moved = std::max(worst_moved, (x - pose.position(start)).norm());
            ++moved;
        } else {
            worst_fixed = std::max(worst_fixed, (x - start).norm());
            ++fixed;
        }
    }
    std::printf("moving mesh: t = %.4f s, displacement %.5f m; %d circle particles within "
                "%.2e m of their pose, %d other wall particles moved at most %.2e m; %d water "
                "particles inside the circle\n",
                sim.time(), pose.d[0], moved, worst_moved, fixed, worst_fixed, inside);
    CHECK(std::abs(pose.d[0]) > 0.01); // the test sees the obstacle away from its start
    CHECK(moved > 100);
    CHECK(worst_moved < 1e-12);
    CHECK(worst_fixed == 0);
    CHECK(inside == 0);
    CHECK(P.total_mass() == mass0);
}
