#pragma once
// The layout of a case file (private to src/io): one entry per key of every table, with its
// type, unit, default, range and the scheme it applies to. It drives the reader's unknown-key
// and inapplicable-key refusals, `--set`, and `sluice schema` (its JSON form), from which the
// bad-input corpus is generated and docs/CASE_REFERENCE.md is checked
// (tests/cli/case_reference.sh).
#include "sluice/io/case_config.hpp"

#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sluice::case_file {

// The scheme (numerics.scheme) a key is read by; under the other one it is refused.
enum class Applies { any, wcsph, projection };

constexpr double kInf = std::numeric_limits<double>::infinity();

// The values a key accepts, as data: an interval (for a number, an integer, or each component
// of a vector), or the strings allowed (for a string, or each string of an array of strings),
// and words for what depends on other keys. The reader enforces the interval and the choices
// (Section's typed look-ups); the `range` text of `sluice schema` is written from them
// (range_text), and tests/cli/case_reference.sh checks each interval docs/CASE_REFERENCE.md
// states against them, so the three cannot drift.
struct Range {
    double lo = -kInf;
    bool lo_open = true;
    double hi = kInf;
    bool hi_open = true;
    // The finite ends are plausibility limits, not laws: beyond them a value is a unit mistake
    // or hostile input ("1e+300 m is implausibly large ...; check the units").
    bool plausibility = false;
    std::vector<std::string_view> choices; // empty: any string
    std::string_view words; // a rule of other keys ("above lo"), after the interval; "" if none

    [[nodiscard]] bool bounded() const { return lo > -kInf || hi < kInf; }
    // A copy whose finite ends are plausibility limits.
    [[nodiscard]] Range implausible_beyond() const {
        Range r = *this;
        r.plausibility = true;
        return r;
    }
    // A copy with a rule of other keys ("above lo") that the reader checks in code.
    [[nodiscard]] Range and_words(std::string_view w) const {
        Range r = *this;
        r.words = w;
        return r;
    }
};

// [lo, hi], (lo, hi), (lo, hi], [lo, hi), [lo, inf), (lo, inf).
Range closed(double lo, double hi);
Range open(double lo, double hi);
Range open_closed(double lo, double hi);
Range closed_open(double lo, double hi);
Range at_least(double lo);
Range above(double lo);
// One of the given strings.
Range one_of(std::vector<std::string_view> choices);
// Only a rule that involves other keys (checked in code): "above lo".
Range words(std::string_view w);

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
    // The values accepted; an empty Range when any value of the type is.
    Range range;
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

// The key's entry; nullptr when the table has no such key. `table` without indices
// ("blocks", "neighbours.gradient").
const KeySpec* find_key(std::string_view table, std::string_view key);

// The range as docs/CASE_REFERENCE.md writes it: "[0.5, 4]", "(0, inf)", "each component in
// [-1e6, 1e6]; above lo", "\"box\", \"ellipse\"", words, or "".
std::string range_text(const KeySpec& k);
// Why v is outside the key's interval ("must be > 0, got 0", "1e+300 m/s is implausibly large
// (the limit is 1e5 m/s); check the units"); "" when it is inside.
std::string range_violation(const KeySpec& k, double v);
// "\"box\", \"ellipse\"": the key's choices as a message lists them.
std::string choices_text(const KeySpec& k);

const char* applies_name(Applies a);
const char* scheme_name(Scheme s);

// The schema as a JSON array of objects {table, key, type, unit, default, range, min, max,
// min_open, max_open, choices, applies, when, doc}, one per key (`sluice schema`): min and max
// the interval's ends (null when unbounded), choices the allowed strings ([] when any).
std::string schema_json();

} // namespace sluice::case_file
