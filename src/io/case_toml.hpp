#pragma once
// A case file's text -> its TOML tree, with the --set overrides applied (private to src/io).
// Every failure throws CaseError naming the file (and the key, for an override).
#include "toml_section.hpp"

#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace sluice::case_file {

// Parses case text held in memory; `path` names it in messages. Refuses text over 1 MiB.
toml::table parse_case_text(std::string_view text, const std::string& path);

// Reads and parses a case file: only a plain file of at most 1 MiB.
toml::table parse_case_file(const std::string& path);

// Stores `value` (TOML text, or a bare string) at `key` in `root`, after checking the key
// against the schema. Missing tables on the way are created; array entries must exist.
// `text` is one --set argument, "key=value"; `r` remembers the key as given with --set.
void apply_override(toml::table& root, const std::string& text, Reader& r);

} // namespace sluice::case_file
