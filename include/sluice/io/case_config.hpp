#pragma once
// Everything a case file says, after validation. Dimension-agnostic: 3-component arrays whose
// last component is ignored (and must be absent from the file) in 2-D.
// Every field is documented for users in docs/CASE_REFERENCE.md; keep the two in step.
#include "sluice/geometry/surface_index.hpp"
#include "sluice/motion/motion_law.hpp"
#include "sluice/physics/options.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sluice {

// What the balancer equalises between ranks: measured task time, or particle counts.
enum class BalanceCost { time, particles };
// How ranks split the curve at the start: equal particle counts, or equal key ranges
// (naive; with most of the domain empty it is badly unbalanced, to exercise the balancer).
enum class InitialDecomposition { balanced, key_range };

using Triple = std::array<double, 3>;

// KernelType, EosType, DensityDiffusion, NeighbourPolicy and NeighbourSelection, the options
// that physics formulas take, are in physics/options.hpp.

// How a step advances the flow: weakly compressible SPH (explicit, EOS pressure) or the
// incompressible projection scheme of Park et al. (2014) (implicit pressure Poisson equation with
// WMLS operators; docs/PROJECTION.md).
enum class Scheme { wcsph, projection };
enum class PressureSolver { bicgstab, sor };
// Preconditioner of the projection scheme's BiCGSTAB (docs/PROJECTION.md, "Preconditioner"):
// the row scaling alone, or block-Jacobi with an LU or ILU(0) factorisation per cell group.
enum class PressurePreconditioner { jacobi, block_lu, block_ilu0, two_level };
// Gradient of the projection scheme's velocity correction (docs/PROJECTION.md, P7).
enum class CorrectionGradient { second_order, first_order };
// Reference pressure of P7's stabilised gradient (docs/PROJECTION.md, P7).
enum class CorrectionReference { minimum, hydrostatic };
// Weight of the number density in the density-deviation source term (docs/PROJECTION.md, P3).
enum class DeviationWeight { pnu_mps, smooth };
// Direction of the projection scheme's wall collision (docs/PROJECTION.md, "Wall collision").
enum class WallCollision { line_of_centres, wall_normal };
// What becomes of a fluid particle that leaves the domain (domain.particle_exit).
enum class ParticleExit { stop, remove };
enum class DensityScheme { summation, continuity };
// How WCSPH dissipates: artificial viscosity + delta-SPH, or a Riemann solver per pair.
enum class Dissipation { artificial, riemann };
enum class WallModel { none, reflective, dummy };
// Initial velocity (and matching pressure) over a block: uniform, the Taylor-Green vortex,
// rigid rotation about the block centre (rotating square patch, Colagrossi 2005), or the
// straining flow of Monaghan's (1994) elliptical drop.
enum class VelocityProfile { uniform, taylor_green, rotating, strain };
// Which lattice points of a block's box are filled: all of them, or those inside the ellipse
// (ellipsoid in 3-D) inscribed in the box.
enum class BlockShape { box, ellipse, mesh };
// motion: a moving object's displacement, angle and velocities (no particles read).
enum class ProbeType { pressure, water_level, surge_front, force, motion };
// What an area sensor reads: the fluid's normal force on the wall under its face per unit area
// (wall_force_sensor), the pressure interpolated on the face (wall_pressure_sensor; under the
// projection scheme plus the traction of its wall collisions), or that traction alone (the
// projection scheme's collisions: how much of the interpolated reading is the wall model's).
// A force probe reads likewise the pair forces, the interpolated load, or its collisions alone.
enum class SensorReading { force, interpolated, collisions };

struct WallMesh;

struct FluidBlock {
    Triple lo{}, hi{}; // [m] axis-aligned box filled on a lattice of spacing dx
    BlockShape shape = BlockShape::box;
    Triple velocity{}; // [m/s] initial velocity (uniform profile)
    VelocityProfile profile = VelocityProfile::uniform;
    double amplitude = 0;        // [m/s] velocity scale of the Taylor-Green profile
    double angular_velocity = 0; // [rad/s] rotating profile, counter-clockwise positive (2-D)
    double strain_rate = 0;      // [1/s] strain profile: v = (-A0 x, A0 y) about the centre
    bool hydrostatic = true;     // initial density/pressure from rho0*|g|*(depth) with the EOS
    // shape = mesh: the closed shape filled (its role unused), lo/hi its bounding box.
    std::shared_ptr<const WallMesh> mesh;

    bool operator==(const FluidBlock& o) const;
};

// A planar reflective wall: particles are kept on the side the normal points to.
struct WallPlane {
    Triple point{};
    Triple normal{};

    bool operator==(const WallPlane&) const = default;
};

// A solid obstacle: an axis-aligned box of fixed dummy wall particles inside the tank.
struct WallBox {
    Triple lo{}, hi{}; // [m] lattice sites of spacing dx centred in the box
    int motion = -1;   // CaseConfig::motions index; -1 = fixed

    bool operator==(const WallBox&) const = default;
};

// What a wall mesh is: a closed solid (its inside is wall) or a surface (wall behind it).
enum class MeshRole { solid, surface };

// A wall shape read from a file ([[walls.meshes]]): the placed shape and where it came from.
struct WallMesh {
    std::string file; // as the case gives it
    std::string path; // resolved against the case file's folder
    MeshRole role = MeshRole::solid;
    double scale = 1;
    Triple rotation{}; // degrees about x, y, z (2-D: only z)
    Triple translation{};
    bool flip_normals = false;
    double section_z = 0; // 2-D case from a triangle mesh: the cutting plane
    std::string digest;   // SHA-256 of the file's bytes: part of the case fingerprint
    int motion = -1;      // CaseConfig::motions index; -1 = fixed
    // The placed shape with its queries, built by the case reader (shared: a CaseConfig is
    // copied freely, the shape is read-only).
    std::shared_ptr<const SurfaceIndex> shape;

    bool operator==(const WallMesh& o) const {
        return file == o.file && path == o.path && role == o.role && scale == o.scale &&
               rotation == o.rotation && translation == o.translation &&
               flip_normals == o.flip_normals && section_z == o.section_z && digest == o.digest &&
               motion == o.motion;
    }
};

inline bool FluidBlock::operator==(const FluidBlock& o) const {
    return lo == o.lo && hi == o.hi && shape == o.shape && velocity == o.velocity &&
           profile == o.profile && amplitude == o.amplitude &&
           angular_velocity == o.angular_velocity && strain_rate == o.strain_rate &&
           hydrostatic == o.hydrostatic && (mesh == nullptr) == (o.mesh == nullptr) &&
           (mesh == nullptr || *mesh == *o.mesh);
}

// A wall surface a probe refers to: a tank face or an obstacle box (or one face of it).
struct ProbeWall {
    int face_axis = -1;     // tank face "x+" etc.: axis (0, 1, 2); -1 = none
    bool face_high = false; // the "+" face
    int box = -1;           // walls.boxes index; -1 = none
    int mesh = -1;          // walls.meshes index; -1 = none

    bool operator==(const ProbeWall&) const = default;
};

struct ProbeConfig {
    std::string name; // file name stem: probes/<name>.csv
    ProbeType type = ProbeType::pressure;
    Triple position{};       // pressure probe point [m]; area sensor: its centre, on the wall
    double x = 0;            // water level: x position [m]
    std::optional<double> y; // water level, 3-D: y position of a point gauge [m]
    double interval = 0;     // [s] sampling interval; 0 = every output interval
    bool every_step = false; // interval = "every_step": after every time step
    // force: the wall region (a tank face or a box), optionally cut to [lo, hi].
    // pressure with a diameter: the wall the sensor sits on (given or found from position).
    ProbeWall wall;
    std::optional<Triple> lo, hi;       // force: part of the region [m]
    std::optional<Triple> moment_about; // force: moment about this point [m]
    double diameter = 0;                // pressure: sensor diameter [m]; 0 = point probe
    int sensor_axis = -1;               // pressure with a diameter: the wall's normal axis
    double sensor_surface = 0;          // ... and the surface's coordinate on it [m]
    int sensor_into_wall = 0;           // ... and the wall's side along the axis (+1 or -1)
    // A sensor on a mesh (wall.mesh >= 0; sensor_axis stays -1): its centre on the surface and
    // the unit normal into the wall there.
    Triple sensor_centre{}, sensor_normal{};
    SensorReading reading = SensorReading::force; // pressure with a diameter
    int direction_axis = 0;                       // surge front: axis of "+x", "-y", ...
    bool direction_negative = false;              // ... and its sign
    double min_thickness = 0;                     // surge front [m]; 0 = 2 dx
    // The CaseConfig::motions index the probe moves with (-1 = fixed): its position, region and
    // moment point are given where the object is at t = 0; a gauge measures in its frame.
    int frame = -1;
    // A motion probe of a free body: it also records the orientation (3-D), the angular
    // velocity and the fluid's load on the body.
    bool body = false;

    bool operator==(const ProbeConfig&) const = default;
};

// A damping zone ([[damping_zones]], physics/damping_zone.hpp): the velocity relaxes to rest,
// at a rate ramped quadratically from 0 at `start` to `strength` at `end` and beyond.
struct DampingZoneConfig {
    Triple start{}, end{}; // [m]
    double strength = 10;  // [1/s]

    bool operator==(const DampingZoneConfig&) const = default;
};

// A NeighbourSelection per operator; read by operators that take a neighbour set (WMLS gradient and
// Laplacian, free-surface detection). The WCSPH kernel sums always use the radius set.
struct OperatorNeighbours {
    NeighbourSelection gradient, laplacian, free_surface;

    bool operator==(const OperatorNeighbours&) const = default;
};

// [projection]: the pressure Poisson solve of the projection scheme (docs/PROJECTION.md).
struct ProjectionSettings {
    PressureSolver solver = PressureSolver::bicgstab;
    double tolerance = 1e-8; // relative residual of the row-scaled system
    int max_iterations = 1000;
    PressurePreconditioner preconditioner = PressurePreconditioner::two_level;
    double relaxation = 1.5; // SOR relaxation factor (Park et al. 2014: 1.5)
    double gamma = 0.01; // relaxation of the density-deviation source term (Park et al. 2014: <= 1)
    double surface_diameter_over_dx = 2.1; // Dilts arc circle (Park et al. 2014: 2.1 l0)
    double surface_density_ratio = 0;      // beta: also surface when n < beta n0 (0 = off)
    CorrectionGradient correction_gradient = CorrectionGradient::second_order;
    CorrectionReference correction_reference = CorrectionReference::hydrostatic;
    DeviationWeight deviation_weight = DeviationWeight::smooth;
    WallCollision wall_collision = WallCollision::wall_normal;
    bool fluid_collision = true; // Koshizuka-type collision of fluid pairs closer than 0.8 dx
    double shifting = 0;         // Fickian shifting, D = A h^2 per step (0 = off; Lind et al. 2012)

    bool operator==(const ProjectionSettings&) const = default;
};

struct CaseConfig {
    std::string source_file; // path of the TOML file (for messages)
    std::string name;        // case name; default: file stem
    std::string description;
    int dimension = 2;

    // [domain]: the box particles may occupy; periodic axes wrap.
    Triple domain_lo{}, domain_hi{};
    std::array<bool, 3> periodic{false, false, false};
    // A fluid particle outside the box (a non-periodic axis): the run stops (exit code 3), or
    // the particle is removed and counted (spray thrown over an open top or a wall).
    ParticleExit particle_exit = ParticleExit::stop;

    // [fluid]
    double rho0 = 1000;          // reference density [kg/m^3]
    double viscosity = 0;        // dynamic viscosity mu [Pa s]
    double sound_speed = 0;      // artificial speed of sound c0 [m/s]
    Triple gravity{0, -9.81, 0}; // body acceleration [m/s^2]
    EosType eos = EosType::linear;
    double gamma = 7;               // Tait exponent
    double background_pressure = 0; // [Pa] added to the EOS

    // [particles]
    double dx = 0; // lattice spacing [m]
    // Each fluid particle starts displaced from its lattice site by up to +-jitter dx / 2 per
    // axis, the same displacement on every rank and in every run (a hash of its id): breaks
    // the exact symmetry of the lattice (see docs/CASE_REFERENCE.md, [particles]).
    double jitter = 0;
    std::vector<FluidBlock> blocks;

    // [numerics]
    Scheme scheme = Scheme::wcsph;
    // Wendland C2 with h = 1.5 dx and alpha = 0.02 by default: the settings of
    // docs/RECOMMENDED_PRACTICE.md for free-surface flow (perf/defaults/README.md measures
    // them against the quintic kernel with h = dx and no artificial viscosity).
    KernelType kernel = KernelType::wendland_c2;
    double h_over_dx = 1.5; // smoothing length h = h_over_dx * dx
    DensityScheme density = DensityScheme::continuity;
    double delta_sph = 0.1; // delta-SPH diffusion coefficient (0 = off; continuity only)
    DensityDiffusion density_diffusion = DensityDiffusion::antuono;
    double artificial_viscosity = 0.02; // Monaghan alpha (0 = off; WCSPH only)
    // riemann: Zhang, Hu & Adams (2017) low-dissipation Riemann solver in the momentum and
    // continuity equations (physics/riemann.hpp); replaces artificial viscosity and delta-SPH.
    Dissipation dissipation = Dissipation::artificial;
    // Artificial viscosity also across fluid-wall pairs (with the walls' no-slip velocity).
    // Off by default: there it acts as a friction on flow along a wall, which slows the lowest
    // layer of a surge front, blunts its nose and doubles the corner impact pressure
    // (docs/IMPACT_LOADS.md).
    bool wall_artificial_viscosity = false;
    double shifting = 0; // particle-shifting coefficient A (0 = off; 4 = Sun et al. 2017)
    // Acoustic damper alpha: bulk viscosity nu_a = alpha h c0 added to the pressure as
    // -rho nu_a div u (0 = off; physics/acoustic_damper.hpp).
    double acoustic_damper = 0;
    double cfl = 0.25;              // acoustic CFL number: dt <= cfl*h/(c0 + |v|max)
    double viscous_cfl = 0.125;     // dt <= viscous_cfl * h^2 / nu
    double force_cfl = 0.25;        // dt <= force_cfl * sqrt(h/|a|max)
    std::optional<double> fixed_dt; // [s]; refused if above the stability limit
    // Verlet skin in units of dx: neighbour lists hold pairs within support + skin and are
    // rebuilt (with the particle sort) only when a particle has moved more than skin/2.
    double neighbour_skin = 0.5;

    // [projection] (scheme = projection only)
    ProjectionSettings projection;

    // [walls]
    WallModel walls = WallModel::none;
    Triple tank_lo{}, tank_hi{};         // tank box: walls sit on its faces
    std::vector<std::string> tank_faces; // which faces carry walls: "x-","x+","y-","y+","z-","z+"
    std::vector<WallPlane> planes;       // extra reflective planes
    std::vector<WallBox> boxes;          // dummy walls only: solid obstacles
    std::vector<WallMesh> meshes;        // dummy walls only: shapes from mesh or vertex files
    // [[motions]]: prescribed motions (motion/motion_law.hpp); the tank's, a box's or a mesh's
    // `motion` is an index into it (-1 = fixed).
    std::vector<MotionLaw> motions;
    std::vector<std::string> motion_digests; // SHA-256 of each motion's file ("" without)
    int tank_motion = -1;
    double restitution = 1.0; // reflective walls: normal velocity kept after a bounce
    bool no_slip = true;      // dummy walls: no-slip (Adami) or free-slip

    // [[damping_zones]]
    std::vector<DampingZoneConfig> damping_zones;

    // [time]
    double end_time = 0;        // [s]
    double output_interval = 0; // [s] snapshots and probe samples; 0 = only the last state

    // [output]
    bool snapshots = true;
    std::vector<std::string> fields{"position", "velocity", "density", "pressure", "id", "kind"};

    // [[probes]]
    std::vector<ProbeConfig> probes;

    // [neighbours.<operator>]
    OperatorNeighbours neighbours;

    // [runtime]
    int particles_per_group = 2000; // target cost of one cell group, in particles
    // Rank balancing: rebalance when the slowest rank's busy time exceeds the mean
    // by this fraction over a window of steps, and/or every N steps (0 = only on imbalance).
    double rebalance_threshold = 0.10;
    int rebalance_window = 10;
    int rebalance_every = 0;
    BalanceCost balance_cost = BalanceCost::time;
    InitialDecomposition initial_decomposition = InitialDecomposition::balanced;
    // On several ranks, start the next step's graph before the step's agreement has arrived
    // (docs/ARCHITECTURE.md, "Time step"). Off by default: byte-identical either way, and no
    // speed-up has been measured yet (perf/strong_scaling/README.md, 2026-11-26).
    bool run_ahead = false;

    // [checkpoint]: <results>/checkpoint.h5 every N steps and/or every M minutes of wall time
    // (0 = off), besides the one written when a run is asked to stop.
    int checkpoint_every_steps = 0;
    double checkpoint_every_minutes = 30;

    // [limits]: a fluid particle outside these bounds stops the run (blow-up detection).
    // Defaults (set by the reader): max_speed = sound_speed, density in [0.01, 2] rho0.
    double max_speed = 0;   // [m/s]
    double min_density = 0; // [kg/m^3]
    double max_density = 0; // [kg/m^3]

    // SHA-256 (hex) of the case content that determines results: the whole file after --set,
    // except time.end_time, case.description and the [checkpoint], [limits] and [runtime]
    // tables. A checkpoint continues only a case with the same fingerprint.
    std::string fingerprint;

    bool operator==(const CaseConfig&) const = default;
};

} // namespace sluice
