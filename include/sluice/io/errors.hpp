#pragma once
// The two kinds of failure a user sees. Both carry a complete, human-readable message.
#include <stdexcept>
#include <string>

namespace sluice {

// A case file (or command-line override) that cannot be run: exit code 2.
// The message names the file, the key and the reason.
class CaseError : public std::runtime_error {
public:
    CaseError(const std::string& file, const std::string& key, const std::string& reason)
        : std::runtime_error(file + ": " + (key.empty() ? std::string() : "key '" + key + "': ") +
                             reason),
          file_(file), key_(key), reason_(reason) {}
    [[nodiscard]] const std::string& file() const { return file_; }
    [[nodiscard]] const std::string& key() const { return key_; }
    [[nodiscard]] const std::string& reason() const { return reason_; }

private:
    std::string file_, key_, reason_;
};

// A run that went wrong physically (NaN, blow-up, escaped particle): exit code 3.
class RunError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// An unexpected failure inside a step (a bug, a resource problem) on some rank, which every
// rank learned of through the step's reduction and raises together: exit code 1, with no rank
// left waiting and no MPI abort needed.
class InternalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace sluice
