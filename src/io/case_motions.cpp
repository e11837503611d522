// [[motions]] (case_motions.hpp).
#include "case_motions.hpp"

#include "sluice/io/case_reader.hpp"

#include "case_fingerprint.hpp"
#include "case_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sluice::case_file {
namespace {

namespace fs = std::filesystem;

const std::vector<std::pair<std::string, MotionKind>> kKinds = {
    {"sway", MotionKind::sway},
    {"roll", MotionKind::roll},
    {"constant_velocity", MotionKind::constant_velocity},
    {"constant_acceleration", MotionKind::constant_acceleration},
    {"file", MotionKind::file},
    {"piston", MotionKind::piston},
    {"flap", MotionKind::flap},
    {"piston_irregular", MotionKind::piston_irregular},
    {"free_body", MotionKind::free_body}};

const std::vector<std::pair<std::string, BodyConstraint>> kConstraints = {
    {"free", BodyConstraint::free},
    {"fixed", BodyConstraint::fixed},
    {"hinge", BodyConstraint::hinge},
    {"plane", BodyConstraint::plane}};

const char* kind_word(MotionKind k) {
    for (const auto& [name, kind] : kKinds)
        if (kind == k)
            return name.c_str();
    return "?";
}

double norm(const Triple& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// The rows of a motion file: t, D displacements and optionally an angle; `#` starts a comment,
// commas and blanks separate values. Refuses (naming `file`) what is not such a table.
void read_series(const Section& s, const std::string& path, const std::string& shown, int dim,
                 MotionLaw& law) {
    std::ifstream in(path);
    s.require(in.good(), "file", fmt::format("cannot read \"{}\"", shown));
    std::string line;
    int line_no = 0;
    std::size_t columns = 0;
    while (std::getline(in, line)) {
        ++line_no;
        if (const auto hash = line.find('#'); hash != std::string::npos)
            line.erase(hash);
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream row(line);
        std::vector<double> v;
        std::string word;
        while (row >> word) {
            double x = 0;
            std::size_t used = 0;
            try {
                x = std::stod(word, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            s.require(used == word.size(), "file",
                      fmt::format("\"{}\" line {}: \"{}\" is not a number", shown, line_no, word));
            s.require(std::isfinite(x), "file",
                      fmt::format("\"{}\" line {}: {} is not finite", shown, line_no, word));
            v.push_back(x);
        }
        if (v.empty())
            continue;
        const auto d = static_cast<std::size_t>(dim);
        s.require(v.size() == 1 + d || v.size() == 2 + d, "file",
                  fmt::format("\"{}\" line {}: {} values; a row is t, {} displacement{} and "
                              "optionally an angle [degrees]",
                              shown, line_no, v.size(), d, d > 1 ? "s" : ""));
        if (columns == 0)
            columns = v.size();
        s.require(v.size() == columns, "file",
                  fmt::format("\"{}\" line {}: {} values, the rows before it have {}", shown,
                              line_no, v.size(), columns));
        s.require(law.series_t.empty() || v[0] > law.series_t.back(), "file",
                  fmt::format("\"{}\" line {}: time {} does not follow {}: times must increase",
                              shown, line_no, v[0],
                              law.series_t.empty() ? 0.0 : law.series_t.back()));
        law.series_t.push_back(v[0]);
        Triple disp{};
        for (std::size_t k = 0; k < d; ++k)
            disp[k] = v[1 + k];
        law.series_d.push_back(disp);
        law.series_angle.push_back(v.size() == 2 + d ? v.back() : 0.0);
    }
    s.require(law.series_t.size() >= 2, "file",
              fmt::format("\"{}\" holds {} row{}; a motion needs at least two", shown,
                          law.series_t.size(), law.series_t.size() == 1 ? "" : "s"));
    s.require(law.series_t.front() <= 0, "file",
              fmt::format("\"{}\" starts at t = {} s; it must cover the motion's start (t = 0 "
                          "of the file is motions.start)",
                          shown, law.series_t.front()));
}

// A free body's keys (kind = "free_body"): its mass, inertia, initial velocity and constraint.
void read_body(const Section& s, int dim, MotionLaw& law) {
    BodyLaw& b = law.body;
    const auto density = s.number("density");
    const auto mass = s.number("mass");
    if (!density && !mass)
        s.fail("density", "missing required key for a free_body motion: density [kg/m^3] (the "
                          "mass from the shape) or mass [kg]");
    s.require(!(density && mass), "mass", "give density or mass, not both");
    if (density) {
        s.require(std::isfinite(*density) && *density > 0, "density",
                  fmt::format("must be finite and > 0; got {}", *density));
        b.density = *density;
    }
    if (mass) {
        s.require(std::isfinite(*mass) && *mass > 0, "mass",
                  fmt::format("must be finite and > 0; got {}", *mass));
        b.mass = *mass;
    }
    b.centre_of_mass = s.triple("centre_of_mass");
    if (s.node("inertia") != nullptr) {
        std::array<double, 9> I{};
        if (dim == 2) {
            const double izz = s.number("inertia").value_or(0);
            s.require(std::isfinite(izz) && izz > 0, "inertia",
                      fmt::format("2-D: the moment of inertia about z through the centre of "
                                  "mass [kg m^2 per metre]; must be finite and > 0, got {}",
                                  izz));
            I = {izz, 0, 0, 0, izz, 0, 0, 0, izz};
        } else {
            const Triple d = *s.triple("inertia");
            s.require(std::isfinite(d[0] + d[1] + d[2]) && d[0] > 0 && d[1] > 0 && d[2] > 0,
                      "inertia",
                      fmt::format("3-D: the principal moments [Ixx, Iyy, Izz] about the centre "
                                  "of mass [kg m^2]; each must be finite and > 0, got [{}, {}, "
                                  "{}]",
                                  d[0], d[1], d[2]));
            // A rigid body's moments obey the triangle inequality (Ixx <= Iyy + Izz, ...).
            for (int a = 0; a < 3; ++a)
                s.require(d[static_cast<std::size_t>(a)] <=
                              d[static_cast<std::size_t>((a + 1) % 3)] +
                                  d[static_cast<std::size_t>((a + 2) % 3)],
                          "inertia",
                          fmt::format("[{}, {}, {}] is no rigid body's: each moment must be at "
                                      "most the sum of the other two",
                                      d[0], d[1], d[2]));
            I = {d[0], 0, 0, 0, d[1], 0, 0, 0, d[2]};
        }
        b.inertia = I;
    }
    law.velocity = s.triple("velocity").value_or(Triple{});
    b.constraint = s.choice("constraint", BodyConstraint::free, kConstraints);
    // A hinged body's velocity follows from its angular velocity; a fixed one has neither.
    s.require(s.node("velocity") == nullptr ||
                  (b.constraint != BodyConstraint::hinge && b.constraint != BodyConstraint::fixed),
              "velocity",
              "does not apply to a hinged or fixed body (a hinge's follows from "
              "angular_velocity)");
    s.require(s.node("angular_velocity") == nullptr || b.constraint != BodyConstraint::fixed,
              "angular_velocity", "does not apply to a fixed body");
    if (dim == 2) {
        b.angular_velocity = {0, 0, s.number("angular_velocity").value_or(0)};
    } else {
        b.angular_velocity = s.triple("angular_velocity").value_or(Triple{});
    }
    b.friction = s.number("friction", b.friction);
    b.restitution = s.number("restitution", b.restitution);
    if (b.constraint == BodyConstraint::hinge)
        s.require(s.node("centre") != nullptr, "centre",
                  "missing required key for a hinged body: the hinge point [m]");
    if (b.constraint == BodyConstraint::plane)
        s.require(dim == 3, "constraint",
                  "\"plane\" restricts a 3-D body to a plane; a 2-D body moves in its plane "
                  "already (\"free\")");
    if (dim == 3 &&
        (b.constraint == BodyConstraint::hinge || b.constraint == BodyConstraint::plane))
        s.require(
            s.node("axis") != nullptr, "axis",
            fmt::format("missing required key for constraint = \"{}\": the {} [unit "
                        "vector]",
                        b.constraint == BodyConstraint::hinge ? "hinge" : "plane",
                        b.constraint == BodyConstraint::hinge ? "hinge axis" : "plane's normal"));
    s.require(b.constraint == BodyConstraint::hinge || s.node("centre") == nullptr, "centre",
              "is a free body's hinge point: only for constraint = \"hinge\"");
    s.require(b.constraint == BodyConstraint::hinge || b.constraint == BodyConstraint::plane ||
                  s.node("axis") == nullptr,
              "axis",
              "is a free body's hinge axis or plane normal: only for constraint = "
              "\"hinge\" or \"plane\"");
}

} // namespace

void read_motions(const Section& root, CaseConfig& c) {
    std::set<std::string> names;
    for (const auto& s : root.entries("motions")) {
        MotionLaw law;
        const auto name = s.string("name");
        if (!name)
            s.fail("name", "missing required key (what walls.tank_motion, walls.boxes.motion "
                           "and walls.meshes.motion refer to)");
        law.name = *name;
        const bool ok =
            !law.name.empty() && std::all_of(law.name.begin(), law.name.end(), [](char ch) {
                return std::isalnum(static_cast<unsigned char>(ch)) != 0 || ch == '_' || ch == '-';
            });
        s.require(ok, "name",
                  fmt::format("\"{}\" is not a valid motion name (letters, digits, '_' and '-' "
                              "only; it becomes a file name)",
                              law.name));
        s.require(law.name.size() <= kMaxNameLength, "name",
                  fmt::format("is {} bytes long; at most {}", law.name.size(), kMaxNameLength));
        s.require(names.insert(law.name).second, "name",
                  fmt::format("another motion is already called \"{}\"", law.name));
        if (s.node("kind") == nullptr)
            s.fail("kind", "missing required key (\"sway\", \"roll\", \"constant_velocity\", "
                           "\"constant_acceleration\", \"file\", \"piston\", \"flap\", "
                           "\"piston_irregular\" or \"free_body\")");
        law.kind = s.choice("kind", MotionKind::sway, kKinds);
        const MotionKind k = law.kind;
        const char* word = kind_word(k);
        const auto only_for = [&](std::string_view key, bool allowed) {
            s.require(allowed || s.node(key) == nullptr, key,
                      fmt::format("does not apply to a motion of kind \"{}\"", word));
        };
        const bool periodic = k == MotionKind::sway || k == MotionKind::roll;
        const bool body = k == MotionKind::free_body;
        const bool rotates =
            k == MotionKind::roll || k == MotionKind::file || k == MotionKind::flap || body;
        const bool piston = k == MotionKind::piston || k == MotionKind::piston_irregular;
        const bool regular = k == MotionKind::piston || k == MotionKind::flap;
        only_for("amplitude", k == MotionKind::sway);
        only_for("angle", k == MotionKind::roll);
        only_for("period", periodic);
        only_for("phase", periodic);
        only_for("velocity", k == MotionKind::constant_velocity || body);
        for (const char* key : {"density", "mass", "centre_of_mass", "inertia", "angular_velocity",
                                "constraint", "friction", "restitution"})
            only_for(key, body);
        only_for("ramp", !body);
        only_for("acceleration", k == MotionKind::constant_acceleration);
        only_for("centre", rotates);
        only_for("axis", rotates);
        only_for("file", k == MotionKind::file);
        only_for("wave_height", regular);
        only_for("wave_period", regular);
        only_for("depth", regular || k == MotionKind::piston_irregular);
        only_for("second_order", k == MotionKind::piston);
        only_for("direction", piston);
        for (const char* key : {"hs", "tp", "gamma", "components", "seed"})
            only_for(key, k == MotionKind::piston_irregular);
        s.require(c.dimension == 3 || s.node("axis") == nullptr, "axis",
                  "2-D rotations are about z: axis is for 3-D cases");

        law.start = s.number("start", 0.0);
        law.ramp = s.number("ramp", 0.0);
        law.g = norm(c.gravity);
        const auto nonzero_vector = [&](std::string_view key, const char* what) {
            const auto v = s.triple(key);
            if (!v)
                s.fail(key, fmt::format("missing required key for a {} motion: {}", word, what));
            s.require(norm(*v) > 0, key, "must not be the zero vector");
            return *v;
        };
        const auto positive = [&](std::string_view key, const char* what) {
            const auto v = s.number(key);
            if (!v)
                s.fail(key, fmt::format("missing required key for a {} motion: {}", word, what));
            s.require(*v > 0, key, fmt::format("must be > 0; got {}", *v));
            return *v;
        };
        switch (k) {
        case MotionKind::sway:
            law.amplitude = nonzero_vector("amplitude", "the displacement amplitude [m]");
            break;
        case MotionKind::roll: {
            const auto a = s.number("angle");
            if (!a)
                s.fail("angle", "missing required key for a roll motion: the amplitude "
                                "[degrees]");
            s.require(*a != 0, "angle", "must not be zero");
            law.angle = *a;
            break;
        }
        case MotionKind::constant_velocity:
            law.velocity = nonzero_vector("velocity", "the velocity [m/s]");
            break;
        case MotionKind::free_body:
            read_body(s, c.dimension, law);
            break;
        case MotionKind::constant_acceleration:
            law.acceleration = nonzero_vector("acceleration", "the acceleration [m/s^2]");
            break;
        case MotionKind::file: {
            const auto file = s.string("file");
            if (!file || file->empty())
                s.fail("file", "missing required key for a file motion: the time series");
            const fs::path folder = fs::path(c.source_file).parent_path();
            const std::string path =
                fs::path(*file).is_absolute() ? *file : (folder / *file).string();
            read_series(s, path, *file, c.dimension, law);
            c.motion_digests.push_back(file_sha256(path));
            break;
        }
        case MotionKind::piston:
        case MotionKind::flap:
            law.wave_height = positive("wave_height", "the wave height [m]");
            law.wave_period = positive("wave_period", "the wave period [s]");
            law.depth = positive("depth", "the still-water depth at the paddle [m]");
            law.second_order = s.boolean("second_order").value_or(false);
            break;
        case MotionKind::piston_irregular:
            law.hs = positive("hs", "the significant wave height [m]");
            law.tp = positive("tp", "the peak period [s]");
            law.depth = positive("depth", "the still-water depth at the paddle [m]");
            law.gamma = s.number("gamma", law.gamma);
            law.components = static_cast<int>(s.integer("components").value_or(law.components));
            law.seed = static_cast<std::uint64_t>(s.integer("seed").value_or(1));
            break;
        }
        if (k != MotionKind::file)
            c.motion_digests.emplace_back();
        if (periodic)
            law.period = positive("period", "the period [s]");
        law.phase = s.number("phase", 0.0);
        if (rotates) {
            if (k != MotionKind::file && !body && s.node("centre") == nullptr)
                s.fail("centre", fmt::format("missing required key for a {} motion: the centre "
                                             "of rotation [m]",
                                             word));
            law.centre = s.triple("centre").value_or(Triple{});
            if (c.dimension == 3) {
                const auto axis = s.triple("axis");
                if (axis)
                    s.require(norm(*axis) > 0, "axis", "must not be the zero vector");
                law.axis = axis.value_or(Triple{0, 0, 1});
            }
        }
        if (piston) {
            const auto dir = s.triple("direction");
            if (dir)
                s.require(norm(*dir) > 0, "direction", "must not be the zero vector");
            law.direction = dir.value_or(Triple{1, 0, 0});
        }
        c.motions.push_back(std::move(law));
    }
}

void read_damping_zones(const Section& root, CaseConfig& c) {
    for (const auto& s : root.entries("damping_zones")) {
        DampingZoneConfig z;
        z.start = s.required_triple("start", "where the damping begins [m]");
        z.end = s.required_triple("end", "where it reaches its strength [m]");
        Triple d{};
        for (std::size_t a = 0; a < 3; ++a)
            d[a] = z.end[a] - z.start[a];
        s.require(norm(d) > 0, "end", "must differ from start (it gives the zone's direction)");
        z.strength = s.number("strength", z.strength);
        s.require(z.strength > 0, "strength", fmt::format("must be > 0; got {}", z.strength));
        c.damping_zones.push_back(z);
    }
}

int motion_reference(const Section& s, std::string_view k, const CaseConfig& c) {
    const auto name = s.string(k);
    if (!name)
        return -1;
    for (std::size_t i = 0; i < c.motions.size(); ++i)
        if (c.motions[i].name == *name)
            return static_cast<int>(i);
    std::vector<std::string> known;
    for (const auto& m : c.motions)
        known.push_back("\"" + m.name + "\"");
    s.fail(k, fmt::format("no [[motions]] entry is called \"{}\"{}", *name,
                          known.empty() ? std::string(" (the case has none)")
                                        : fmt::format("; known: {}", fmt::join(known, ", "))));
}

void check_motions(const Section& root, const CaseConfig& c) {
    if (c.motions.empty())
        return;
    const auto entries = root.entries("motions");
    std::vector<bool> used(c.motions.size(), false);
    if (c.tank_motion >= 0)
        used[static_cast<std::size_t>(c.tank_motion)] = true;
    for (const auto& b : c.boxes)
        if (b.motion >= 0)
            used[static_cast<std::size_t>(b.motion)] = true;
    for (const auto& m : c.meshes)
        if (m.motion >= 0)
            used[static_cast<std::size_t>(m.motion)] = true;
    for (std::size_t i = 0; i < c.motions.size(); ++i) {
        const Section& s = entries[i];
        const MotionLaw& law = c.motions[i];
        s.require(used[i], "name",
                  fmt::format("motion \"{}\" moves nothing: name it in walls.tank_motion, a "
                              "walls.boxes entry's motion or a walls.meshes entry's motion",
                              law.name));
        if (law.kind == MotionKind::free_body) {
            s.require(c.tank_motion != static_cast<int>(i), "kind",
                      fmt::format("motion \"{}\" is a free body: the tank cannot be one (make the "
                                  "body a walls.boxes or walls.meshes entry)",
                                  law.name));
            int objects = 0;
            bool on_mesh = false;
            for (const auto& m : c.meshes)
                if (m.motion == static_cast<int>(i)) {
                    on_mesh = true;
                    ++objects;
                }
            for (const auto& b : c.boxes)
                objects += b.motion == static_cast<int>(i) ? 1 : 0;
            s.require(objects == 1, "name",
                      fmt::format("free body \"{}\" is named by {} wall objects: a body is one "
                                  "box or one mesh (give each its own [[motions]] entry)",
                                  law.name, objects));
            // Friction and restitution act in contact only (contact/contact_world.hpp).
            for (const char* key : {"friction", "restitution"})
                s.require(s.node(key) == nullptr || body_in_contact(law, objects == 1 && !on_mesh),
                          key,
                          "acts in contact only, which takes box bodies that move freely or in "
                          "a plane normal to a world axis (not hinged, fixed or mesh bodies)");
            s.require(!on_mesh ||
                          (law.body.mass > 0 && law.body.centre_of_mass && law.body.inertia),
                      "mass",
                      fmt::format("free body \"{}\" is a mesh: give its mass, centre_of_mass "
                                  "and inertia (they are computed from the shape for boxes "
                                  "only)",
                                  law.name));
        }
        if (law.kind == MotionKind::file) {
            const double covered = law.start + law.series_t.back();
            s.require(covered >= c.end_time, "file",
                      fmt::format("the time series ends at t = {} s (start + its last time), "
                                  "before time.end_time = {} s",
                                  covered, c.end_time));
        }
        for (int a = 0; a < c.dimension; ++a)
            s.require(!c.periodic[static_cast<std::size_t>(a)], "name",
                      fmt::format("moving walls in a periodic domain (the {} axis) are not "
                                  "supported: a wall object would wrap",
                                  kAxis[static_cast<std::size_t>(a)]));
        s.require(c.walls == WallModel::dummy, "name",
                  "moving walls are dummy wall particles: they need walls.model = \"dummy\"");
        s.require(c.scheme == Scheme::wcsph, "name",
                  "moving walls are supported by numerics.scheme = \"wcsph\" only (the "
                  "projection scheme's wall collision and Neumann condition take fixed walls)");
        // Prescribed motion enters the Riemann solver's wall states (riemann.hpp); a free
        // body's load is summed with the default dissipation's pair terms (body_load.hpp).
        s.require(law.kind != MotionKind::free_body || c.dissipation == Dissipation::artificial,
                  "kind",
                  fmt::format("free body \"{}\" needs numerics.dissipation = \"artificial\" "
                              "(its load is summed from that scheme's fluid-wall pairs)",
                              law.name));
        s.require(!c.run_ahead, "name",
                  "moving walls need runtime.run_ahead = false (the walls' next positions "
                  "depend on the agreed time step)");
    }
}

} // namespace sluice::case_file
