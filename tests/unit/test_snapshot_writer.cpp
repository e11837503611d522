// Snapshots: values read back with the HDF5 C API are bit-identical to what was written, and
// the .xmf series lists every snapshot.
#include "sluice/io/snapshot_writer.hpp"

#include <doctest/doctest.h>
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace sluice;
namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("sluice_snapshot_" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

Particles<2> sample(double shift) {
    Particles<2> ps;
    ps.push_back(7, Kind::fluid, Vec<2>(0.1 + shift, 0.2), Vec<2>(1.5, -2.25), 1000.5, 0.01);
    ps.push_back(3, Kind::wall, Vec<2>(-0.3, 1.0 / 3.0), Vec<2>(0, 0), 999.75, 0.02);
    ps.push_back(12, Kind::fluid, Vec<2>(2.0, 1e-9), Vec<2>(-0.5, 0.125), 1001.0, 0.01);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        ps.p[i] = 100.0 * static_cast<double>(i) + shift;
        ps.a[i] = Vec<2>(0.5 * static_cast<double>(i), -9.81);
    }
    return ps;
}

template <class T>
std::vector<T> read_dataset(hid_t file, const char* name, hid_t type, std::size_t count) {
    std::vector<T> out(count);
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    REQUIRE(set >= 0);
    const hid_t space = H5Dget_space(set);
    CHECK(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) == count);
    H5Sclose(space);
    REQUIRE(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) >= 0);
    H5Dclose(set);
    return out;
}

template <class T>
T read_attribute(hid_t file, const char* name, hid_t type) {
    T value{};
    const hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
    REQUIRE(attr >= 0);
    REQUIRE(H5Aread(attr, type, &value) >= 0);
    H5Aclose(attr);
    return value;
}

void check_snapshot(const fs::path& path, const Particles<2>& ps, double time, long step) {
    const std::size_t n = ps.size();
    const hid_t f = H5Fopen(path.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const auto pos = read_dataset<double>(f, "/position", H5T_NATIVE_DOUBLE, 3 * n);
    const auto vel = read_dataset<double>(f, "/velocity", H5T_NATIVE_DOUBLE, 3 * n);
    const auto acc = read_dataset<double>(f, "/acceleration", H5T_NATIVE_DOUBLE, 3 * n);
    const auto rho = read_dataset<double>(f, "/density", H5T_NATIVE_DOUBLE, n);
    const auto p = read_dataset<double>(f, "/pressure", H5T_NATIVE_DOUBLE, n);
    const auto m = read_dataset<double>(f, "/mass", H5T_NATIVE_DOUBLE, n);
    const auto id = read_dataset<std::uint64_t>(f, "/id", H5T_NATIVE_UINT64, n);
    const auto kind = read_dataset<std::uint8_t>(f, "/kind", H5T_NATIVE_UINT8, n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 2; ++a) {
            const std::size_t k = 3 * i + static_cast<std::size_t>(a);
            CHECK(pos[k] == ps.x[i][a]);
            CHECK(vel[k] == ps.v[i][a]);
            CHECK(acc[k] == ps.a[i][a]);
        }
        CHECK(pos[3 * i + 2] == 0.0); // 2-D padded with z = 0
        CHECK(vel[3 * i + 2] == 0.0);
        CHECK(rho[i] == ps.rho[i]);
        CHECK(p[i] == ps.p[i]);
        CHECK(m[i] == ps.mass[i]);
        CHECK(id[i] == ps.id[i]);
        CHECK(kind[i] == static_cast<std::uint8_t>(ps.kind[i]));
    }
    CHECK(read_attribute<double>(f, "time", H5T_NATIVE_DOUBLE) == time);
    CHECK(read_attribute<std::int64_t>(f, "step", H5T_NATIVE_INT64) == step);
    CHECK(read_attribute<std::int32_t>(f, "dimension", H5T_NATIVE_INT32) == 2);
    H5Fclose(f);
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST_CASE("two snapshots read back exactly and the .xmf lists both") {
    TempDir dir;
    SnapshotWriter<2> writer(dir.path.string(), {"position", "velocity", "density", "pressure",
                                                 "acceleration", "mass", "id", "kind"});
    const auto a = sample(0.0);
    const auto b = sample(0.5);
    const std::string first = writer.write(a, 0.0, 0);
    const std::string second = writer.write(b, 0.125, 250);
    CHECK(writer.count() == 2);
    CHECK(fs::path(first) == dir.path / "snapshots" / "snap_000000.h5");
    CHECK(fs::path(second) == dir.path / "snapshots" / "snap_000001.h5");
    check_snapshot(first, a, 0.0, 0);
    check_snapshot(second, b, 0.125, 250);

    const std::string xmf = slurp(dir.path / "snapshots.xmf");
    CHECK(xmf.find("snapshots/snap_000000.h5:/position") != std::string::npos);
    CHECK(xmf.find("snapshots/snap_000001.h5:/position") != std::string::npos);
    CHECK(xmf.find("snapshots/snap_000001.h5:/kind") != std::string::npos);
    CHECK(xmf.find("CollectionType=\"Temporal\"") != std::string::npos);
    CHECK(xmf.find("TopologyType=\"Polyvertex\"") != std::string::npos);
    CHECK(xmf.find("<Time Value=\"0.125\"/>") != std::string::npos);

    // No temporary file is left behind.
    for (const auto& e : fs::recursive_directory_iterator(dir.path))
        CHECK(e.path().extension() != ".tmp");
}

TEST_CASE("position is always written; unlisted fields are not; old series is cleared") {
    TempDir dir;
    {
        SnapshotWriter<2> w(dir.path.string(), {"position", "pressure"});
        w.write(sample(0), 0, 0);
        w.write(sample(0), 1, 1);
    }
    SnapshotWriter<2> writer(dir.path.string(), {"pressure"});
    CHECK_FALSE(fs::exists(dir.path / "snapshots" / "snap_000001.h5"));
    CHECK_FALSE(fs::exists(dir.path / "snapshots.xmf"));
    const std::string path = writer.write(sample(0), 0, 0);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    CHECK(H5Lexists(f, "position", H5P_DEFAULT) > 0);
    CHECK(H5Lexists(f, "pressure", H5P_DEFAULT) > 0);
    CHECK(H5Lexists(f, "velocity", H5P_DEFAULT) == 0);
    H5Fclose(f);
    const std::string xmf = slurp(dir.path / "snapshots.xmf");
    CHECK(xmf.find("velocity") == std::string::npos);

    CHECK_THROWS_AS(SnapshotWriter<2>(dir.path.string(), {"vorticity"}), std::invalid_argument);
}

TEST_CASE("3-D snapshots keep all three components") {
    TempDir dir;
    SnapshotWriter<3> writer(dir.path.string(), {"position"});
    Particles<3> ps;
    ps.push_back(1, Kind::fluid, Vec<3>(1, 2, 3), Vec<3>(0, 0, 0), 1000, 1);
    const std::string path = writer.write(ps, 0.5, 10);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const auto pos = read_dataset<double>(f, "/position", H5T_NATIVE_DOUBLE, 3);
    CHECK(pos == std::vector<double>{1, 2, 3});
    H5Fclose(f);
}
