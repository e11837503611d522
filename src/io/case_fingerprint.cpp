#include "case_fingerprint.hpp"

#include <fmt/format.h>
#include <openssl/evp.h>

#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace sluice {

std::string case_fingerprint(const toml::table& root) {
    toml::table t = root;
    for (const char* table : {"checkpoint", "limits", "runtime"})
        t.erase(table);
    if (auto* time = t["time"].as_table())
        time->erase("end_time");
    if (auto* c = t["case"].as_table())
        c->erase("description");
    std::ostringstream text;
    text << toml::toml_formatter(t);
    return sha256_hex(text.str());
}

std::string sha256_hex(const std::string& s) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_Digest(s.data(), s.size(), digest, &length, EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("cannot compute the case fingerprint (OpenSSL SHA-256)");
    std::string hex;
    for (unsigned int i = 0; i < length; ++i)
        hex += fmt::format("{:02x}", digest[i]);
    return hex;
}

std::string file_sha256(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return sha256_hex(bytes);
}

} // namespace sluice
