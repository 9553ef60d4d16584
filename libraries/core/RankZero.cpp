#include "core/RankZero.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <string>

namespace mfdyn {

void shareFailure(std::exception_ptr failure) {
    if (!Communicator::distributed()) {
        if (failure) std::rethrow_exception(failure);
        return;
    }
    // The kind and the failing rank travel in front of the text, so that an input error stays
    // one on every rank (scripts and tests tell bad input from a failed run by it) and the report
    // says where it happened.
    std::string text;
    if (failure) {
        char kind = 'E';
        try {
            std::rethrow_exception(failure);
        } catch (const InputError& e) {
            kind = 'I', text = e.what();
        } catch (const RunError& e) {
            kind = 'R', text = e.what();
        } catch (const std::exception& e) {
            text = e.what();
        } catch (...) {
            text = "unknown exception";
        }
        text = kind + std::to_string(Communicator::rank()) + "\n" + text;
    }
    const std::string shared =
        globalFirstMessage(failure ? std::int64_t(Communicator::rank()) : noMessageKey, std::move(text));
    if (shared.empty()) return;
    // Its own exception keeps every detail (a filesystem error's path) where it is reported:
    // the lowest failing rank's text is the one rank 0 prints.
    if (failure) std::rethrow_exception(failure);
    const std::size_t end = shared.find('\n');
    const std::string message = shared.substr(end + 1) + " (on rank " + shared.substr(1, end - 1) + " of " +
                                std::to_string(Communicator::size()) + ")";
    if (shared[0] == 'I') throw InputError(message);
    if (shared[0] == 'R') throw RunError(message);
    throw Error(message);
}

}  // namespace mfdyn
