// Probes evaluated without gathering the particles: footprints, the per-rank selection, the
// merge on rank 0 and the probe functions (physics/probes.hpp, physics/wall_loads.hpp).
#include "probe_sampling.hpp"

#include "particle_messages.hpp"
#include "sluice/solver/mesh_walls.hpp"
#include "vec_triple.hpp"

#include "sluice/physics/initial_profiles.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/probes.hpp"
#include "sluice/physics/wall_loads.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

namespace sluice {
namespace {

template <int D>
struct Box {
    Vec<D> lo, hi;
    [[nodiscard]] bool holds(const Vec<D>& x) const {
        for (int a = 0; a < D; ++a)
            if (!(x[a] >= lo[a] && x[a] <= hi[a]))
                return false;
        return true;
    }
    [[nodiscard]] Box grown(Real by) const { return {lo.array() - by, hi.array() + by}; }
};

// The pose now of the motion a probe moves with (ProbeConfig::frame), if any.
template <int D>
std::optional<Pose> probe_pose(const Simulation<D>& sim, const ProbeConfig& probe) {
    if (probe.frame < 0)
        return std::nullopt;
    // A frame names a motion that moves an object (the case reader refuses an unused one).
    const auto& objects = sim.motion().objects();
    for (std::size_t k = 0; k < objects.size(); ++k)
        if (objects[k].motion == probe.frame)
            return sim.motion().poses(sim.time())[k];
    throw std::logic_error("probe_pose: the probe's motion moves no wall object");
}

// The box in the domain's frame that holds `body` (given where the object is at t = 0) moved
// by `pose`: the box around its moved corners (all space when it is unbounded and turns).
template <int D>
Box<D> moved_box(const Box<D>& body, const Pose& pose) {
    const Real inf = std::numeric_limits<Real>::infinity();
    bool bounded = true;
    for (int a = 0; a < D; ++a)
        bounded = bounded && std::isfinite(body.lo[a]) && std::isfinite(body.hi[a]);
    if (!bounded) {
        if (pose.angle != 0)
            return {Vec<D>::Constant(-inf), Vec<D>::Constant(inf)};
        const Vec<D> d = from_pose_point<D>(pose.d);
        return {body.lo + d, body.hi + d};
    }
    const Bounds b = moved_bounds({to_pose_point<D>(body.lo), to_pose_point<D>(body.hi)}, pose, D);
    return {from_pose_point<D>(b.lo), from_pose_point<D>(b.hi)};
}

// Where a point of the object's t = 0 placement is now, and where a point now was at t = 0.
template <int D>
Vec<D> moved_point(const Vec<D>& x0, const Pose& pose) {
    return from_pose_point<D>(pose.position(to_pose_point<D>(x0)));
}
template <int D>
Vec<D> body_point(const Vec<D>& x, const Pose& pose) {
    return from_pose_point<D>(pose.body_point(to_pose_point<D>(x)));
}

// The particles as the object moving with `pose` sees them: positions where they would be
// relative to its t = 0 placement, velocities turned back with it. The pair terms of the wall
// loads take differences of positions and of velocities, turned alike, and scalar pressures
// and densities, so a load summed here is the lab frame's turned into the object's axes: a
// sensor laid out where its wall is at t = 0 reads as it would on that wall held still.
template <int D>
Particles<D> seen_from_object(const Particles<D>& P, const Pose& pose) {
    Particles<D> seen = P;
    for (std::size_t i = 0; i < seen.size(); ++i) {
        seen.x[i] = body_point(seen.x[i], pose);
        seen.v[i] = from_pose_point<D>(pose.R.transpose() * to_pose_point<D>(seen.v[i]));
    }
    return seen;
}

// A length far below any spacing, for comparing coordinates of the geometry: 1e-9 of the
// domain's largest extent.
template <int D>
double geometry_eps(const CaseConfig& cfg) {
    double size = 0;
    for (int a = 0; a < D; ++a)
        size = std::max(size, cfg.domain_hi[a] - cfg.domain_lo[a]);
    return 1e-9 * size;
}

// How deep the wall layers behind a surface reach: layers x dx.
template <int D>
double wall_layer_depth(const CaseConfig& cfg) {
    return wall_layers(kernel_support_factor(cfg.kernel) * cfg.h_over_dx * cfg.dx, cfg.dx) * cfg.dx;
}

// The region of a force probe: the half-space behind a tank face (its layers and the corners
// it shares) or an obstacle box, cut to the probe's lo/hi.
template <int D>
Box<D> force_box(const CaseConfig& cfg, const ProbeConfig& probe) {
    const double inf = std::numeric_limits<double>::infinity();
    const double eps = geometry_eps<D>(cfg);
    Box<D> box;
    for (int a = 0; a < D; ++a) {
        const auto k = static_cast<std::size_t>(a);
        double l = -inf, h = inf;
        if (probe.wall.mesh >= 0) {
            const WallMesh& m = cfg.meshes[static_cast<std::size_t>(probe.wall.mesh)];
            const double grow = m.role == MeshRole::surface ? wall_layer_depth<D>(cfg) : 0.0;
            l = m.shape->lo()[k] - grow - eps;
            h = m.shape->hi()[k] + grow + eps;
        } else if (probe.wall.box >= 0) {
            const WallBox& b = cfg.boxes[static_cast<std::size_t>(probe.wall.box)];
            l = b.lo[k] - eps;
            h = b.hi[k] + eps;
        } else if (a == probe.wall.face_axis) {
            if (probe.wall.face_high)
                l = cfg.tank_hi[k] - eps;
            else
                h = cfg.tank_lo[k] + eps;
        }
        if (probe.lo)
            l = std::max(l, (*probe.lo)[k]);
        if (probe.hi)
            h = std::min(h, (*probe.hi)[k]);
        box.lo[a] = Real(l);
        box.hi[a] = Real(h);
    }
    return box;
}

// A force probe's wall surfaces for the interpolated reading: the tank face's plane across
// the tank, or the obstacle box's faces, each cut to the probe's region. A box face that lies
// on the tank's boundary (an obstacle standing on the floor) has no fluid side and is left out.
template <int D>
std::vector<WallPatch<D>> force_patches(const CaseConfig& cfg, const ProbeConfig& probe) {
    const Box<D> region = force_box<D>(cfg, probe);
    const double eps = geometry_eps<D>(cfg);
    std::vector<WallPatch<D>> out;
    // The patch on plane x[axis] = at, spanning [lo, hi] (tangentially) within the region.
    const auto add = [&](int axis, double at, int into_wall, const Triple& lo, const Triple& hi) {
        if (at < double(region.lo[axis]) || at > double(region.hi[axis]))
            return;
        WallPatch<D> patch;
        patch.normal_axis = axis;
        patch.into_wall = into_wall;
        patch.at = Real(at);
        for (int a = 0; a < D; ++a) {
            const auto k = static_cast<std::size_t>(a);
            patch.lo[a] = std::max(Real(lo[k]), region.lo[a]);
            patch.hi[a] = std::min(Real(hi[k]), region.hi[a]);
        }
        out.push_back(patch);
    };
    if (probe.wall.box < 0) {
        const auto k = static_cast<std::size_t>(probe.wall.face_axis);
        add(probe.wall.face_axis, probe.wall.face_high ? cfg.tank_hi[k] : cfg.tank_lo[k],
            probe.wall.face_high ? 1 : -1, cfg.tank_lo, cfg.tank_hi);
        return out;
    }
    const WallBox& b = cfg.boxes[static_cast<std::size_t>(probe.wall.box)];
    Triple lo = b.lo, hi = b.hi; // the part of the box inside the tank
    for (std::size_t k = 0; k < static_cast<std::size_t>(D); ++k) {
        lo[k] = std::max(lo[k], cfg.tank_lo[k]);
        hi[k] = std::min(hi[k], cfg.tank_hi[k]);
    }
    for (int a = 0; a < D; ++a) {
        const auto k = static_cast<std::size_t>(a);
        // An obstacle's wall lies inside its box: its lo face has the wall above it (+1).
        if (b.lo[k] > cfg.tank_lo[k] + eps && b.lo[k] < cfg.tank_hi[k] - eps)
            add(a, b.lo[k], 1, lo, hi);
        if (b.hi[k] > cfg.tank_lo[k] + eps && b.hi[k] < cfg.tank_hi[k] - eps)
            add(a, b.hi[k], -1, lo, hi);
    }
    return out;
}

// Every particle a probe's value depends on lies in its footprint. The kernel sums of the
// pressure probes and the wall loads reach one support from the points and wall particles they
// sum for; before the first step the wall particles they read are refreshed from the fluid
// (refresh_dummy_walls), one support further. A gauge reads its surroundings (gauge_bulk_reach dx,
// a margin of another dx); the probe function applies the exact bounds.
template <int D>
Box<D> fixed_footprint(const Simulation<D>& sim, const ProbeConfig& probe) {
    const Real inf = std::numeric_limits<Real>::infinity();
    const Real reach = 2 * sim.kernel_support();
    const Real dx = Real(sim.config().dx);
    Box<D> box{Vec<D>::Constant(-inf), Vec<D>::Constant(inf)};
    switch (probe.type) {
    case ProbeType::pressure:
        for (int a = 0; a < D; ++a) {
            const auto k = static_cast<std::size_t>(a);
            const Real c = probe.diameter > 0 && probe.wall.mesh >= 0
                               ? Real(probe.sensor_centre[k])
                               : (a == probe.sensor_axis ? Real(probe.sensor_surface)
                                                         : Real(probe.position[k]));
            box.lo[a] = c;
            box.hi[a] = c;
        }
        return box.grown(reach + Real(probe.diameter) / 2);
    case ProbeType::water_level: {
        const Real half = Real(gauge_bulk_reach + 1) * dx; // the probe applies the exact bounds
        box.lo[0] = Real(probe.x) - half;
        box.hi[0] = Real(probe.x) + half;
        if (D == 3 && probe.y) {
            box.lo[1] = Real(*probe.y) - half;
            box.hi[1] = Real(*probe.y) + half;
        }
        return box;
    }
    case ProbeType::force:
        return force_box<D>(sim.config(), probe).grown(reach);
    case ProbeType::surge_front:
    case ProbeType::motion:
        break; // binned columns, or no particles
    }
    return box;
}

// An area sensor's centre on its wall and the unit normal into the wall, where the wall is at
// t = 0.
template <int D>
std::pair<Vec<D>, Vec<D>> sensor_centre_normal(const ProbeConfig& probe) {
    if (probe.wall.mesh >= 0)
        return {to_vec<D>(probe.sensor_centre), to_vec<D>(probe.sensor_normal)};
    Vec<D> centre = to_vec<D>(probe.position);
    centre[probe.sensor_axis] = Real(probe.sensor_surface);
    Vec<D> normal = Vec<D>::Zero();
    normal[probe.sensor_axis] = Real(probe.sensor_into_wall);
    return {centre, normal};
}

// The footprint where the probe is now (moved with its object).
template <int D>
Box<D> footprint(const Simulation<D>& sim, const ProbeConfig& probe) {
    const Box<D> box = fixed_footprint(sim, probe);
    const std::optional<Pose> pose = probe_pose(sim, probe);
    return pose ? moved_box(box, *pose) : box;
}

// The wall-load probes' pair terms: the momentum equation's own parameters, loads relative to
// the background pressure.
template <int D>
WallLoadParams<D> wall_load_params(const Simulation<D>& sim) {
    WallLoadParams<D> w = wall_load_params(sim.momentum());
    w.p_gauge = w.p_floor; // the background pressure
    w.riemann = sim.config().dissipation == Dissipation::riemann;
    w.no_slip = sim.config().no_slip;
    return w;
}

// An interpolated area sensor's face, and the box holding the wall particles whose contacts
// it reads (contact_traction: h beyond the face, a support deep).
template <int D>
SensorFace<D> sensor_face(const ProbeConfig& probe) {
    Vec<D> point;
    for (int d = 0; d < D; ++d)
        point[d] = Real(probe.position[static_cast<std::size_t>(d)]);
    point[probe.sensor_axis] = Real(probe.sensor_surface);
    return {point, probe.sensor_axis, probe.sensor_into_wall, Real(probe.diameter)};
}

// The wall particles a force probe on a moving object reads: the object's own, in the region
// the probe names where the object was at t = 0 (and, for a mesh, of that mesh).
template <int D>
std::vector<std::size_t> carried_wall_particles(const Simulation<D>& sim, const Particles<D>& P,
                                                const ProbeConfig& probe, const Pose& pose) {
    const CaseConfig& cfg = sim.config();
    const Box<D> region = force_box<D>(cfg, probe);
    const int layers = wall_layers(sim.kernel_support(), cfg.dx);
    std::vector<std::size_t> walls;
    for (std::size_t j = 0; j < P.size(); ++j) {
        if (P.kind[j] != Kind::wall)
            continue;
        const Vec<D> x0 = body_point(P.x[j], pose);
        if (region.holds(x0) &&
            (probe.wall.mesh < 0 ||
             wall_particle_of_mesh(cfg, static_cast<std::size_t>(probe.wall.mesh), layers,
                                   to_triple<D>(x0))))
            walls.push_back(j);
    }
    return walls;
}

// Of the wall particles `walls`, only the mesh's own (wall_particle_of_mesh): a mesh's region
// also holds other walls' layers (a floor under an obstacle, side walls beside a bed).
template <int D>
void keep_walls_of_mesh(const Simulation<D>& sim, const Particles<D>& P, std::size_t mesh,
                        std::vector<std::size_t>& walls) {
    const CaseConfig& cfg = sim.config();
    const int layers = wall_layers(sim.kernel_support(), cfg.dx);
    std::erase_if(walls, [&](std::size_t j) {
        return !wall_particle_of_mesh(cfg, mesh, layers, to_triple<D>(P.x[j]));
    });
}

// A force-reading area sensor on a mesh: the mesh's own wall particles near the face
// (wall_particle_of_mesh) read by oriented_wall_force_sensor.
template <int D>
Real mesh_sensor_reading(const Simulation<D>& sim, const Particles<D>& P,
                         const ProbeConfig& probe) {
    const CaseConfig& cfg = sim.config();
    OrientedSensorFace<D> face;
    face.centre = to_vec<D>(probe.sensor_centre);
    face.into_wall = to_vec<D>(probe.sensor_normal);
    face.diameter = Real(probe.diameter);
    const Real reach = face.diameter / 2 + sim.kernel_support();
    std::vector<std::size_t> walls = wall_particles_in(P, Vec<D>(face.centre.array() - reach),
                                                       Vec<D>(face.centre.array() + reach));
    keep_walls_of_mesh(sim, P, static_cast<std::size_t>(probe.wall.mesh), walls);
    return oriented_wall_force_sensor(P, sim.kernel(), wall_load_params(sim), face, walls,
                                      Real(cfg.dx));
}

template <int D>
Box<D> sensor_contact_box(const Simulation<D>& sim, const ProbeConfig& probe) {
    const SensorFace<D> face = sensor_face<D>(probe);
    const Real reach = face.diameter / 2 + Real(sim.h());
    Box<D> box{face.centre.array() - reach, face.centre.array() + reach};
    const int a = face.normal_axis;
    const Real far = face.centre[a] + Real(face.into_wall) * sim.kernel_support();
    box.lo[a] = std::min(face.centre[a], far);
    box.hi[a] = std::max(face.centre[a], far);
    return box;
}

// A free body's columns after its motion's: 3-D its orientation (a unit quaternion) and angular
// velocity, then the fluid's force and moment (about the centre of mass) of the last step.
template <int D>
void append_body_columns(const WallMotion<D>& motion, int frame, const Pose& pose,
                         std::vector<double>& row) {
    if constexpr (D == 3) {
        const Eigen::Quaterniond q(pose.R);
        for (double v : {q.w(), q.x(), q.y(), q.z()})
            row.push_back(v);
        for (int k = 0; k < 3; ++k)
            row.push_back(pose.omega[k]);
    }
    for (std::size_t b = 0; b < motion.bodies().size(); ++b) {
        const auto& o = motion.objects()[static_cast<std::size_t>(motion.body_object(b))];
        if (o.motion != frame)
            continue;
        const BodyLoad& load = motion.loads()[b];
        for (int k = 0; k < D; ++k)
            row.push_back(load.force[k]);
        if constexpr (D == 3) {
            for (int k = 0; k < 3; ++k)
                row.push_back(load.moment[k]);
        } else {
            row.push_back(load.moment[2]);
        }
    }
}

// The same probe read as though its wall were held still at its t = 0 placement.
inline ProbeConfig fixed_sensor(ProbeConfig probe) {
    probe.frame = -1;
    return probe;
}

// One row of a probe's CSV (after the time) from the particles of its footprint (a force
// probe: its components, then its moment); a surge front from its merged columns.
template <int D>
std::vector<double> probe_row(const Simulation<D>& sim, const Particles<D>& P,
                              const std::vector<WallContact<D>>& contacts,
                              const ProbeConfig& probe) {
    const CaseConfig& cfg = sim.config();
    const Real dx = Real(cfg.dx);
    const std::optional<Pose> pose = probe_pose(sim, probe);
    switch (probe.type) {
    case ProbeType::motion: {
        std::vector<double> row;
        for (int d = 0; d < D; ++d)
            row.push_back(pose->d[d]);
        row.push_back(pose->angle * 180 / std::numbers::pi);
        for (int d = 0; d < D; ++d)
            row.push_back(pose->d_rate[d]);
        row.push_back(pose->angle_rate * 180 / std::numbers::pi);
        if (probe.body) // the body's orientation, angular velocity and the fluid's last load
            append_body_columns<D>(sim.motion(), probe.frame, *pose, row);
        return row;
    }
    case ProbeType::pressure: {
        const Real p_min = sim.applied_pressure_floor();
        if (probe.diameter <= 0) {
            Vec<D> point;
            for (int d = 0; d < D; ++d)
                point[d] = Real(probe.position[static_cast<std::size_t>(d)]);
            if (pose)
                point = moved_point(point, *pose);
            return {double(pressure_probe(P, sim.kernel(), point, p_min))};
        }
        if (pose) {
            // On a moving wall: the reading in the wall's frame (the walls' pressures were
            // extrapolated with g - a_w), then where the sensor is now and its normal.
            std::vector<double> row =
                probe_row(sim, seen_from_object(P, *pose), contacts, fixed_sensor(probe));
            const auto [centre, normal] = sensor_centre_normal<D>(probe);
            const Vec<D> x = moved_point(centre, *pose);
            const Vec<D> n = from_pose_point<D>(pose->direction(to_pose_point<D>(normal)));
            for (int d = 0; d < D; ++d)
                row.push_back(double(x[d]));
            for (int d = 0; d < D; ++d)
                row.push_back(double(n[d]));
            return row;
        }
        if (probe.wall.mesh >= 0)
            return {double(mesh_sensor_reading(sim, P, probe))};
        const SensorFace<D> face = sensor_face<D>(probe);
        if (probe.reading == SensorReading::force)
            return {double(wall_force_sensor(P, sim.kernel(), wall_load_params(sim), face, dx))};
        // The pressure on the face, and the traction of the wall collisions under it
        // (projection; none under WCSPH), or that traction alone.
        const Real traction =
            contact_traction(contacts, face, dx, sim.kernel_support(), Real(sim.h()));
        if (probe.reading == SensorReading::collisions)
            return {double(traction)};
        return {double(wall_pressure_sensor(P, sim.kernel(), face, dx / 4, p_min) + traction)};
    }
    case ProbeType::water_level: {
        std::optional<Real> y;
        if (probe.y)
            y = Real(*probe.y);
        if (pose) { // along the object's own vertical: the particles seen from its frame
            Particles<D> seen = P;
            for (auto& x : seen.x)
                x = body_point(x, *pose);
            return {double(gauge_water_level(seen, dx, Real(probe.x), y))};
        }
        return {double(gauge_water_level(P, dx, Real(probe.x), y))};
    }
    case ProbeType::force: {
        Vec<D> about = Vec<D>::Zero();
        if (probe.moment_about)
            for (int d = 0; d < D; ++d)
                about[d] = Real((*probe.moment_about)[static_cast<std::size_t>(d)]);
        if (pose) // a moving object: the moment about the point carried with it
            about = moved_point(about, *pose);
        const WallLoadParams<D> prm = wall_load_params(sim);
        const Box<D> region = force_box<D>(cfg, probe);
        WallLoad load;
        if (probe.reading == SensorReading::collisions) {
            // The momentum the scheme's wall collisions gave the region's wall particles.
            load = contact_wall_load(contacts, region.lo, region.hi, about);
        } else if (probe.reading == SensorReading::interpolated) {
            // The pressure on the wall's surfaces, and the momentum the scheme's wall
            // collisions gave the wall particles of the region (projection; none under WCSPH).
            load = interpolated_wall_load(P, sim.kernel(), force_patches<D>(cfg, probe), dx / 2,
                                          prm.p_floor, about);
            const WallLoad contact = contact_wall_load(contacts, region.lo, region.hi, about);
            for (std::size_t a = 0; a < 3; ++a) {
                load.force[a] += contact.force[a];
                load.moment[a] += contact.moment[a];
            }
        } else if (pose) { // the reader allows only this reading on a moving object
            load = wall_load(P, sim.kernel(), prm, carried_wall_particles(sim, P, probe, *pose),
                             about);
        } else {
            std::vector<std::size_t> walls = wall_particles_in(P, region.lo, region.hi);
            if (probe.wall.mesh >= 0)
                keep_walls_of_mesh(sim, P, static_cast<std::size_t>(probe.wall.mesh), walls);
            load = wall_load(P, sim.kernel(), prm, walls, about);
        }
        std::vector<double> row(load.force.begin(), load.force.begin() + D);
        if (probe.moment_about) {
            if (D == 3)
                row.insert(row.end(), load.moment.begin(), load.moment.end());
            else
                row.push_back(load.moment[2]);
        }
        return row;
    }
    case ProbeType::surge_front:
        break;
    }
    return {std::nan("")};
}

template <int D>
FrontColumns<D> front_columns(const CaseConfig& cfg, const ProbeConfig& probe) {
    return FrontColumns<D>(Real(cfg.dx), probe.direction_axis, probe.direction_negative);
}

} // namespace

template <int D>
std::vector<std::vector<double>> sample_probes(const Simulation<D>& sim,
                                               const std::vector<std::size_t>& due) {
    const CaseConfig& cfg = sim.config();
    const Particles<D>& P = sim.particles();
    std::vector<Box<D>> boxes;
    std::vector<FrontColumns<D>> fronts;
    for (std::size_t k : due) {
        const ProbeConfig& probe = cfg.probes[k];
        if (probe.type == ProbeType::surge_front) {
            fronts.push_back(front_columns<D>(cfg, probe));
            fronts.back().add(P, sim.owned());
        } else if (probe.type != ProbeType::motion && probe.reading != SensorReading::collisions) {
            // (a collisions reading needs the wall contacts below, not particles)
            boxes.push_back(footprint(sim, probe));
        }
    }
    // The regions of the due force probes and area sensors that read the interpolated load
    // (whose wall collisions they add) or the collisions alone.
    std::vector<Box<D>> contact_regions;
    for (std::size_t k : due) {
        const ProbeConfig& probe = cfg.probes[k];
        if (probe.reading == SensorReading::force)
            continue;
        if (probe.type == ProbeType::force)
            contact_regions.push_back(force_box<D>(cfg, probe));
        else if (probe.type == ProbeType::pressure && probe.diameter > 0)
            contact_regions.push_back(sensor_contact_box(sim, probe));
    }
    // This rank's message: how many particles, the particles of any footprint (each once, in
    // this rank's order), each front's columns, then the wall collisions in those regions.
    tasks::Bytes mine, picked;
    std::uint64_t count = 0;
    for (std::size_t i = 0; i < sim.owned(); ++i)
        if (std::any_of(boxes.begin(), boxes.end(),
                        [&](const Box<D>& b) { return b.holds(P.x[i]); })) {
            messages::pack_particle(P, i, picked);
            ++count;
        }
    tasks::put(mine, count);
    mine.insert(mine.end(), picked.begin(), picked.end());
    for (const auto& f : fronts) {
        tasks::put(mine, static_cast<std::uint64_t>(f.columns().size()));
        for (const auto& [key, c] : f.columns()) {
            tasks::put(mine, key);
            tasks::put(mine, c.count);
            tasks::put(mine, c.furthest);
        }
    }
    if (!contact_regions.empty()) {
        std::vector<WallContact<D>> near;
        for (const WallContact<D>& c : sim.wall_contacts())
            if (std::any_of(contact_regions.begin(), contact_regions.end(),
                            [&](const Box<D>& b) { return b.holds(c.wall_x); }))
                near.push_back(c);
        tasks::put(mine, static_cast<std::uint64_t>(near.size()));
        for (const WallContact<D>& c : near) {
            tasks::put(mine, c.fluid);
            tasks::put(mine, c.wall);
            tasks::put(mine, c.wall_x);
            tasks::put(mine, c.force);
        }
    }
    const auto gathered = sim.comm().gather(mine, 0);
    if (sim.comm().rank() != 0)
        return {};

    // Ranks own consecutive runs of the curve: rank order is the order of a full gather.
    Particles<D> local;
    std::vector<WallContact<D>> contacts;
    std::vector<FrontColumns<D>> merged;
    for (std::size_t k : due)
        if (cfg.probes[k].type == ProbeType::surge_front)
            merged.push_back(front_columns<D>(cfg, cfg.probes[k]));
    for (const auto& b : gathered) {
        std::size_t pos = 0;
        const auto n = tasks::take<std::uint64_t>(b, pos);
        const std::size_t bytes = n * messages::particle_bytes<D>;
        messages::unpack_particles<D>(std::span<const std::byte>(b).subspan(pos, bytes), local);
        pos += bytes;
        for (auto& f : merged) {
            const auto columns = tasks::take<std::uint64_t>(b, pos);
            for (std::uint64_t c = 0; c < columns; ++c) {
                const auto key = tasks::take<CellKey<D>>(b, pos);
                typename FrontColumns<D>::Column col;
                col.count = tasks::take<long>(b, pos);
                col.furthest = tasks::take<Real>(b, pos);
                f.merge(key, col);
            }
        }
        if (!contact_regions.empty()) {
            const auto n_contacts = tasks::take<std::uint64_t>(b, pos);
            for (std::uint64_t c = 0; c < n_contacts; ++c) {
                WallContact<D> contact;
                contact.fluid = tasks::take<ParticleId>(b, pos);
                contact.wall = tasks::take<ParticleId>(b, pos);
                contact.wall_x = tasks::take<Vec<D>>(b, pos);
                contact.force = tasks::take<Vec<D>>(b, pos);
                contacts.push_back(contact);
            }
        }
    }
    // Before the first step the wall particles hold no extrapolated pressure yet: the probes
    // (wall forces, area sensors) see the state the first step will see.
    if (sim.steps() == 0 && cfg.walls == WallModel::dummy) {
        Vec<D> g;
        for (int d = 0; d < D; ++d)
            g[d] = Real(cfg.gravity[static_cast<std::size_t>(d)]);
        refresh_dummy_walls(local, sim.kernel(), sim.eos(), g, Real(std::pow(cfg.dx, D)));
    }
    std::vector<std::vector<double>> rows;
    std::size_t front = 0;
    for (std::size_t k : due) {
        const ProbeConfig& probe = cfg.probes[k];
        if (probe.type == ProbeType::surge_front)
            rows.push_back({double(merged[front++].front(Real(probe.min_thickness)))});
        else
            rows.push_back(probe_row(sim, local, contacts, probe));
    }
    return rows;
}

template std::vector<std::vector<double>> sample_probes<2>(const Simulation<2>&,
                                                           const std::vector<std::size_t>&);
template std::vector<std::vector<double>> sample_probes<3>(const Simulation<3>&,
                                                           const std::vector<std::size_t>&);

} // namespace sluice
