#pragma once
// The layout of a case file: which keys each table accepts (private to src/io). This schema
// and docs/CASE_REFERENCE.md describe the same layout; keep them in step.
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace sluice::case_file {

// Keys each table accepts. Entries of arrays of tables are listed under the array's name
// without an index ("walls.planes"); "" is the top level.
extern const std::map<std::string, std::vector<std::string>, std::less<>> kSchema;
// The tables written as arrays of tables ([[blocks]]): --set picks their entries by index.
extern const std::set<std::string, std::less<>> kArrayTables;

} // namespace sluice::case_file
