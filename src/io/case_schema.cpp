// The keys of every table of a case file (case_schema.hpp; docs/CASE_REFERENCE.md); their
// ranges' text and checks are in case_schema_range.cpp.
#include "case_schema.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace sluice::case_file {
namespace {

// Keys of a neighbour-selection table; one copy per operator (neighbours.<operator>).
constexpr std::string_view kOperator = "neighbours.<operator>";
constexpr std::string_view kOperators[] = {"neighbours.gradient", "neighbours.laplacian",
                                           "neighbours.free_surface"};

// clang-format off
const KeySpec kKeys[] = {
    // The tables of the file.
    {"", "case", "table", "", "required", {}, Applies::any, "", "Name, description and dimension."},
    {"", "domain", "table", "", "required", {}, Applies::any, "", "The box the fluid may occupy."},
    {"", "fluid", "table", "", "required", {}, Applies::any, "", "Fluid properties."},
    {"", "particles", "table", "", "required", {}, Applies::any, "", "Lattice spacing."},
    {"", "blocks", "array of tables", "", "required", {}, Applies::any, "", "Fluid blocks (at least one)."},
    {"", "numerics", "table", "", "", {}, Applies::any, "", "Scheme, kernel and time-step limits."},
    {"", "walls", "table", "", "", {}, Applies::any, "", "Tank walls, planes and obstacles."},
    {"", "motions", "array of tables", "", "", {}, Applies::wcsph, "walls.model = \"dummy\"", "Prescribed motions of wall objects (the tank, a box, a mesh): sway, roll, constant velocity or acceleration, a time series, wave-makers."},
    {"", "damping_zones", "array of tables", "", "", {}, Applies::wcsph, "", "Sponge layers that absorb waves (the far end of a flume)."},
    {"", "time", "table", "", "required", {}, Applies::any, "", "End time and output interval."},
    {"", "output", "table", "", "", {}, Applies::any, "", "Snapshot contents."},
    {"", "probes", "array of tables", "", "", {}, Applies::any, "", "Time series."},
    {"", "runtime", "table", "", "", {}, Applies::any, "", "Performance settings (no effect on results)."},
    {"", "neighbours", "table", "", "", {}, Applies::projection, "", "Neighbour selection per operator."},
    {"", "checkpoint", "table", "", "", {}, Applies::any, "", "When to save the state."},
    {"", "limits", "table", "", "", {}, Applies::any, "", "Blow-up detection."},
    {"", "projection", "table", "", "", {}, Applies::projection, "", "Pressure solve of the projection scheme."},
    {"neighbours", "gradient", "table", "", "", {}, Applies::projection, "", "Neighbours of the WMLS gradient."},
    {"neighbours", "laplacian", "table", "", "", {}, Applies::projection, "", "Neighbours of the WMLS Laplacian."},
    {"neighbours", "free_surface", "table", "", "", {}, Applies::projection, "", "Neighbours of free-surface detection."},
    // Their keys.
    {"case", "name", "string", "", "file name without extension", words("at most 200 bytes; no /, \\, control characters, . or .."), Applies::any, "",
     "Case name; the default results folder is results/<name>."},
    {"case", "description", "string", "", "\"\"", {}, Applies::any, "",
     "Free text, copied to summary.json."},
    {"case", "dimension", "integer", "", "required", closed(2, 3), Applies::any, "",
     "2 or 3."},
    {"domain", "lo", "vector", "m", "required", closed(-1e6, 1e6).implausible_beyond(), Applies::any, "",
     "Lower corner."},
    {"domain", "hi", "vector", "m", "required", closed(-1e6, 1e6).implausible_beyond().and_words("above lo"), Applies::any, "",
     "Upper corner; above lo on every axis."},
    {"domain", "periodic", "array of dimension booleans", "", "all false", {}, Applies::any, "",
     "Axes that wrap around ([true, false]: periodic in x)."},
    {"domain", "particle_exit", "string", "", "\"stop\"", one_of({"stop", "remove"}), Applies::any, "",
     "A fluid particle leaving the domain: \"stop\" the run (exit code 3, last good snapshot) or \"remove\" it and count it (summary.json, the log)."},
    {"fluid", "rho0", "number", "kg/m³", "required", open_closed(0, 1e6).implausible_beyond(), Applies::any, "",
     "Reference density; > 0."},
    {"fluid", "viscosity", "number", "Pa·s", "required", closed(0, 1e6).implausible_beyond(), Applies::any, "",
     "Dynamic viscosity μ; ≥ 0 (0 = inviscid)."},
    {"fluid", "sound_speed", "number", "m/s", "required", open_closed(0, 1e6).implausible_beyond(), Applies::any, "",
     "Artificial speed of sound c₀; > 0."},
    {"fluid", "gravity", "vector", "m/s²", "[0, -9.81] in 2-D, [0, 0, -9.81] in 3-D", closed(-1e6, 1e6).implausible_beyond(), Applies::any, "",
     "Body acceleration (down the last axis by default)."},
    {"fluid", "eos", "string", "", "\"linear\"", one_of({"linear", "tait"}), Applies::wcsph, "",
     "Equation of state: \"linear\" p = c₀²(ρ − ρ₀) + p_b, or \"tait\" p = ρ₀c₀²/γ ((ρ/ρ₀)^γ − 1) + p_b."},
    {"fluid", "gamma", "number", "", "7", open_closed(0, 20), Applies::wcsph, "",
     "Tait exponent γ; in (0, 20]."},
    {"fluid", "background_pressure", "number", "Pa", "0", closed(0, 1e12).implausible_beyond(), Applies::any, "",
     "p_b added by the equation of state; ≥ 0."},
    {"particles", "dx", "number", "m", "required", at_least(1e-9), Applies::any, "",
     "Lattice spacing of the initial particles; ≥ 10⁻⁹."},
    {"particles", "jitter", "number", "dx", "0", closed(0, 0.1), Applies::any, "",
     "Each fluid particle starts displaced from its lattice site by up to ±jitter·dx/2 along each axis: a fixed pseudo-random offset computed from its id, so every rank, thread count and run starts from the same positions."},
    {"blocks", "lo", "vector", "m", "required unless shape = \"mesh\"", {}, Applies::any, "",
     "Lower corner."},
    {"blocks", "hi", "vector", "m", "required unless shape = \"mesh\"", words("above lo"), Applies::any, "",
     "Upper corner; above lo on every axis."},
    {"blocks", "shape", "string", "", "\"box\"", one_of({"box", "ellipse", "mesh"}), Applies::any, "",
     "\"box\" (every lattice site of the box), \"ellipse\": only the sites whose centres lie inside the ellipse inscribed in the box (an ellipsoid in 3-D; a circle or ball when the box is a square or cube), or \"mesh\": the sites inside a closed shape from a file (keys file, scale, rotation, translation, flip_normals, section_z as for [[walls.meshes]]; lo and hi, each optional then, cut it: the part of the shape inside them is filled, e.g. a container's volume up to a water level)."},
    {"blocks", "file", "string", "", "required with shape = \"mesh\"", words("a closed shape's .stl, .obj, .ply or .off file; in 2-D also a vertex file"), Applies::any, "shape = \"mesh\"",
     "The closed shape to fill, relative to the case file's folder (as walls.meshes.file); its normals point out."},
    {"blocks", "scale", "number", "", "1", open_closed(0, 1e6), Applies::any, "shape = \"mesh\"",
     "As walls.meshes.scale."},
    {"blocks", "rotation", "vector (3-D) or number (2-D)", "degrees", "0", closed(-360, 360), Applies::any, "shape = \"mesh\"",
     "As walls.meshes.rotation."},
    {"blocks", "translation", "vector", "m", "zeros", closed(-1e6, 1e6).implausible_beyond(), Applies::any, "shape = \"mesh\"",
     "As walls.meshes.translation."},
    {"blocks", "flip_normals", "boolean", "", "false", {}, Applies::any, "shape = \"mesh\"",
     "As walls.meshes.flip_normals."},
    {"blocks", "section_z", "number", "m", "0", closed(-1e6, 1e6), Applies::any, "shape = \"mesh\"",
     "As walls.meshes.section_z."},
    {"blocks", "velocity", "vector", "m/s", "zeros", closed(-1e5, 1e5).implausible_beyond(), Applies::any, "",
     "Initial velocity (uniform profile; added to any other profile)."},
    {"blocks", "profile", "string", "", "\"uniform\"", one_of({"uniform", "taylor_green", "rotating", "strain"}), Applies::any, "",
     "Initial velocity field and its pressure: \"uniform\", \"taylor_green\" (Taylor–Green vortex of speed amplitude over the block), \"rotating\" or \"strain\" (below)."},
    {"blocks", "amplitude", "number", "m/s", "0", closed(-1e5, 1e5).implausible_beyond(), Applies::any, "",
     "Velocity scale of the taylor_green profile."},
    {"blocks", "angular_velocity", "number", "rad/s", "required with rotating (not allowed otherwise)", {}, Applies::any, "profile = \"rotating\"",
     "ω of the rotating profile, counter-clockwise positive."},
    {"blocks", "strain_rate", "number", "1/s", "required with strain (not allowed otherwise)", {}, Applies::any, "profile = \"strain\"",
     "A₀ of the strain profile."},
    {"blocks", "hydrostatic", "boolean", "", "true", {}, Applies::any, "",
     "Start with the hydrostatic pressure ρ₀·|g|·(depth below the block's top) and the matching density from the EOS, instead of p = p_b. A mesh block's top is its bounding box's: right for a shape with a flat top (a reservoir's water)."},
    {"numerics", "scheme", "string", "", "\"wcsph\"", one_of({"wcsph", "projection"}), Applies::any, "",
     "\"wcsph\" (weakly compressible SPH: EOS pressure, explicit) or \"projection\" (incompressible projection of Park et al. (2014): WMLS operators, implicit pressure Poisson equation; settings in [projection], algorithm in docs/PROJECTION.md)."},
    {"numerics", "kernel", "string", "", "\"wendland_c2\"", one_of({"quintic", "wendland_c2", "cubic_spline"}), Applies::any, "",
     "Smoothing kernel: \"wendland_c2\" (support 2h; free-surface flow), \"quintic\" (3h; 2–3× smaller errors in resolved viscous flows such as Poiseuille and Taylor–Green), \"cubic_spline\" (2h). docs/RECOMMENDED_PRACTICE.md, \"Kernel and h/dx\"."},
    {"numerics", "h_over_dx", "number", "", "1.5", closed(0.5, 4), Applies::any, "",
     "Smoothing length h = h_over_dx·dx; in [0.5, 4]. Left out, each kernel's support is 3 dx: 1.5 for \"wendland_c2\" and \"cubic_spline\", 1.0 for \"quintic\"."},
    {"numerics", "density", "string", "", "\"continuity\"", one_of({"continuity", "summation"}), Applies::wcsph, "",
     "\"continuity\" (density integrated in time) or \"summation\" (density from a kernel sum)."},
    {"numerics", "delta_sph", "number", "", "0.1", closed(0, 1), Applies::wcsph, "",
     "δ-SPH density diffusion coefficient; in [0, 1], 0 = off."},
    {"numerics", "density_diffusion", "string", "", "\"antuono\"", one_of({"antuono", "fourtakas"}), Applies::wcsph, "",
     "Form of the δ-SPH term: \"antuono\" (Antuono et al."},
    {"numerics", "artificial_viscosity", "number", "", "0.02", closed(0, 10), Applies::wcsph, "",
     "Monaghan α; in [0, 10], 0 = off. 0.02 sets still water's noise floor and keeps impact peaks bounded; a resolved viscous flow wants 0 (docs/RECOMMENDED_PRACTICE.md). 0 with dissipation = \"riemann\"."},
    {"numerics", "wall_artificial_viscosity", "boolean", "", "false", {}, Applies::wcsph, "walls.model = \"dummy\"",
     "Let the artificial viscosity act across fluid–wall pairs too (with the wall particles' boundary velocity: the no-slip mirror or, free-slip, the fluid's)."},
    {"numerics", "dissipation", "string", "", "\"artificial\"", one_of({"artificial", "riemann"}), Applies::wcsph, "",
     "WCSPH only."},
    {"numerics", "shifting", "number", "", "0", closed(0, 20), Applies::wcsph, "",
     "Particle-shifting coefficient A (0 = off); displacement per step −A·U·h·dt·Σ(1 + 0.2(W/W(dx))⁴)∇W V with U the largest fluid speed (Sun et al."},
    {"numerics", "acoustic_damper", "number", "", "0", closed(0, 1), Applies::wcsph, "",
     "Acoustic damper α (0 = off): a bulk viscosity ν_a = α·h·c₀ whose stress enters the pressure, p = p_EOS − ρ·ν_a·∇·u, with the SPH divergence of the velocity at the start of the step over fluid and wall partners at rest (after Sun, Pilloton, Antuono & Colagrossi 2023)."},
    {"numerics", "cfl", "number", "", "0.25", open_closed(0, 1), Applies::any, "",
     "Acoustic limit dt ≤ cfl·h/(c₀ + |v|max); in (0, 1]."},
    {"numerics", "viscous_cfl", "number", "", "0.125", open_closed(0, 1), Applies::any, "",
     "Viscous limit dt ≤ viscous_cfl·h²/ν; in (0, 1]."},
    {"numerics", "force_cfl", "number", "", "0.25", open_closed(0, 1), Applies::any, "",
     "Force limit dt ≤ force_cfl·√(h/|a|max); in (0, 1]."},
    {"numerics", "dt", "number", "s", "adaptive", above(0).and_words("at most the stability limit"), Applies::any, "",
     "Fixed time step; > 0."},
    {"numerics", "neighbour_skin", "number", "dx", "0.5", closed(0, 2), Applies::wcsph, "",
     "Verlet skin: neighbour lists hold every pair within support + skin and are rebuilt, together with the particle sort, migration between ranks and regrouping, only when some particle has moved more than skin/2 since the last rebuild (or after a checkpoint)."},
    {"projection", "solver", "string", "", "\"bicgstab\"", one_of({"bicgstab", "sor"}), Applies::projection, "",
     "\"bicgstab\" (BiCGSTAB with Jacobi preconditioning; the WMLS Laplacian is not symmetric) or \"sor\" (Park et al.'s (2014) successive over-relaxation; Gauss–Seidel inside a cell group, Jacobi across groups and ranks)."},
    {"projection", "tolerance", "number", "", "1e-8", open(0, 1), Applies::projection, "",
     "Stop when ‖b̂ − Âp‖₂ ≤ tolerance·‖b̂‖₂ for the row-scaled system (units of pressure; docs/PROJECTION.md, P4); in (0, 1)."},
    {"projection", "max_iterations", "integer", "", "1000", closed(1, 1000000), Applies::projection, "",
     "BiCGSTAB iterations (two operator products each) or SOR sweeps per step; a solve that has not converged by then stops the run with exit code 3 and a message naming the solver, the residual and these keys."},
    {"projection", "preconditioner", "string", "", "\"two_level\"", one_of({"jacobi", "block_ilu0", "block_lu", "two_level"}), Applies::projection, "projection.solver = \"bicgstab\"",
     "Preconditioner of BiCGSTAB: \"jacobi\" (the row scaling alone), \"block_ilu0\" (block-Jacobi: ILU(0) of each cell group's diagonal block, couplings to other groups and ranks dropped), \"block_lu\" (the same blocks, exact sparse LU) or \"two_level\" (a coarse-grid correction on aggregates of particles, one per cell of the cell grid, with the Galerkin operator solved exactly on every rank, then the row scaling; without a free surface the row scaling alone); docs/PROJECTION.md, \"Preconditioner\"; only with solver = \"bicgstab\"."},
    {"projection", "relaxation", "number", "", "1.5", open(0, 2), Applies::projection, "projection.solver = \"sor\"",
     "SOR relaxation factor (Park et al. 2014: 1.5); in (0, 2); only with solver = \"sor\"."},
    {"projection", "gamma", "number", "", "0.01", closed(0, 1), Applies::projection, "",
     "Relaxation γ of the density-deviation part of the source term (Park et al. 2014: γ ≤ 1); in [0, 1]."},
    {"projection", "surface_diameter_over_dx", "number", "", "2.1", closed(1, 4), Applies::projection, "",
     "Circle diameter of Dilts' arc free-surface test in lattice spacings (Park et al. 2014: 2.1); in [1, 4]."},
    {"projection", "surface_density_ratio", "number", "", "0", closed_open(0, 1), Applies::projection, "",
     "β of the number-density surface criterion (MPS, Koshizuka & Oka 1996): a particle with n_i < β n0 is also a free-surface particle (p = 0), besides the arc test; 0 = off; in [0, 1)."},
    {"projection", "correction_gradient", "string", "", "\"second_order\"", one_of({"second_order", "first_order"}), Applies::projection, "",
     "Gradient of the velocity correction P7: \"second_order\" (the WMLS fit of the PPE, Park et al. 2014) or \"first_order\" (the linear WMLS fit, exact for linear fields; docs/WMLS.md W18)."},
    {"projection", "correction_reference", "string", "", "\"hydrostatic\"", one_of({"minimum", "hydrostatic"}), Applies::projection, "",
     "Reference pressure of P7's stabilised gradient: \"hydrostatic\" (the smallest positive neighbour pressure less its hydrostatic difference from the particle, and wall pressures floored at the hydrostatic continuation of the particle's, so that a hydrostatic field is corrected exactly) or \"minimum\" (the smallest positive neighbour pressure, Koshizuka & Oka 1996; walls clamped at 0); docs/PROJECTION.md, P7."},
    {"projection", "deviation_weight", "string", "", "\"smooth\"", one_of({"smooth", "pnu_mps"}), Applies::projection, "",
     "Weight of the number density n_i in the density-deviation term of the source P3: \"smooth\" (the smooth weight w_s of the wall rows, which reads a disordered arrangement of the lattice's volume as uncompressed) or \"pnu_mps\" (the WMLS fits' weight, Park et al. 2014); docs/PROJECTION.md, P3."},
    {"projection", "wall_collision", "string", "", "\"wall_normal\"", one_of({"wall_normal", "line_of_centres"}), Applies::projection, "",
     "Direction in which a fluid particle that would come within 0.8 dx of a wall particle loses its velocity into the wall: \"wall_normal\" (along the wall's normal from its wall neighbours, so that flow along a wall is not braked) or \"line_of_centres\" (along the line to that wall particle, as before 2026-11-28); docs/PROJECTION.md, \"Wall collision\"."},
    {"projection", "fluid_collision", "boolean", "", "true", {}, Applies::projection, "",
     "Koshizuka-type collision of fluid pairs closer than 0.8 dx that approach (restitution 0.2, momentum-conserving; docs/PROJECTION.md, \"Collisions\")."},
    {"projection", "shifting", "number", "", "0", closed(0, 0.5), Applies::projection, "",
     "Fickian particle-shifting coefficient A of the projection scheme (0 = off): each step, displacement −A·h²·Σ(1 + 0.2(W/W(dx))⁴)∇W V from the positions at the start of the step (Lind et al. 2012 with a velocity-independent D = A h², as Skillen et al. 2013); only its tangential part near the free surface; capped at 0.1 dx; no correction of the velocity (docs/PROJECTION.md, \"Particle shifting\")."},
    {"walls", "model", "string", "", "\"none\"", one_of({"none", "reflective", "dummy"}), Applies::any, "",
     "\"none\", \"reflective\" (particles bounce off the tank faces, planes and meshes) or \"dummy\" (layers of wall particles, Adami et al."},
    {"walls", "tank_lo", "vector", "m", "required unless model = \"none\"", words("inside the domain"), Applies::any, "walls.model = \"reflective\" | \"dummy\"",
     "Lower corner of the tank; inside the domain."},
    {"walls", "tank_hi", "vector", "m", "required unless model = \"none\"", words("above tank_lo, inside the domain"), Applies::any, "walls.model = \"reflective\" | \"dummy\"",
     "Upper corner of the tank; above tank_lo, inside the domain."},
    {"walls", "tank_faces", "array of strings", "", "all faces: [\"x-\", \"x+\", \"y-\", \"y+\"] (2-D) plus \"z-\", \"z+\" (3-D)", one_of({"x-", "x+", "y-", "y+", "z-", "z+"}), Applies::any, "walls.model = \"reflective\" | \"dummy\"",
     "Faces of the tank that carry a wall; - is the low side."},
    {"walls", "restitution", "number", "", "1.0", closed(0, 1), Applies::any, "",
     "Reflective walls and planes: fraction of the normal velocity kept after a bounce; in [0, 1]."},
    {"walls", "no_slip", "boolean", "", "true", {}, Applies::wcsph, "walls.model = \"dummy\"",
     "Dummy walls: no-slip (true) or free-slip (false)."},
    {"walls", "tank_motion", "string", "", "fixed", words("a [[motions]] name"), Applies::wcsph, "walls.model = \"dummy\"",
     "The motion the tank's walls follow (all its faces, rigidly): the name of a [[motions]] entry."},
    {"walls", "planes", "array of tables", "", "", {}, Applies::any, "", "Extra reflective planes."},
    {"walls", "boxes", "array of tables", "", "", {}, Applies::any, "walls.model = \"dummy\"", "Solid obstacles of dummy wall particles."},
    {"walls", "meshes", "array of tables", "", "", {}, Applies::any, "walls.model = \"dummy\" | \"reflective\"", "Walls and obstacles from triangle meshes (3-D) or polylines (2-D): dummy wall layers laid behind them, or reflective faces (a particle whose move enters a triangle or segment from the side its normal points to is mirrored back across it)."},
    {"walls.meshes", "file", "string", "", "required", words("a readable .stl, .obj, .ply or .off file; in 2-D also a vertex file (.csv, .txt, .dat)"), Applies::any, "",
     "The shape's file, relative to the case file's folder. 3-D: a triangle mesh (STL ASCII or binary, OBJ, PLY, OFF). 2-D: a vertex file (one \"x, y\" pair per line, joined in order; a last vertex equal to the first closes it) or a triangle mesh cut by the plane z = section_z."},
    {"walls.meshes", "role", "string", "", "required", one_of({"solid", "surface"}), Applies::any, "",
     "\"solid\": a closed shape whose inside is wall (an obstacle), its wall layers laid inside under its surface; \"surface\": an open or closed shape (a bed, a terrain, a container) whose wall layers are laid on the side its normals point away from: the normals point into the fluid."},
    {"walls.meshes", "scale", "number", "", "1", open_closed(0, 1e6), Applies::any, "",
     "Factor applied to the file's coordinates first (e.g. 0.001 for a mesh in millimetres)."},
    {"walls.meshes", "rotation", "vector (3-D) or number (2-D)", "degrees", "0", closed(-360, 360), Applies::any, "",
     "Rotation after scaling, about the axes through the origin: 3-D [about x, about y, about z], applied in that order; 2-D one angle about z, counter-clockwise."},
    {"walls.meshes", "translation", "vector", "m", "zeros", closed(-1e6, 1e6).implausible_beyond(), Applies::any, "",
     "Shift applied last."},
    {"walls.meshes", "motion", "string", "", "fixed", words("a [[motions]] name"), Applies::wcsph, "walls.model = \"dummy\"",
     "The motion this shape's wall particles follow rigidly: the name of a [[motions]] entry."},
    {"walls.meshes", "flip_normals", "boolean", "", "false", {}, Applies::any, "",
     "Reverse every triangle's (segment's) orientation: for a mesh whose normals point the wrong way."},
    {"walls.meshes", "section_z", "number", "m", "0", closed(-1e6, 1e6), Applies::any, "",
     "2-D case with a triangle mesh file: the plane z = section_z (in the file's coordinates) that cuts the mesh into the case's polyline, before scale, rotation and translation."},
    {"walls.planes", "point", "vector", "m", "required", closed(-1e6, 1e6).implausible_beyond(), Applies::any, "",
     "A point on the plane."},
    {"walls.planes", "normal", "vector", "", "required", words("not the zero vector"), Applies::any, "",
     "Direction pointing to the fluid side; not zero."},
    {"walls.boxes", "lo", "vector", "m", "required", {}, Applies::any, "",
     "Lower corner."},
    {"walls.boxes", "hi", "vector", "m", "required", words("above lo"), Applies::any, "",
     "Upper corner; above lo on every axis."},
    {"walls.boxes", "motion", "string", "", "fixed", words("a [[motions]] name"), Applies::wcsph, "walls.model = \"dummy\"",
     "The motion this box follows rigidly (a piston paddle, a moving obstacle): the name of a [[motions]] entry."},
    {"motions", "name", "string", "", "required", words("letters, digits, _ and -; at most 200 bytes; unique"), Applies::wcsph, "",
     "What wall objects refer to (walls.tank_motion, walls.boxes.motion, walls.meshes.motion); also probes/<name>_motion.csv."},
    {"motions", "kind", "string", "", "required", one_of({"sway", "roll", "constant_velocity", "constant_acceleration", "file", "piston", "flap", "piston_irregular", "free_body"}), Applies::wcsph, "",
     "\"sway\": translation amplitude·sin(2πt/period + phase); \"roll\": rotation about centre (and axis, 3-D) by angle·sin(2πt/period + phase); \"constant_velocity\", \"constant_acceleration\": translation from rest; \"file\": displacement and angle from a time series; \"piston\", \"flap\": regular waves of wave_height and wave_period in depth (linear wave-maker theory, Biésel transfer function); \"piston_irregular\": a JONSWAP sea; \"free_body\": not prescribed, the fluid's force and moment and gravity move the object (docs/FLOATING_BODIES.md)."},
    {"motions", "start", "number", "s", "0", closed(0, 1e9), Applies::wcsph, "",
     "Time the motion starts; the object rests before it (a free body is held and released then)."},
    {"motions", "ramp", "number", "s", "0", closed(0, 1e9), Applies::wcsph, "not kind = \"free_body\"",
     "Duration of a smooth ramp-in after start (a quintic smoothstep: no jump in velocity or acceleration); 0 = none."},
    {"motions", "amplitude", "vector", "m", "required for sway", closed(-1e6, 1e6).implausible_beyond(), Applies::wcsph, "kind = \"sway\"",
     "Displacement amplitude (direction and size); not zero."},
    {"motions", "angle", "number", "degrees", "required for roll", closed(-90, 90), Applies::wcsph, "kind = \"roll\"",
     "Roll amplitude; not zero; counter-clockwise positive about axis."},
    {"motions", "period", "number", "s", "required for sway and roll", open_closed(0, 1e6), Applies::wcsph, "kind = \"sway\" | \"roll\"",
     "Period of the sway or roll; > 0."},
    {"motions", "phase", "number", "degrees", "0", closed(-360, 360), Applies::wcsph, "kind = \"sway\" | \"roll\"",
     "Phase of the sinusoid at start (the ramp takes a non-zero start in smoothly)."},
    {"motions", "velocity", "vector", "m/s", "required for constant_velocity; zeros for free_body", closed(-1e6, 1e6).implausible_beyond(), Applies::wcsph, "kind = \"constant_velocity\" | \"free_body\"",
     "constant_velocity: the velocity reached (after ramp); not zero. free_body: the velocity of its centre of mass at release (start); not for a hinged or fixed body."},
    {"motions", "acceleration", "vector", "m/s²", "required for constant_acceleration", closed(-1e6, 1e6).implausible_beyond(), Applies::wcsph, "kind = \"constant_acceleration\"",
     "The acceleration (reached after ramp); not zero."},
    {"motions", "centre", "vector", "m", "zeros; required for roll and flap", closed(-1e6, 1e6).implausible_beyond(), Applies::wcsph, "kind = \"roll\" | \"file\" | \"flap\" | \"free_body\"",
     "Centre of rotation (a flap's hinge), where the object is at t = 0; it moves with the translation. free_body: the hinge point of constraint = \"hinge\" (required there, refused otherwise)."},
    {"motions", "axis", "vector", "", "[0, 0, 1] (3-D only)", words("3-D only; not the zero vector"), Applies::wcsph, "kind = \"roll\" | \"file\" | \"flap\" | \"free_body\"",
     "3-D: axis of rotation (right-handed); 2-D rotations are about z, counter-clockwise. free_body (3-D): the hinge axis of constraint = \"hinge\" or the plane's normal of \"plane\" (required there, refused otherwise)."},
    {"motions", "file", "string", "", "required for file", words("a readable CSV file of at least two rows, time increasing, covering the run"), Applies::wcsph, "kind = \"file\"",
     "Time series relative to the case file's folder: rows \"t, dx, dy\" (2-D) or \"t, dx, dy, dz\" (3-D) [s, m], optionally one more column, the angle [degrees] about centre/axis; lines starting with # are comments. Taken relative to the first row; interpolated by a modified Akima spline; t runs from start."},
    {"motions", "wave_height", "number", "m", "required for piston and flap", open_closed(0, 1e3), Applies::wcsph, "kind = \"piston\" | \"flap\"",
     "Height H of the regular waves to generate; > 0 (above Miche's breaking limit a warning)."},
    {"motions", "wave_period", "number", "s", "required for piston and flap", open_closed(0, 1e3), Applies::wcsph, "kind = \"piston\" | \"flap\"",
     "Period T of the regular waves; > 0."},
    {"motions", "depth", "number", "m", "required for wave-makers", open_closed(0, 1e4), Applies::wcsph, "kind = \"piston\" | \"flap\" | \"piston_irregular\"",
     "Still-water depth h at the paddle; > 0 (the wave number solves ω² = g k tanh kh with g = |fluid.gravity|)."},
    {"motions", "second_order", "boolean", "", "false", {}, Applies::wcsph, "kind = \"piston\"",
     "Add the second-order stroke (Madsen 1971) that cancels the spurious free second harmonic of first-order generation."},
    {"motions", "direction", "vector", "", "+x: [1, 0] (2-D), [1, 0, 0] (3-D)", words("not the zero vector"), Applies::wcsph, "kind = \"piston\" | \"piston_irregular\"",
     "Direction of the piston's stroke (towards the waves)."},
    {"motions", "hs", "number", "m", "required for piston_irregular", open_closed(0, 1e3), Applies::wcsph, "kind = \"piston_irregular\"",
     "Significant wave height H_m0 = 4√m0 of the JONSWAP sea; > 0."},
    {"motions", "tp", "number", "s", "required for piston_irregular", open_closed(0, 1e3), Applies::wcsph, "kind = \"piston_irregular\"",
     "Peak period; > 0."},
    {"motions", "gamma", "number", "", "3.3", closed(1, 10), Applies::wcsph, "kind = \"piston_irregular\"",
     "JONSWAP peak enhancement factor γ; in [1, 10] (1 = Pierson-Moskowitz)."},
    {"motions", "components", "integer", "", "64", closed(2, 4096), Applies::wcsph, "kind = \"piston_irregular\"",
     "Number of wave components, equally spaced in frequency from 0.5/tp to 3/tp (the record repeats after 1/Δf)."},
    {"motions", "seed", "integer", "", "1", closed(0, 4294967295.0), Applies::wcsph, "kind = \"piston_irregular\"",
     "Seed of the components' random phases (the same phases on every machine)."},
    {"motions", "density", "number", "kg/m³", "required for free_body (density or mass)", open_closed(0, 1e6), Applies::wcsph, "kind = \"free_body\"",
     "The body's uniform density: its mass, centre of mass and inertia follow from the box's volume (boxes only; a mesh body gives mass, centre_of_mass and inertia). 500 floats half-immersed in water."},
    {"motions", "mass", "number", "kg (2-D: kg/m)", "required for free_body (density or mass)", open_closed(0, 1e12), Applies::wcsph, "kind = \"free_body\"",
     "The body's mass (2-D: per metre of width); not with density."},
    {"motions", "centre_of_mass", "vector", "m", "the shape's centroid", closed(-1e6, 1e6).implausible_beyond(), Applies::wcsph, "kind = \"free_body\"",
     "Centre of mass where the body is at t = 0 (required for a mesh body)."},
    {"motions", "inertia", "number (2-D) or vector (3-D)", "kg m² (2-D: kg m²/m)", "the shape's at uniform density", words("positive; 3-D: principal moments [Ixx, Iyy, Izz] about the world axes, each at most the sum of the other two"), Applies::wcsph, "kind = \"free_body\"",
     "Moment of inertia about the centre of mass: 2-D about z (per metre of width); 3-D the principal moments along the world axes at t = 0 (required for a mesh body)."},
    {"motions", "angular_velocity", "number (2-D) or vector (3-D)", "rad/s", "0", closed(-1e4, 1e4), Applies::wcsph, "kind = \"free_body\"",
     "Angular velocity at release (2-D: about z, counter-clockwise)."},
    {"motions", "constraint", "string", "", "\"free\"", one_of({"free", "fixed", "hinge", "plane"}), Applies::wcsph, "kind = \"free_body\"",
     "What the body may do: \"free\" (every degree of freedom; 2-D: x, y and the rotation about z), \"fixed\" (it stays; its load is still computed), \"hinge\" (rotation about axis through centre only), \"plane\" (3-D: translation in the plane normal to axis and rotation about axis)."},
    {"motions", "friction", "number", "", "0.5", closed(0, 10), Applies::wcsph, "kind = \"free_body\"",
     "Coulomb friction coefficient of the body's surface in contact with walls and other bodies (a pair takes the product of its two surfaces'; the fixed walls' is 1); refused for a body that takes no part in contact (hinged, fixed, mesh)."},
    {"motions", "restitution", "number", "", "0", closed(0, 1), Applies::wcsph, "kind = \"free_body\"",
     "Coefficient of restitution of the body's surface in contact (the product of the pair's; the fixed walls' is 1); 0: no bounce; refused for a body that takes no part in contact."},
    {"damping_zones", "start", "vector", "m", "required", closed(-1e6, 1e6).implausible_beyond(), Applies::wcsph, "",
     "Where the damping begins: the fluid's velocity relaxes to rest at a rate growing as the square of the distance past start along end − start (Altomare et al. 2017), nothing before it."},
    {"damping_zones", "end", "vector", "m", "required", words("not start"), Applies::wcsph, "",
     "Where the rate reaches strength (and stays so beyond)."},
    {"damping_zones", "strength", "number", "1/s", "10", open_closed(0, 1e6), Applies::wcsph, "",
     "The largest relaxation rate σ: dv/dt = −σ v; > 0. A zone absorbs waves of period T best when σ T is of order 10 and its length at least one wavelength."},
    {"time", "end_time", "number", "s", "required", above(0), Applies::any, "",
     "Simulated time to reach; > 0."},
    {"time", "output_interval", "number", "s", "0", at_least(0), Applies::any, "",
     "Interval between snapshots (and default probe interval); ≥ 0."},
    {"output", "snapshots", "boolean", "", "true", {}, Applies::any, "",
     "Write particle snapshots."},
    {"output", "fields", "array of strings", "", "[\"position\", \"velocity\", \"density\", \"pressure\", \"id\", \"kind\"]", one_of({"position", "velocity", "density", "pressure", "acceleration", "mass", "id", "kind", "spacing"}), Applies::any, "",
     "Fields in each snapshot, from position, velocity, density, pressure, acceleration, mass, id, kind, spacing; no duplicates."},
    {"probes", "name", "string", "", "required", words("letters, digits, _ and -; at most 200 bytes; unique"), Applies::any, "",
     "File name stem: letters, digits, _ and - only; unique; at most 200 bytes."},
    {"probes", "type", "string", "", "required", one_of({"pressure", "water_level", "surge_front", "force", "motion"}), Applies::any, "",
     "\"pressure\", \"water_level\", \"surge_front\", \"force\" or \"motion\" (a moving object's displacement, angle and velocities, from its motion)."},
    {"probes", "frame", "string", "", "fixed; a force probe or an area sensor: its wall object's motion", words("a [[motions]] name"), Applies::wcsph, "",
     "The motion the probe moves with: its position, x (and y), lo/hi and moment_about are where the object is at t = 0; a water_level gauge measures along the object's own vertical, from its t = 0 datum; a force probe on a moving object reads that object's wall particles and reports world-frame components; an area sensor moves with the wall it sits on (given, frame must name that wall's motion) and reads in the wall's frame. Required for type = \"motion\"."},
    {"probes", "position", "vector", "m", "required for pressure (not allowed otherwise)", {}, Applies::any, "type = \"pressure\"",
     "Sampling point, inside the domain; for an area sensor its centre, on a wall surface (within dx)."},
    {"probes", "x", "number", "m", "required for water_level (not allowed otherwise)", {}, Applies::any, "type = \"water_level\"",
     "Horizontal position of the gauge, inside the tank (the domain without walls)."},
    {"probes", "y", "number", "m", "whole width", {}, Applies::any, "type = \"water_level\"",
     "water_level in 3-D only: a point gauge at (x, y)."},
    {"probes", "interval", "number or \"every_step\"", "s", "0", at_least(0).and_words("or the string \"every_step\""), Applies::any, "",
     "Sampling interval; ≥ 0."},
    {"probes", "diameter", "number", "m", "point probe", open_closed(0, 1e6).implausible_beyond(), Applies::any, "type = \"pressure\"",
     "pressure only: an area sensor (flush-mounted transducer) of this diameter; > 0."},
    {"probes", "reading", "string", "", "\"force\"", one_of({"force", "interpolated", "collisions"}), Applies::any, "type = \"force\" | \"pressure\", with a diameter",
     "area sensor: \"force\", the fluid's normal force on the wall under the face per unit area; \"interpolated\", the pressure interpolated on the face. force probe: \"force\", the sum of the fluid-wall pair forces; \"interpolated\", the interpolated pressure integrated over the wall's surface (no viscous traction). Under the projection scheme the default is \"interpolated\" (which adds the momentum of its wall collisions) and \"force\" is refused; \"collisions\" (projection only) reads that collision part alone."},
    {"probes", "face", "string", "", "–", one_of({"x-", "x+", "y-", "y+", "z-", "z+"}), Applies::any, "type = \"force\" | \"pressure\"",
     "force: the tank face loaded (\"x-\", \"x+\", …; must be in walls.tank_faces)."},
    {"probes", "mesh", "integer", "", "–", words("a walls.meshes index"), Applies::any, "type = \"force\" | \"pressure\"",
     "force: the [[walls.meshes]] index loaded (0 = first): its own wall particles (inside a solid; behind a surface within its wall layers), cut to lo/hi; other walls' particles there do not count. pressure with a diameter: the area sensor sits on that mesh, centred at its surface point nearest position (within dx), facing along the nearest triangle's (segment's) normal; reading = \"force\" only."},
    {"probes", "box", "integer", "", "–", words("a walls.boxes index"), Applies::any, "type = \"force\" | \"pressure\"",
     "force: the [[walls.boxes]] index loaded (0 = first)."},
    {"probes", "lo", "vector", "m", "the whole face or box", {}, Applies::any, "type = \"force\"",
     "force only: limits the region to the wall particles inside [lo, hi] (a part of a face: a panel)."},
    {"probes", "hi", "vector", "m", "the whole face or box", {}, Applies::any, "type = \"force\"",
     "force only: limits the region to the wall particles inside [lo, hi] (a part of a face: a panel)."},
    {"probes", "moment_about", "vector", "m", "no moment", closed(-1e6, 1e6).implausible_beyond(), Applies::any, "type = \"force\"",
     "force only: also write the moment about this point."},
    {"probes", "direction", "string", "", "\"+x\"", one_of({"+x", "-x", "+y", "-y", "+z", "-z"}), Applies::any, "type = \"surge_front\"",
     "surge_front only: \"+x\", \"-x\", \"+y\", \"-y\" (3-D also \"+z\", \"-z\")."},
    {"probes", "min_thickness", "number", "m", "2·dx", open_closed(0, 1e6).implausible_beyond(), Applies::any, "type = \"surge_front\"",
     "surge_front only: the fluid depth a column needs to count as the front; > 0."},
    {"neighbours.<operator>", "selection", "string", "", "\"radius\"", one_of({"radius", "convex-hull"}), Applies::projection, "",
     "\"radius\": every particle within the operator's support."},
    {"neighbours.<operator>", "candidate_radius_over_dx", "number", "dx", "3.1", open_closed(0, 10), Applies::projection, "selection = \"convex-hull\"",
     "convex-hull only: candidates are the particles within this many lattice spacings; in (0, 10]."},
    {"neighbours.<operator>", "union_with_radius", "boolean", "", "false", {}, Applies::projection, "selection = \"convex-hull\"",
     "convex-hull only: add every particle within the support to the hull neighbours. The candidates are the particles within the operator radius, so true would give the radius set: refused (use selection = \"radius\")."},
    {"neighbours.<operator>", "hull_points", "string", "", "\"boundary\"", one_of({"vertices", "boundary"}), Applies::projection, "selection = \"convex-hull\"",
     "convex-hull only: \"vertices\" keeps the hull corners; \"boundary\" also the images lying on a hull edge (3-D: facet), within 10⁻⁹ of the hull's size — e.g."},
    {"runtime", "particles_per_group", "integer", "particles", "2000", closed(1, 2147483647), Applies::any, "",
     "Target size of the cell groups the task scheduler works on; ≥ 1."},
    {"runtime", "rebalance_threshold", "number", "fraction", "0.10", open_closed(0, 10), Applies::any, "",
     "On several ranks, move the cut points when the slowest rank's busy time exceeds the mean by more than this over a window; in (0, 10]."},
    {"runtime", "rebalance_window", "integer", "steps", "10", closed(1, 1000000), Applies::any, "",
     "Steps over which busy time is summed before the imbalance is judged; ≥ 1."},
    {"runtime", "rebalance_every", "integer", "steps", "0", closed(0, 1000000000), Applies::any, "",
     "Also rebalance every this many steps whatever the imbalance (0: only when unbalanced)."},
    {"runtime", "balance_cost", "string", "", "\"time\"", one_of({"time", "particles"}), Applies::any, "",
     "What the balancer equalises: \"time\" (measured task time per cell group) or \"particles\"."},
    {"runtime", "initial_decomposition", "string", "", "\"balanced\"", one_of({"balanced", "key-range"}), Applies::any, "",
     "How ranks split the curve at start: \"balanced\" (equal particle counts) or \"key-range\" (equal key ranges; naive and usually unbalanced, for testing the balancer)."},
    {"runtime", "run_ahead", "boolean", "", "false", {}, Applies::wcsph, "",
     "On several ranks, start the next step's graph (density, walls and, without shifting, accelerations) while the step's time-step agreement is in flight, with kick held until it arrives; a failure, rebuild, rebalance or request discards the early work and the step runs again. Results are byte-identical either way. Off by default: no speed-up has been measured yet."},
    {"checkpoint", "every_steps", "integer", "steps", "0", closed(0, 1000000000), Applies::any, "",
     "Write <results>/checkpoint.h5 after every this many steps (counted from the start of the run); 0 = off."},
    {"checkpoint", "every_minutes", "number", "minutes", "30", closed(0, 1e6), Applies::any, "",
     "Also write one when this much wall time has passed since the last (rank 0's clock decides; all ranks write at the same step); 0 = off."},
    {"limits", "max_speed", "number", "m/s", "fluid.sound_speed", above(0), Applies::any, "",
     "Largest speed a fluid particle may reach; > 0."},
    {"limits", "min_density", "number", "kg/m^3", "0.01  rho0", at_least(0).and_words("below fluid.rho0"), Applies::wcsph, "",
     "Smallest density; ≥ 0 and below rho0."},
    {"limits", "max_density", "number", "kg/m^3", "2  rho0", words("above fluid.rho0"), Applies::wcsph, "",
     "Largest density; above rho0."},
};
// clang-format on

std::vector<KeySpec> expand() {
    std::vector<KeySpec> out;
    for (const auto& k : kKeys) {
        if (k.table != kOperator) {
            out.push_back(k);
            continue;
        }
        for (const auto op : kOperators) {
            KeySpec copy = k;
            copy.table = op;
            out.push_back(copy);
        }
    }
    return out;
}

std::string joined(std::string_view table, std::string_view key) {
    return table.empty() ? std::string(key) : std::string(table) + "." + std::string(key);
}

} // namespace

const KeySpec* find_key(std::string_view table, std::string_view key) {
    static const auto index = [] {
        std::map<std::pair<std::string_view, std::string_view>, const KeySpec*> m;
        for (const auto& k : case_keys())
            m.emplace(std::pair(k.table, k.key), &k);
        return m;
    }();
    const auto it = index.find(std::pair(table, key));
    return it == index.end() ? nullptr : it->second;
}

const std::vector<KeySpec>& case_keys() {
    static const std::vector<KeySpec> keys = expand();
    return keys;
}

const std::map<std::string, std::vector<std::string>, std::less<>> kSchema = [] {
    std::map<std::string, std::vector<std::string>, std::less<>> m;
    for (const auto& k : case_keys())
        m[std::string(k.table)].emplace_back(k.key);
    return m;
}();

const std::set<std::string, std::less<>> kArrayTables = [] {
    std::set<std::string, std::less<>> s;
    for (const auto& k : case_keys())
        if (k.type == "array of tables")
            s.insert(joined(k.table, k.key));
    return s;
}();

const char* applies_name(Applies a) {
    switch (a) {
    case Applies::wcsph:
        return "wcsph";
    case Applies::projection:
        return "projection";
    default:
        return "any";
    }
}

const char* scheme_name(Scheme s) {
    return s == Scheme::projection ? "projection" : "wcsph";
}

std::string schema_json() {
    const auto finite_or_null = [](double v) {
        return std::isinf(v) ? nlohmann::ordered_json() : nlohmann::ordered_json(v);
    };
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const auto& k : case_keys())
        out.push_back(
            {{"table", k.table},
             {"key", k.key},
             {"type", k.type},
             {"unit", k.unit},
             {"default", k.default_text},
             {"range", range_text(k)},
             {"min", finite_or_null(k.range.lo)},
             {"max", finite_or_null(k.range.hi)},
             {"min_open", k.range.lo_open},
             {"max_open", k.range.hi_open},
             {"choices", std::vector<std::string>(k.range.choices.begin(), k.range.choices.end())},
             {"applies", applies_name(k.applies)},
             {"when", k.when},
             {"doc", k.doc}});
    return out.dump(1) + "\n";
}

} // namespace sluice::case_file
