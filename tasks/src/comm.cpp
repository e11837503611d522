#include "sluice/tasks/comm.hpp"

#include <mpi.h>

#include <atomic>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <utility>

namespace sluice::tasks {

namespace {
std::atomic<std::uint64_t> g_bytes_sent{0};

int to_int(std::size_t n) {
    if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("message larger than 2 GiB");
    return static_cast<int>(n);
}

bool mpi_active() {
    int init = 0, fin = 0;
    MPI_Initialized(&init);
    MPI_Finalized(&fin);
    return init != 0 && fin == 0;
}
} // namespace

MpiSession::MpiSession(int* argc, char*** argv) {
    int init = 0;
    MPI_Initialized(&init);
    if (init != 0) {
        MPI_Query_thread(&provided_);
    } else {
        // MULTIPLE lets the task that packs a halo message post it (StepGraph); FUNNELED is
        // enough for everything else, and the step graph falls back to posting from the main
        // thread when the library gives no more.
        MPI_Init_thread(argc, argv, MPI_THREAD_MULTIPLE, &provided_);
        owns_ = true;
    }
    if (provided_ < MPI_THREAD_FUNNELED)
        throw std::runtime_error("the MPI library does not provide MPI_THREAD_FUNNELED");
}

MpiSession::~MpiSession() {
    if (owns_ && mpi_active())
        MPI_Finalize();
}

Comm Comm::world() {
    Comm c;
    if (mpi_active()) {
        MPI_Comm_rank(MPI_COMM_WORLD, &c.rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &c.size_);
    }
    return c;
}

void Comm::exchange(const std::vector<int>& peers, const std::vector<Bytes>& send,
                    std::vector<Bytes>& recv, int tag) const {
    recv.assign(peers.size(), {});
    if (!parallel() || peers.empty())
        return;
    std::vector<MPI_Request> req(peers.size());
    for (std::size_t k = 0; k < peers.size(); ++k) {
        MPI_Isend(send[k].data(), to_int(send[k].size()), MPI_BYTE, peers[k], tag, MPI_COMM_WORLD,
                  &req[k]);
        count_sent(send[k].size());
    }
    for (std::size_t k = 0; k < peers.size(); ++k) {
        MPI_Status st;
        MPI_Probe(peers[k], tag, MPI_COMM_WORLD, &st);
        int n = 0;
        MPI_Get_count(&st, MPI_BYTE, &n);
        recv[k].resize(static_cast<std::size_t>(n));
        MPI_Recv(recv[k].data(), n, MPI_BYTE, peers[k], tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    MPI_Waitall(static_cast<int>(req.size()), req.data(), MPI_STATUSES_IGNORE);
}

void Comm::all_to_all(const std::vector<Bytes>& send, std::vector<Bytes>& recv) const {
    recv.assign(static_cast<std::size_t>(size_), {});
    if (!parallel()) {
        recv[0] = send[0];
        return;
    }
    std::vector<int> scount(static_cast<std::size_t>(size_)), rcount(scount.size());
    std::vector<int> sdisp(scount.size()), rdisp(scount.size());
    for (std::size_t r = 0; r < scount.size(); ++r)
        scount[r] = to_int(send[r].size());
    MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, MPI_COMM_WORLD);
    Bytes sbuf, rbuf;
    std::size_t total = 0;
    for (std::size_t r = 0; r < scount.size(); ++r) {
        sdisp[r] = to_int(sbuf.size());
        sbuf.insert(sbuf.end(), send[r].begin(), send[r].end());
        rdisp[r] = to_int(total);
        total += static_cast<std::size_t>(rcount[r]);
    }
    rbuf.resize(total);
    MPI_Alltoallv(sbuf.data(), scount.data(), sdisp.data(), MPI_BYTE, rbuf.data(), rcount.data(),
                  rdisp.data(), MPI_BYTE, MPI_COMM_WORLD);
    count_sent(sbuf.size() - send[static_cast<std::size_t>(rank_)].size());
    for (std::size_t r = 0; r < scount.size(); ++r)
        recv[r].assign(rbuf.begin() + rdisp[r], rbuf.begin() + rdisp[r] + rcount[r]);
}

std::vector<Bytes> Comm::all_gather(std::span<const std::byte> mine) const {
    if (!parallel())
        return {Bytes(mine.begin(), mine.end())};
    const int n = to_int(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), disp(counts.size());
    MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::size_t total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        disp[r] = to_int(total);
        total += static_cast<std::size_t>(counts[r]);
    }
    Bytes all(total);
    MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), disp.data(), MPI_BYTE,
                   MPI_COMM_WORLD);
    count_sent(mine.size() * static_cast<std::size_t>(size_ - 1));
    std::vector<Bytes> out(counts.size());
    for (std::size_t r = 0; r < counts.size(); ++r)
        out[r].assign(all.begin() + disp[r], all.begin() + disp[r] + counts[r]);
    return out;
}

struct PendingAllGather::Impl {
    Bytes mine, all;
    int ranks = 1;
    MPI_Request request = MPI_REQUEST_NULL;
    bool active = false;
};

PendingAllGather::PendingAllGather() : impl_(std::make_unique<Impl>()) {}
PendingAllGather::PendingAllGather(PendingAllGather&&) noexcept = default;
PendingAllGather& PendingAllGather::operator=(PendingAllGather&& other) noexcept {
    if (this != &other) {
        if (active())
            (void)wait();
        impl_ = std::move(other.impl_);
    }
    return *this;
}
PendingAllGather::~PendingAllGather() {
    if (active())
        (void)wait();
}

bool PendingAllGather::active() const {
    return impl_ && impl_->active;
}

bool PendingAllGather::test() {
    if (!active())
        throw std::logic_error("PendingAllGather::test: nothing in flight");
    if (impl_->request == MPI_REQUEST_NULL)
        return true;
    int done = 0;
    MPI_Test(&impl_->request, &done, MPI_STATUS_IGNORE);
    return done != 0;
}

std::vector<Bytes> PendingAllGather::wait() {
    if (!active())
        throw std::logic_error("PendingAllGather::wait: nothing in flight");
    if (impl_->request != MPI_REQUEST_NULL)
        MPI_Wait(&impl_->request, MPI_STATUS_IGNORE);
    impl_->active = false;
    const std::size_t each = impl_->mine.size();
    std::vector<Bytes> out(static_cast<std::size_t>(impl_->ranks));
    for (std::size_t r = 0; r < out.size(); ++r)
        out[r].assign(impl_->all.begin() + static_cast<std::ptrdiff_t>(r * each),
                      impl_->all.begin() + static_cast<std::ptrdiff_t>((r + 1) * each));
    return out;
}

PendingAllGather Comm::start_all_gather(std::span<const std::byte> mine) const {
    PendingAllGather p;
    PendingAllGather::Impl& d = *p.impl_;
    d.mine.assign(mine.begin(), mine.end());
    d.ranks = size_;
    d.active = true;
    if (!parallel()) {
        d.all = d.mine;
        return p;
    }
    d.all.resize(d.mine.size() * static_cast<std::size_t>(size_));
    const int n = to_int(d.mine.size());
    MPI_Iallgather(d.mine.data(), n, MPI_BYTE, d.all.data(), n, MPI_BYTE, MPI_COMM_WORLD,
                   &d.request);
    count_sent(d.mine.size() * static_cast<std::size_t>(size_ - 1));
    return p;
}

std::vector<Bytes> Comm::gather(std::span<const std::byte> mine, int root) const {
    if (!parallel())
        return {Bytes(mine.begin(), mine.end())};
    const int n = to_int(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), disp(counts.size());
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, root, MPI_COMM_WORLD);
    std::size_t total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        disp[r] = to_int(total);
        total += static_cast<std::size_t>(counts[r]);
    }
    Bytes all(rank_ == root ? total : 0);
    MPI_Gatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), disp.data(), MPI_BYTE, root,
                MPI_COMM_WORLD);
    if (rank_ != root)
        count_sent(mine.size());
    std::vector<Bytes> out;
    if (rank_ == root) {
        out.resize(counts.size());
        for (std::size_t r = 0; r < counts.size(); ++r)
            out[r].assign(all.begin() + disp[r], all.begin() + disp[r] + counts[r]);
    }
    return out;
}

std::string Comm::broadcast(const std::string& s, int root) const {
    if (!parallel())
        return s;
    int n = to_int(s.size());
    MPI_Bcast(&n, 1, MPI_INT, root, MPI_COMM_WORLD);
    std::string out = s;
    out.resize(static_cast<std::size_t>(n));
    MPI_Bcast(out.data(), n, MPI_CHAR, root, MPI_COMM_WORLD);
    return out;
}

void Comm::barrier() const {
    if (parallel())
        MPI_Barrier(MPI_COMM_WORLD);
}

void Comm::abort(int code) const {
    if (mpi_active())
        MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);
}

bool Comm::workers_may_post() {
    if (!mpi_active())
        return false;
    int provided = 0;
    MPI_Query_thread(&provided);
    return std::getenv("SLUICE_POST_FROM_MAIN") == nullptr && provided == MPI_THREAD_MULTIPLE;
}

std::uint64_t Comm::bytes_sent() {
    return g_bytes_sent.load();
}
void Comm::count_sent(std::uint64_t bytes) {
    g_bytes_sent += bytes;
}

} // namespace sluice::tasks
