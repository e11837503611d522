#pragma once
// A wall object's prescribed motion as the case states it ([[motions]] in a case file,
// docs/CASE_REFERENCE.md), and the rigid motion it makes. Pure data and numerics: the case
// reader fills a MotionLaw (a time series' rows included), make_motion turns it into the
// poses of motion/rigid_motion.hpp.
#include "sluice/motion/rigid_motion.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sluice {

enum class MotionKind {
    sway,                  // translation: amplitude sin(2 pi t / period + phase)
    roll,                  // rotation about centre/axis: angle sin(2 pi t / period + phase)
    constant_velocity,     // translation at `velocity`
    constant_acceleration, // translation at `acceleration` from rest
    file,                  // translation and angle from a time series
    piston,                // piston wave-maker, regular waves (Biesel; optional 2nd order)
    flap,                  // flap wave-maker hinged at `centre`, regular waves
    piston_irregular,      // piston wave-maker, JONSWAP sea
    free_body,             // not prescribed: the fluid's force and gravity move the object
                           // (motion/rigid_body.hpp; solver/wall_motion.hpp integrates it)
};

// What a free body may do (motion/rigid_body.hpp).
enum class BodyConstraint {
    free,  // every degree of freedom (2-D: x, y and the rotation about z)
    fixed, // nothing: the body stays where it is (its load is still computed)
    hinge, // rotation only, about `axis` through `centre` (2-D: about z)
    plane, // 3-D: translation in the plane normal to `axis`, rotation about `axis`
};

// A free body's mass and how it may move (MotionKind::free_body). Its initial velocity is the
// law's `velocity`, its hinge point `centre`, its hinge axis or plane normal `axis`; it is held
// at rest until `start`.
struct BodyLaw {
    using V3 = std::array<double, 3>;
    double density = 0; // [kg/m^3]: the mass from the shape's volume; 0 when `mass` is given
    double mass = 0;    // [kg; 2-D: kg per metre of width]; 0 when `density` is given
    std::optional<V3> centre_of_mass; // [m] at t = 0; default: the shape's centroid
    // About the centre of mass, world axes at t = 0, row-major [kg m^2; 2-D: kg m^2 per metre,
    // only the zz entry is used]; default: the shape's, at uniform density.
    std::optional<std::array<double, 9>> inertia;
    V3 angular_velocity{}; // [rad/s] at release (2-D: z only)
    BodyConstraint constraint = BodyConstraint::free;
    // Contact with walls and other bodies (contact/contact_world.hpp): Coulomb friction and
    // restitution coefficients (a pair of surfaces takes the product of the two; walls are 1).
    double friction = 0.5, restitution = 0;

    bool operator==(const BodyLaw&) const = default;
};

struct MotionLaw {
    std::string name;
    MotionKind kind = MotionKind::sway;
    double start = 0; // [s] nothing moves before
    double ramp = 0;  // [s] smooth ramp-in after start
    using V3 = std::array<double, 3>;
    V3 amplitude{};                     // sway [m]
    double angle = 0;                   // roll amplitude [deg]
    double period = 0;                  // sway, roll [s]
    double phase = 0;                   // sway, roll [deg]
    V3 velocity{};                      // constant_velocity [m/s]
    V3 acceleration{};                  // constant_acceleration [m/s^2]
    V3 centre{};                        // rotation centre (roll, file, flap hinge) [m]
    V3 axis{0, 0, 1};                   // rotation axis (unit; z in 2-D)
    V3 direction{1, 0, 0};              // piston stroke direction (unit)
    double wave_height = 0;             // piston, flap [m]
    double wave_period = 0;             // piston, flap [s]
    double depth = 0;                   // still-water depth at the paddle [m]
    bool second_order = false;          // piston: Madsen's (1971) second-order stroke
    double hs = 0, tp = 0, gamma = 3.3; // piston_irregular: JONSWAP sea
    int components = 64;
    std::uint64_t seed = 1;
    double g = 9.81; // |gravity| [m/s^2]: the wave-maker's dispersion relation
    // file: rows of time [s], displacement [m] (x, y, z) and angle [deg] about centre/axis,
    // taken relative to their values at t = 0 (interpolated by a modified Akima spline).
    std::vector<double> series_t;
    std::vector<V3> series_d;
    std::vector<double> series_angle;
    BodyLaw body; // free_body

    bool operator==(const MotionLaw&) const = default;
};

// Whether a free body of this law takes part in contact (contact/contact_world.hpp): a box
// (`is_box`) that moves freely (every 2-D body), or in a plane normal to a world axis.
bool body_in_contact(const MotionLaw& law, bool is_box);

// The rigid motion of a law (a free body's: at rest, its motion is integrated by the solver).
RigidMotion make_motion(const MotionLaw& law);

} // namespace sluice
