// The [[probes]] tables of a case file (case_probes.hpp).
#include "case_probes.hpp"

#include "sluice/physics/kernels.hpp"

#include "case_limits.hpp"
#include "case_motions.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sluice::case_file {
namespace {

const std::vector<std::pair<std::string, ProbeType>> kProbeTypes = {
    {"pressure", ProbeType::pressure},
    {"water_level", ProbeType::water_level},
    {"surge_front", ProbeType::surge_front},
    {"force", ProbeType::force},
    {"motion", ProbeType::motion}};

const std::vector<std::pair<std::string, SensorReading>> kSensorReadings = {
    {"force", SensorReading::force},
    {"interpolated", SensorReading::interpolated},
    {"collisions", SensorReading::collisions}};

// An area sensor's or force probe's `reading`. The force reading sums the WCSPH momentum
// equation's fluid-wall pair forces; the projection scheme applies no such forces, so there the
// interpolated pressure is the default and the force reading is refused. The collisions reading
// is the projection scheme's wall collisions alone; WCSPH has none, so there it is refused.
SensorReading read_reading(const Section& s, const CaseConfig& c, std::string_view instead) {
    const bool wcsph = c.scheme == Scheme::wcsph;
    const SensorReading r = s.choice(
        "reading", wcsph ? SensorReading::force : SensorReading::interpolated, kSensorReadings);
    s.require(wcsph || r != SensorReading::force, "reading",
              fmt::format("the force reading sums the pair forces of the WCSPH momentum "
                          "equation; the projection scheme has none (use \"interpolated\"{})",
                          instead));
    s.require(!wcsph || r != SensorReading::collisions, "reading",
              "the collisions reading is the momentum the projection scheme's wall collisions "
              "give the wall; WCSPH has no wall collisions (its \"force\" reading holds every "
              "fluid-wall force)");
    return r;
}

bool inside_domain(const CaseConfig& c, const Triple& p) {
    const double eps = slack(c);
    for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a)
        if (p[a] < c.domain_lo[a] - eps || p[a] > c.domain_hi[a] + eps)
            return false;
    return true;
}

// A tank face name ("x+") as a ProbeWall; false when it is not one of this dimension's.
bool parse_face(const std::string& f, int dim, ProbeWall& w) {
    if (f.size() != 2 || (f[1] != '+' && f[1] != '-') || f[0] < 'x' || f[0] >= 'x' + dim)
        return false;
    w.face_axis = f[0] - 'x';
    w.face_high = f[1] == '+';
    return true;
}

// An index into an array of tables of the case ([[walls.boxes]], [[walls.meshes]]) given by
// key k: refused unless it names one of its `count` entries.
int read_entry_index(const Section& s, std::string_view k, std::string_view array,
                     std::string_view plural, std::size_t count) {
    const auto i = s.integer(k);
    s.require(i && *i >= 0 && static_cast<std::size_t>(*i) < count, k,
              fmt::format("must be the index of a [[{}]] entry, 0 to {}; the case has {} {}", array,
                          count == 0 ? 0 : count - 1, count, plural));
    return static_cast<int>(*i);
}

// The face, box or mesh of a force or sensor probe (at most one).
std::optional<ProbeWall> read_probe_wall(const Section& s, const CaseConfig& c) {
    const bool has_face = s.node("face") != nullptr, has_box = s.node("box") != nullptr,
               has_mesh = s.node("mesh") != nullptr;
    if (!has_face && !has_box && !has_mesh)
        return std::nullopt;
    s.require(int(has_face) + int(has_box) + int(has_mesh) == 1, has_mesh ? "mesh" : "box",
              "give one of face, box and mesh");
    s.require(c.walls == WallModel::dummy, has_face ? "face" : (has_box ? "box" : "mesh"),
              "wall loads and wall sensors need dummy wall particles (walls.model = \"dummy\")");
    ProbeWall w;
    if (has_mesh) {
        w.mesh = read_entry_index(s, "mesh", "walls.meshes", "meshes", c.meshes.size());
    } else if (has_face) {
        const std::string f = *s.string("face");
        s.require(parse_face(f, c.dimension, w), "face",
                  fmt::format("unknown face \"{}\"; allowed: \"x-\", \"x+\", \"y-\", \"y+\"{}", f,
                              c.dimension == 3 ? ", \"z-\", \"z+\"" : ""));
        s.require(std::find(c.tank_faces.begin(), c.tank_faces.end(), f) != c.tank_faces.end(),
                  "face",
                  fmt::format("the tank face \"{}\" carries no wall (walls.tank_faces = [{}])", f,
                              join_list(c.tank_faces)));
    } else {
        w.box = read_entry_index(s, "box", "walls.boxes", "boxes", c.boxes.size());
    }
    return w;
}

// A force probe's region: a face (the half-space behind it) or a box, cut to [lo, hi]; it
// must reach wall particles.
void read_force_region(const Section& s, const CaseConfig& c, ProbeConfig& p) {
    const auto w = read_probe_wall(s, c);
    if (!w)
        s.reader().fail(s.key("face"),
                        "missing required key: a force probe needs face (a tank face, \"x+\") "
                        "or box (a walls.boxes index)");
    p.wall = *w;
    p.reading = read_reading(s, c, ": the pressure integrated over the wall's surface");
    s.require(p.wall.mesh < 0 || p.reading == SensorReading::force, "reading",
              "a mesh's load is read from the momentum equation's wall pairs (reading = "
              "\"force\"); the interpolated reading needs a tank face or a walls.boxes box");
    p.lo = s.triple("lo");
    p.hi = s.triple("hi");
    p.moment_about = s.triple("moment_about");
    const auto dim = static_cast<std::size_t>(c.dimension);
    const double eps = slack(c);
    // Where the region's wall particles can be: the face's wall layers (one kernel support
    // thick, corners included) or the box.
    const double support = kernel_support_factor(c.kernel) * c.h_over_dx * c.dx;
    const double thick = std::ceil(support / c.dx - 1e-9) * c.dx;
    Triple wlo{}, whi{};
    for (std::size_t a = 0; a < dim; ++a) {
        if (p.wall.mesh >= 0) {
            const WallMesh& m = c.meshes[static_cast<std::size_t>(p.wall.mesh)];
            const double grow = m.role == MeshRole::surface ? thick : 0.0;
            wlo[a] = m.shape->lo()[a] - grow;
            whi[a] = m.shape->hi()[a] + grow;
        } else if (p.wall.box >= 0) {
            wlo[a] = c.boxes[static_cast<std::size_t>(p.wall.box)].lo[a];
            whi[a] = c.boxes[static_cast<std::size_t>(p.wall.box)].hi[a];
        } else if (static_cast<int>(a) == p.wall.face_axis) {
            wlo[a] = p.wall.face_high ? c.tank_hi[a] : c.tank_lo[a] - thick;
            whi[a] = p.wall.face_high ? c.tank_hi[a] + thick : c.tank_lo[a];
        } else {
            wlo[a] = c.tank_lo[a] - thick;
            whi[a] = c.tank_hi[a] + thick;
        }
    }
    for (std::size_t a = 0; a < dim; ++a) {
        const double lo = p.lo ? (*p.lo)[a] : wlo[a], hi = p.hi ? (*p.hi)[a] : whi[a];
        if (p.lo && p.hi)
            s.require(lo < hi, "hi",
                      fmt::format("must be above lo on every axis; on {}: lo = {}, hi = {}",
                                  kAxis[a], lo, hi));
        if (std::max(lo, wlo[a]) > std::min(hi, whi[a]) + eps) {
            const bool low = p.lo && lo > whi[a];
            s.fail(low ? "lo" : "hi",
                   fmt::format("the force region touches no wall: on {}, {} = {} is {} the "
                               "{}'s wall particles, which lie in [{}, {}]",
                               kAxis[a], low ? "lo" : "hi", low ? lo : hi, low ? "above" : "below",
                               p.wall.mesh >= 0 ? "mesh" : (p.wall.box >= 0 ? "box" : "face"),
                               wlo[a], whi[a]));
        }
    }
}

// An area sensor's wall: the given face or box, or the one its centre lies on (recorded in
// p.wall, so that the sensor moves with its wall); the centre must be on that wall's surface
// within dx.
void read_sensor_wall(const Section& s, const CaseConfig& c, ProbeConfig& p) {
    s.require(c.walls == WallModel::dummy, "diameter",
              "an area sensor sits on dummy wall particles (walls.model = \"dummy\")");
    const auto given = read_probe_wall(s, c);
    if (given && given->mesh >= 0) {
        // On a mesh: the face centred at the mesh point nearest the given position, facing
        // along the nearest element's normal.
        const WallMesh& m = c.meshes[static_cast<std::size_t>(given->mesh)];
        const ClosestPoint q = m.shape->closest(p.position);
        s.require(q.distance <= c.dx + slack(c), "position",
                  fmt::format("the sensor is off the mesh \"{}\": its centre must lie on its "
                              "surface within dx = {} (the nearest surface point is {:.4g} m "
                              "away)",
                              m.file, c.dx, q.distance));
        p.wall = *given;
        p.sensor_centre = q.point;
        for (std::size_t a = 0; a < 3; ++a)
            p.sensor_normal[a] = -q.normal[a]; // into the wall
        return;
    }
    const auto dim = static_cast<std::size_t>(c.dimension);
    const double eps = slack(c);
    double best = std::numeric_limits<double>::infinity();
    // A candidate surface: normal axis, coordinate, and the tangential extent of the wall.
    ProbeWall found;
    const auto consider = [&](const ProbeWall& wall, std::size_t axis, double at, int into_wall,
                              const Triple& lo, const Triple& hi) {
        const double d = std::abs(p.position[axis] - at);
        if (d > c.dx + eps || d >= best)
            return;
        for (std::size_t a = 0; a < dim; ++a)
            if (a != axis && (p.position[a] < lo[a] - eps || p.position[a] > hi[a] + eps))
                return;
        best = d;
        found = wall;
        p.sensor_axis = static_cast<int>(axis);
        p.sensor_surface = at;
        p.sensor_into_wall = into_wall;
    };
    for (const auto& f : c.tank_faces) {
        ProbeWall w;
        if (!parse_face(f, c.dimension, w))
            continue;
        if (given && (given->face_axis != w.face_axis || given->face_high != w.face_high))
            continue;
        const auto a = static_cast<std::size_t>(w.face_axis);
        // The tank's walls lie outside it: beyond tank_hi, below tank_lo.
        consider(w, a, w.face_high ? c.tank_hi[a] : c.tank_lo[a], w.face_high ? 1 : -1, c.tank_lo,
                 c.tank_hi);
    }
    for (std::size_t b = 0; b < c.boxes.size(); ++b) {
        if (given && given->box != static_cast<int>(b))
            continue;
        ProbeWall w;
        w.box = static_cast<int>(b);
        for (std::size_t a = 0; a < dim; ++a) {
            // An obstacle's wall lies inside its box: above its lo face, below its hi face.
            consider(w, a, c.boxes[b].lo[a], 1, c.boxes[b].lo, c.boxes[b].hi);
            consider(w, a, c.boxes[b].hi[a], -1, c.boxes[b].lo, c.boxes[b].hi);
        }
    }
    if (p.sensor_axis < 0)
        s.fail("position",
               fmt::format("the sensor is off every wall: its centre must lie on the surface "
                           "of {} within dx = {}",
                           given ? (given->box >= 0 ? "the given box" : "the given tank face")
                                 : "a walled tank face or a walls.boxes obstacle",
                           c.dx));
    p.wall = found;
}

} // namespace

namespace {

// The motion of a probe's wall object (a force probe's region, an area sensor's wall); -1
// for a fixed one.
int wall_motion(const CaseConfig& c, const ProbeWall& w) {
    if (w.box >= 0)
        return c.boxes[static_cast<std::size_t>(w.box)].motion;
    if (w.mesh >= 0)
        return c.meshes[static_cast<std::size_t>(w.mesh)].motion;
    return c.tank_motion;
}

// The motion a probe moves with: `frame` when given; a force probe or an area sensor on a
// moving wall object moves with it. What cannot follow a moving object yet is refused.
void read_probe_frame(const Section& s, const CaseConfig& c, ProbeConfig& p) {
    p.frame = motion_reference(s, "frame", c);
    if (p.type == ProbeType::motion) {
        if (p.frame < 0)
            s.fail("frame", "missing required key for a motion probe: the [[motions]] name "
                            "whose displacement it records");
        p.body = c.motions[static_cast<std::size_t>(p.frame)].kind == MotionKind::free_body;
        return;
    }
    if (p.type == ProbeType::force && p.frame < 0)
        p.frame = wall_motion(c, p.wall);
    if (p.type == ProbeType::pressure && p.diameter > 0) {
        // A sensor is mounted on its wall: it moves with it, and with nothing else.
        const int carried = wall_motion(c, p.wall);
        s.require(p.frame < 0 || p.frame == carried, "frame",
                  carried < 0 ? std::string("an area sensor moves with its wall, and the wall "
                                            "it sits on does not move")
                              : fmt::format("an area sensor moves with its wall, which moves "
                                            "with \"{}\"",
                                            c.motions[static_cast<std::size_t>(carried)].name));
        p.frame = carried;
    }
    if (p.frame < 0)
        return;
    const char* key = s.node("frame") != nullptr ? "frame" : "type";
    s.require(p.type != ProbeType::surge_front, key,
              "a surge front is measured in the domain's frame; frame does not apply");
    s.require(p.type != ProbeType::force || p.reading == SensorReading::force, "reading",
              "a force probe on a moving wall object reads its wall pairs' force (reading = "
              "\"force\")");
}

} // namespace

void read_probes(const Section& root, CaseConfig& c) {
    std::set<std::string> names;
    for (const auto& s : root.entries("probes")) {
        ProbeConfig p;
        const auto name = s.string("name");
        if (!name)
            s.reader().fail(s.key("name"), "missing required key (becomes probes/<name>.csv)");
        p.name = *name;
        // Names become file names: keep them portable and unsurprising.
        const bool ok = !p.name.empty() && std::all_of(p.name.begin(), p.name.end(), [](char ch) {
            return std::isalnum(static_cast<unsigned char>(ch)) != 0 || ch == '_' || ch == '-';
        });
        s.require(ok, "name",
                  fmt::format("\"{}\" is not a valid probe name (letters, digits, '_' and '-' "
                              "only; it becomes a file name)",
                              p.name));
        s.require(p.name.size() <= kMaxNameLength, "name",
                  fmt::format("is {} bytes long; at most {} (it becomes a file name)",
                              p.name.size(), kMaxNameLength));
        s.require(names.insert(p.name).second, "name",
                  fmt::format("another probe is already called \"{}\"", p.name));

        if (s.node("type") == nullptr)
            s.reader().fail(s.key("type"), "missing required key (\"pressure\", \"water_level\", "
                                           "\"surge_front\", \"force\" or \"motion\")");
        p.type = s.choice("type", ProbeType::pressure, kProbeTypes);
        const char* type_word = p.type == ProbeType::pressure      ? "pressure"
                                : p.type == ProbeType::water_level ? "water_level"
                                : p.type == ProbeType::force       ? "force"
                                : p.type == ProbeType::motion      ? "motion"
                                                                   : "surge_front";
        const auto only_for = [&](std::string_view key, bool allowed) {
            s.require(allowed || s.node(key) == nullptr, key,
                      fmt::format("does not apply to a {} probe", type_word));
        };
        const bool pressure = p.type == ProbeType::pressure;
        const bool force = p.type == ProbeType::force;
        only_for("position", pressure);
        only_for("x", p.type == ProbeType::water_level);
        only_for("y", p.type == ProbeType::water_level);
        only_for("diameter", pressure);
        only_for("reading", pressure || force);
        only_for("face", pressure || force);
        only_for("box", pressure || force);
        only_for("mesh", pressure || force);
        only_for("lo", force);
        only_for("hi", force);
        only_for("moment_about", force);
        only_for("direction", p.type == ProbeType::surge_front);
        only_for("min_thickness", p.type == ProbeType::surge_front);

        if (pressure) {
            p.position = s.required_triple("position", "point where pressure is sampled [m]");
            s.require(inside_domain(c, p.position), "position",
                      "the probe lies outside the domain");
            if (s.node("diameter") != nullptr) {
                p.diameter = s.required_number("diameter", "sensor diameter [m]");
                read_sensor_wall(s, c, p);
                p.reading = read_reading(s, c, "");
                s.require(p.wall.mesh < 0 || p.reading == SensorReading::force, "reading",
                          "a sensor on a mesh reads the wall pairs' force (reading = "
                          "\"force\"); the interpolated reading needs a tank face or a "
                          "walls.boxes box");
            } else {
                s.require(s.node("reading") == nullptr, "reading",
                          "only an area sensor (with a diameter) has a reading; a point probe "
                          "interpolates the fluid's pressure");
                s.require(s.node("face") == nullptr && s.node("box") == nullptr &&
                              s.node("mesh") == nullptr,
                          s.node("face") != nullptr ? "face"
                                                    : (s.node("box") != nullptr ? "box" : "mesh"),
                          "only an area sensor (with a diameter) sits on a wall");
            }
        }
        if (p.type == ProbeType::water_level) {
            p.x = s.required_number("x", "x position of the water-level gauge [m]");
            s.require(p.x >= c.domain_lo[0] - slack(c) && p.x <= c.domain_hi[0] + slack(c), "x",
                      fmt::format("the probe lies outside the domain: x = {} is not in [{}, {}]",
                                  p.x, c.domain_lo[0], c.domain_hi[0]));
            if (c.walls != WallModel::none)
                s.require(p.x >= c.tank_lo[0] - slack(c) && p.x <= c.tank_hi[0] + slack(c), "x",
                          fmt::format("the gauge lies outside the tank: x = {} is not in "
                                      "[{}, {}]",
                                      p.x, c.tank_lo[0], c.tank_hi[0]));
            if (s.node("y") != nullptr) {
                s.require(c.dimension == 3, "y",
                          "a gauge's y applies in 3-D only (in 2-D y is the vertical)");
                p.y = s.required_number("y", "y position of the water-level gauge [m]");
                const double lo = c.walls != WallModel::none ? c.tank_lo[1] : c.domain_lo[1];
                const double hi = c.walls != WallModel::none ? c.tank_hi[1] : c.domain_hi[1];
                s.require(*p.y >= lo - slack(c) && *p.y <= hi + slack(c), "y",
                          fmt::format("the gauge lies outside the {}: y = {} is not in [{}, {}]",
                                      c.walls != WallModel::none ? "tank" : "domain", *p.y, lo,
                                      hi));
            }
        }
        if (p.type == ProbeType::surge_front) {
            const std::string dir = s.string("direction").value_or("+x");
            const bool known = dir.size() == 2 && (dir[0] == '+' || dir[0] == '-') &&
                               dir[1] >= 'x' && dir[1] < 'x' + c.dimension;
            s.require(known, "direction",
                      fmt::format("unknown value \"{}\"; allowed: {}", dir,
                                  c.dimension == 3 ? "\"+x\", \"-x\", \"+y\", \"-y\", \"+z\", "
                                                     "\"-z\""
                                                   : "\"+x\", \"-x\", \"+y\", \"-y\""));
            p.direction_axis = dir[1] - 'x';
            p.direction_negative = dir[0] == '-';
            p.min_thickness = s.number("min_thickness", 2 * c.dx);
        }
        if (force)
            read_force_region(s, c, p);
        read_probe_frame(s, c, p);

        const toml::node* iv = s.node("interval");
        if (iv != nullptr && iv->is_string()) {
            s.require(iv->as_string()->get() == "every_step", "interval",
                      fmt::format("unknown value \"{}\"; a number of seconds or \"every_step\"",
                                  iv->as_string()->get()));
            p.every_step = true;
        } else {
            p.interval = s.number("interval", p.interval);
        }
        s.require(p.interval == 0 || c.end_time / p.interval <= kMaxOutputs, "interval",
                  fmt::format("{} s would take {:.3g} samples up to end_time = {} s; at most {:g}",
                              p.interval, c.end_time / p.interval, c.end_time, kMaxOutputs));
        c.probes.push_back(p);
    }
}

} // namespace sluice::case_file
