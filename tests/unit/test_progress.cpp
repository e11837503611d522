// The progress report: what a terminal, a batch log and a log file receive.
#include "sluice/io/progress.hpp"

#include <doctest/doctest.h>

#include <cstdio>
#include <string>
#include <vector>

using namespace sluice;

namespace {

// Everything written to a temporary stream.
std::string contents(std::FILE* f) {
    std::fflush(f);
    std::rewind(f);
    std::string out;
    char buf[4096];
    std::size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0)
        out.append(buf, n);
    return out;
}

std::size_t count(const std::string& s, const std::string& part) {
    std::size_t n = 0;
    for (auto p = s.find(part); p != std::string::npos; p = s.find(part, p + 1))
        ++n;
    return n;
}

} // namespace

TEST_CASE("on a terminal the line is rewritten in place and ended by finish()") {
    std::FILE* f = std::tmpfile();
    REQUIRE(f != nullptr);
    {
        Progress p(2.0, f, /*terminal=*/true, 10.0);
        p.update(1, 0.5, 1e-3, 2.5e6);
        p.update(2, 1.0, 1e-3, 2.5e6); // within 0.2 s of the first: not printed
        p.finish();
    }
    const std::string out = contents(f);
    std::fclose(f);
    CHECK(count(out, "\r") == 2);
    CHECK(count(out, "\n") == 1);
    CHECK(out.back() == '\n');
    CHECK(out.find("step 1  t 0.5/2 s  25.0%  dt 1.00e-03 s  2.50e+06 pstep/s  ETA") !=
          std::string::npos);
    // The final line shows the last state and the wall time instead of an ETA.
    CHECK(out.find("step 2  t 1/2 s  50.0%") != std::string::npos);
    CHECK(out.find("wall 0s") != std::string::npos);
}

TEST_CASE("in a batch job plain lines come at the given interval, never a carriage return") {
    std::FILE* f = std::tmpfile();
    REQUIRE(f != nullptr);
    {
        Progress p(1.0, f, /*terminal=*/false, 1000.0);
        for (int k = 1; k <= 50; ++k)
            p.update(k, 0.01 * k, 0.01, 1e5);
        p.finish();
    }
    const std::string out = contents(f);
    std::fclose(f);
    CHECK(count(out, "\r") == 0);
    CHECK(count(out, "\n") == 2); // the first report and the final one
    CHECK(out.find("step 1 ") != std::string::npos);
    CHECK(out.find("step 50  t 0.5/1 s  50.0%") != std::string::npos);
}

TEST_CASE("the log sink gets the first and the final line whatever the console does") {
    std::vector<std::string> lines;
    Progress p(1.0, nullptr, false, 10.0); // quiet console
    p.log_to([&](const std::string& l) { lines.push_back(l); }, 1000.0);
    for (int k = 1; k <= 10; ++k)
        p.update(k, 0.1 * k, 0.1, 1e4);
    p.finish();
    p.finish(); // idempotent
    REQUIRE(lines.size() == 2);
    CHECK(lines[0].rfind("step 1  t 0.1/1 s", 0) == 0);
    CHECK(lines[1].rfind("step 10  t 1/1 s  100.0%", 0) == 0);
    CHECK(lines[1].find("wall") != std::string::npos);
}
