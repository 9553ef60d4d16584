#pragma once
// The processes of a run and the bytes they exchange: the one place mfdyn speaks MPI
// (Communicator.cpp; Partitioner.cpp speaks Zoltan over the same communicator). Everything
// above it - the global reductions of Parallel.hpp, the decomposition's migration and halos,
// the pieces a run writes - is written in these few calls, so a serial build (no MPI found, or
// -DMFDYN_MPI=OFF) compiles the same solvers with the one-process answers below.
//
// A run started without mpirun is one process even in an MPI build: MPI is initialised only
// when the launcher's environment says there are ranks (OMPI_COMM_WORLD_SIZE, PMIX_RANK or
// PMI_SIZE), so a solver binary runs serially with no MPI start-up cost and no singleton daemon.
#include <cstddef>
#include <string>
#include <vector>

namespace mfdyn::Communicator {

// Called once by runApplication before anything else; finalise() at exit. Thread support is
// MPI_THREAD_FUNNELED: OpenMP threads compute, the master thread communicates.
void initialise(int& argc, char**& argv);
void finalise();

// MPI compiled in (whatever the number of ranks).
bool mpiBuilt();
int rank();
int size();
// More than one rank: the branch every global operation takes.
inline bool distributed() { return size() > 1; }
// "rank 2 of 4" style prefixes for messages.
std::string rankName();

// Every rank's `bytes` bytes, in rank order, into `all` (size() * bytes).
void allGather(const void* mine, std::size_t bytes, void* all);
// Variable sizes: every rank's buffer, in rank order.
std::vector<std::vector<char>> allGatherVariable(const std::vector<char>& mine);
// The root's bytes to every rank.
void broadcast(void* data, std::size_t bytes, int root);
// Point-to-point exchange with a known pattern: send[k] goes to sendRanks[k], receive[k]
// (already sized by the caller) comes from receiveRanks[k]. Non-blocking sends and receives,
// then a wait for all; no collective, so only the ranks named take part.
void exchange(const std::vector<int>& sendRanks, const std::vector<std::vector<char>>& send,
              const std::vector<int>& receiveRanks, std::vector<std::vector<char>>& receive);
// Every rank's send[r] to rank r; returns what each rank sent here (sizes exchanged first).
std::vector<std::vector<char>> allToAll(const std::vector<std::vector<char>>& send);
void barrier();
// Waits up to `seconds` for every rank to arrive; false when some rank did not (it is stuck in
// other work or has failed). For error paths: a collective that might never complete.
bool barrierWithin(double seconds);
// Ends every rank of the job with `status` (MPI_Abort); on one process std::exit.
[[noreturn]] void abortAll(int status);
// The MPI_Comm (as a pointer to it) for the partitioner; nullptr without MPI.
void* nativeHandle();

}  // namespace mfdyn::Communicator
