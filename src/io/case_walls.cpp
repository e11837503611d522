// The [walls] table of a case file (case_walls.hpp).
#include "case_walls.hpp"

#include "sluice/io/case_reader.hpp"
#include "sluice/physics/kernels.hpp"

#include "case_limits.hpp"
#include "case_meshes.hpp"
#include "case_motions.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace sluice::case_file {
namespace {

const std::vector<std::pair<std::string, WallModel>> kWalls = {
    {"none", WallModel::none}, {"reflective", WallModel::reflective}, {"dummy", WallModel::dummy}};

// Two axis-aligned boxes share volume (more than the slack on every axis).
bool boxes_overlap(const Triple& lo1, const Triple& hi1, const Triple& lo2, const Triple& hi2,
                   std::size_t dim, double eps) {
    bool overlap = true;
    for (std::size_t a = 0; a < dim; ++a)
        overlap = overlap && std::min(hi1[a], hi2[a]) - std::max(lo1[a], lo2[a]) > eps;
    return overlap;
}

// How far two overlapping boxes reach into each other: the smallest overlap over the axes, and
// that axis ("by 0.02 m along x" is what separating them takes).
std::string overlap_depth(const Triple& lo1, const Triple& hi1, const Triple& lo2,
                          const Triple& hi2, std::size_t dim) {
    double depth = std::numeric_limits<double>::infinity();
    std::size_t along = 0;
    for (std::size_t a = 0; a < dim; ++a) {
        const double d = std::min(hi1[a], hi2[a]) - std::max(lo1[a], lo2[a]);
        if (d < depth) {
            depth = d;
            along = a;
        }
    }
    return fmt::format("by {:.4g} m along {}", depth, kAxis[along]);
}

} // namespace

void read_walls(const Section& s, CaseConfig& c) {
    c.walls = s.choice("model", c.walls, kWalls);
    const double eps = slack(c);
    const auto dim = static_cast<std::size_t>(c.dimension);
    if (c.walls != WallModel::none) {
        c.tank_lo = s.required_triple("tank_lo", "lower corner of the tank [m]; needed when "
                                                 "walls.model is not \"none\"");
        c.tank_hi = s.required_triple("tank_hi", "upper corner of the tank [m]; needed when "
                                                 "walls.model is not \"none\"");
        for (std::size_t a = 0; a < dim; ++a) {
            s.require(c.tank_lo[a] < c.tank_hi[a], "tank_hi",
                      fmt::format("must be above walls.tank_lo on every axis; on {}: lo = {}, "
                                  "hi = {}",
                                  kAxis[a], c.tank_lo[a], c.tank_hi[a]));
            s.require(c.tank_lo[a] >= c.domain_lo[a] - eps, "tank_lo",
                      fmt::format("the tank lies outside the domain: {} = {} is below "
                                  "domain.lo = {}",
                                  kAxis[a], c.tank_lo[a], c.domain_lo[a]));
            s.require(c.tank_hi[a] <= c.domain_hi[a] + eps, "tank_hi",
                      fmt::format("the tank lies outside the domain: {} = {} is above "
                                  "domain.hi = {}",
                                  kAxis[a], c.tank_hi[a], c.domain_hi[a]));
        }
        std::vector<std::string> all = {"x-", "x+", "y-", "y+"};
        if (c.dimension == 3)
            all.insert(all.end(), {"z-", "z+"});
        c.tank_faces = s.strings("tank_faces").value_or(all);
        std::set<std::string> seen;
        for (const auto& f : c.tank_faces) {
            // The schema's choices include z; a 2-D case has no z faces.
            s.require(std::find(all.begin(), all.end(), f) != all.end(), "tank_faces",
                      fmt::format("unknown face \"{}\"; allowed in {}-D: {}", f, c.dimension,
                                  join_list(all)));
            s.require(seen.insert(f).second, "tank_faces",
                      fmt::format("face \"{}\" is listed twice", f));
            const auto a = static_cast<std::size_t>(f[0] - 'x');
            s.require(
                !c.periodic[a], "tank_faces",
                fmt::format("face \"{}\" carries a wall but the {} axis is periodic", f, kAxis[a]));
        }
    } else {
        // Without walls there is no tank; keys given anyway are still checked for type.
        (void)s.triple("tank_lo");
        (void)s.triple("tank_hi");
        (void)s.strings("tank_faces");
    }
    c.tank_motion = motion_reference(s, "tank_motion", c);
    c.restitution = s.number("restitution", c.restitution);
    c.no_slip = s.boolean("no_slip").value_or(c.no_slip);

    for (const auto& p : s.entries("planes")) {
        WallPlane w;
        w.point = p.required_triple("point", "a point on the plane [m]");
        w.normal = p.required_triple("normal", "normal pointing into the fluid side");
        // Scaled by its largest component first, so that neither [1e200, 1e200] overflows
        // nor [1e-200, 0] underflows on the way to a unit vector.
        double largest = 0;
        for (double x : w.normal)
            largest = std::max(largest, std::abs(x));
        p.require(largest > 0, "normal", "must not be the zero vector");
        double len2 = 0;
        for (double& x : w.normal) {
            x /= largest;
            len2 += x * x;
        }
        // Stored as a unit vector so the solver can use it for distances directly.
        const double len = std::sqrt(len2);
        for (double& x : w.normal)
            x /= len;
        c.planes.push_back(w);
    }

    // Boxes are shells of dummy particles `layers` sites deep (as the tank's walls); their sum
    // is held to the particle limit here, before anything is allocated.
    const double layers = std::ceil(kernel_support_factor(c.kernel) * c.h_over_dx);
    double box_particles = 0;
    for (const auto& b : s.entries("boxes")) {
        b.require(c.walls == WallModel::dummy, "lo",
                  "wall boxes are made of dummy wall particles: they need walls.model = \"dummy\"");
        WallBox box;
        box.lo = b.required_triple("lo", "lower corner of the solid box [m]");
        box.hi = b.required_triple("hi", "upper corner of the solid box [m]");
        box.motion = motion_reference(b, "motion", c);
        for (std::size_t a = 0; a < dim; ++a) {
            b.require(box.lo[a] < box.hi[a], "hi",
                      fmt::format("must be above lo on every axis; on {}: lo = {}, hi = {}",
                                  kAxis[a], box.lo[a], box.hi[a]));
            b.require(box.lo[a] >= c.domain_lo[a] - eps, "lo",
                      fmt::format("the box lies outside the domain: {} = {} is below "
                                  "domain.lo = {}",
                                  kAxis[a], box.lo[a], c.domain_lo[a]));
            b.require(box.hi[a] <= c.domain_hi[a] + eps, "hi",
                      fmt::format("the box lies outside the domain: {} = {} is above "
                                  "domain.hi = {}",
                                  kAxis[a], box.hi[a], c.domain_hi[a]));
            // Its wall layers are laid from each face inwards, the first dx/2 inside: a box
            // thinner than dx cannot hold one layer with its surface where the case puts it.
            b.require(box.hi[a] - box.lo[a] >= c.dx * (1 - 1e-9), "hi",
                      fmt::format("the box is {} m thick along {}, less than dx = {} m: it "
                                  "cannot hold one layer of wall particles",
                                  box.hi[a] - box.lo[a], kAxis[a], c.dx));
        }
        // Tank wall layers lie outside the walled faces; a box reaching past one would put
        // two wall particles on one site.
        for (const auto& f : c.tank_faces) {
            const auto a = static_cast<std::size_t>(f[0] - 'x');
            const bool low = f[1] == '-';
            const bool inside =
                low ? box.lo[a] >= c.tank_lo[a] - eps : box.hi[a] <= c.tank_hi[a] + eps;
            b.require(inside, low ? "lo" : "hi",
                      fmt::format("the box extends {:.4g} m beyond the tank wall \"{}\" at {} = {}",
                                  low ? c.tank_lo[a] - box.lo[a] : box.hi[a] - c.tank_hi[a], f,
                                  kAxis[a], low ? c.tank_lo[a] : c.tank_hi[a]));
        }
        for (std::size_t j = 0; j < c.boxes.size(); ++j)
            b.require(
                !boxes_overlap(box.lo, box.hi, c.boxes[j].lo, c.boxes[j].hi, dim, eps), "lo",
                fmt::format("the box overlaps walls.boxes[{}] {}", j,
                            overlap_depth(box.lo, box.hi, c.boxes[j].lo, c.boxes[j].hi, dim)));
        // A free body displaces the fluid it is placed in (a floating box): the blocks' sites
        // within it are left out. A fixed box must not lie in a block.
        const bool displaces =
            box.motion >= 0 &&
            c.motions[static_cast<std::size_t>(box.motion)].kind == MotionKind::free_body;
        for (std::size_t j = 0; j < c.blocks.size() && !displaces; ++j)
            b.require(
                !boxes_overlap(box.lo, box.hi, c.blocks[j].lo, c.blocks[j].hi, dim, eps), "lo",
                fmt::format("the box overlaps the fluid of blocks[{}] {} (only a free "
                            "body's box may: it displaces the fluid)",
                            j, overlap_depth(box.lo, box.hi, c.blocks[j].lo, c.blocks[j].hi, dim)));
        double all = 1, deep = 1; // lattice sites of the box, and those below its shell
        for (std::size_t a = 0; a < dim; ++a) {
            const double n = std::max(1.0, std::round((box.hi[a] - box.lo[a]) / c.dx));
            all *= n;
            deep *= std::max(0.0, n - 2 * layers);
        }
        box_particles += all - deep;
        b.require(box_particles <= hostile_case_particles, "hi",
                  fmt::format("the wall boxes would hold about {:.3g} particles (their surface "
                              "{:g} lattice sites deep), beyond any machine (more than {:.0e}); "
                              "increase dx or make the boxes smaller",
                              box_particles, layers, hostile_case_particles));
        c.boxes.push_back(box);
    }
    read_wall_meshes(s, c);
}

// Fluid must start on the inner side of every wall-carrying tank face.
void check_blocks_in_tank(const Section& root, const CaseConfig& c) {
    if (c.walls == WallModel::none)
        return;
    const double eps = slack(c);
    for (std::size_t i = 0; i < c.blocks.size(); ++i) {
        const auto& b = c.blocks[i];
        for (const auto& f : c.tank_faces) {
            const auto a = static_cast<std::size_t>(f[0] - 'x');
            const bool low = f[1] == '-';
            const bool inside = low ? b.lo[a] >= c.tank_lo[a] - eps : b.hi[a] <= c.tank_hi[a] + eps;
            if (!inside)
                root.reader().fail(
                    fmt::format("blocks[{}].{}", i, low ? "lo" : "hi"),
                    fmt::format("the block extends beyond the tank wall \"{}\" at {} = {}", f,
                                kAxis[a], low ? c.tank_lo[a] : c.tank_hi[a]));
            // The lattice keeps its last particle centre dx/4 inside a walled upper face
            // (block_lattice_count): a block that leaves no room for one is refused.
            if (!low && std::floor((c.tank_hi[a] - b.lo[a]) / c.dx + 0.25 + 1e-9) < 1)
                root.reader().fail(
                    fmt::format("blocks[{}].hi", i),
                    fmt::format("the block starts {} m from the tank wall \"{}\", less than "
                                "3/4 dx = {} m: no particle fits on its lattice",
                                c.tank_hi[a] - b.lo[a], f, 0.75 * c.dx));
        }
    }
}

} // namespace sluice::case_file
