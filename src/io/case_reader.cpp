// TOML case file -> validated CaseConfig: each section of the case read and checked, in file
// order. The sections are read by case_fluid.cpp ([case], [domain], [fluid], [particles],
// [[blocks]]), case_numerics.cpp (the scheme, [numerics], [projection], [neighbours.*]),
// case_motions.cpp ([[motions]]), case_walls.cpp, case_probes.cpp and case_run_control.cpp ([time],
// [output], [runtime], [checkpoint], [limits]); case_size.cpp checks the case's size. The TOML
// machinery (typed look-ups, the schema and its ranges, --set) is in toml_section.hpp,
// case_schema.hpp and case_toml.hpp.
#include "sluice/io/case_reader.hpp"

#include "case_fingerprint.hpp"
#include "case_fluid.hpp"
#include "case_motions.hpp"
#include "case_numerics.hpp"
#include "case_probes.hpp"
#include "case_run_control.hpp"
#include "case_schema.hpp"
#include "case_size.hpp"
#include "case_toml.hpp"
#include "case_walls.hpp"
#include "toml_section.hpp"

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace sluice {
namespace {

using namespace case_file;

CaseConfig build(const toml::table& root, Reader& r, const std::string& path) {
    CaseConfig c;
    c.source_file = path;
    r.check_keys(root, "", "");
    const Section top(r, root, "");

    read_case_table(top.sub("case"), c, r, path);
    read_domain(top.sub("domain"), c);
    read_fluid(top.sub("fluid"), c);
    read_particles(top.sub("particles"), c);
    read_blocks(top, c);
    check_block_thickness(top, c);
    // The scheme first: it decides which keys of the file apply.
    read_scheme(top, c);
    read_numerics(top.sub("numerics"), c);
    read_projection(top.sub("projection"), c);
    read_motions(top, c);
    read_damping_zones(top, c);
    read_walls(top.sub("walls"), c);
    check_walls_for_scheme(top, c);
    check_blocks_in_tank(top, c);
    read_time(top.sub("time"), c);
    read_output(top.sub("output"), c);
    read_probes(top, c);
    read_runtime(top.sub("runtime"), c);
    read_neighbours(top.sub("neighbours"), c);
    read_checkpoint_table(top.sub("checkpoint"), c);
    read_limits(top.sub("limits"), c);
    check_motions(top, c);
    check_case_size(top, c);
    return c;
}

} // namespace

CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides) {
    Reader r(path);
    toml::table root = case_file::parse_case_file(path);
    for (const auto& o : overrides)
        case_file::apply_override(root, o, r);
    CaseConfig c = build(root, r, path);
    c.fingerprint = case_fingerprint(root);
    // A shape's file is part of the case: a checkpoint continues only the same geometry.
    std::string all = c.fingerprint;
    for (const auto& m : c.meshes)
        all += m.digest;
    for (const auto& b : c.blocks)
        if (b.mesh)
            all += b.mesh->digest;
    for (const auto& d : c.motion_digests)
        all += d;
    if (all != c.fingerprint)
        c.fingerprint = sha256_hex(all);
    return c;
}

std::string case_schema_json() {
    return case_file::schema_json();
}

CaseConfig read_case_text(std::string_view text, const std::string& name,
                          const std::vector<std::string>& overrides) {
    Reader r(name);
    toml::table root = case_file::parse_case_text(text, name);
    for (const auto& o : overrides)
        case_file::apply_override(root, o, r);
    return build(root, r, name);
}

} // namespace sluice
