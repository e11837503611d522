#pragma once
// The layout of a case file (private to src/io): one entry per key of every table, with its
// type, unit, default, range and the scheme it applies to. It drives the reader's unknown-key
// and inapplicable-key refusals, `--set`, and `sluice schema` (its JSON form), from which the
// bad-input corpus is generated and docs/CASE_REFERENCE.md is checked
// (tests/cli/case_reference.py).
#include "sluice/io/case_config.hpp"

#include <functional>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sluice::case_file {

// The scheme (numerics.scheme) a key is read by; under the other one it is refused.
enum class Applies { any, wcsph, projection };

struct KeySpec {
    // Table of the key: "numerics"; entries of an array of tables are listed under the
    // array's name without an index ("walls.planes"); "" is the top level.
    std::string_view table;
    std::string_view key;
    // As docs/CASE_REFERENCE.md writes it: "number", "integer", "string", "boolean", "vector",
    // "array of strings", ...; "table" and "array of tables" for the tables of a table.
    std::string_view type;
    std::string_view unit; // "" when dimensionless or not a quantity
    // The default as docs/CASE_REFERENCE.md writes it (without markup): a TOML value where it
    // is one ("0.25", "\"quintic\""), else words ("required", "fluid.sound_speed"). Where it
    // is a TOML value, the reader's default is that value (tests/unit/test_case_schema.cpp).
    std::string_view default_text;
    // An interval "[0.5, 4]", "(0, inf)", a list of allowed values "\"box\", \"ellipse\"", or
    // words; "" when any value of the type is accepted.
    std::string_view range;
    Applies applies = Applies::any;
    // A further condition for the key to apply, "KEY = VALUE" with KEY relative to the key's
    // own table when it has no dot ("profile = \"rotating\""); "" when none.
    std::string_view when;
    std::string_view doc; // one line
};

// Every key of every table, in the order of docs/CASE_REFERENCE.md.
const std::vector<KeySpec>& case_keys();

// Keys each table accepts (derived from case_keys()).
extern const std::map<std::string, std::vector<std::string>, std::less<>> kSchema;
// The tables written as arrays of tables ([[blocks]]): --set picks their entries by index.
extern const std::set<std::string, std::less<>> kArrayTables;

const char* applies_name(Applies a);
const char* scheme_name(Scheme s);

// The schema as a JSON array of objects {table, key, type, unit, default, range, applies,
// when, doc}, one per key (`sluice schema`).
std::string schema_json();

} // namespace sluice::case_file
