#include "sluice/solver/motion_check.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/io/wall_extent.hpp"
#include "sluice/motion/rigid_body.hpp"
#include "sluice/motion/wave_theory.hpp"
#include "sluice/solver/initial_state.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace sluice {
namespace {

constexpr const char* kAxisLetter = "xyz";

struct Extent {
    std::array<double, 3> lo{}, hi{};
};

// A wall object with a motion: its box at t = 0 (what it occupies, wall layers included) and
// the key that gives it its motion.
struct MovingObject {
    Extent at_rest;
    bool inside_tank = false; // an obstacle within a fixed tank: it must stay inside
    int motion = -1;
    std::string key;
};

std::vector<MovingObject> moving_objects(const CaseConfig& cfg, int layers) {
    const double depth = layers * cfg.dx;
    std::vector<MovingObject> out;
    if (cfg.tank_motion >= 0) {
        Extent tank{cfg.tank_lo, cfg.tank_hi};
        for (int a = 0; a < 3; ++a) {
            tank.lo[a] -= depth;
            tank.hi[a] += depth;
        }
        out.push_back({tank, false, cfg.tank_motion, "walls.tank_motion"});
    }
    for (std::size_t b = 0; b < cfg.boxes.size(); ++b)
        if (cfg.boxes[b].motion >= 0)
            out.push_back({{cfg.boxes[b].lo, cfg.boxes[b].hi},
                           cfg.tank_motion < 0,
                           cfg.boxes[b].motion,
                           fmt::format("walls.boxes[{}].motion", b)});
    for (std::size_t m = 0; m < cfg.meshes.size(); ++m) {
        const WallMesh& mesh = cfg.meshes[m];
        if (mesh.motion < 0 || !mesh.shape)
            continue;
        const double reach = mesh.role == MeshRole::surface ? depth : 0.0;
        Extent e;
        for (int a = 0; a < 3; ++a) {
            e.lo[a] = mesh.shape->lo()[a] - reach;
            e.hi[a] = mesh.shape->hi()[a] + reach;
        }
        out.push_back({e, false, mesh.motion, fmt::format("walls.meshes[{}].motion", m)});
    }
    return out;
}

// An extent moved by a pose (motion/rigid_motion.hpp's moved_bounds).
Extent moved(const Extent& e, const Pose& p, int dim) {
    const Bounds b =
        moved_bounds({{e.lo[0], e.lo[1], e.lo[2]}, {e.hi[0], e.hi[1], e.hi[2]}}, p, dim);
    return {{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
}

std::vector<double> sample_times(const CaseConfig& cfg, const MotionLaw& law) {
    std::vector<double> t;
    constexpr int n = 400;
    for (int k = 0; k <= n; ++k)
        t.push_back(cfg.end_time * k / n);
    if (law.kind == MotionKind::sway || law.kind == MotionKind::roll)
        for (double s = law.start; s <= cfg.end_time; s += law.period / 16)
            t.push_back(s);
    for (double s : law.series_t)
        if (s + law.start >= 0 && s + law.start <= cfg.end_time)
            t.push_back(s + law.start);
    std::sort(t.begin(), t.end());
    return t;
}

} // namespace

void check_motion_paths(const CaseConfig& cfg, int layers) {
    const int dim = cfg.dimension;
    Extent grid;
    double size = 0;
    for (int a = 0; a < dim; ++a) {
        const AxisExtent e = wall_extent(cfg, static_cast<std::size_t>(a));
        grid.lo[a] = e.lo;
        grid.hi[a] = e.hi;
        size = std::max(size, e.hi - e.lo);
    }
    const double slack = 1e-9 * size;
    for (const MovingObject& o : moving_objects(cfg, layers)) {
        const MotionLaw& law = cfg.motions[static_cast<std::size_t>(o.motion)];
        const RigidMotion motion = make_motion(law);
        for (double t : sample_times(cfg, law)) {
            const Extent now = moved(o.at_rest, motion.pose(t), dim);
            for (int a = 0; a < dim; ++a) {
                if (now.lo[a] < grid.lo[a] - slack || now.hi[a] > grid.hi[a] + slack)
                    throw CaseError(
                        cfg.source_file, o.key,
                        fmt::format("motion \"{}\" carries the object (wall layers included) "
                                    "out of the domain at t = {:.4g} s: along {} it spans [{:.4g}, "
                                    "{:.4g}] m, the domain and fixed walls [{:.4g}, {:.4g}] m; "
                                    "enlarge [domain] or reduce the motion",
                                    law.name, t, kAxisLetter[a], now.lo[a], now.hi[a], grid.lo[a],
                                    grid.hi[a]));
                // An obstacle may enter a walled face's layers (a flap's foot dips into the
                // bed as it turns), not pass out through them; an open face does not hold it.
                const auto walled = [&](char side) {
                    const std::string face{kAxisLetter[a], side};
                    return std::find(cfg.tank_faces.begin(), cfg.tank_faces.end(), face) !=
                           cfg.tank_faces.end();
                };
                const double depth = layers * cfg.dx;
                if (o.inside_tank && cfg.walls == WallModel::dummy &&
                    ((walled('-') &&
                      now.lo[a] < cfg.tank_lo[static_cast<std::size_t>(a)] - depth - slack) ||
                     (walled('+') &&
                      now.hi[a] > cfg.tank_hi[static_cast<std::size_t>(a)] + depth + slack)))
                    throw CaseError(
                        cfg.source_file, o.key,
                        fmt::format("motion \"{}\" moves the object out through the tank's wall "
                                    "layers at t = {:.4g} s: along {} it spans [{:.4g}, {:.4g}] m, "
                                    "the tank [{:.4g}, {:.4g}] m (a paddle's stroke must fit its "
                                    "travel)",
                                    law.name, t, kAxisLetter[a], now.lo[a], now.hi[a],
                                    cfg.tank_lo[static_cast<std::size_t>(a)],
                                    cfg.tank_hi[static_cast<std::size_t>(a)]));
            }
        }
    }
}

std::vector<CaseWarning> motion_warnings(const CaseConfig& cfg) {
    std::vector<CaseWarning> out;
    for (std::size_t i = 0; i < cfg.motions.size(); ++i) {
        const MotionLaw& law = cfg.motions[i];
        if (law.kind != MotionKind::piston && law.kind != MotionKind::flap)
            continue;
        const double k = wave_number(2 * std::numbers::pi / law.wave_period, law.depth, law.g);
        const double limit = breaking_steepness_limit(k, law.depth);
        if (law.wave_height > limit)
            out.push_back(
                {fmt::format("motions[{}].wave_height", i),
                 fmt::format("H = {:.4g} m is above the breaking limit {:.4g} m (Miche: "
                             "0.142 L tanh kh, L = {:.4g} m, kh = {:.3g}): the waves "
                             "will break at the paddle",
                             law.wave_height, limit, 2 * std::numbers::pi / k, k * law.depth)});
    }
    return out;
}

std::vector<std::string> motion_summary(const CaseConfig& cfg) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < cfg.motions.size(); ++i) {
        const MotionLaw& law = cfg.motions[i];
        const int m = static_cast<int>(i);
        std::vector<std::string> moves;
        if (cfg.tank_motion == m)
            moves.emplace_back("the tank");
        for (std::size_t b = 0; b < cfg.boxes.size(); ++b)
            if (cfg.boxes[b].motion == m)
                moves.push_back(fmt::format("walls.boxes[{}]", b));
        for (std::size_t k = 0; k < cfg.meshes.size(); ++k)
            if (cfg.meshes[k].motion == m)
                moves.push_back(fmt::format("walls.meshes[{}]", k));
        std::string what;
        switch (law.kind) {
        case MotionKind::sway:
            what = fmt::format("sway, period {} s", law.period);
            break;
        case MotionKind::roll:
            what = fmt::format("roll {} deg, period {} s", law.angle, law.period);
            break;
        case MotionKind::constant_velocity:
            what = "constant velocity";
            break;
        case MotionKind::constant_acceleration:
            what = "constant acceleration";
            break;
        case MotionKind::file:
            what = fmt::format("time series, {} rows to t = {} s", law.series_t.size(),
                               law.start + law.series_t.back());
            break;
        case MotionKind::piston:
        case MotionKind::flap: {
            const double k = wave_number(2 * std::numbers::pi / law.wave_period, law.depth, law.g);
            const double kh = k * law.depth;
            const bool piston = law.kind == MotionKind::piston;
            const double stroke = law.wave_height / (piston ? piston_height_to_stroke(kh)
                                                            : flap_height_to_stroke(kh));
            what = fmt::format("{} wave-maker, H = {} m, T = {} s, h = {} m: L = {:.4g} m, "
                               "kh = {:.3g}, stroke {:.4g} m{}{}",
                               piston ? "piston" : "flap", law.wave_height, law.wave_period,
                               law.depth, 2 * std::numbers::pi / k, kh, stroke,
                               piston ? "" : " at the still-water level",
                               law.second_order ? " + Madsen second order" : "");
            break;
        }
        case MotionKind::free_body: {
            std::optional<MassProperties> shape;
            for (const WallBox& b : cfg.boxes)
                if (b.motion == m)
                    shape = box_mass_properties({b.lo[0], b.lo[1], b.lo[2]},
                                                {b.hi[0], b.hi[1], b.hi[2]}, cfg.dimension);
            const MassProperties mp = body_mass_properties(law.body, shape);
            const char* constraint[] = {"free", "fixed", "hinge", "plane"};
            const int dim = cfg.dimension;
            const std::string inertia =
                dim == 2 ? fmt::format("{:.4g} kg m^2 per metre", mp.inertia(2, 2))
                         : fmt::format("diag [{:.4g}, {:.4g}, {:.4g}] kg m^2", mp.inertia(0, 0),
                                       mp.inertia(1, 1), mp.inertia(2, 2));
            what = fmt::format("free body, mass {:.4g} kg{}, centre of mass [{:.4g}], inertia "
                               "{}, constraint {}",
                               mp.mass, dim == 2 ? " per metre" : "",
                               fmt::join(mp.centre.data(), mp.centre.data() + dim, ", "), inertia,
                               constraint[static_cast<int>(law.body.constraint)]);
            break;
        }
        case MotionKind::piston_irregular:
            what = fmt::format("piston wave-maker, JONSWAP Hs = {} m, Tp = {} s, gamma = {}, {} "
                               "components, seed {}",
                               law.hs, law.tp, law.gamma, law.components, law.seed);
            break;
        }
        out.push_back(
            fmt::format("motion \"{}\": {}{}; moves {}", law.name, what,
                        law.start > 0 || law.ramp > 0
                            ? fmt::format(", from t = {} s, ramp {} s", law.start, law.ramp)
                            : std::string(),
                        fmt::join(moves, ", ")));
    }
    for (std::size_t z = 0; z < cfg.damping_zones.size(); ++z) {
        const DampingZoneConfig& d = cfg.damping_zones[z];
        const int dim = cfg.dimension;
        out.push_back(fmt::format("damping zone {}: from [{}] to [{}] m, sigma up to {} 1/s", z,
                                  fmt::join(d.start.begin(), d.start.begin() + dim, ", "),
                                  fmt::join(d.end.begin(), d.end.begin() + dim, ", "), d.strength));
    }
    return out;
}

} // namespace sluice
