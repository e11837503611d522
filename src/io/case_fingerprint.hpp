#pragma once
// The fingerprint of a case: what a checkpoint must match to be continued (private to src/io).
#include <toml++/toml.h>

#include <string>

namespace sluice {

// SHA-256 (64 hex digits) of the parsed case (after --set) in a canonical text form (toml++'s
// formatter; tables keep their keys sorted), without the keys that do not change results or
// may change on a restart: time.end_time, case.description, [checkpoint], [limits], [runtime].
// Comments, key order and spacing in the file therefore do not matter.
std::string case_fingerprint(const toml::table& root);

// SHA-256 (64 hex digits) of any bytes (the files a case reads besides itself).
std::string sha256_hex(const std::string& bytes);

// SHA-256 of a file's bytes (a mesh, a motion's time series).
std::string file_sha256(const std::string& path);

} // namespace sluice
