// Checkpoint files: every value read back is bit-identical to what was written (2-D and 3-D);
// a failed write leaves the previous checkpoint intact; a file from another case, of another
// format version, truncated, with a damaged byte, or not a checkpoint at all is refused with
// a CaseError saying why. The case fingerprint ignores what may change on a restart and
// nothing else; the [checkpoint] and [limits] keys are validated.
#include "sluice/io/case_reader.hpp"
#include "sluice/io/checkpoint.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/io/snapshot_writer.hpp"

#include <doctest/doctest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace sluice;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("sluice_checkpoint_" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof(double)) == 0;
}

template <int D>
Checkpoint<D> sample_checkpoint(std::size_t n) {
    Checkpoint<D> c;
    c.case_fingerprint = std::string(64, 'a');
    c.ranks = 3;
    c.solver =
        SolverState{0.123456789, 4321, 1.0 / 3.0 * 1e-4, 2.5e-5, 1.75, 1e-4, 0.5, 2e-3, 0, {}};
    // A free body's state and load (its 25 numbers, as wall_motion.hpp's body_state).
    for (int k = 0; k < 25; ++k)
        c.solver.bodies.push_back(1.0 / 3.0 * (k - 12));
    c.output.out_next = 0.15;
    c.output.last_output_time = 0.1;
    c.output.wall_seconds = 12.345678901;
    c.output.probe_next = {0.13, 0.2000000001};
    c.output.probe_bytes = {1234, 56};
    c.output.snapshot_time = {0.0, 0.05, 0.1};
    c.output.snapshot_particles = {n, n, n};
    for (std::size_t i = 0; i < n; ++i) {
        Vec<D> x, v;
        for (int d = 0; d < D; ++d) {
            x[d] = std::sqrt(static_cast<double>(i + 2 + d)) / 7.0; // inexact decimals
            v[d] = -1e-310 * static_cast<double>(d + 1);            // subnormal
        }
        c.particles.push_back(1000 + 7 * i, i % 5 == 0 ? Kind::wall : Kind::fluid, x, v,
                              1000.0 + 1.0 / static_cast<double>(i + 3),
                              0.01 + 1e-17 * static_cast<double>(i));
        c.particles.v_half[i] = -x;
        c.particles.a[i] = 9.81 * x;
        c.particles.p[i] = i == 1 ? -0.0 : 1e5 / static_cast<double>(i + 1);
    }
    return c;
}

template <int D>
void check_equal(const Checkpoint<D>& a, const Checkpoint<D>& b) {
    CHECK(a.case_fingerprint == b.case_fingerprint);
    CHECK(a.ranks == b.ranks);
    CHECK(a.solver.step == b.solver.step);
    CHECK(a.solver.bodies == b.solver.bodies); // bitwise
    for (auto [x, y] : {std::pair{a.solver.time, b.solver.time},
                        {a.solver.dt, b.solver.dt},
                        {a.solver.dt_prev, b.solver.dt_prev},
                        {a.solver.u_max, b.solver.u_max},
                        {a.solver.limit_acoustic, b.solver.limit_acoustic},
                        {a.solver.limit_viscous, b.solver.limit_viscous},
                        {a.solver.limit_force, b.solver.limit_force},
                        {a.output.out_next, b.output.out_next},
                        {a.output.last_output_time, b.output.last_output_time},
                        {a.output.wall_seconds, b.output.wall_seconds}})
        CHECK(same_bits(x, y));
    CHECK(a.output.probe_next == b.output.probe_next);
    CHECK(a.output.probe_bytes == b.output.probe_bytes);
    CHECK(a.output.snapshot_time == b.output.snapshot_time);
    CHECK(a.output.snapshot_particles == b.output.snapshot_particles);
    const auto& P = a.particles;
    const auto& Q = b.particles;
    REQUIRE(P.size() == Q.size());
    CHECK(P.id == Q.id);
    CHECK(P.kind == Q.kind);
    for (std::size_t i = 0; i < P.size(); ++i) {
        for (int d = 0; d < D; ++d) {
            CHECK(same_bits(P.x[i][d], Q.x[i][d]));
            CHECK(same_bits(P.v[i][d], Q.v[i][d]));
            CHECK(same_bits(P.v_half[i][d], Q.v_half[i][d]));
            CHECK(same_bits(P.a[i][d], Q.a[i][d]));
        }
        CHECK(same_bits(P.rho[i], Q.rho[i]));
        CHECK(same_bits(P.mass[i], Q.mass[i]));
        CHECK(same_bits(P.p[i], Q.p[i]));
    }
}

// Reads `path` expecting a refusal; returns the message.
template <int D>
std::string refusal(const std::string& path, const std::string& fingerprint) {
    try {
        (void)read_checkpoint<D>(path, fingerprint);
    } catch (const CaseError& e) {
        CHECK(e.file() == path);
        return e.what();
    }
    FAIL("checkpoint " << path << " was not refused");
    return {};
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

// Opens `path` and sets the int32 root attribute `name`.
void set_int_attribute(const std::string& path, const char* name, std::int32_t value) {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const hid_t a = H5Aopen(f, name, H5P_DEFAULT);
    REQUIRE(a >= 0);
    CHECK(H5Awrite(a, H5T_NATIVE_INT32, &value) >= 0);
    H5Aclose(a);
    H5Fclose(f);
}

// File offset of the (single) chunk of dataset `name`.
haddr_t chunk_address(const std::string& path, const char* name) {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(d);
    hsize_t offset[2];
    unsigned mask = 0;
    haddr_t addr = HADDR_UNDEF;
    hsize_t size = 0;
    CHECK(H5Dget_chunk_info(d, space, 0, offset, &mask, &addr, &size) >= 0);
    H5Sclose(space);
    H5Dclose(d);
    H5Fclose(f);
    return addr;
}

} // namespace

TEST_CASE("a checkpoint reads back bit for bit, 2-D and 3-D") {
    TempDir dir;
    const auto c2 = sample_checkpoint<2>(37);
    write_checkpoint<2>(checkpoint_path(dir.path.string()), c2);
    check_equal(c2, read_checkpoint<2>(checkpoint_path(dir.path.string()), c2.case_fingerprint));

    const auto c3 = sample_checkpoint<3>(11);
    const std::string p3 = (dir.path / "three.h5").string();
    write_checkpoint<3>(p3, c3);
    check_equal(c3, read_checkpoint<3>(p3, c3.case_fingerprint));
    // No temporary file is left behind.
    for (const auto& e : fs::directory_iterator(dir.path))
        CHECK(!e.path().filename().string().starts_with("."));

    // An empty particle set (a rank layout never writes one, but the format allows it).
    const auto c0 = sample_checkpoint<2>(0);
    write_checkpoint<2>(p3 + ".empty", c0);
    check_equal(c0, read_checkpoint<2>(p3 + ".empty", c0.case_fingerprint));
}

TEST_CASE("a failed write leaves the previous checkpoint as it was") {
    TempDir dir;
    const std::string path = checkpoint_path(dir.path.string());
    const auto old = sample_checkpoint<2>(20);
    write_checkpoint<2>(path, old);
    const auto size_before = fs::file_size(path);
    // The temporary name is taken by a folder: the new file cannot be created.
    fs::create_directories(dir.path / ".checkpoint.h5.tmp");
    auto next = sample_checkpoint<2>(25);
    next.solver.step = 9999;
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // the failure is expected: no HDF5 report
    CHECK_THROWS_AS(write_checkpoint<2>(path, next), std::runtime_error);
    CHECK(fs::file_size(path) == size_before);
    check_equal(old, read_checkpoint<2>(path, old.case_fingerprint));
}

TEST_CASE("checkpoints that cannot continue the case are refused with the reason") {
    TempDir dir;
    const auto c = sample_checkpoint<2>(40);
    const std::string good = (dir.path / "good.h5").string();
    write_checkpoint<2>(good, c);

    SUBCASE("another case") {
        const std::string m = refusal<2>(good, std::string(64, 'b'));
        CHECK(contains(m, "another case"));
    }
    SUBCASE("another dimension") {
        CHECK(contains(refusal<3>(good, c.case_fingerprint), "2-D"));
    }
    SUBCASE("another format version") {
        const std::string p = (dir.path / "v2.h5").string();
        fs::copy_file(good, p);
        set_int_attribute(p, "format_version", checkpoint_format_version + 1);
        CHECK(contains(refusal<2>(p, c.case_fingerprint), "format version"));
    }
    SUBCASE("truncated at any length") {
        const auto full = fs::file_size(good);
        for (const double frac : {0.0, 0.1, 0.5, 0.9, 0.999}) {
            const std::string p = (dir.path / "cut.h5").string();
            fs::copy_file(good, p, fs::copy_options::overwrite_existing);
            fs::resize_file(p, static_cast<std::uintmax_t>(frac * static_cast<double>(full)));
            CAPTURE(frac);
            CHECK(contains(refusal<2>(p, c.case_fingerprint), "refused as a checkpoint"));
        }
    }
    SUBCASE("a damaged byte in the particle data") {
        const std::string p = (dir.path / "flip.h5").string();
        fs::copy_file(good, p);
        const haddr_t at = chunk_address(p, "x");
        REQUIRE(at != HADDR_UNDEF);
        std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(static_cast<std::streamoff>(at + 20));
        char byte = 0;
        f.get(byte);
        f.seekp(static_cast<std::streamoff>(at + 20));
        f.put(static_cast<char>(byte ^ 0x10));
        f.close();
        CHECK(contains(refusal<2>(p, c.case_fingerprint), "damaged"));
    }
    SUBCASE("a solver state whose time step cannot move the clock") {
        // Written by a damaged or hand-made file: the run would spin (dt = 0, NaN, or lost in
        // t's rounding) or jump past its end (dt = inf) instead of stopping.
        const double inf = std::numeric_limits<double>::infinity();
        for (const auto& [t, dt] : std::vector<std::pair<double, double>>{
                 {0.5, inf}, {0.5, std::nan("")}, {0.5, 0.0}, {0.5, -1e-4}, {1e300, 1e-4}}) {
            auto bad = c;
            bad.solver.time = t;
            bad.solver.dt = dt;
            const std::string p = (dir.path / "clock.h5").string();
            write_checkpoint<2>(p, bad);
            CAPTURE(t);
            CAPTURE(dt);
            CHECK(contains(refusal<2>(p, c.case_fingerprint), "implausible state"));
        }
        // The sample's own clock (t, dt) is accepted.
        CHECK(read_checkpoint<2>(good, c.case_fingerprint).solver.dt == c.solver.dt);
    }
    SUBCASE("not a checkpoint") {
        const std::string text = (dir.path / "text.h5").string();
        std::ofstream(text) << "hello\n";
        CHECK(contains(refusal<2>(text, c.case_fingerprint), "not a readable HDF5 file"));
        SnapshotWriter<2> snaps(dir.path.string(), {"position"});
        const std::string snap = snaps.write(c.particles, 0.0, 0);
        CHECK(contains(refusal<2>(snap, c.case_fingerprint), "not a sluice checkpoint"));
        CHECK(contains(refusal<2>((dir.path / "absent.h5").string(), c.case_fingerprint),
                       "no such file"));
    }
}

namespace {

const std::string kCase = R"(# a small case
[case]
name = "fp"
description = "first"
dimension = 2

[domain]
lo = [0.0, 0.0]
hi = [1.0, 1.0]

[fluid]
rho0 = 1000.0
viscosity = 1.0e-3
sound_speed = 20.0

[particles]
dx = 0.05

[[blocks]]
lo = [0.0, 0.0]
hi = [0.5, 0.5]

[walls]
model = "dummy"
tank_lo = [0.0, 0.0]
tank_hi = [1.0, 1.0]
tank_faces = ["x-", "x+", "y-"]

[time]
end_time = 0.1
output_interval = 0.01
)";

// The same case with comments, spacing and key order changed.
const std::string kCaseReordered = R"(
[time]
output_interval = 0.01   # seconds
end_time = 0.1
[particles]
dx = 0.05
[fluid]
sound_speed = 20.0
viscosity = 0.001
rho0 = 1000.0
[case]
dimension = 2
name = "fp"
[domain]
hi = [1.0, 1.0]
lo = [0.0, 0.0]
[[blocks]]
hi = [0.5, 0.5]
lo = [0.0, 0.0]
[walls]
tank_faces = ["x-", "x+", "y-"]
model = "dummy"
tank_hi = [1.0, 1.0]
tank_lo = [0.0, 0.0]
)";

std::string case_file(const TempDir& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir.path / name;
    std::ofstream(p) << text;
    return p.string();
}

} // namespace

TEST_CASE("the case fingerprint covers what determines results and nothing else") {
    TempDir dir;
    const std::string path = case_file(dir, "fp.toml", kCase);
    const std::string fp = read_case(path).fingerprint;
    CHECK(fp.size() == 64);
    CHECK(read_case(case_file(dir, "re.toml", kCaseReordered)).fingerprint == fp);
    for (const char* same :
         {"time.end_time=5", "case.description=\"other\"", "checkpoint.every_steps=7",
          "limits.max_speed=3", "runtime.particles_per_group=10", "runtime.rebalance_every=4"}) {
        CAPTURE(same);
        CHECK(read_case(path, {same}).fingerprint == fp);
    }
    for (const char* other : {"fluid.sound_speed=21", "particles.dx=0.04", "blocks.0.hi=[0.5,0.6]",
                              "time.output_interval=0.02", "numerics.kernel=wendland_c2",
                              "output.snapshots=false", "case.name=\"other\""}) {
        CAPTURE(other);
        CHECK(read_case(path, {other}).fingerprint != fp);
    }
}

TEST_CASE("[checkpoint] and [limits] keys: defaults and refused values") {
    TempDir dir;
    const std::string path = case_file(dir, "keys.toml", kCase);
    const CaseConfig c = read_case(path);
    CHECK(c.checkpoint_every_steps == 0);
    CHECK(c.checkpoint_every_minutes == 30);
    CHECK(c.max_speed == 20.0);   // the sound speed
    CHECK(c.min_density == 10.0); // 0.01 rho0
    CHECK(c.max_density == 2000.0);
    const CaseConfig d = read_case(path, {"checkpoint.every_steps=100",
                                          "checkpoint.every_minutes=0.5", "limits.max_speed=3",
                                          "limits.min_density=500", "limits.max_density=1100"});
    CHECK(d.checkpoint_every_steps == 100);
    CHECK(d.checkpoint_every_minutes == 0.5);
    CHECK(d.max_speed == 3);
    CHECK(d.min_density == 500);
    CHECK(d.max_density == 1100);
    for (const auto& [set, key] : std::vector<std::pair<std::string, std::string>>{
             {"checkpoint.every_steps=-1", "checkpoint.every_steps"},
             {"checkpoint.every_steps=1.5", "checkpoint.every_steps"},
             {"checkpoint.every_minutes=-2", "checkpoint.every_minutes"},
             {"checkpoint.every_minutes=nan", "checkpoint.every_minutes"},
             {"checkpoint.every_secs=3", "checkpoint.every_secs"},
             {"limits.max_speed=0", "limits.max_speed"},
             {"limits.min_density=1000", "limits.min_density"},
             {"limits.max_density=999", "limits.max_density"},
             {"limits.max_density=\"big\"", "limits.max_density"}}) {
        CAPTURE(set);
        try {
            (void)read_case(path, {set});
            FAIL("accepted " << set);
        } catch (const CaseError& e) {
            CHECK(e.key() == key);
        }
    }
}
