// Wall loads and area pressure sensors (wall_loads.hpp): a cell hash of the fluid, then the
// fluid-wall pair terms of the momentum equation summed per wall particle; or a cell hash of
// every particle, then Shepard interpolations of the pressure on the wall's surface.
#include "sluice/physics/wall_loads.hpp"

#include "sluice/physics/cell_hash.hpp"
#include "sluice/physics/walls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <variant>

namespace sluice {
namespace {

// Particles bucketed by cells of edge `size` (ascending index within a cell): the fluid alone,
// or every kind (the interpolated readings sum over wall particles too).
template <int D>
struct ParticleCells {
    Real inv;
    std::unordered_map<CellKey<D>, std::vector<std::size_t>, CellKeyHash<D>> cells;
    std::vector<CellKey<D>> offsets = cell_neighbour_offsets<D>();

    ParticleCells(const Particles<D>& P, Real size, bool fluid_only) : inv(1 / size) {
        for (std::size_t i = 0; i < P.size(); ++i) {
            CellKey<D> k;
            if ((!fluid_only || P.kind[i] == Kind::fluid) && cell_key_of<D>(P.x[i], inv, k))
                cells[k].push_back(i);
        }
    }
    // Calls f(i) for every particle of the 3^D cells around x, in a fixed order.
    template <class F>
    void around(const Vec<D>& x, F&& f) const {
        CellKey<D> k;
        if (!cell_key_of<D>(x, inv, k))
            return;
        for (const CellKey<D>& o : offsets) {
            CellKey<D> n = k;
            for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a)
                n[a] += o[a];
            const auto it = cells.find(n);
            if (it == cells.end())
                continue;
            for (std::size_t i : it->second)
                f(i);
        }
    }
};

template <int D>
ParticleCells<D> fluid_cells(const Particles<D>& P, Real size) {
    return ParticleCells<D>(P, size, true);
}

template <int D>
ParticleCells<D> all_cells(const Particles<D>& P, Real size) {
    return ParticleCells<D>(P, size, false);
}

// Calls on_force(j, F_j, pairs_j) for every wall particle j of `walls`, in order, with the
// force the fluid exerts on it (double) and the number of fluid particles that contributed.
template <int D, class K, class OnForce>
void for_each_wall_force(const Particles<D>& P, const K& kernel, const WallLoadParams<D>& prm,
                         const std::vector<std::size_t>& walls, OnForce&& on_force) {
    const Real support = kernel.support();
    const Real support2 = support * support;
    const ParticleCells<D> fluid = fluid_cells(P, support);
    const Real eta2 = Real(0.01) * prm.h * prm.h;
    const Real two_mu = 2 * prm.mu;
    const Real av = prm.alpha * prm.h * prm.c0;
    const bool laminar = two_mu > 0 && prm.wall_viscous;
    const bool artificial = !prm.riemann && av > 0 && prm.wall_artificial;
    for (std::size_t j : walls) {
        const Vec<D> xj = P.x[j];
        // The boundary velocity of the viscous terms (walls.hpp, dummy_wall_state), with the
        // wall particle's own velocity: its wall's on a moving wall, zero on a fixed one.
        Vec<D> v_bc = P.v_bc[j];
        if ((laminar || artificial) && prm.adami_v_bc) {
            AdamiSums<D> sums;
            fluid.around(xj, [&](std::size_t i) {
                const Vec<D> dx = xj - P.x[i];
                const Real r2 = dx.squaredNorm();
                if (r2 < support2)
                    sums.add(kernel.W(std::sqrt(r2)), P.p[i], P.rho[i], dx, P.v[i]);
            });
            v_bc = sums.boundary_velocity(prm.no_slip, P.v[j]);
        }
        const Real rho_j = P.rho[j];
        const Real pj = std::max(P.p[j], prm.p_floor);
        const Real m_j = P.mass[j];
        Eigen::Matrix<double, D, 1> f = Eigen::Matrix<double, D, 1>::Zero();
        std::size_t pairs = 0;
        fluid.around(xj, [&](std::size_t i) {
            const Vec<D> dx = P.x[i] - xj; // x_i - x_j, as in the momentum loop
            const Real r2 = dx.squaredNorm();
            if (r2 >= support2 || r2 <= 0)
                return;
            const Real dWr = grad_factor(kernel, r2);
            const Real rho_i = P.rho[i];
            const Real pi = std::max(P.p[i], prm.p_floor);
            const Vec<D>& v_i = P.v[i];
            Real s;
            if (prm.riemann) {
                // No dissipation in fluid-wall pairs (riemann_acceleration): dU = 0.
                const Real p_star = riemann_pressure(rho_i, rho_j, pi, pj, 0, prm.c0, 0);
                s = 2 * (p_star - prm.p_gauge) / (rho_i * rho_j);
            } else {
                s = (pi - prm.p_gauge) / (rho_i * rho_i) + (pj - prm.p_gauge) / (rho_j * rho_j);
            }
            const Vec<D> v_ij = v_i - v_bc;
            if (artificial) {
                const Real vr = std::min(v_ij.dot(dx), Real(0));
                s -= av * vr / ((r2 + eta2) * (Real(0.5) * (rho_i + rho_j)));
            }
            // a_ij of fluid i (per unit m_j), then the wall's share -m_i a_ij.
            Vec<D> a_ij = -s * dWr * dx;
            if (laminar)
                a_ij += two_mu / (rho_i * rho_j) * (dWr * r2 / (r2 + eta2)) * v_ij;
            f -= (double(P.mass[i]) * double(m_j)) * a_ij.template cast<double>();
            ++pairs;
        });
        on_force(j, f, pairs);
    }
}

// Adds force f at offset r from the moment point to a load (2-D: the moment's z component).
template <int D>
void add_load(WallLoad& out, const Eigen::Matrix<double, D, 1>& r,
              const Eigen::Matrix<double, D, 1>& f) {
    for (int a = 0; a < D; ++a)
        out.force[static_cast<std::size_t>(a)] += f[a];
    if constexpr (D == 2) {
        out.moment[2] += r[0] * f[1] - r[1] * f[0];
    } else {
        out.moment[0] += r[1] * f[2] - r[2] * f[1];
        out.moment[1] += r[2] * f[0] - r[0] * f[2];
        out.moment[2] += r[0] * f[1] - r[1] * f[0];
    }
}

template <int D, class K>
WallLoad load_with(const Particles<D>& P, const K& kernel, const WallLoadParams<D>& prm,
                   const std::vector<std::size_t>& walls, const Vec<D>& c) {
    WallLoad out;
    out.wall_particles = walls.size();
    for_each_wall_force(P, kernel, prm, walls,
                        [&](std::size_t j, const auto& f, std::size_t pairs) {
                            out.pairs += pairs;
                            add_load<D>(out, (P.x[j] - c).template cast<double>(), f);
                        });
    return out;
}

// The axes along the wall surface of normal `axis` (the second unused in 2-D).
template <int D>
std::array<int, 2> tangent_axes(int axis) {
    std::array<int, 2> tangent{};
    for (int a = 0, k = 0; a < D; ++a)
        if (a != axis)
            tangent[static_cast<std::size_t>(k++)] = a;
    return tangent;
}

// A sensor face's sample points: centres of the n^(D-1) cells of a lattice of spacing <=
// `spacing` over the diameter's square, kept where inside the disc (every one in 2-D); a
// zero diameter gives the centre alone.
template <int D>
std::vector<Vec<D>> face_samples(const SensorFace<D>& face, Real spacing) {
    const Real radius = face.diameter / 2;
    const int n = std::max(1, static_cast<int>(std::ceil(face.diameter / spacing - Real(1e-9))));
    const Real step = face.diameter / Real(n);
    const std::array<int, 2> tangent = tangent_axes<D>(face.normal_axis);
    const int n2 = D == 3 ? n : 1;
    std::vector<Vec<D>> out;
    for (int u = 0; u < n; ++u)
        for (int w = 0; w < n2; ++w) {
            Vec<D> y = face.centre;
            const Real du = (Real(u) + Real(0.5)) * step - radius;
            y[tangent[0]] += du;
            Real r2t = du * du;
            if constexpr (D == 3) {
                const Real dw = (Real(w) + Real(0.5)) * step - radius;
                y[tangent[1]] += dw;
                r2t += dw * dw;
            }
            if (D == 3 && n > 1 && r2t > radius * radius)
                continue;
            out.push_back(y);
        }
    return out;
}

// The Shepard interpolation of the pressure at y, sum_j p_j W_j V_j / sum_j W_j V_j with each
// p_j clipped below at p_min, over the candidates `each` offers (each(f) calls f(j) in a fixed
// order); `wet`: whether a fluid particle is within the support. Zero weight (nothing within
// the support) reads 0.
template <int D, class K, class Candidates>
Real shepard_pressure(const Particles<D>& P, const K& kernel, const Vec<D>& y, Real p_min,
                      Candidates&& each, bool& wet) {
    const Real support2 = kernel.support() * kernel.support();
    Real num = 0, den = 0;
    wet = false;
    each([&](std::size_t j) {
        const Real r2 = (P.x[j] - y).squaredNorm();
        if (r2 >= support2)
            return;
        const Real wv = kernel.W(std::sqrt(r2)) * P.mass[j] / P.rho[j];
        num += std::max(P.p[j], p_min) * wv;
        den += wv;
        wet = wet || P.kind[j] == Kind::fluid;
    });
    return den > 0 ? num / den : Real(0);
}

template <int D, class K>
Real sensor_with(const Particles<D>& P, const K& kernel, const SensorFace<D>& face, Real spacing,
                 Real p_min) {
    const Real support = kernel.support();
    const Real radius = face.diameter / 2;
    // The particles that can reach any sample point.
    std::vector<std::size_t> near;
    const Real reach2 = (radius + support) * (radius + support);
    for (std::size_t j = 0; j < P.size(); ++j)
        if ((P.x[j] - face.centre).squaredNorm() < reach2)
            near.push_back(j);
    const auto each_near = [&](auto&& f) {
        for (std::size_t j : near)
            f(j);
    };
    double sum = 0;
    int points = 0, wet = 0;
    for (const Vec<D>& y : face_samples(face, spacing)) {
        bool fluid = false;
        sum += double(shepard_pressure(P, kernel, y, p_min, each_near, fluid));
        ++points;
        wet += fluid ? 1 : 0;
    }
    if (wet == 0 || points == 0)
        return std::numeric_limits<Real>::quiet_NaN();
    return Real(sum / points);
}

// The cell centres of a lattice of spacing <= `spacing` on a patch, and the area (length in 2-D)
// of each cell; none when the patch is empty along a tangential axis.
template <int D>
std::vector<Vec<D>> patch_samples(const WallPatch<D>& patch, Real spacing, double& cell_area) {
    const std::array<int, 2> tangent = tangent_axes<D>(patch.normal_axis);
    std::array<int, 2> n{1, 1};
    std::array<Real, 2> step{0, 0};
    cell_area = 1;
    for (std::size_t t = 0; t < static_cast<std::size_t>(D - 1); ++t) {
        const Real extent = patch.hi[tangent[t]] - patch.lo[tangent[t]];
        if (!(extent > 0))
            return {};
        n[t] = std::max(1, static_cast<int>(std::ceil(extent / spacing - Real(1e-9))));
        step[t] = extent / Real(n[t]);
        cell_area *= double(step[t]);
    }
    std::vector<Vec<D>> out;
    out.reserve(static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]));
    for (int u = 0; u < n[0]; ++u)
        for (int w = 0; w < (D == 3 ? n[1] : 1); ++w) {
            Vec<D> y = patch.lo;
            y[patch.normal_axis] = patch.at;
            y[tangent[0]] += (Real(u) + Real(0.5)) * step[0];
            if constexpr (D == 3)
                y[tangent[1]] += (Real(w) + Real(0.5)) * step[1];
            out.push_back(y);
        }
    return out;
}

template <int D, class K>
WallLoad interpolated_load_with(const Particles<D>& P, const K& kernel,
                                const std::vector<WallPatch<D>>& patches, Real spacing,
                                Real p_floor, const Vec<D>& c) {
    const ParticleCells<D> cells = all_cells(P, kernel.support());
    WallLoad out;
    for (const WallPatch<D>& patch : patches) {
        double area = 0;
        for (const Vec<D>& y : patch_samples(patch, spacing, area)) {
            ++out.wall_particles;
            bool wet = false;
            const Real p = shepard_pressure(
                P, kernel, y, p_floor, [&](auto&& f) { cells.around(y, f); }, wet);
            if (!wet)
                continue;
            ++out.pairs;
            Eigen::Matrix<double, D, 1> f = Eigen::Matrix<double, D, 1>::Zero();
            f[patch.normal_axis] = double(patch.into_wall) * (double(p) - double(p_floor)) * area;
            add_load<D>(out, (y - c).template cast<double>(), f);
        }
    }
    return out;
}

// Largest tangential offset (max norm) between a point and a wall particle on the surface.
template <int D>
Real tangential_distance(const Vec<D>& a, const Vec<D>& b, const std::array<int, 2>& tangent) {
    Real d = std::abs(a[tangent[0]] - b[tangent[0]]);
    if constexpr (D == 3)
        d = std::max(d, std::abs(a[tangent[1]] - b[tangent[1]]));
    return d;
}

template <int D, class K>
Real force_sensor_with(const Particles<D>& P, const K& kernel, const WallLoadParams<D>& prm,
                       const SensorFace<D>& face, Real wall_dx) {
    const int axis = face.normal_axis;
    const std::array<int, 2> tangent = tangent_axes<D>(axis);
    const Real surface = face.centre[axis];
    const Real reach = face.diameter / 2 + wall_dx; // tangential reach of the columns kept
    // The wall particles behind the face, every layer the fluid reaches through the surface.
    std::vector<std::size_t> walls;
    for (std::size_t j = 0; j < P.size(); ++j) {
        const Real depth = Real(face.into_wall) * (P.x[j][axis] - surface);
        if (P.kind[j] == Kind::wall && depth > 0 && depth < kernel.support() &&
            tangential_distance<D>(P.x[j], face.centre, tangent) <= reach)
            walls.push_back(j);
    }
    std::vector<double> normal_force(walls.size());
    std::size_t pairs = 0, k = 0;
    for_each_wall_force(P, kernel, prm, walls, [&](std::size_t, const auto& f, std::size_t n) {
        normal_force[k++] = double(face.into_wall) * f[axis];
        pairs += n;
    });
    if (pairs == 0)
        return std::numeric_limits<Real>::quiet_NaN();
    // Each sample point reads the traction of the wall column (all layers at one tangential
    // position) whose patch of the surface holds it: the nearest column, if within half a
    // spacing; the column's force over its patch's area, wall_dx^(D-1).
    const double patch = D == 3 ? double(wall_dx) * double(wall_dx) : double(wall_dx);
    const Real same_column = wall_dx / 4;
    double sum = 0;
    std::size_t points = 0;
    for (const Vec<D>& y : face_samples(face, wall_dx / 8)) {
        ++points;
        std::size_t nearest = walls.size();
        Real best = wall_dx / 2 * (1 + Real(1e-6));
        for (std::size_t m = 0; m < walls.size(); ++m) {
            const Real d = tangential_distance<D>(P.x[walls[m]], y, tangent);
            if (d < best) {
                best = d;
                nearest = m;
            }
        }
        if (nearest == walls.size())
            continue; // off the wall's edge: no wall carries this part of the face
        double column = 0;
        for (std::size_t m = 0; m < walls.size(); ++m)
            if (tangential_distance<D>(P.x[walls[m]], P.x[walls[nearest]], tangent) < same_column)
                column += normal_force[m];
        sum += column / patch;
    }
    return Real(double(prm.p_gauge) + sum / double(points));
}

template <int D, class K>
Real oriented_force_sensor_with(const Particles<D>& P, const K& kernel,
                                const WallLoadParams<D>& prm, const OrientedSensorFace<D>& face,
                                const std::vector<std::size_t>& candidates, Real wall_dx) {
    const Real radius = face.diameter / 2;
    std::vector<std::size_t> walls;
    std::size_t innermost = 0;
    for (std::size_t j : candidates) {
        const Vec<D> r = P.x[j] - face.centre;
        const Real depth = r.dot(face.into_wall);
        if (P.kind[j] != Kind::wall || !(depth > 0) || depth >= kernel.support())
            continue;
        if ((r - depth * face.into_wall).norm() > radius)
            continue;
        walls.push_back(j);
        innermost += depth < wall_dx ? 1 : 0;
    }
    double normal_force = 0;
    std::size_t pairs = 0;
    for_each_wall_force(P, kernel, prm, walls, [&](std::size_t, const auto& f, std::size_t n) {
        for (int d = 0; d < D; ++d)
            normal_force += double(face.into_wall[d]) * double(f[d]);
        pairs += n;
    });
    if (pairs == 0 || innermost == 0)
        return std::numeric_limits<Real>::quiet_NaN();
    const double area = double(innermost) * std::pow(double(wall_dx), D - 1);
    return Real(double(prm.p_gauge) + normal_force / area);
}

// Whether x lies in the closed box [lo, hi].
template <int D>
bool in_closed_box(const Vec<D>& x, const Vec<D>& lo, const Vec<D>& hi) {
    for (int a = 0; a < D; ++a)
        if (!(x[a] >= lo[a] && x[a] <= hi[a]))
            return false;
    return true;
}

// The contacts that `keep` accepts, in (fluid, wall) id order (a pair meets once per step,
// except through two periodic images, whose positions break the tie): the order every contact
// sum follows, so that it does not depend on the order the contacts were recorded in (threads,
// ranks).
template <int D, class Keep>
std::vector<const WallContact<D>*> contacts_in_id_order(const std::vector<WallContact<D>>& contacts,
                                                        Keep&& keep) {
    std::vector<const WallContact<D>*> out;
    for (const WallContact<D>& c : contacts)
        if (keep(c))
            out.push_back(&c);
    std::sort(out.begin(), out.end(), [](const WallContact<D>* a, const WallContact<D>* b) {
        if (a->fluid != b->fluid)
            return a->fluid < b->fluid;
        if (a->wall != b->wall)
            return a->wall < b->wall;
        return std::lexicographical_compare(a->wall_x.data(), a->wall_x.data() + D,
                                            b->wall_x.data(), b->wall_x.data() + D);
    });
    return out;
}

} // namespace

template <int D>
void refresh_dummy_walls(Particles<D>& P, const AnyKernel<D>& kernel, const Eos& eos,
                         const Vec<D>& gravity, Real wall_volume) {
    std::visit(
        [&](const auto& k) {
            const Real support = k.support();
            const ParticleCells<D> fluid = fluid_cells(P, support);
            for (std::size_t w = 0; w < P.size(); ++w) {
                if (P.kind[w] != Kind::wall)
                    continue;
                AdamiSums<D> sums;
                fluid.around(P.x[w], [&](std::size_t f) {
                    const Vec<D> dx = P.x[w] - P.x[f];
                    const Real r2 = dx.squaredNorm();
                    if (r2 < support * support)
                        sums.add(k.W(std::sqrt(r2)), P.p[f], P.rho[f], dx, P.v[f]);
                });
                P.p[w] = sums.pressure(gravity, eos.p_background);
                P.rho[w] = eos.density(P.p[w]);
                P.mass[w] = P.rho[w] * wall_volume;
            }
        },
        kernel);
}

template <int D>
std::vector<std::size_t> wall_particles_in(const Particles<D>& P, const Vec<D>& lo,
                                           const Vec<D>& hi) {
    std::vector<std::size_t> out;
    for (std::size_t j = 0; j < P.size(); ++j)
        if (P.kind[j] == Kind::wall && in_closed_box<D>(P.x[j], lo, hi))
            out.push_back(j);
    return out;
}

template <int D>
WallLoad wall_load(const Particles<D>& P, const AnyKernel<D>& kernel, const WallLoadParams<D>& prm,
                   const std::vector<std::size_t>& walls, const Vec<D>& moment_point) {
    return std::visit([&](const auto& k) { return load_with(P, k, prm, walls, moment_point); },
                      kernel);
}

template <int D>
Real wall_pressure_sensor(const Particles<D>& P, const AnyKernel<D>& kernel,
                          const SensorFace<D>& face, Real spacing, Real p_min) {
    return std::visit([&](const auto& k) { return sensor_with(P, k, face, spacing, p_min); },
                      kernel);
}

template <int D>
WallLoad interpolated_wall_load(const Particles<D>& P, const AnyKernel<D>& kernel,
                                const std::vector<WallPatch<D>>& patches, Real spacing,
                                Real p_floor, const Vec<D>& moment_point) {
    return std::visit(
        [&](const auto& k) {
            return interpolated_load_with(P, k, patches, spacing, p_floor, moment_point);
        },
        kernel);
}

template <int D>
WallLoad contact_wall_load(const std::vector<WallContact<D>>& contacts, const Vec<D>& lo,
                           const Vec<D>& hi, const Vec<D>& moment_point) {
    const auto inside = [&](const WallContact<D>& c) { return in_closed_box<D>(c.wall_x, lo, hi); };
    WallLoad out;
    for (const WallContact<D>* c : contacts_in_id_order(contacts, inside)) {
        add_load<D>(out, (c->wall_x - moment_point).template cast<double>(),
                    c->force.template cast<double>());
        ++out.pairs;
    }
    return out;
}

template <int D>
Real contact_traction(const std::vector<WallContact<D>>& contacts, const SensorFace<D>& face,
                      Real wall_dx, Real depth, Real spread) {
    const int axis = face.normal_axis;
    const std::array<int, 2> tangent = tangent_axes<D>(axis);
    const Real surface = face.centre[axis];
    const Real reach = face.diameter / 2 + spread;
    const auto near = contacts_in_id_order(contacts, [&](const WallContact<D>& c) {
        const Real d = Real(face.into_wall) * (c.wall_x[axis] - surface);
        return d > 0 && d < depth &&
               tangential_distance<D>(c.wall_x, face.centre, tangent) <= reach;
    });
    if (near.empty())
        return 0;
    const double area = D == 3 ? 4.0 * double(spread) * double(spread) : 2.0 * double(spread);
    double sum = 0;
    std::size_t points = 0;
    for (const Vec<D>& y : face_samples(face, wall_dx / 8)) {
        ++points;
        for (const WallContact<D>* c : near)
            if (tangential_distance<D>(c->wall_x, y, tangent) < spread)
                sum += double(face.into_wall) * double(c->force[axis]) / area;
    }
    return points > 0 ? Real(sum / double(points)) : Real(0);
}

template <int D>
Real wall_force_sensor(const Particles<D>& P, const AnyKernel<D>& kernel,
                       const WallLoadParams<D>& prm, const SensorFace<D>& face, Real wall_dx) {
    return std::visit([&](const auto& k) { return force_sensor_with(P, k, prm, face, wall_dx); },
                      kernel);
}

template <int D>
Real oriented_wall_force_sensor(const Particles<D>& P, const AnyKernel<D>& kernel,
                                const WallLoadParams<D>& prm, const OrientedSensorFace<D>& face,
                                const std::vector<std::size_t>& candidates, Real wall_dx) {
    return std::visit(
        [&](const auto& k) {
            return oriented_force_sensor_with(P, k, prm, face, candidates, wall_dx);
        },
        kernel);
}

template Real oriented_wall_force_sensor<2>(const Particles<2>&, const AnyKernel<2>&,
                                            const WallLoadParams<2>&, const OrientedSensorFace<2>&,
                                            const std::vector<std::size_t>&, Real);
template Real oriented_wall_force_sensor<3>(const Particles<3>&, const AnyKernel<3>&,
                                            const WallLoadParams<3>&, const OrientedSensorFace<3>&,
                                            const std::vector<std::size_t>&, Real);
template void refresh_dummy_walls<2>(Particles<2>&, const AnyKernel<2>&, const Eos&, const Vec<2>&,
                                     Real);
template void refresh_dummy_walls<3>(Particles<3>&, const AnyKernel<3>&, const Eos&, const Vec<3>&,
                                     Real);
template std::vector<std::size_t> wall_particles_in<2>(const Particles<2>&, const Vec<2>&,
                                                       const Vec<2>&);
template std::vector<std::size_t> wall_particles_in<3>(const Particles<3>&, const Vec<3>&,
                                                       const Vec<3>&);
template WallLoad wall_load<2>(const Particles<2>&, const AnyKernel<2>&, const WallLoadParams<2>&,
                               const std::vector<std::size_t>&, const Vec<2>&);
template WallLoad wall_load<3>(const Particles<3>&, const AnyKernel<3>&, const WallLoadParams<3>&,
                               const std::vector<std::size_t>&, const Vec<3>&);
template Real wall_pressure_sensor<2>(const Particles<2>&, const AnyKernel<2>&,
                                      const SensorFace<2>&, Real, Real);
template Real wall_pressure_sensor<3>(const Particles<3>&, const AnyKernel<3>&,
                                      const SensorFace<3>&, Real, Real);
template WallLoad contact_wall_load<2>(const std::vector<WallContact<2>>&, const Vec<2>&,
                                       const Vec<2>&, const Vec<2>&);
template WallLoad contact_wall_load<3>(const std::vector<WallContact<3>>&, const Vec<3>&,
                                       const Vec<3>&, const Vec<3>&);
template Real contact_traction<2>(const std::vector<WallContact<2>>&, const SensorFace<2>&, Real,
                                  Real, Real);
template Real contact_traction<3>(const std::vector<WallContact<3>>&, const SensorFace<3>&, Real,
                                  Real, Real);
template Real wall_force_sensor<2>(const Particles<2>&, const AnyKernel<2>&,
                                   const WallLoadParams<2>&, const SensorFace<2>&, Real);
template Real wall_force_sensor<3>(const Particles<3>&, const AnyKernel<3>&,
                                   const WallLoadParams<3>&, const SensorFace<3>&, Real);
template WallLoad interpolated_wall_load<2>(const Particles<2>&, const AnyKernel<2>&,
                                            const std::vector<WallPatch<2>>&, Real, Real,
                                            const Vec<2>&);
template WallLoad interpolated_wall_load<3>(const Particles<3>&, const AnyKernel<3>&,
                                            const std::vector<WallPatch<3>>&, Real, Real,
                                            const Vec<3>&);

} // namespace sluice
