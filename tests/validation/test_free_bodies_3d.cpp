// Free bodies in 3-D (docs/FLOATING_BODIES.md), coarse: a fluid block in zero gravity, with no
// tank, thrown off-centre at a free box: the fluid's momentum plus the box's stays what it was
// to round-off (the last agreed load's impulse counted), the box is pushed along the block's
// way and set turning, its orientation stays a rotation, and its motion probe writes the
// 3-D columns (quaternion, angular velocity, force, moment) the run's way.
#include "validation_support.hpp"

#include "sluice/io/case_reader.hpp"
#include "sluice/solver/simulation.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <string>

using namespace sluice;
using namespace sluice::testing;

namespace {

const std::string kThrown =
    "[case]\ndimension = 3\n[domain]\nlo = [0, 0, 0]\nhi = [1.0, 0.6, 0.6]\n"
    "[fluid]\nrho0 = 1000\nviscosity = 1e-3\nsound_speed = 20\ngravity = [0, 0, 0]\n"
    "[particles]\ndx = 0.04\n[[blocks]]\nlo = [0.04, 0.2, 0.24]\nhi = [0.28, 0.44, 0.48]\n"
    "velocity = [1.5, 0, 0]\nhydrostatic = false\n"
    "[numerics]\nkernel = \"wendland_c2\"\nh_over_dx = 1.5\nartificial_viscosity = 0.05\n"
    "dt = 4e-4\n"
    "[walls]\nmodel = \"dummy\"\ntank_lo = [0, 0, 0]\ntank_hi = [1.0, 0.6, 0.6]\n"
    "tank_faces = []\n"
    "[[walls.boxes]]\nlo = [0.4, 0.2, 0.2]\nhi = [0.56, 0.36, 0.36]\nmotion = \"box\"\n"
    "[[motions]]\nname = \"box\"\nkind = \"free_body\"\ndensity = 700\n"
    "[time]\nend_time = 0.2\noutput_interval = 0.1\n"
    "[[probes]]\nname = \"box\"\ntype = \"motion\"\nframe = \"box\"\ninterval = 0.01\n";

} // namespace

TEST_CASE("3-D: momentum kept to round-off, the box pushed and turned") {
    const CaseConfig cfg = read_case_text(kThrown, "thrown3d.toml");
    Simulation<3> sim(cfg);
    const auto momentum = [&] {
        const Particles<3>& P = sim.particles();
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < P.size(); ++i)
            if (P.kind[i] == Kind::fluid)
                p += double(P.mass[i]) * P.v_half[i].cast<double>();
        const RigidBody& b = sim.motion().bodies()[0];
        return Eigen::Vector3d(p + b.mass().mass * b.velocity() +
                               sim.dt() * sim.motion().loads()[0].force);
    };
    const Eigen::Vector3d p0 = momentum();
    while (sim.time() < cfg.end_time)
        sim.step();
    const Eigen::Vector3d p1 = momentum();
    const RigidBody& b = sim.motion().bodies()[0];
    MESSAGE(fmt::format("momentum [{:.12g}, {:.12g}, {:.12g}] -> [{:.12g}, {:.12g}, {:.12g}]; "
                        "box velocity [{:.3g}, {:.3g}, {:.3g}], angular velocity [{:.3g}, {:.3g}, "
                        "{:.3g}]",
                        p0.x(), p0.y(), p0.z(), p1.x(), p1.y(), p1.z(), b.velocity().x(),
                        b.velocity().y(), b.velocity().z(), b.angular_velocity().x(),
                        b.angular_velocity().y(), b.angular_velocity().z()));
    CHECK((p1 - p0).norm() < 1e-11 * p0.norm());
    CHECK(b.velocity().x() > 0.05);
    // The block hits the box above its centre (z 0.24-0.48 against 0.2-0.36): it turns about y.
    CHECK(std::abs(b.angular_velocity().y()) > 1e-3);
    const Eigen::Matrix3d R = b.orientation();
    CHECK((R * R.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
}

TEST_CASE("3-D: a free body's motion probe writes its orientation and load") {
    const CaseConfig cfg = read_case_text(kThrown, "thrown3d_probe.toml");
    const FolderRun run = run_in_temp_folder(cfg, "thrown3d", 2);
    const auto rows = read_csv(run.folder + "/probes/box.csv");
    REQUIRE(rows.size() >= 15);
    for (const auto& r : rows) {
        REQUIRE(r.size() == 22); // time, 4 + 4 motion columns, quaternion, omega, F, M
        double q2 = 0;
        for (int k = 9; k < 13; ++k)
            q2 += std::stod(r[static_cast<std::size_t>(k)]) *
                  std::stod(r[static_cast<std::size_t>(k)]);
        CHECK(q2 == doctest::Approx(1.0).epsilon(1e-12));
    }
    CHECK(std::stod(rows.back()[16]) != 0); // the fluid's Fx on it
    std::filesystem::remove_all(run.folder);
}
