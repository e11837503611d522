// [[motions]], walls.*.motion, [[damping_zones]] and the motion probe in a case file: a valid
// moving case reads to the expected laws and references; every mistake (an unknown motion, a
// key of another kind, a motion that moves nothing, a time series that is not one or ends
// before the run, an unsupported combination) is a CaseError naming the key.
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"

#include "case_files.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace sluice;
using sluice::testing::scratch_dir;
using sluice::testing::write_case;

namespace {

const std::string kMoving = R"(
[case]
dimension = 2
[domain]
lo = [-0.2, -0.2]
hi = [1.2, 1.0]
[fluid]
rho0 = 1000
viscosity = 1e-6
sound_speed = 20
[particles]
dx = 0.02
[[blocks]]
lo = [0, 0]
hi = [1, 0.3]
[walls]
model = "dummy"
tank_lo = [0, 0]
tank_hi = [1, 0.8]
tank_motion = "roll"
[[walls.boxes]]
lo = [0.4, 0.5]
hi = [0.5, 0.6]
[[motions]]
name = "roll"
kind = "roll"
angle = 4
period = 1.2
centre = [0.5, 0.3]
ramp = 0.5
[time]
end_time = 0.5
[[probes]]
name = "level"
type = "water_level"
x = 0.05
frame = "roll"
[[probes]]
name = "tank"
type = "motion"
frame = "roll"
)";

std::string edit(const std::string& from, const std::string& to, std::string text = kMoving) {
    const auto pos = text.find(from);
    REQUIRE_MESSAGE(pos != std::string::npos, "test edit target not found: " << from);
    text.replace(pos, from.size(), to);
    return text;
}

std::string expect_error(const std::string& text, const std::string& key) {
    const std::string path = write_case("bad_motion", text);
    try {
        (void)read_case(path);
    } catch (const CaseError& e) {
        CHECK_MESSAGE(e.key() == key, "message: " << std::string(e.what()));
        CHECK(e.file() == path);
        return e.reason();
    }
    FAIL("no CaseError for key " << key);
    return {};
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// A motion file next to the case files.
void write_series(const std::string& name, const std::string& text) {
    std::ofstream(scratch_dir() / name) << text;
}

} // namespace

TEST_CASE("a rolling tank reads to its law, its references and its probes' frames") {
    const CaseConfig c = read_case(write_case("moving", kMoving));
    REQUIRE(c.motions.size() == 1);
    const MotionLaw& m = c.motions[0];
    CHECK(m.kind == MotionKind::roll);
    CHECK(m.angle == 4);
    CHECK(m.period == 1.2);
    CHECK(m.ramp == 0.5);
    CHECK(m.centre[0] == 0.5);
    CHECK(m.g == doctest::Approx(9.81));
    CHECK(c.tank_motion == 0);
    CHECK(c.boxes[0].motion == -1);
    REQUIRE(c.probes.size() == 2);
    CHECK(c.probes[0].frame == 0);
    CHECK(c.probes[1].type == ProbeType::motion);
    // The motion is part of the case's identity (a checkpoint of another motion is refused).
    const CaseConfig other = read_case(write_case("moving2", edit("angle = 4", "angle = 5")));
    CHECK(other.fingerprint != c.fingerprint);
}

TEST_CASE("motion references and kinds") {
    CHECK(contains(
        expect_error(edit("tank_motion = \"roll\"", "tank_motion = \"sway\""), "walls.tank_motion"),
        "known: \"roll\""));
    CHECK(contains(expect_error(edit("tank_motion = \"roll\"\n", ""), "motions[0].name"),
                   "moves nothing"));
    expect_error(edit("kind = \"roll\"", "kind = \"spin\""), "motions[0].kind");
    expect_error(edit("kind = \"roll\"\n", ""), "motions[0].kind");
    CHECK(contains(expect_error(edit("period = 1.2", "period = 1.2\nvelocity = [1, 0]"),
                                "motions[0].velocity"),
                   "does not apply to a motion of kind \"roll\""));
    expect_error(edit("angle = 4", "angle = 0"), "motions[0].angle");
    expect_error(edit("period = 1.2\n", ""), "motions[0].period");
    expect_error(edit("centre = [0.5, 0.3]\n", ""), "motions[0].centre");
    expect_error(edit("centre = [0.5, 0.3]", "centre = [0.5, 0.3]\naxis = [0, 0, 1]"),
                 "motions[0].axis");
    expect_error(edit("name = \"roll\"", "name = \"roll/x\""), "motions[0].name");
    expect_error(edit("[time]", "[[motions]]\nname = \"roll\"\nkind = \"sway\"\n"
                                "amplitude = [0.1, 0]\nperiod = 1\n[time]"),
                 "motions[1].name");
    expect_error(edit("[[walls.boxes]]\nlo = [0.4, 0.5]\nhi = [0.5, 0.6]\n", "",
                      edit("model = \"dummy\"", "model = \"reflective\"")),
                 "motions[0].name");
    CHECK(contains(
        expect_error(edit("[time]", "[runtime]\nrun_ahead = true\n[time]"), "motions[0].name"),
        "run_ahead"));
    // The Riemann dissipation takes prescribed motion (its wall states carry the wall's
    // velocity); a free body's load is summed with the default dissipation's pairs.
    const std::string riemann =
        edit("[particles]", "[numerics]\ndissipation = \"riemann\"\n[particles]");
    CHECK_NOTHROW(read_case(write_case("riemann_roll", riemann)));
    CHECK(contains(expect_error(edit("hi = [0.5, 0.6]\n", "hi = [0.5, 0.6]\nmotion = \"float\"\n",
                                     edit("[time]",
                                          "[[motions]]\nname = \"float\"\nkind = "
                                          "\"free_body\"\ndensity = 500\n[time]",
                                          riemann)),
                                "motions[1].kind"),
                   "artificial"));
    // A wave-maker needs its wave.
    const std::string piston =
        edit("kind = \"roll\"\nangle = 4\nperiod = 1.2\ncentre = [0.5, 0.3]",
             "kind = \"piston\"\nwave_height = 0.02\nwave_period = 1.0\ndepth = 0.3");
    CHECK_NOTHROW(read_case(write_case("piston", piston)));
    expect_error(edit("wave_height = 0.02\n", "", piston), "motions[0].wave_height");
    expect_error(edit("depth = 0.3", "depth = -0.3", piston), "motions[0].depth");
    expect_error(edit("depth = 0.3", "depth = 0.3\ndirection = [0, 0]", piston),
                 "motions[0].direction");
    expect_error(edit("depth = 0.3", "depth = 0.3\nhs = 0.1", piston), "motions[0].hs");
}

TEST_CASE("motion files: read, and refused naming motions.file") {
    const std::string with_file =
        edit("kind = \"roll\"\nangle = 4\nperiod = 1.2\ncentre = [0.5, 0.3]",
             "kind = \"file\"\nfile = \"roll.csv\"\ncentre = [0.5, 0.3]");
    write_series("roll.csv", "# t, dx, dy, angle\n0, 0, 0, 0\n0.25, 0.01, 0, 1\n"
                             "0.5, 0.02, 0, 2.0\n");
    const CaseConfig c = read_case(write_case("file_ok", with_file));
    REQUIRE(c.motions[0].series_t.size() == 3);
    CHECK(c.motions[0].series_angle[2] == 2.0);
    CHECK(c.motions[0].series_d[1][0] == 0.01);

    const auto refused = [&](const std::string& rows, const std::string& says) {
        write_series("roll.csv", rows);
        const std::string why = expect_error(with_file, "motions[0].file");
        CHECK_MESSAGE(contains(why, says), "reason: " << why);
    };
    refused("0, 0, 0\n0.5, x, 0\n", "is not a number");
    refused("0, 0, 0\n0.5, 0, 0, 1\n", "the rows before it");
    refused("0, 0, 0\n0, 0.1, 0\n", "times must increase");
    refused("0, 0, 0\n", "at least two");
    refused("0.1, 0, 0\n0.6, 0, 0\n", "must cover the motion's start");
    refused("0, 0, 0\n0.3, 0.1, 0\n", "before time.end_time");
    refused("0, 0\n0.6, 0\n", "a row is t, 2 displacements");
    std::filesystem::remove(scratch_dir() / "roll.csv");
    CHECK(contains(expect_error(with_file, "motions[0].file"), "cannot read"));
}

TEST_CASE("probes that follow a motion, damping zones") {
    expect_error(edit("type = \"motion\"\nframe = \"roll\"", "type = \"motion\""),
                 "probes[1].frame");
    expect_error(edit("frame = \"roll\"\n[[probes]]", "frame = \"pitch\"\n[[probes]]"),
                 "probes[0].frame");
    expect_error(edit("[time]", "[[probes]]\nname = \"front\"\ntype = \"surge_front\"\n"
                                "frame = \"roll\"\n[time]"),
                 "probes[0].frame"); // before [time]: the first probe of the file
    // An area sensor moves with the wall it sits on, told or not; on a fixed wall it cannot
    // be given another motion's frame.
    const std::string sensors =
        kMoving + "[[probes]]\nname = \"wall\"\ntype = \"pressure\"\nposition = [0, 0.1]\n"
                  "diameter = 0.04\n[[probes]]\nname = \"told\"\ntype = \"pressure\"\n"
                  "position = [1, 0.1]\ndiameter = 0.04\nframe = \"roll\"\nreading = "
                  "\"interpolated\"\n[[probes]]\nname = \"box\"\ntype = \"pressure\"\n"
                  "position = [0.45, 0.5]\ndiameter = 0.04\n";
    const CaseConfig s = read_case(write_case("sensors", sensors));
    REQUIRE(s.probes.size() == 5);
    CHECK(s.probes[2].frame == 0);
    CHECK(s.probes[2].wall.face_axis == 0);
    CHECK(!s.probes[2].wall.face_high);
    CHECK(s.probes[3].frame == 0);
    CHECK(s.probes[3].wall.face_high);
    CHECK(s.probes[4].frame == -1);
    CHECK(s.probes[4].wall.box == 0);
    CHECK(contains(expect_error(edit("position = [0.45, 0.5]\ndiameter = 0.04\n",
                                     "position = [0.45, 0.5]\ndiameter = 0.04\nframe = "
                                     "\"roll\"\n",
                                     sensors),
                                "probes[4].frame"),
                   "does not move"));
    const std::string zone =
        edit("[time]", "[[damping_zones]]\nstart = [0.7, 0]\nend = [1.0, 0]\nstrength = 5\n[time]");
    const CaseConfig c = read_case(write_case("zone", zone));
    REQUIRE(c.damping_zones.size() == 1);
    CHECK(c.damping_zones[0].strength == 5);
    expect_error(edit("end = [1.0, 0]", "end = [0.7, 0]", zone), "damping_zones[0].end");
    expect_error(edit("strength = 5", "strength = 0", zone), "damping_zones[0].strength");
}

TEST_CASE("free bodies: read with their mass and constraint; mistakes named") {
    // The box becomes a free body of density 500; the tank stays fixed.
    const std::string body =
        edit("hi = [0.5, 0.6]\n", "hi = [0.5, 0.6]\nmotion = \"float\"\n",
             edit("[time]", "[[motions]]\nname = \"float\"\nkind = \"free_body\"\ndensity = 500\n"
                            "[time]"));
    const CaseConfig c = read_case(write_case("body", body));
    REQUIRE(c.motions.size() == 2);
    CHECK(c.motions[1].kind == MotionKind::free_body);
    CHECK(c.motions[1].body.density == 500);
    CHECK(c.motions[1].body.constraint == BodyConstraint::free);
    CHECK(c.boxes[0].motion == 1);
    const std::string free_box = edit("density = 500",
                                      "density = 500\nvelocity = [0.1, 0]\n"
                                      "angular_velocity = 0.5",
                                      body);
    const CaseConfig v = read_case(write_case("body_v", free_box));
    CHECK(v.motions[1].velocity[0] == 0.1);
    CHECK(v.motions[1].body.angular_velocity[2] == 0.5);
    // A free body's box may lie in the water (it displaces it); a fixed box may not.
    const std::string in_water = edit("lo = [0.4, 0.5]", "lo = [0.4, 0.25]", body);
    CHECK_NOTHROW(read_case(write_case("body_in_water", in_water)));
    expect_error(edit("motion = \"float\"\n", "",
                      edit("[[motions]]\nname = \"float\"\nkind = "
                           "\"free_body\"\ndensity = 500\n",
                           "", in_water)),
                 "walls.boxes[0].lo");
    // Mass: one of density and mass, finite and positive.
    CHECK(contains(expect_error(edit("density = 500\n", "", body), "motions[1].density"),
                   "density [kg/m^3]"));
    expect_error(edit("density = 500", "density = 500\nmass = 3", body), "motions[1].mass");
    expect_error(edit("density = 500", "mass = -1", body), "motions[1].mass");
    expect_error(edit("density = 500", "density = 0", body), "motions[1].density");
    expect_error(edit("density = 500", "density = 500\ninertia = -2", body), "motions[1].inertia");
    // Keys of prescribed motions, and a ramp, are not a free body's.
    expect_error(edit("density = 500", "density = 500\nperiod = 1", body), "motions[1].period");
    expect_error(edit("density = 500", "density = 500\nramp = 0.1", body), "motions[1].ramp");
    // Constraints: a hinge needs its point; a plane is 3-D only; centre belongs to a hinge.
    expect_error(edit("density = 500", "density = 500\nconstraint = \"hinge\"", body),
                 "motions[1].centre");
    CHECK_NOTHROW(read_case(write_case(
        "body_hinge", edit("density = 500",
                           "density = 500\nconstraint = \"hinge\"\ncentre = [0.45, 0.7]", body))));
    expect_error(edit("density = 500", "density = 500\nconstraint = \"plane\"", body),
                 "motions[1].constraint");
    expect_error(edit("density = 500", "density = 500\ncentre = [0.45, 0.7]", body),
                 "motions[1].centre");
    expect_error(edit("density = 500", "density = 500\nconstraint = \"sideways\"", body),
                 "motions[1].constraint");
    // Keys that would change nothing: a hinge's velocity, a fixed body's angular velocity,
    // friction on a body that takes no part in contact.
    const std::string hinged =
        edit("density = 500", "density = 500\nconstraint = \"hinge\"\ncentre = [0.45, 0.7]", body);
    expect_error(edit("density = 500", "density = 500\nvelocity = [0.1, 0]", hinged),
                 "motions[1].velocity");
    expect_error(edit("density = 500", "density = 500\nfriction = 0.3", hinged),
                 "motions[1].friction");
    CHECK_NOTHROW(read_case(
        write_case("body_friction", edit("density = 500", "density = 500\nfriction = 0.3", body))));
    expect_error(
        edit("density = 500", "density = 500\nconstraint = \"fixed\"\nangular_velocity = 1", body),
        "motions[1].angular_velocity");
    // One body, one wall object; never the tank.
    expect_error(edit("\nmotion = \"float\"", "\nmotion = \"roll\"",
                      edit("tank_motion = \"roll\"", "tank_motion = \"float\"", body)),
                 "motions[1].kind");
    expect_error(edit("[time]",
                      "[[walls.boxes]]\nlo = [0.6, 0.5]\nhi = [0.7, 0.6]\n"
                      "motion = \"float\"\n[time]",
                      body),
                 "motions[1].name");
}
