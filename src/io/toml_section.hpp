#pragma once
// Typed, schema-checked look-ups in a parsed case file, and the wording of every message about
// a key (private to src/io). The readers of the case's sections (case_fluid.cpp,
// case_numerics.cpp, case_walls.cpp, case_probes.cpp, case_run_control.cpp) use these.
#include "sluice/io/case_config.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sluice::case_file {

// "numerics" + "kernel" -> "numerics.kernel"; "" is the top level.
std::string join_key(std::string_view path, std::string_view key);
// "a, b, c".
std::string join_list(const std::vector<std::string>& items);
// "a string", "an integer", ...: what a message says a value was.
std::string type_name(const toml::node& n);
// "unknown key; did you mean 'x'? allowed: ..." — typos are the usual cause.
std::string unknown_key_reason(std::string_view key, std::string_view table,
                               const std::vector<std::string>& allowed);

// Raises CaseErrors for one file and remembers which keys came from --set, so a bad value
// given on the command line is not blamed on a line of the file.
class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& key, const std::string& reason,
                           const toml::node* at = nullptr) const;

    void mark_overridden(const std::string& key) { overridden_.insert(key); }
    [[nodiscard]] const std::string& file() const { return file_; }

    int dim = 2; // known once [case] is read; array lengths depend on it

    // Every key of `t` must be in the schema of table `schema`; `path` is its display path.
    void check_keys(const toml::table& t, const std::string& path, const std::string& schema) const;

    [[nodiscard]] double as_number(const toml::node& n, const std::string& key) const;

    // An array of exactly `dim` numbers; the unused third component stays 0 in 2-D.
    [[nodiscard]] Triple as_triple(const toml::node& n, const std::string& key) const;

private:
    std::string file_;
    std::set<std::string, std::less<>> overridden_;
};

// One table of the file with its display path ("blocks[1]"), for concise typed look-ups.
// Optional getters return nullopt when the key is absent; type errors throw, and so does a
// value outside the key's range in the case schema (its interval, for a vector each
// component's, or its choices; case_schema.hpp).
class Section {
public:
    Section(const Reader& r, const toml::table& t, std::string path);

    [[nodiscard]] std::string key(std::string_view k) const { return join_key(path_, k); }
    [[nodiscard]] const toml::node* node(std::string_view k) const { return t_.get(k); }
    [[nodiscard]] const toml::table& table() const { return t_; }
    [[nodiscard]] const Reader& reader() const { return r_; }

    [[noreturn]] void fail(std::string_view k, const std::string& reason) const {
        r_.fail(key(k), reason, node(k));
    }
    void require(bool ok, std::string_view k, const std::string& reason) const {
        if (!ok)
            fail(k, reason);
    }
    [[nodiscard]] std::optional<double> number(std::string_view k) const;
    [[nodiscard]] double number(std::string_view k, double def) const {
        return number(k).value_or(def);
    }
    [[nodiscard]] double required_number(std::string_view k, std::string_view what) const;

    [[nodiscard]] std::optional<std::int64_t> integer(std::string_view k) const;
    [[nodiscard]] std::optional<bool> boolean(std::string_view k) const;
    [[nodiscard]] std::optional<std::string> string(std::string_view k) const;
    [[nodiscard]] std::optional<Triple> triple(std::string_view k) const;
    [[nodiscard]] Triple required_triple(std::string_view k, std::string_view what) const;
    [[nodiscard]] std::optional<std::vector<std::string>> strings(std::string_view k) const;

    // A string the schema lists choices for, as the value `options` pairs it with (the
    // schema's choices are checked by string(); each must be in `options`).
    template <class E>
    [[nodiscard]] E choice(std::string_view k, E def,
                           const std::vector<std::pair<std::string, E>>& options) const {
        const auto s = string(k);
        if (!s)
            return def;
        for (const auto& [name, value] : options)
            if (*s == name)
                return value;
        throw std::logic_error(fmt::format("the case schema allows \"{}\" for {}, which the "
                                           "reader does not know",
                                           *s, key(k)));
    }

    // Sub-table; an absent one reads as empty so that defaults and "missing key" apply.
    [[nodiscard]] Section sub(std::string_view k) const;

    // Entries of an array of tables ([[k]]), each with its keys checked.
    [[nodiscard]] std::vector<Section> entries(std::string_view k) const;

private:
    [[noreturn]] void missing(std::string_view k, std::string_view what) const;
    // The schema's range of k (case_schema.hpp) enforced on a value read from it.
    void check_range(std::string_view k, double v) const;
    void check_choice(std::string_view k, const std::string& v) const;

    // The value of k if it holds a T (a toml++ value type); `expected` opens the type error.
    template <class T>
    [[nodiscard]] std::optional<T> typed(std::string_view k, std::string_view expected) const {
        const auto* n = node(k);
        if (n == nullptr)
            return std::nullopt;
        const auto* v = n->as<T>();
        if (v == nullptr)
            fail(k, std::string(expected) + ", got " + type_name(*n));
        return v->get();
    }

    const Reader& r_;
    const toml::table& t_;
    std::string path_;
    std::string schema_; // the table's name in the schema: path_ without indices
};

} // namespace sluice::case_file
