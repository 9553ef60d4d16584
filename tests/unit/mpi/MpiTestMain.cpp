// GoogleTest under mpirun: every rank runs every test, in the same order, so the collectives the
// tests make meet. MPI is started before the first test and ended after the last; each rank's
// exit status is its own result, and mpirun fails when any rank failed.
#include "core/Communicator.hpp"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    mfdyn::Communicator::initialise(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    const int status = RUN_ALL_TESTS();
    mfdyn::Communicator::finalise();
    return status;
}
