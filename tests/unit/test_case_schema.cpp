// The case schema (`sluice schema`, src/io/case_schema.cpp) against the reader: every key whose
// documented default is a TOML value reads the same whether the key is absent or set to that
// value, and every key the schema marks as one scheme's is refused under the other.
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"

#include "shape_files.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace sluice;

namespace {

// Dummy walls, a box obstacle, a wall plane and one probe of each kind but force (probes[i]:
// pressure, water_level, surge_front): every table where a key can apply.
const std::string kBase = R"(
[case]
name = "schema"
dimension = 2

[domain]
lo = [0, 0]
hi = [2.0, 1.0]

[fluid]
rho0 = 1000
viscosity = 1e-3
sound_speed = 30

[particles]
dx = 0.02

[[blocks]]
lo = [0, 0]
hi = [0.5, 0.4]

[numerics]
scheme = "SCHEME"

[walls]
model = "dummy"
tank_lo = [0, 0]
tank_hi = [2, 1]
tank_faces = ["x-", "x+", "y-"]

[[walls.planes]]
point = [1.9, 0]
normal = [-1, 0]

[[walls.boxes]]
lo = [1.0, 0]
hi = [1.2, 0.2]

[[walls.meshes]]
file = "MESHFILE"
role = "solid"

[time]
end_time = 0.5

[[probes]]
name = "P"
type = "pressure"
position = [1.99, 0.05]

[[probes]]
name = "H"
type = "water_level"
x = 0.3

[[probes]]
name = "F"
type = "surge_front"
)";

// The base case's mesh: a box cut by z = 0 into the square [1.4, 1.6] x [0.3, 0.5].
std::string mesh_file() {
    static const std::string path = [] {
        const std::string p = sluice::test::temp_path("schema_box.stl");
        sluice::test::write_ascii_stl(sluice::test::box_shape({1.4, 0.3, -1}, {1.6, 0.5, 1}), p);
        return p;
    }();
    return path;
}

// A mesh block's shape for the keys that apply with blocks.shape = "mesh": a box cut by z = 0
// into the base block's rectangle.
std::string block_mesh_file() {
    static const std::string path = [] {
        const std::string p = sluice::test::temp_path("schema_block.stl");
        sluice::test::write_ascii_stl(sluice::test::box_shape({0, 0, -1}, {0.5, 0.4, 1}), p);
        return p;
    }();
    return path;
}

// A complete [[motions]] entry of each kind (2-D, the base's geometry) after its name and kind.
const std::map<std::string, std::string> kMotionSamples = {
    {"sway", "amplitude = [0.01, 0]\nperiod = 1\n"},
    {"roll", "angle = 2\nperiod = 1\ncentre = [1.1, 0.1]\n"},
    {"constant_velocity", "velocity = [0.1, 0]\n"},
    {"constant_acceleration", "acceleration = [0.1, 0]\n"},
    {"piston", "wave_height = 0.01\nwave_period = 1\ndepth = 0.4\n"},
    {"flap", "wave_height = 0.01\nwave_period = 1\ndepth = 0.4\ncentre = [1.0, 0]\n"},
    {"piston_irregular", "hs = 0.01\ntp = 1\ndepth = 0.4\n"},
    {"free_body", "density = 500\n"},
    {"file", "file = \"absent.csv\"\n"}}; // read after every other key

// The base with an entry of [[motions]] or [[damping_zones]] (which the base lacks) for a key
// of that table: a motion of the kind the key's condition names, moving the box when
// `move_box`; other tables' keys leave the text as it is.
std::string with_entry(std::string text, const std::string& table, const std::string& when,
                       bool move_box) {
    std::string entry;
    if (table == "motions") {
        std::string kind = "sway";
        // "not kind = ..." names the kind a key is not for: any other (sway) takes it.
        if (const auto p = when.find("kind = \""); p != std::string::npos && p == 0)
            kind = when.substr(p + 8, when.find('"', p + 8) - (p + 8));
        entry = "[[motions]]\nname = \"m\"\nkind = \"" + kind + "\"\n" + kMotionSamples.at(kind);
        if (move_box) {
            const std::string box_hi = "hi = [1.2, 0.2]\n";
            text.insert(text.find(box_hi) + box_hi.size(), "motion = \"m\"\n");
        }
    } else if (table == "damping_zones") {
        entry = "[[damping_zones]]\nstart = [1.5, 0]\nend = [1.9, 0]\n";
    } else {
        return text;
    }
    text.insert(text.find("[time]"), entry + "\n");
    return text;
}

std::string base(const std::string& scheme) {
    std::string t = kBase;
    t.replace(t.find("SCHEME"), 6, scheme);
    t.replace(t.find("MESHFILE"), 8, mesh_file());
    return t;
}

nlohmann::json schema() {
    return nlohmann::json::parse(case_schema_json());
}

// A default that is one TOML value ("0.25", "\"quintic\"", "[\"id\"]"), not words.
bool is_toml_value(const std::string& text) {
    try {
        const toml::table t = toml::parse("v = " + text);
        return t.size() == 1 && t.contains("v");
    } catch (const toml::parse_error&) {
        return false;
    }
}

// The --set path of a key in the base case: entries of arrays of tables by index (a probe of
// the kind the key needs).
std::string set_path(const std::string& table, const std::string& key, const std::string& when) {
    if (table == "blocks" || table == "walls.planes" || table == "walls.boxes" ||
        table == "walls.meshes" || table == "motions" || table == "damping_zones")
        return table + ".0." + key;
    if (table == "probes") {
        int i = 0;
        if (when.find("water_level") != std::string::npos)
            i = 1;
        else if (when.find("surge_front") != std::string::npos)
            i = 2;
        return "probes." + std::to_string(i) + "." + key;
    }
    return table.empty() ? key : table + "." + key;
}

// The "KEY = VALUE" condition of a key as a --set override (the first alternative of
// "a" | "b"); empty when there is none or it is the probe kind (chosen by set_path).
std::vector<std::string> when_overrides(const std::string& table, const std::string& when) {
    // An area sensor's key (the base's probe P is 0.01 m off x+): "type = \"pressure\", with a
    // diameter", or "type = \"force\" | \"pressure\", with a diameter" for the reading.
    if (when.ends_with("\"pressure\", with a diameter"))
        return {"probes.0.diameter=0.02"};
    // A motion's kind is that of the entry with_entry writes.
    if (when.empty() || when.rfind("type = ", 0) == 0 || table == "motions")
        return {};
    if (table == "blocks" && when == "shape = \"mesh\"")
        return {"blocks.0.shape=\"mesh\"", "blocks.0.file=\"" + block_mesh_file() + "\""};
    const auto eq = when.find(" = ");
    std::string key = when.substr(0, eq);
    std::string value = when.substr(eq + 3);
    value = value.substr(0, value.find(" |"));
    if (key.find('.') == std::string::npos)
        key = set_path(table, key, "");
    return {key + "=" + value};
}

// Keys whose default is not a TOML value: computed from other keys, or "absent" means off.
const std::set<std::string> kComputedDefaults = {"case.name",
                                                 "domain.periodic",
                                                 "fluid.gravity",
                                                 "blocks.velocity",
                                                 "numerics.dt",
                                                 "walls.tank_faces",
                                                 "probes.diameter",
                                                 "probes.face",
                                                 "probes.box",
                                                 "probes.lo",
                                                 "probes.mesh",
                                                 "walls.meshes.translation",
                                                 "blocks.translation",
                                                 "probes.hi",
                                                 "probes.moment_about",
                                                 "probes.y",
                                                 "probes.min_thickness",
                                                 "limits.max_speed",
                                                 "limits.min_density",
                                                 "limits.max_density",
                                                 "walls.tank_motion",
                                                 "walls.boxes.motion",
                                                 "walls.meshes.motion",
                                                 "probes.frame",
                                                 "motions.centre",
                                                 "motions.axis",
                                                 "motions.direction",
                                                 "motions.centre_of_mass",
                                                 "motions.inertia"};

} // namespace

TEST_CASE("schema: fields of every key, no key twice") {
    std::set<std::string> seen;
    for (const auto& k : schema()) {
        for (const char* f :
             {"table", "key", "type", "unit", "default", "range", "applies", "when", "doc"})
            REQUIRE_MESSAGE(k.contains(f), k.dump());
        const std::string full = k["table"].get<std::string>() + "." + k["key"].get<std::string>();
        CHECK_MESSAGE(seen.insert(full).second, "listed twice: " << full);
        CHECK_MESSAGE(!k["doc"].get<std::string>().empty(), full);
        const std::string applies = k["applies"];
        CHECK((applies == "any" || applies == "wcsph" || applies == "projection"));
    }
}

TEST_CASE("schema: a documented default is what the reader uses when the key is absent") {
    int checked = 0;
    for (const auto& k : schema()) {
        const std::string table = k["table"], key = k["key"], type = k["type"];
        const std::string def = k["default"], applies = k["applies"], when = k["when"];
        const std::string full = table.empty() ? key : table + "." + key;
        if (type == "table" || type == "array of tables" || def.rfind("required", 0) == 0)
            continue;
        if (!is_toml_value(def)) {
            CHECK_MESSAGE(kComputedDefaults.count(full) == 1,
                          full << ": default \"" << def
                               << "\" is neither a TOML value nor a known computed default");
            continue;
        }
        std::string text =
            with_entry(base(applies == "projection" ? "projection" : "wcsph"), table, when, true);
        if (full == "walls.model") // its default ("none") allows no tank, box or plane
            text.erase(text.find("[walls]"), text.find("[time]") - text.find("[walls]"));
        const std::vector<std::string> cond = when_overrides(table, when);
        std::vector<std::string> with = cond;
        with.push_back(set_path(table, key, when) + "=" + def);
        INFO("key ", full, " = ", def);
        CaseConfig absent, given;
        REQUIRE_NOTHROW(absent = read_case_text(text, "schema.toml", cond));
        REQUIRE_NOTHROW(given = read_case_text(text, "schema.toml", with));
        CHECK(absent == given);
        ++checked;
    }
    CHECK(checked >= 50);
}

TEST_CASE("schema: a key of one scheme is refused under the other, naming it") {
    int checked = 0;
    for (const auto& k : schema()) {
        const std::string table = k["table"], key = k["key"], applies = k["applies"];
        if (applies == "any" || k["type"] == "table")
            continue;
        const std::string other = applies == "wcsph" ? "projection" : "wcsph";
        const std::string full = table.empty() ? key : table + "." + key;
        const std::string def = k["default"];
        // A key of an array of tables the base lacks: an entry of it (refused as a whole, the
        // table named); one of an entry the base has: set in that entry, a string for a
        // motion's name (refused naming the entry's key); the others as they are.
        std::string text = base(other), expected = full;
        std::vector<std::string> overrides;
        if (table == "motions" || table == "damping_zones" || k["type"] == "array of tables") {
            text = with_entry(text, table.empty() ? key : table, k["when"], false);
            expected = table.empty() ? key : table;
        } else if (table == "walls.boxes" || table == "walls.meshes" || table == "probes") {
            overrides = {set_path(table, key, "") + "=\"m\""};
            expected = table + "[0]." + key;
        } else {
            overrides = {full + "=" + def};
        }
        try {
            (void)read_case_text(text, "schema.toml", overrides);
            FAIL("accepted " << full << " under " << other);
        } catch (const CaseError& e) {
            CHECK_MESSAGE(e.key() == expected, std::string(e.what()));
            // A wall object's or probe's motion under the other scheme names a motion that
            // cannot exist there ([[motions]] is refused as a whole).
            const std::string why = overrides.empty() || expected == full
                                        ? "applies only to numerics.scheme = \"" + applies + "\""
                                        : "no [[motions]] entry is called";
            CHECK_MESSAGE(std::string(e.reason()).find(why) != std::string::npos,
                          std::string(e.what()));
        }
        ++checked;
    }
    CHECK(checked >= 15);
}

TEST_CASE("schema: an empty [projection] table is refused under wcsph") {
    try {
        (void)read_case_text(base("wcsph") + "\n[projection]\n", "schema.toml");
        FAIL("accepted [projection] under wcsph");
    } catch (const CaseError& e) {
        CHECK(e.key() == "projection");
    }
}

TEST_CASE("schema: the projection scheme refuses the WCSPH equation of state, density and walls") {
    // Each is read by the WCSPH scheme only (the projection scheme keeps rho0 and the volume
    // dx^D, and its wall particles carry no boundary velocity): under "projection" the key is
    // named, under "wcsph" it is accepted.
    const std::vector<std::string> keys = {
        "fluid.eos=\"tait\"",  "fluid.gamma=7",         "numerics.density=\"summation\"",
        "walls.no_slip=false", "limits.min_density=10", "limits.max_density=2000"};
    for (const auto& kv : keys) {
        const std::string key = kv.substr(0, kv.find('='));
        INFO(kv);
        CHECK_NOTHROW((void)read_case_text(base("wcsph"), "schema.toml", {kv}));
        try {
            (void)read_case_text(base("projection"), "schema.toml", {kv});
            FAIL("accepted " << key << " under projection");
        } catch (const CaseError& e) {
            CHECK(e.key() == key);
            CHECK(std::string(e.what()).find("schema.toml") != std::string::npos);
            CHECK(std::string(e.reason())
                      .find("applies only to numerics.scheme = \"wcsph\" (the "
                            "scheme is \"projection\")") != std::string::npos);
        }
    }
}

TEST_CASE("schema: every choice of a string key is one the reader knows") {
    // The reader refuses a string outside the schema's choices; each choice must map to one of
    // its values (Section::choice throws std::logic_error otherwise). A choice may still be
    // refused for the rest of the base case (CaseError): only the mapping is tested here.
    int checked = 0;
    for (const auto& k : schema()) {
        if (k["type"] != "string" || k["choices"].empty())
            continue;
        const std::string table = k["table"], key = k["key"], when = k["when"];
        const std::string applies = k["applies"];
        const std::string text =
            with_entry(base(applies == "projection" ? "projection" : "wcsph"), table, when, true);
        for (const auto& c : k["choices"]) {
            const std::string choice = c.get<std::string>();
            std::vector<std::string> with = when_overrides(table, when);
            with.push_back(set_path(table, key, when) + "=\"" + choice + "\"");
            INFO(table, ".", key, " = ", choice);
            try {
                (void)read_case_text(text, "schema.toml", with);
            } catch (const CaseError&) {
            }
            ++checked;
        }
    }
    CHECK(checked >= 40);
}

TEST_CASE("schema: a value outside a key's interval is refused, naming the key") {
    // Just outside each end of every interval of a number or integer key, set in the base case
    // of its scheme: refused with the key named (the reader's one generic check).
    int checked = 0;
    for (const auto& k : schema()) {
        const std::string type = k["type"];
        if ((type != "number" && type != "integer") || (k["min"].is_null() && k["max"].is_null()))
            continue;
        const std::string table = k["table"], key = k["key"], when = k["when"];
        const std::string applies = k["applies"];
        const std::string full = table.empty() ? key : table + "." + key;
        const std::string text =
            with_entry(base(applies == "projection" ? "projection" : "wcsph"), table, when, true);
        std::vector<std::string> values;
        const auto shown = [&](double v) {
            if (type == "integer")
                return std::to_string(static_cast<long long>(v));
            std::ostringstream out;
            out << std::setprecision(17) << v;
            return out.str();
        };
        const double step = type == "integer" ? 1 : 0.5;
        if (!k["min"].is_null()) {
            const double lo = k["min"].get<double>();
            values.push_back(shown(k["min_open"].get<bool>() ? lo : lo - step));
        }
        if (!k["max"].is_null()) {
            const double hi = k["max"].get<double>();
            values.push_back(shown(k["max_open"].get<bool>() ? hi : hi + step));
        }
        for (const auto& v : values) {
            std::vector<std::string> with = when_overrides(table, when);
            with.push_back(set_path(table, key, when) + "=" + v);
            INFO(full, " = ", v);
            try {
                (void)read_case_text(text, "schema.toml", with);
                FAIL("accepted " << full << " = " << v);
            } catch (const CaseError& e) {
                const std::string named = e.key();
                // Keys of arrays of tables are named with their index (probes[4].diameter).
                CHECK_MESSAGE(named.find(key) != std::string::npos, e.what());
                CHECK_MESSAGE(named.rfind(table.substr(0, table.find('.')), 0) == 0, e.what());
            }
            ++checked;
        }
    }
    CHECK(checked >= 50);
}
