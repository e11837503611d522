// Parsing a case file and applying --set overrides (case_toml.hpp).
#include "case_toml.hpp"

#include "case_schema.hpp"
#include "sluice/io/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

namespace sluice::case_file {
namespace {

// Far beyond any real case (a few KiB); larger input is a mistake or hostile.
constexpr std::uintmax_t kMaxCaseFileBytes = 1 << 20;

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos)
        return {};
    const auto e = s.find_last_not_of(" \t");
    return std::string(s.substr(b, e - b + 1));
}

// "blocks[0].lo" -> {"blocks", "0", "lo"}.
std::vector<std::string> split_key(std::string key) {
    for (auto& ch : key)
        if (ch == '[' || ch == ']')
            ch = '.';
    std::vector<std::string> parts;
    std::string cur;
    for (char ch : key) {
        if (ch == '.') {
            if (!cur.empty())
                parts.push_back(cur);
            cur.clear();
        } else {
            cur += ch;
        }
    }
    if (!cur.empty())
        parts.push_back(cur);
    return parts;
}

std::optional<std::size_t> parse_index(const std::string& s) {
    if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char ch) {
            return std::isdigit(static_cast<unsigned char>(ch)) != 0;
        }))
        return std::nullopt;
    return static_cast<std::size_t>(std::stoul(s));
}

} // namespace

toml::table parse_case_text(std::string_view text, const std::string& path) {
    if (text.size() > kMaxCaseFileBytes)
        throw CaseError(path, "",
                        fmt::format("is {} bytes long; a case file is at most {} bytes (a few KiB "
                                    "is usual)",
                                    text.size(), kMaxCaseFileBytes));
    try {
        return toml::parse(text, std::string_view(path));
    } catch (const toml::parse_error& e) {
        throw CaseError(path, "",
                        fmt::format("TOML syntax error at line {}, column {}: {}",
                                    e.source().begin.line, e.source().begin.column,
                                    e.description()));
    }
}

toml::table parse_case_file(const std::string& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status))
        throw CaseError(path, "", "is a directory, not a case file");
    // A FIFO would block forever and a device (/dev/zero) never ends: only plain files.
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        throw CaseError(path, "", "is not a regular file");
    if (std::filesystem::exists(status)) {
        const auto size = std::filesystem::file_size(path, ec);
        if (!ec && size > kMaxCaseFileBytes)
            throw CaseError(path, "",
                            fmt::format("is {} bytes long; a case file is at most {} bytes "
                                        "(a few KiB is usual)",
                                        size, kMaxCaseFileBytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw CaseError(path, "",
                        fmt::format("cannot read the case file ({})", std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw CaseError(path, "", "cannot read the case file (I/O error)");
    return parse_case_text(text.str(), path);
}

void apply_override(toml::table& root, const std::string& text, Reader& r) {
    const auto eq = text.find('=');
    if (eq == std::string::npos)
        r.fail(trim(text), fmt::format("--set \"{}\" must look like key=value", text));
    const std::string raw_key = trim(std::string_view(text).substr(0, eq));
    const std::string value = trim(std::string_view(text).substr(eq + 1));
    const auto parts = split_key(raw_key);
    if (parts.empty())
        r.fail(raw_key, fmt::format("--set \"{}\" has no key", text));

    toml::table* cur = &root;
    std::string schema;  // path without indices
    std::string display; // path with indices, as messages print it
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::string& part = parts[i];
        const auto& allowed = kSchema.at(schema);
        const std::string shown = join_key(display, part);
        if (std::find(allowed.begin(), allowed.end(), part) == allowed.end())
            r.fail(shown, unknown_key_reason(part, schema, allowed) + " (given with --set)");
        const std::string child = join_key(schema, part);
        const bool last = i + 1 == parts.size();

        if (kSchema.count(child) == 0) { // a value key
            if (!last)
                r.fail(join_key(shown, parts[i + 1]),
                       fmt::format("unknown key: '{}' is a value, not a table (given with --set)",
                                   shown));
            // TOML first ("0.1", "[0, 1]", "true", "\"s\""); anything else is a bare string.
            std::optional<toml::table> parsed;
            try {
                const std::string doc = "v = " + value;
                parsed = toml::parse(std::string_view(doc), std::string_view("--set"));
            } catch (const toml::parse_error&) {
            }
            if (parsed && parsed->size() == 1 && parsed->contains("v"))
                parsed->get("v")->visit([&](auto&& node) { cur->insert_or_assign(part, node); });
            else
                cur->insert_or_assign(part, value);
            r.mark_overridden(shown);
            return;
        }

        if (last)
            r.fail(shown, "--set must name a single value, not a whole table (e.g. " +
                              join_key(shown, kSchema.at(child).front()) + "=...)");
        schema = child;
        toml::node* n = cur->get(part);
        if (kArrayTables.count(child) != 0) {
            const auto idx = parse_index(parts[i + 1]);
            if (!idx)
                r.fail(shown, fmt::format("[[{}]] entries are chosen by index, e.g. {}.0.{}", child,
                                          shown, kSchema.at(child).front()) +
                                  " (given with --set)");
            toml::array* arr = n != nullptr ? n->as_array() : nullptr;
            const std::size_t have = arr != nullptr ? arr->size() : 0;
            if (*idx >= have || !(*arr)[*idx].is_table())
                r.fail(
                    fmt::format("{}[{}]", shown, *idx),
                    fmt::format("no such entry: the file has {} [[{}]] entr{} (given with --set)",
                                have, child, have == 1 ? "y" : "ies"));
            cur = (*arr)[*idx].as_table();
            display = fmt::format("{}[{}]", shown, *idx);
            ++i; // the index is consumed
        } else {
            if (n == nullptr)
                n = &cur->insert_or_assign(part, toml::table{}).first->second;
            if (!n->is_table())
                r.fail(shown, fmt::format("expected a table [{}], got {}", shown, type_name(*n)),
                       n);
            cur = n->as_table();
            display = shown;
        }
    }
    r.fail(raw_key, "--set must name a value, not a whole table");
}

} // namespace sluice::case_file
