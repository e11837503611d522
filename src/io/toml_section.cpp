// Typed, schema-checked look-ups in a parsed case file (toml_section.hpp).
#include "toml_section.hpp"

#include "case_schema.hpp"
#include "sluice/io/errors.hpp"

#include <algorithm>
#include <cmath>

namespace sluice::case_file {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

// Keys and values quoted in messages may hold control characters (TOML escapes allow them):
// shown as \xNN so a message never rewrites the terminal.
std::string printable(std::string_view s) {
    std::string out;
    for (const char ch : s) {
        const auto u = static_cast<unsigned char>(ch);
        if (u < 0x20 || u == 0x7f)
            out += fmt::format("\\x{:02x}", u);
        else
            out += ch;
    }
    return out;
}

const toml::table& empty_table() {
    static const toml::table t;
    return t;
}

// "blocks[2]" -> "blocks": indices are not part of the schema.
std::string schema_of(const std::string& path) {
    std::string out;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '[') {
            i = path.find(']', i);
            if (i == std::string::npos)
                break;
            continue;
        }
        out += path[i];
    }
    return out;
}

} // namespace

std::string join_key(std::string_view path, std::string_view key) {
    return path.empty() ? std::string(key) : fmt::format("{}.{}", path, key);
}

std::string join_list(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& s : items)
        out += (out.empty() ? "" : ", ") + s;
    return out;
}

std::string unknown_key_reason(std::string_view key, std::string_view table,
                               const std::vector<std::string>& allowed) {
    std::string best;
    std::size_t best_d = 3; // only suggest close matches
    for (const auto& a : allowed) {
        const std::size_t d = edit_distance(key, a);
        if (d < best_d) {
            best_d = d;
            best = a;
        }
    }
    std::string where = table.empty() ? "at the top level" : fmt::format("in [{}]", table);
    std::string r = fmt::format("unknown key {}", where);
    if (!best.empty())
        r += fmt::format("; did you mean '{}'?", best);
    return r + fmt::format(" (allowed: {})", join_list(allowed));
}

std::string type_name(const toml::node& n) {
    switch (n.type()) {
    case toml::node_type::table:
        return "a table";
    case toml::node_type::array:
        return "an array";
    case toml::node_type::string:
        return "a string";
    case toml::node_type::integer:
        return "an integer";
    case toml::node_type::floating_point:
        return "a floating-point number";
    case toml::node_type::boolean:
        return "a boolean";
    case toml::node_type::date:
        return "a date";
    case toml::node_type::time:
        return "a time";
    case toml::node_type::date_time:
        return "a date-time";
    default:
        return "nothing";
    }
}

// ---------------------------------------------------------------------------------------------
// Reader

void Reader::fail(const std::string& key, const std::string& reason, const toml::node* at) const {
    std::string r = printable(reason);
    if (overridden_.count(key) != 0)
        r += " (value given with --set)";
    else if (at != nullptr && at->source().begin.line > 0)
        r += fmt::format(" (line {})", at->source().begin.line);
    throw CaseError(file_, printable(key), r);
}

void Reader::check_keys(const toml::table& t, const std::string& path,
                        const std::string& schema) const {
    const auto& allowed = kSchema.at(schema);
    for (const auto& [k, v] : t)
        if (std::find(allowed.begin(), allowed.end(), k.str()) == allowed.end())
            fail(join_key(path, k.str()), unknown_key_reason(k.str(), schema, allowed), &v);
}

double Reader::as_number(const toml::node& n, const std::string& key) const {
    double v = 0;
    if (const auto* i = n.as_integer())
        v = static_cast<double>(i->get());
    else if (const auto* f = n.as_floating_point())
        v = f->get();
    else
        fail(key, "expected a number, got " + type_name(n), &n);
    if (!std::isfinite(v))
        fail(key, fmt::format("must be a finite number, got {}", v), &n);
    return v;
}

Triple Reader::as_triple(const toml::node& n, const std::string& key) const {
    const auto* arr = n.as_array();
    if (arr == nullptr)
        fail(key, fmt::format("expected an array of {} numbers, got {}", dim, type_name(n)), &n);
    if (arr->size() != static_cast<std::size_t>(dim))
        fail(key,
             fmt::format("expected exactly {} numbers for a {}-D case ({}), got {}", dim, dim,
                         dim == 2 ? "x, y" : "x, y, z", arr->size()),
             &n);
    Triple out{0, 0, 0};
    for (std::size_t a = 0; a < arr->size(); ++a)
        out[a] = as_number((*arr)[a], fmt::format("{}[{}]", key, a));
    return out;
}

// ---------------------------------------------------------------------------------------------
// Section

Section::Section(const Reader& r, const toml::table& t, std::string path)
    : r_(r), t_(t), path_(std::move(path)), schema_(schema_of(path_)) {}

void Section::check_range(std::string_view k, double v) const {
    const KeySpec* spec = find_key(schema_, k);
    if (spec == nullptr || !spec->range.bounded())
        return;
    if (const std::string why = range_violation(*spec, v); !why.empty())
        fail(k, why);
}

void Section::check_choice(std::string_view k, const std::string& v) const {
    const KeySpec* spec = find_key(schema_, k);
    if (spec == nullptr || spec->range.choices.empty())
        return;
    const auto& choices = spec->range.choices;
    if (std::find(choices.begin(), choices.end(), v) == choices.end())
        fail(k, fmt::format("unknown value \"{}\"; allowed: {}", v, choices_text(*spec)));
}

std::optional<double> Section::number(std::string_view k) const {
    const auto* n = node(k);
    if (n == nullptr)
        return std::nullopt;
    const double v = r_.as_number(*n, key(k));
    check_range(k, v);
    return v;
}

double Section::required_number(std::string_view k, std::string_view what) const {
    auto v = number(k);
    if (!v)
        missing(k, what);
    return *v;
}

std::optional<std::int64_t> Section::integer(std::string_view k) const {
    const auto v = typed<std::int64_t>(k, "expected an integer");
    if (v)
        check_range(k, static_cast<double>(*v));
    return v;
}

std::optional<bool> Section::boolean(std::string_view k) const {
    return typed<bool>(k, "expected true or false");
}

std::optional<std::string> Section::string(std::string_view k) const {
    const KeySpec* spec = find_key(schema_, k);
    const bool listed = spec != nullptr && !spec->range.choices.empty();
    if (const auto* n = node(k); listed && n != nullptr && !n->is_string())
        fail(k, fmt::format("expected a string, got {}; allowed: {}", type_name(*n),
                            choices_text(*spec)));
    const auto v = typed<std::string>(k, "expected a string");
    if (v)
        check_choice(k, *v);
    return v;
}

std::optional<Triple> Section::triple(std::string_view k) const {
    const auto* n = node(k);
    if (n == nullptr)
        return std::nullopt;
    const Triple v = r_.as_triple(*n, key(k));
    for (int a = 0; a < r_.dim; ++a)
        check_range(k, v[static_cast<std::size_t>(a)]);
    return v;
}

Triple Section::required_triple(std::string_view k, std::string_view what) const {
    auto v = triple(k);
    if (!v)
        missing(k, what);
    return *v;
}

std::optional<std::vector<std::string>> Section::strings(std::string_view k) const {
    const auto* n = node(k);
    if (n == nullptr)
        return std::nullopt;
    const auto* arr = n->as_array();
    if (arr == nullptr)
        fail(k, "expected an array of strings, got " + type_name(*n));
    std::vector<std::string> out;
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const auto* s = (*arr)[i].as_string();
        if (s == nullptr)
            r_.fail(fmt::format("{}[{}]", key(k), i),
                    "expected a string, got " + type_name((*arr)[i]), n);
        out.push_back(s->get());
        check_choice(k, out.back());
    }
    return out;
}

Section Section::sub(std::string_view k) const {
    const auto* n = node(k);
    if (n == nullptr)
        return {r_, empty_table(), key(k)};
    const auto* t = n->as_table();
    if (t == nullptr)
        fail(k, fmt::format("expected a table [{}], got {}", key(k), type_name(*n)));
    r_.check_keys(*t, key(k), schema_of(key(k)));
    return {r_, *t, key(k)};
}

std::vector<Section> Section::entries(std::string_view k) const {
    std::vector<Section> out;
    const auto* n = node(k);
    if (n == nullptr)
        return out;
    const auto* arr = n->as_array();
    const std::string schema = schema_of(key(k));
    if (arr == nullptr)
        fail(k, fmt::format("expected an array of tables [[{}]], got {}", key(k), type_name(*n)));
    for (std::size_t i = 0; i < arr->size(); ++i) {
        const std::string path = fmt::format("{}[{}]", key(k), i);
        const auto* t = (*arr)[i].as_table();
        if (t == nullptr)
            r_.fail(path,
                    fmt::format("expected a table in [[{}]], got {}", key(k), type_name((*arr)[i])),
                    n);
        r_.check_keys(*t, path, schema);
        out.emplace_back(r_, *t, path);
    }
    return out;
}

void Section::missing(std::string_view k, std::string_view what) const {
    r_.fail(key(k), fmt::format("missing required key ({})", what), nullptr);
}

} // namespace sluice::case_file
