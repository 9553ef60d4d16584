// Failures of one rank's work made every rank's (core/RankZero.hpp), on three ranks.
#include "core/Communicator.hpp"
#include "core/Error.hpp"
#include "core/RankZero.hpp"

#include <gtest/gtest.h>

#include <exception>
#include <string>

using namespace mfdyn;

TEST(RankZero, AFailureOfOneRankIsThrownOnEveryRankWithItsWordsAndKind) {
    const int rank = Communicator::rank();
    std::string message;
    bool input = false;
    try {
        std::exception_ptr failure;
        if (rank == 2) failure = std::make_exception_ptr(InputError("rank 2's file is bad"));
        if (rank == 1) failure = std::make_exception_ptr(Error("rank 1 could not write"));
        shareFailure(failure);
    } catch (const InputError& e) {
        input = true;
        message = e.what();
    } catch (const Error& e) {
        message = e.what();
    }
    // The lowest failing rank's words; a failing rank keeps its own exception.
    EXPECT_EQ(message, rank == 2   ? "rank 2's file is bad"
                       : rank == 1 ? "rank 1 could not write"
                                   : "rank 1 could not write (on rank 1 of 3)");
    EXPECT_EQ(input, rank == 2);

    int ran = 0;
    EXPECT_THROW(onRankZero([&] {
                     ++ran;
                     throw InputError("only rank 0 looked");
                 }),
                 InputError);
    EXPECT_EQ(ran, rank == 0 ? 1 : 0);
    EXPECT_NO_THROW(shareFailure(nullptr));
}
