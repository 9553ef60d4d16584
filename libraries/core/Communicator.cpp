// The processes of a run (Communicator.hpp). MPI_COMM_WORLD; every operation is a thin wrapper
// so that the callers' byte layouts and orders are the only logic, and are shared by the serial
// branch. Compiled with MFDYN_WITH_MPI in an MPI build (core/CMakeLists.txt).
#include "core/Communicator.hpp"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

#ifdef MFDYN_WITH_MPI
#include <mpi.h>
#endif

namespace mfdyn::Communicator {

namespace {
int rank_ = 0;
int size_ = 1;
bool initialised_ = false;  // this process called MPI_Init_thread (and must finalise)
#ifdef MFDYN_WITH_MPI
// A second communicator over the same ranks for the error path's barrier (barrierWithin): a
// barrier there can never be matched with a collective of the run that other ranks are inside.
MPI_Comm errorComm_ = MPI_COMM_NULL;
#endif

bool launchedByMpirun() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
        if (std::getenv(name)) return true;
    return false;
}

#ifdef MFDYN_WITH_MPI
void check(int code, const char* what) {
    if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI call failed: ") + what);
}
#endif
}  // namespace

void initialise(int& argc, char**& argv) {
#ifdef MFDYN_WITH_MPI
    if (initialised_ || !launchedByMpirun()) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    initialised_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // Errors come back as codes (check() above turns them into exceptions, which the
    // application's handler ends the job with) instead of the default silent abort.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_dup(MPI_COMM_WORLD, &errorComm_);
    MPI_Comm_set_errhandler(errorComm_, MPI_ERRORS_RETURN);
#else
    (void)argc, (void)argv;
#endif
}

void finalise() {
#ifdef MFDYN_WITH_MPI
    if (initialised_) {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
        initialised_ = false;
    }
#endif
}

bool mpiBuilt() {
#ifdef MFDYN_WITH_MPI
    return true;
#else
    return false;
#endif
}

int rank() { return rank_; }
int size() { return size_; }

std::string rankName() { return "rank " + std::to_string(rank_) + " of " + std::to_string(size_); }

void allGather(const void* mine, std::size_t bytes, void* all) {
    if (size_ == 1) {
        if (bytes) std::memcpy(all, mine, bytes);
        return;
    }
#ifdef MFDYN_WITH_MPI
    check(MPI_Allgather(mine, int(bytes), MPI_BYTE, all, int(bytes), MPI_BYTE, MPI_COMM_WORLD), "MPI_Allgather");
#endif
}

std::vector<std::vector<char>> allGatherVariable(const std::vector<char>& mine) {
    std::vector<std::vector<char>> all(static_cast<std::size_t>(size_));
    if (size_ == 1) {
        all[0] = mine;
        return all;
    }
#ifdef MFDYN_WITH_MPI
    const long long count = (long long)mine.size();
    std::vector<long long> counts(static_cast<std::size_t>(size_));
    allGather(&count, sizeof count, counts.data());
    std::vector<int> sizes(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    long long total = 0;
    for (int r = 0; r < size_; ++r) {
        sizes[std::size_t(r)] = int(counts[std::size_t(r)]);
        offsets[std::size_t(r)] = int(total);
        total += counts[std::size_t(r)];
    }
    std::vector<char> flat(std::size_t(total) + 1);
    check(MPI_Allgatherv(mine.data(), int(mine.size()), MPI_BYTE, flat.data(), sizes.data(), offsets.data(),
                         MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Allgatherv");
    for (int r = 0; r < size_; ++r)
        all[std::size_t(r)].assign(flat.begin() + offsets[std::size_t(r)],
                                   flat.begin() + offsets[std::size_t(r)] + sizes[std::size_t(r)]);
#endif
    return all;
}

void broadcast(void* data, std::size_t bytes, int root) {
    if (size_ == 1) return;
#ifdef MFDYN_WITH_MPI
    check(MPI_Bcast(data, int(bytes), MPI_BYTE, root, MPI_COMM_WORLD), "MPI_Bcast");
#else
    (void)data, (void)bytes, (void)root;
#endif
}

void exchange(const std::vector<int>& sendRanks, const std::vector<std::vector<char>>& send,
              const std::vector<int>& receiveRanks, std::vector<std::vector<char>>& receive) {
    if (size_ == 1) {
        // One process exchanges only with itself.
        for (std::size_t k = 0; k < receiveRanks.size(); ++k)
            for (std::size_t s = 0; s < sendRanks.size(); ++s)
                if (sendRanks[s] == receiveRanks[k]) receive[k] = send[s];
        return;
    }
#ifdef MFDYN_WITH_MPI
    std::vector<MPI_Request> requests(sendRanks.size() + receiveRanks.size());
    const int tag = 21;
    for (std::size_t k = 0; k < receiveRanks.size(); ++k)
        check(MPI_Irecv(receive[k].data(), int(receive[k].size()), MPI_BYTE, receiveRanks[k], tag, MPI_COMM_WORLD,
                        &requests[k]),
              "MPI_Irecv");
    for (std::size_t k = 0; k < sendRanks.size(); ++k)
        check(MPI_Isend(send[k].data(), int(send[k].size()), MPI_BYTE, sendRanks[k], tag, MPI_COMM_WORLD,
                        &requests[receiveRanks.size() + k]),
              "MPI_Isend");
    check(MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
#endif
}

std::vector<std::vector<char>> allToAll(const std::vector<std::vector<char>>& send) {
    std::vector<std::vector<char>> receive(static_cast<std::size_t>(size_));
    if (size_ == 1) {
        receive[0] = send[0];
        return receive;
    }
#ifdef MFDYN_WITH_MPI
    std::vector<long long> sendCounts(static_cast<std::size_t>(size_)), receiveCounts(static_cast<std::size_t>(size_));
    for (int r = 0; r < size_; ++r) sendCounts[std::size_t(r)] = (long long)send[std::size_t(r)].size();
    check(MPI_Alltoall(sendCounts.data(), 1, MPI_LONG_LONG, receiveCounts.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD),
          "MPI_Alltoall");
    std::vector<int> ranks(static_cast<std::size_t>(size_));
    for (int r = 0; r < size_; ++r) {
        ranks[std::size_t(r)] = r;
        receive[std::size_t(r)].resize(std::size_t(receiveCounts[std::size_t(r)]));
    }
    exchange(ranks, send, ranks, receive);
#endif
    return receive;
}

void barrier() {
    if (size_ == 1) return;
#ifdef MFDYN_WITH_MPI
    check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
#endif
}

bool barrierWithin(double seconds) {
    if (size_ == 1) return true;
#ifdef MFDYN_WITH_MPI
    MPI_Request request;
    if (MPI_Ibarrier(errorComm_, &request) != MPI_SUCCESS) return false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        int done = 0;
        if (MPI_Test(&request, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS) return false;
        if (done) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
#else
    (void)seconds;
    return true;
#endif
}

void abortAll(int status) {
#ifdef MFDYN_WITH_MPI
    if (initialised_) MPI_Abort(MPI_COMM_WORLD, status);
#endif
    std::exit(status);
}

void* nativeHandle() {
#ifdef MFDYN_WITH_MPI
    static MPI_Comm world = MPI_COMM_WORLD;
    return &world;
#else
    return nullptr;
#endif
}

}  // namespace mfdyn::Communicator
