#pragma once
// Work that one rank does alone, and the failures of rank-local work made every rank's.
//
// Under mpirun the case's own files have one writer, rank 0: the case lock, particles.pvd, the
// sweep of temporaries, the CSV files. Every rank writes its own piece of a time directory. When
// such work throws on some ranks only, the others go on to the next collective (a reduction, a
// barrier) and wait there for ever. So after it every rank calls shareFailure: a collective that
// either returns on every rank or throws on every rank, with the words of the lowest failing rank.
// It is also a barrier: no rank returns from it before every rank has entered it.
#include "core/Communicator.hpp"

#include <exception>

namespace mfdyn {

// `failure`: this rank's exception, or nullptr. On one process it is rethrown as it is. On several,
// every rank throws when any rank failed: a failing rank its own exception, the others an
// InputError, RunError or Error (the failing one's kind) with the lowest failing rank's message
// and " (on rank <r> of <n>)".
void shareFailure(std::exception_ptr failure);

// Runs `work` on rank 0 alone; every rank then returns, or throws what it threw (shareFailure).
// On one process: work().
template <class Work>
void onRankZero(Work&& work) {
    std::exception_ptr failure;
    if (Communicator::rank() == 0) {
        try {
            work();
        } catch (...) {
            failure = std::current_exception();
        }
    }
    shareFailure(failure);
}

}  // namespace mfdyn
