// The [case], [domain], [fluid], [particles] and [[blocks]] tables of a case file
// (case_fluid.hpp).
#include "case_fluid.hpp"

#include "case_limits.hpp"
#include "case_meshes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sluice::case_file {
namespace {

const std::vector<std::pair<std::string, EosType>> kEos = {{"linear", EosType::linear},
                                                           {"tait", EosType::tait}};
const std::vector<std::pair<std::string, VelocityProfile>> kProfiles = {
    {"uniform", VelocityProfile::uniform},
    {"taylor_green", VelocityProfile::taylor_green},
    {"rotating", VelocityProfile::rotating},
    {"strain", VelocityProfile::strain}};
const std::vector<std::pair<std::string, ParticleExit>> kParticleExits = {
    {"stop", ParticleExit::stop}, {"remove", ParticleExit::remove}};
const std::vector<std::pair<std::string, BlockShape>> kShapes = {
    {"box", BlockShape::box}, {"ellipse", BlockShape::ellipse}, {"mesh", BlockShape::mesh}};

// shape = "mesh": a closed shape's file (the [[walls.meshes]] keys but role); the block is the
// part of it inside lo/hi (each optional), its lattice from that box's lower corner.
void read_block_mesh(const Section& s, const CaseConfig& c, FluidBlock& b) {
    const auto lo = s.triple("lo"), hi = s.triple("hi");
    auto m = std::make_shared<WallMesh>();
    const ShapeReport r = read_shape_file(s, c, *m);
    require_closed_outward(s, c, *m, r, " to fill", "");
    // lo and hi, where given, cut the shape: a container's volume filled to a level.
    for (std::size_t a = 0; a < 3; ++a) {
        b.lo[a] = lo ? std::max(r.lo[a], (*lo)[a]) : r.lo[a];
        b.hi[a] = hi ? std::min(r.hi[a], (*hi)[a]) : r.hi[a];
    }
    b.mesh = std::move(m);
}

// Keys of the rotating and strain profiles: each needs its rate, only in 2-D, and the strain
// profile's pressure is known for an ellipse only. An ellipse has no flat top, so the
// hydrostatic start (depth below the box top) is refused under gravity.
void read_block_profile(const Section& s, const CaseConfig& c, FluidBlock& b) {
    const auto rate = [&](std::string_view key, VelocityProfile owner, const char* owner_name,
                          const char* what) {
        const auto v = s.number(key);
        if (b.profile != owner) {
            s.require(!v, key, fmt::format("applies only to profile = \"{}\"", owner_name));
            return 0.0;
        }
        if (!v)
            s.reader().fail(s.key(key), fmt::format("missing required key ({}; needed with "
                                                    "profile = \"{}\")",
                                                    what, owner_name));
        s.require(c.dimension == 2, "profile",
                  fmt::format("\"{}\" is a 2-D profile; this case is 3-D", owner_name));
        return *v;
    };
    b.angular_velocity = rate("angular_velocity", VelocityProfile::rotating, "rotating",
                              "angular velocity [rad/s], counter-clockwise positive");
    b.strain_rate = rate("strain_rate", VelocityProfile::strain, "strain", "strain rate A0 [1/s]");
    if (b.shape == BlockShape::mesh)
        s.require(b.profile == VelocityProfile::uniform, "profile",
                  "a mesh block starts with a uniform velocity (profile = \"uniform\")");
    if (b.profile == VelocityProfile::strain)
        s.require(b.shape == BlockShape::ellipse, "shape",
                  "profile = \"strain\" needs shape = \"ellipse\" (its initial pressure is "
                  "known for an elliptical drop only)");
    const auto up = static_cast<std::size_t>(c.dimension - 1);
    if (b.shape == BlockShape::ellipse && b.hydrostatic && c.gravity[up] != 0)
        s.require(false, "hydrostatic",
                  "an ellipse-shaped block has no flat top for the hydrostatic start; set "
                  "hydrostatic = false (or switch gravity off)");
}

} // namespace

void read_case_table(const Section& s, CaseConfig& c, Reader& r, const std::string& path) {
    const auto d = s.integer("dimension");
    if (!d)
        s.reader().fail(s.key("dimension"), "missing required key (2 or 3)");
    c.dimension = static_cast<int>(*d);
    r.dim = c.dimension;

    c.name = s.string("name").value_or(std::filesystem::path(path).stem().string());
    // The name becomes the default results folder results/<name>.
    const bool bad_name =
        c.name.empty() || c.name == "." || c.name == ".." ||
        std::any_of(c.name.begin(), c.name.end(), [](char ch) {
            return ch == '/' || ch == '\\' || std::iscntrl(static_cast<unsigned char>(ch)) != 0;
        });
    s.require(!bad_name, "name",
              fmt::format("\"{}\" cannot be used as a folder name (no '/', '\\', control "
                          "characters, '.' or '..')",
                          c.name));
    s.require(c.name.size() <= kMaxNameLength, "name",
              fmt::format("is {} bytes long; at most {} (it becomes a folder name)", c.name.size(),
                          kMaxNameLength));
    c.description = s.string("description").value_or("");
}

void read_domain(const Section& s, CaseConfig& c) {
    c.domain_lo = s.required_triple("lo", "lower corner of the domain [m]");
    c.domain_hi = s.required_triple("hi", "upper corner of the domain [m]");
    for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a)
        s.require(c.domain_lo[a] < c.domain_hi[a], "hi",
                  fmt::format("must be above domain.lo on every axis; on {}: lo = {}, hi = {}",
                              kAxis[a], c.domain_lo[a], c.domain_hi[a]));
    if (const auto* n = s.node("periodic")) {
        const auto* arr = n->as_array();
        s.require(
            arr != nullptr && arr->size() == static_cast<std::size_t>(c.dimension), "periodic",
            fmt::format("expected an array of exactly {} booleans (one per axis)", c.dimension));
        for (std::size_t a = 0; a < arr->size(); ++a) {
            const auto* b = (*arr)[a].as_boolean();
            if (b == nullptr)
                s.reader().fail(fmt::format("{}[{}]", s.key("periodic"), a),
                                "expected true or false, got " + type_name((*arr)[a]), n);
            c.periodic[a] = b->get();
        }
    }
    c.particle_exit = s.choice("particle_exit", c.particle_exit, kParticleExits);
}

void read_fluid(const Section& s, CaseConfig& c) {
    c.rho0 = s.required_number("rho0", "reference density [kg/m^3]");
    c.viscosity = s.required_number("viscosity", "dynamic viscosity [Pa s], 0 for inviscid");
    c.sound_speed = s.required_number("sound_speed", "artificial speed of sound [m/s]");
    // Gravity points down the last axis: -y in 2-D, -z in 3-D.
    c.gravity = c.dimension == 2 ? Triple{0, -9.81, 0} : Triple{0, 0, -9.81};
    if (auto g = s.triple("gravity"))
        c.gravity = *g;
    c.eos = s.choice("eos", c.eos, kEos);
    c.gamma = s.number("gamma", c.gamma);
    c.background_pressure = s.number("background_pressure", c.background_pressure);
}

void read_particles(const Section& s, CaseConfig& c) {
    c.dx = s.required_number("dx", "lattice spacing [m]");
    c.jitter = s.number("jitter", c.jitter);
}

void read_blocks(const Section& root, CaseConfig& c) {
    const auto blocks = root.entries("blocks");
    if (blocks.empty())
        root.reader().fail("blocks", "missing required key: at least one [[blocks]] fluid block "
                                     "is needed");
    const double eps = slack(c);
    for (const auto& s : blocks) {
        FluidBlock b;
        b.shape = s.choice("shape", b.shape, kShapes);
        if (b.shape == BlockShape::mesh) {
            read_block_mesh(s, c, b);
        } else {
            for (const char* key :
                 {"file", "scale", "rotation", "translation", "flip_normals", "section_z"})
                s.require(s.node(key) == nullptr, key, "applies only to shape = \"mesh\"");
            b.lo = s.required_triple("lo", "lower corner of the block [m]");
            b.hi = s.required_triple("hi", "upper corner of the block [m]");
        }
        for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a) {
            s.require(b.lo[a] < b.hi[a], "hi",
                      fmt::format("must be above lo on every axis; on {}: lo = {}, hi = {}",
                                  kAxis[a], b.lo[a], b.hi[a]));
            s.require(b.lo[a] >= c.domain_lo[a] - eps, "lo",
                      fmt::format("the block lies outside the domain: {} = {} is below "
                                  "domain.lo = {}",
                                  kAxis[a], b.lo[a], c.domain_lo[a]));
            s.require(b.hi[a] <= c.domain_hi[a] + eps, "hi",
                      fmt::format("the block lies outside the domain: {} = {} is above "
                                  "domain.hi = {}",
                                  kAxis[a], b.hi[a], c.domain_hi[a]));
        }
        if (auto v = s.triple("velocity"))
            b.velocity = *v;
        b.profile = s.choice("profile", b.profile, kProfiles);
        b.amplitude = s.number("amplitude", b.amplitude);
        b.hydrostatic = s.boolean("hydrostatic").value_or(b.hydrostatic);
        read_block_profile(s, c, b);

        // Two blocks sharing volume would put two particles on one lattice site.
        for (std::size_t j = 0; j < c.blocks.size(); ++j) {
            bool overlap = true;
            for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a)
                overlap = overlap && std::min(b.hi[a], c.blocks[j].hi[a]) -
                                             std::max(b.lo[a], c.blocks[j].lo[a]) >
                                         eps;
            s.require(!overlap, "lo", fmt::format("the block overlaps blocks[{}]", j));
        }
        c.blocks.push_back(b);
    }
}

// The lattice puts round(extent / dx) particles along each axis: a block thinner than dx/2
// would silently hold none.
void check_block_thickness(const Section& root, const CaseConfig& c) {
    for (std::size_t i = 0; i < c.blocks.size(); ++i)
        for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a) {
            const double extent = c.blocks[i].hi[a] - c.blocks[i].lo[a];
            if (std::round(extent / c.dx) < 1)
                root.reader().fail(fmt::format("blocks[{}].hi", i),
                                   fmt::format("the block is {} m thick along {}, less than "
                                               "half of dx = {} m: it would hold no particle",
                                               extent, kAxis[a], c.dx));
        }
}

} // namespace sluice::case_file
