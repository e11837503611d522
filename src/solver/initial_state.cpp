#include "sluice/solver/initial_state.hpp"

#include "sluice/solver/mesh_walls.hpp"

#include "initial_lattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>
#include <utility>
#include <vector>

namespace sluice {

using detail::AxisSites;
using detail::block_particles;
using detail::box_axis_sites;
using detail::box_particles;
using detail::face_walled;
using detail::lattice_count;
using detail::tank_axis_sites;

namespace {

// A number in [-1/2, 1/2) from (id, axis), the same on every rank and machine: SplitMix64's
// output function (Steele, Lea & Flood 2014) over id * 3 + axis. Not <random>: its
// distributions differ between standard libraries, and a counter-based hash needs no generator
// state to agree across ranks.
double lattice_offset(std::uint64_t id, int axis) {
    std::uint64_t z = (id * 3 + static_cast<std::uint64_t>(axis) + 1) * 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
}

// Calls f(k, x) for every lattice site k (integer coordinates) at x = lo + (k + 1/2) dx.
template <int D, class F>
void for_each_lattice_site(const std::array<double, D>& lo, const std::array<int, D>& n, double dx,
                           F&& f) {
    std::array<int, D> k{};
    std::size_t total = 1;
    for (int d = 0; d < D; ++d)
        total *= static_cast<std::size_t>(n[d]);
    for (std::size_t idx = 0; idx < total; ++idx) {
        std::size_t r = idx;
        Vec<D> x;
        for (int d = 0; d < D; ++d) {
            k[d] = static_cast<int>(r % static_cast<std::size_t>(n[d]));
            r /= static_cast<std::size_t>(n[d]);
            x[d] = Real(lo[d] + (k[d] + 0.5) * dx);
        }
        f(std::as_const(k), std::as_const(x));
    }
}

// Calls f(k, x) for every site k of the product of the per-axis site lists, axis 0 fastest (the
// order of for_each_lattice_site).
template <int D, class F>
void for_each_site(const std::array<std::vector<double>, D>& sites, F&& f) {
    std::array<int, D> k{};
    std::size_t total = 1;
    for (int d = 0; d < D; ++d)
        total *= sites[d].size();
    for (std::size_t idx = 0; idx < total; ++idx) {
        std::size_t r = idx;
        Vec<D> x;
        for (int d = 0; d < D; ++d) {
            const std::size_t n = sites[d].size();
            k[d] = static_cast<int>(r % n);
            r /= n;
            x[d] = Real(sites[d][static_cast<std::size_t>(k[d])]);
        }
        f(std::as_const(k), std::as_const(x));
    }
}

// Wall sites along one axis of the span [a, b]: n_a layers a + (k + 1/2) dx laid from a, n_b
// layers b - (k + 1/2) dx laid from b, and between the two stacks round((b - a)/dx) - n_a - n_b
// sites of spacing dx centred between them. Where the stacks would overlap (b - a shorter than
// n_a + n_b layers: `thin`), round((b - a)/dx) sites, at least one, centred in [a, b]. When dx
// divides b - a (to 1e-9) the sites are a + (k + 1/2) dx, computed as the lattice of earlier
// versions was, so such geometry stays bitwise identical.
AxisSites axis_sites(double a, double b, int n_a, int n_b, double dx) {
    const double q = (b - a) / dx;
    const int n = std::max(1, static_cast<int>(std::round(q)));
    AxisSites s;
    s.x.reserve(static_cast<std::size_t>(n));
    s.thin = q < n_a + n_b - 1e-9;
    if (s.thin) {
        s.mid = n;
    } else {
        s.n_a = n_a;
        s.n_b = n_b;
        s.mid = n - n_a - n_b;
    }
    if (std::abs(q - std::round(q)) < 1e-9) {
        for (int k = 0; k < n; ++k)
            s.x.push_back(a + (k + 0.5) * dx);
        return s;
    }
    for (int k = 0; k < s.n_a; ++k)
        s.x.push_back(a + (k + 0.5) * dx);
    const double centre = s.thin ? 0.5 * (a + b) : 0.5 * ((a + n_a * dx) + (b - n_b * dx));
    for (int k = 0; k < s.mid; ++k)
        s.x.push_back(centre + (k - 0.5 * (s.mid - 1)) * dx);
    for (int k = s.n_b - 1; k >= 0; --k)
        s.x.push_back(b - (k + 0.5) * dx);
    return s;
}

template <int D, class F>
void for_each_lattice_point(const std::array<double, D>& lo, const std::array<int, D>& n, double dx,
                            F&& f) {
    for_each_lattice_site<D>(lo, n, dx,
                             [&](const std::array<int, D>&, const Vec<D>& x) { f(Vec<D>(x)); });
}

// Velocity gradient term tr(G^2) of a block's profile about its centre (0 if none).
double profile_trace_g2(const FluidBlock& b) {
    switch (b.profile) {
    case VelocityProfile::rotating:
        return -2 * b.angular_velocity * b.angular_velocity;
    case VelocityProfile::strain:
        return 2 * b.strain_rate * b.strain_rate;
    default:
        return 0;
    }
}

} // namespace

namespace detail {

// A free body's box displaces the fluid of the blocks it lies in (case_walls.cpp lets it).
bool box_displaces_fluid(const CaseConfig& cfg, const WallBox& box) {
    return box.motion >= 0 &&
           cfg.motions[static_cast<std::size_t>(box.motion)].kind == MotionKind::free_body;
}

bool has_displacing_box(const CaseConfig& cfg) {
    return std::any_of(cfg.boxes.begin(), cfg.boxes.end(),
                       [&](const WallBox& b) { return box_displaces_fluid(cfg, b); });
}

// A block's lattice site that a mesh or a free body's box holds instead of fluid: within dx/2
// of the box (its first wall layer lies dx/2 inside its faces).
bool fluid_site_taken(const CaseConfig& cfg, const Triple& at) {
    if (!cfg.meshes.empty() && fluid_site_taken_by_mesh(cfg, at))
        return true;
    const double keep = 0.5 * cfg.dx * (1 - 1e-6); // a site dx/2 from a face stays fluid
    for (const WallBox& b : cfg.boxes) {
        if (!box_displaces_fluid(cfg, b))
            continue;
        bool inside = true;
        for (std::size_t a = 0; a < static_cast<std::size_t>(cfg.dimension); ++a)
            inside = inside && at[a] > b.lo[a] - keep && at[a] < b.hi[a] + keep;
        if (inside)
            return true;
    }
    return false;
}

int lattice_count(double lo, double hi, double dx) {
    return std::max(0, static_cast<int>(std::round((hi - lo) / dx)));
}

bool face_walled(const CaseConfig& cfg, int axis, bool upper) {
    static constexpr const char* names[3][2] = {{"x-", "x+"}, {"y-", "y+"}, {"z-", "z+"}};
    const std::string want = names[axis][upper ? 1 : 0];
    return std::find(cfg.tank_faces.begin(), cfg.tank_faces.end(), want) != cfg.tank_faces.end();
}

AxisSites tank_axis_sites(const CaseConfig& cfg, int d, int layers) {
    const bool lo_walled = face_walled(cfg, d, false), hi_walled = face_walled(cfg, d, true);
    const double a = cfg.tank_lo[d] - (lo_walled ? layers * cfg.dx : 0.0);
    const double b = cfg.tank_hi[d] + (hi_walled ? layers * cfg.dx : 0.0);
    return axis_sites(a, b, lo_walled ? layers : 0, hi_walled ? layers : 0, cfg.dx);
}

AxisSites box_axis_sites(const WallBox& b, int d, int layers, double dx) {
    return axis_sites(b.lo[d], b.hi[d], layers, layers, dx);
}

std::size_t block_particles(const CaseConfig& cfg, const FluidBlock& b) {
    std::array<double, 3> lo{};
    std::array<int, 3> n{1, 1, 1};
    std::size_t all = 1;
    for (std::size_t d = 0; d < static_cast<std::size_t>(cfg.dimension); ++d) {
        lo[d] = b.lo[d];
        n[d] = block_lattice_count(cfg, b, static_cast<int>(d));
        all *= static_cast<std::size_t>(n[d]);
    }
    if (b.shape == BlockShape::box && cfg.meshes.empty() && !has_displacing_box(cfg))
        return all;
    std::size_t total = 0;
    const auto count_in = [&](auto dim) {
        constexpr int D = decltype(dim)::value;
        std::array<double, D> l{};
        std::array<int, D> k{};
        for (int d = 0; d < D; ++d) {
            l[d] = lo[static_cast<std::size_t>(d)];
            k[d] = n[static_cast<std::size_t>(d)];
        }
        for_each_lattice_point<D>(l, k, cfg.dx, [&](const Vec<D>& x) {
            Triple at{};
            for (int d = 0; d < D; ++d)
                at[static_cast<std::size_t>(d)] = x[d];
            total += inside_block_shape(b, at, D) && !fluid_site_taken(cfg, at) ? 1 : 0;
        });
    };
    if (cfg.dimension == 2)
        count_in(std::integral_constant<int, 2>{});
    else
        count_in(std::integral_constant<int, 3>{});
    return total;
}

} // namespace detail

namespace {

// Lattice sites of a wall box within `layers` sites of its surface: deeper sites are more than
// one kernel support from any fluid particle, so they would never take part in a sum.
template <int D>
bool in_box_shell(const std::array<int, D>& k, const std::array<int, D>& n, int layers) {
    for (int d = 0; d < D; ++d)
        if (k[d] < layers || k[d] >= n[d] - layers)
            return true;
    return false;
}

} // namespace

int block_lattice_count(const CaseConfig& cfg, const FluidBlock& b, int axis) {
    int n = lattice_count(b.lo[axis], b.hi[axis], cfg.dx);
    if (face_walled(cfg, axis, true)) {
        // The last centre lo + (n - 1/2) dx at least dx/4 inside the face: n <= (face - lo)/dx
        // + 1/4. Closer than that (0.75 dx from the first wall layer, or on the face as a
        // 0.61 m block at dx = 0.02 m put it) the start is far from equilibrium.
        const double fit = std::floor((cfg.tank_hi[axis] - b.lo[axis]) / cfg.dx + 0.25 + 1e-9);
        n = std::min(n, static_cast<int>(std::max(0.0, fit)));
    }
    return n;
}

bool inside_block_shape(const FluidBlock& b, const Triple& x, int dimension) {
    double r2 = 0;
    for (std::size_t d = 0; d < static_cast<std::size_t>(dimension); ++d) {
        if (x[d] < b.lo[d] || x[d] > b.hi[d])
            return false;
        const double half = 0.5 * (b.hi[d] - b.lo[d]);
        const double xi = (x[d] - 0.5 * (b.lo[d] + b.hi[d])) / half;
        r2 += xi * xi;
    }
    if (b.shape == BlockShape::mesh)
        return b.mesh->shape->inside(x);
    return b.shape == BlockShape::box || r2 <= 1;
}

double block_max_speed(const FluidBlock& b, int dimension) {
    double v2 = 0, r2 = 0;
    for (std::size_t d = 0; d < static_cast<std::size_t>(dimension); ++d) {
        v2 += b.velocity[d] * b.velocity[d];
        const double half = 0.5 * (b.hi[d] - b.lo[d]);
        r2 += half * half; // distance from the centre to a corner of the box
    }
    const double r = std::sqrt(r2);
    double profile = 0;
    if (b.profile == VelocityProfile::taylor_green)
        profile = b.amplitude;
    else if (b.profile == VelocityProfile::rotating)
        profile = std::abs(b.angular_velocity) * r;
    else if (b.profile == VelocityProfile::strain)
        profile = std::abs(b.strain_rate) * r;
    return std::sqrt(v2) + profile;
}

template <int D>
ParticleId visit_fluid_blocks(const CaseConfig& cfg, const Eos& eos, ParticleId first_id,
                              const InitialSink<D>& sink) {
    ParticleId next_id = first_id;
    const double dx = cfg.dx;
    const double volume = std::pow(dx, D);
    Vec<D> g;
    for (int d = 0; d < D; ++d)
        g[d] = Real(cfg.gravity[d]);
    const int up = vertical_axis<D>();
    for (const FluidBlock& b : cfg.blocks) {
        std::array<double, D> lo{};
        std::array<int, D> n{};
        for (int d = 0; d < D; ++d) {
            lo[d] = b.lo[d];
            n[d] = block_lattice_count(cfg, b, d);
        }
        const double top = b.hi[up];
        // Continuity scheme: every particle carries the reference mass rho0 dx^D of its lattice
        // cell, and its density is the hydrostatic one of the weight above it. For the
        // particle volumes m/rho to tile the column (which the SPH sums assume, e.g.
        // sum_j V_j grad W_ij = 0 in the bulk), the column must sit compressed under its own
        // weight: each particle is placed at the height of its mass coordinate in the
        // compressed column, z = int dsigma / rho. A lattice of uniform spacing dx with
        // V = rho0 dx^D / rho < dx^D is not in discrete equilibrium: the pressure term then
        // behaves like rho0 grad(p/rho^2) instead of grad(p)/rho and the column, short of
        // support by ~3.5 (rho - rho0)/rho0 of g at the bottom, sinks and over-pressurises
        // the floor by ~3 % at c0 = 20 m/s. The surface of the settled column lies
        // ~ g H^2 / (2 c0^2) below the block's top (2 mm for H = 0.4 m, c0 = 20 m/s).
        const bool settle = b.hydrostatic && cfg.density == DensityScheme::continuity && g[up] != 0;
        const double g_abs = std::abs(g[up]);
        const double sigma_total = cfg.rho0 * (top - b.lo[up]);
        Triple centre{}, half{};
        for (int d = 0; d < D; ++d) {
            centre[d] = 0.5 * (b.lo[d] + b.hi[d]);
            half[d] = 0.5 * (b.hi[d] - b.lo[d]);
        }
        // The settled height depends on the lattice row alone: computed once per row (the
        // same call, hence the same bits), since the distributed start visits every site twice.
        std::vector<Real> settled_row(settle ? static_cast<std::size_t>(n[up]) : 0);
        std::vector<bool> row_done(settled_row.size(), false);
        for_each_lattice_site<D>(lo, n, dx, [&](const std::array<int, D>& site, Vec<D> x) {
            Triple at{};
            for (int d = 0; d < D; ++d)
                at[d] = x[d];
            if (!inside_block_shape(b, at, D))
                return;
            if (detail::fluid_site_taken(cfg, at))
                return;
            const double lattice_up = x[up];
            if (settle) {
                const auto row = static_cast<std::size_t>(site[up]);
                if (!row_done[row])
                    settled_row[row] =
                        Real(b.lo[up] + settled_height(eos, g_abs, sigma_total,
                                                       cfg.rho0 * (x[up] - b.lo[up])));
                row_done[row] = true;
                x[up] = settled_row[row];
            }
            Vec<D> v;
            for (int d = 0; d < D; ++d)
                v[d] = Real(b.velocity[d]);
            double p = eos.p_background;
            // Hydrostatic pressure: the weight of the water above the particle, rho0 g times
            // the height of lattice cells above its lattice centre (settling keeps that mass).
            if (b.hydrostatic)
                p += cfg.rho0 * g_abs * (top - lattice_up);
            if (b.profile == VelocityProfile::taylor_green) {
                // u = -A cos(kx) sin(ky), v = A sin(kx) cos(ky), p = -rho A^2/4 (cos 2kx + cos 2ky)
                // on the block's own period L (Taylor & Green 1937), x measured from lo.
                const double k = 2 * std::numbers::pi / (b.hi[0] - b.lo[0]);
                const double X = k * (x[0] - b.lo[0]), Y = k * (x[1] - b.lo[1]);
                v[0] += Real(-b.amplitude * std::cos(X) * std::sin(Y));
                v[1] += Real(b.amplitude * std::sin(X) * std::cos(Y));
                p +=
                    -cfg.rho0 * b.amplitude * b.amplitude / 4 * (std::cos(2 * X) + std::cos(2 * Y));
            }
            // Rotation and strain about the block centre (2-D; the reader refuses 3-D), with the
            // pressure that keeps the velocity gradient steady at t = 0 and vanishes on the
            // block's edge (see the header for the formulas).
            const double xi = at[0] - centre[0], eta = at[1] - centre[1];
            if (b.profile == VelocityProfile::rotating) {
                v[0] += Real(-b.angular_velocity * eta);
                v[1] += Real(b.angular_velocity * xi);
            } else if (b.profile == VelocityProfile::strain) {
                v[0] += Real(-b.strain_rate * xi);
                v[1] += Real(b.strain_rate * eta);
            }
            if (b.profile == VelocityProfile::rotating && b.shape == BlockShape::box)
                p += rotating_rectangle_pressure(cfg.rho0, b.angular_velocity, 2 * half[0],
                                                 2 * half[1], at[0] - b.lo[0], at[1] - b.lo[1]);
            else if (profile_trace_g2(b) != 0)
                p += ellipse_pressure(cfg.rho0, profile_trace_g2(b), half[0], half[1], xi, eta);
            const double rho = eos.density(Real(p));
            // Continuity: the mass of a lattice cell of the reference fluid, so a column holds
            // the mass of its height and the initial pressure lives in rho alone. Summation:
            // density comes from masses and positions, so the masses carry the initial field.
            const double m =
                cfg.density == DensityScheme::summation ? rho * volume : cfg.rho0 * volume;
            // particles.jitter: displaced after the fields were sampled at the lattice site (the
            // displacement, at most 0.05 dx, only breaks the lattice's symmetry).
            for (int d = 0; d < D && cfg.jitter > 0; ++d)
                x[d] += Real(cfg.jitter * dx * lattice_offset(next_id, d));
            sink({next_id++, Kind::fluid, x, v, Real(rho), Real(m)});
        });
    }
    return next_id;
}

template <int D>
ParticleId visit_wall_particles(const CaseConfig& cfg, int layers, ParticleId first_id,
                                const InitialSink<D>& sink) {
    ParticleId next_id = first_id;
    const double dx = cfg.dx;
    std::array<std::vector<double>, D> sites;
    std::array<AxisSites, D> axes;
    for (int d = 0; d < D; ++d) {
        axes[d] = tank_axis_sites(cfg, d, layers);
        sites[d] = axes[d].x;
    }
    const double mass = cfg.rho0 * std::pow(dx, D);
    for_each_site<D>(sites, [&](const std::array<int, D>& k, const Vec<D>& x) {
        bool inside_tank = true;
        for (int d = 0; d < D; ++d)
            inside_tank = inside_tank && k[d] >= axes[d].n_a && k[d] < axes[d].n_a + axes[d].mid;
        if (inside_tank)
            return;
        sink({next_id++, Kind::wall, x, Vec<D>::Zero(), Real(cfg.rho0), Real(mass), 0});
    });
    // Solid obstacles: `layers` layers inside each face of the box.
    for (std::size_t ib = 0; ib < cfg.boxes.size(); ++ib) {
        const WallBox& b = cfg.boxes[ib];
        std::array<std::vector<double>, D> bs;
        std::array<int, D> bn{};
        for (int d = 0; d < D; ++d) {
            bs[d] = box_axis_sites(b, d, layers, dx).x;
            bn[d] = static_cast<int>(bs[d].size());
        }
        for_each_site<D>(bs, [&](const std::array<int, D>& k, const Vec<D>& x) {
            if (in_box_shell<D>(k, bn, layers))
                sink({next_id++, Kind::wall, x, Vec<D>::Zero(), Real(cfg.rho0), Real(mass),
                      wall_object_index_of_box(ib)});
        });
    }
    return visit_mesh_wall_particles<D>(cfg, layers, next_id, sink);
}

namespace {
template <int D>
InitialSink<D> append_to(Particles<D>& P) {
    return
        [&P](const InitialParticle<D>& q) { P.push_back(q.id, q.kind, q.x, q.v, q.rho, q.mass); };
}
} // namespace

template <int D>
void add_fluid_blocks(const CaseConfig& cfg, const Eos& eos, Particles<D>& P) {
    visit_fluid_blocks<D>(cfg, eos, static_cast<ParticleId>(P.size()), append_to(P));
}

template <int D>
void add_wall_particles(const CaseConfig& cfg, int layers, Particles<D>& P) {
    visit_wall_particles<D>(cfg, layers, static_cast<ParticleId>(P.size()), append_to(P));
}

std::size_t count_fluid_particles(const CaseConfig& cfg) {
    std::size_t total = 0;
    for (const FluidBlock& b : cfg.blocks)
        total += block_particles(cfg, b);
    return total;
}

std::size_t detail::box_particles(const CaseConfig& cfg, const WallBox& b, int layers,
                                  std::array<int, 3>& n) {
    std::size_t all = 1, deep = 1;
    for (int d = 0; d < cfg.dimension; ++d) {
        n[static_cast<std::size_t>(d)] =
            static_cast<int>(box_axis_sites(b, d, layers, cfg.dx).x.size());
        all *= static_cast<std::size_t>(n[static_cast<std::size_t>(d)]);
        deep *= static_cast<std::size_t>(std::max(0, n[static_cast<std::size_t>(d)] - 2 * layers));
    }
    return all - deep;
}

std::size_t count_wall_particles(const CaseConfig& cfg, int layers) {
    if (cfg.walls != WallModel::dummy)
        return 0;
    std::size_t outer = 1, inner = 1;
    for (int d = 0; d < cfg.dimension; ++d) {
        const AxisSites s = tank_axis_sites(cfg, d, layers);
        outer *= s.x.size();
        inner *= static_cast<std::size_t>(s.mid);
    }
    std::size_t boxes = 0;
    std::array<int, 3> n{};
    for (const WallBox& b : cfg.boxes)
        boxes += box_particles(cfg, b, layers, n);
    std::size_t meshes = 0;
    for (std::size_t k : count_mesh_wall_particles(cfg, layers))
        meshes += k;
    return outer - inner + boxes + meshes;
}

template ParticleId visit_fluid_blocks<2>(const CaseConfig&, const Eos&, ParticleId,
                                          const InitialSink<2>&);
template ParticleId visit_fluid_blocks<3>(const CaseConfig&, const Eos&, ParticleId,
                                          const InitialSink<3>&);
template ParticleId visit_wall_particles<2>(const CaseConfig&, int, ParticleId,
                                            const InitialSink<2>&);
template ParticleId visit_wall_particles<3>(const CaseConfig&, int, ParticleId,
                                            const InitialSink<3>&);
template void add_fluid_blocks<2>(const CaseConfig&, const Eos&, Particles<2>&);
template void add_fluid_blocks<3>(const CaseConfig&, const Eos&, Particles<3>&);
template void add_wall_particles<2>(const CaseConfig&, int, Particles<2>&);
template void add_wall_particles<3>(const CaseConfig&, int, Particles<3>&);

} // namespace sluice
