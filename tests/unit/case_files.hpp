#pragma once
// Case files written by a unit test: a scratch folder per test binary run, removed at exit,
// and write_case(), which puts a TOML text there and returns its path.
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace sluice::testing {

inline const std::filesystem::path& scratch_dir() {
    static const struct Dir {
        std::filesystem::path path;
        Dir() {
            path = std::filesystem::temp_directory_path() /
                   ("sluice_test_" + std::to_string(::getpid()));
            std::filesystem::create_directories(path);
        }
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    } dir;
    return dir.path;
}

inline std::string write_case(const std::string& name, const std::string& text) {
    std::filesystem::path p = scratch_dir() / name;
    p += ".toml";
    std::ofstream(p) << text;
    return p.string();
}

} // namespace sluice::testing
