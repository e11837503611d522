#pragma once
// Small RAII and error helpers over the HDF5 C API, shared by the snapshot and checkpoint
// writers (private to src/io).

// With the parallel (OpenMPI) HDF5 build, <hdf5.h> includes <mpi.h>: the target compiling this
// file needs MPI's include directories (sluice_core links MPI::MPI_C for that). Fail with
// that advice rather than "mpi.h: not found" if it is ever lost.
#include <H5pubconf.h>
#if defined(H5_HAVE_PARALLEL) && !__has_include(<mpi.h>)
#error "parallel HDF5 needs <mpi.h>: link sluice_core to MPI::MPI_C in CMakeLists.txt"
#endif
#include <hdf5.h>

#include <stdexcept>
#include <string>

namespace sluice::h5 {

// Closes an HDF5 handle on scope exit, so a failed write leaks nothing.
class Handle {
public:
    Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
        if (id_ < 0)
            throw std::runtime_error("HDF5: cannot " + what);
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
    Handle& operator=(Handle&&) = delete;
    ~Handle() {
        if (id_ >= 0)
            close_(id_);
    }
    [[nodiscard]] hid_t get() const { return id_; }

private:
    hid_t id_;
    herr_t (*close_)(hid_t);
};

inline void check(herr_t status, const std::string& what) {
    if (status < 0)
        throw std::runtime_error("HDF5: cannot " + what);
}

template <class T>
void write_attribute(hid_t obj, const char* name, T value, hid_t mem_type, hid_t file_type) {
    const Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a scalar dataspace");
    const Handle attr(H5Acreate2(obj, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      H5Aclose, std::string("create attribute ") + name);
    check(H5Awrite(attr.get(), mem_type, &value), std::string("write attribute ") + name);
}

// Switches HDF5's automatic error printing off for the lifetime of the object (reading a file
// that may be damaged: the caller reports the problem in one sentence instead).
class QuietErrors {
public:
    QuietErrors() {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;
    ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

} // namespace sluice::h5
