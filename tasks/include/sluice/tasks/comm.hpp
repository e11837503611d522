#pragma once
// The only door to MPI. Everything here is called from the main thread; the one call a TBB
// worker makes is the MPI_Isend of a halo message it has just packed (StepGraph, only with
// MPI_THREAD_MULTIPLE: workers_may_post). No worker ever waits inside MPI. When MPI was not
// initialised (unit tests, tools) the world is one rank and every exchange is a no-op, so the
// solver has a single code path.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sluice::tasks {

using Bytes = std::vector<std::byte>;

// Initialises MPI for the lifetime of the object, asking for MPI_THREAD_MULTIPLE (pack tasks
// post their messages) and requiring at least FUNNELED (with which the main thread posts them).
class MpiSession {
public:
    MpiSession(int* argc, char*** argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    [[nodiscard]] int provided_level() const { return provided_; }

private:
    int provided_ = 0;
    bool owns_ = false;
};

// An all-gather in flight (MPI_Iallgather): started by Comm::start_all_gather, completed by
// wait(). Every rank must contribute the same number of bytes. Destroying one in flight waits
// for it (every rank started it, so it completes).
class PendingAllGather {
public:
    PendingAllGather();
    ~PendingAllGather();
    PendingAllGather(PendingAllGather&&) noexcept;
    PendingAllGather& operator=(PendingAllGather&&) noexcept;
    PendingAllGather(const PendingAllGather&) = delete;
    PendingAllGather& operator=(const PendingAllGather&) = delete;

    // Started and not yet waited for.
    [[nodiscard]] bool active() const;
    // Completes it; every rank's contribution in rank order.
    [[nodiscard]] std::vector<Bytes> wait();
    // Whether it has completed (MPI_Test; then wait() returns at once).
    [[nodiscard]] bool test();

private:
    friend class Comm;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

class Comm {
public:
    // MPI_COMM_WORLD, or a one-rank world when MPI is not initialised.
    static Comm world();

    [[nodiscard]] int rank() const { return rank_; }
    [[nodiscard]] int size() const { return size_; }
    [[nodiscard]] bool parallel() const { return size_ > 1; }

    // Point-to-point exchange with a symmetric set of peers: send[k] goes to peers[k] and
    // recv[k] is what peers[k] sent. Non-blocking sends, receives matched by probe; returns
    // once every message of this exchange is complete.
    void exchange(const std::vector<int>& peers, const std::vector<Bytes>& send,
                  std::vector<Bytes>& recv, int tag) const;

    // Every rank sends send[r] to rank r (used when the balancer moves cut points).
    void all_to_all(const std::vector<Bytes>& send, std::vector<Bytes>& recv) const;

    // Each rank contributes `mine`; every rank gets all contributions in rank order.
    [[nodiscard]] std::vector<Bytes> all_gather(std::span<const std::byte> mine) const;

    // The same for contributions of one size on every rank, without waiting: the rank goes on
    // while the messages travel and collects them with PendingAllGather::wait().
    [[nodiscard]] PendingAllGather start_all_gather(std::span<const std::byte> mine) const;

    // Rank `root` gets every rank's contribution in rank order (others get an empty vector).
    [[nodiscard]] std::vector<Bytes> gather(std::span<const std::byte> mine, int root = 0) const;

    // Broadcast of a string from `root`.
    [[nodiscard]] std::string broadcast(const std::string& s, int root) const;

    void barrier() const;
    [[noreturn]] void abort(int code) const;

    // Whether a step graph's pack tasks may post their own halo messages (MPI_Isend from a
    // TBB worker): MPI gave MPI_THREAD_MULTIPLE, and SLUICE_POST_FROM_MAIN is not set (which
    // keeps the main thread posting, to compare the two).
    [[nodiscard]] static bool workers_may_post();

    // Bytes this rank has sent through this object's functions and the step graphs.
    [[nodiscard]] static std::uint64_t bytes_sent();
    static void count_sent(std::uint64_t bytes);

private:
    int rank_ = 0, size_ = 1;
};

// Packs/unpacks plain values (numbers, fixed-size vectors) as raw bytes.
template <class T>
void put(Bytes& b, const T& v) {
    const std::size_t n = b.size();
    b.resize(n + sizeof(T));
    std::memcpy(b.data() + n, static_cast<const void*>(&v), sizeof(T));
}
template <class T>
void take_into(std::span<const std::byte> b, std::size_t& pos, T& v) {
    std::memcpy(static_cast<void*>(&v), b.data() + pos, sizeof(T));
    pos += sizeof(T);
}
template <class T>
T take(std::span<const std::byte> b, std::size_t& pos) {
    T v{};
    take_into(b, pos, v);
    return v;
}

} // namespace sluice::tasks
