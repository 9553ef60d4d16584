// Local and global reductions: on one process GlobalReduce is LocalReduce (bit for bit), both are
// independent of the thread count (fixed blocks summed in order), and an empty range gives the
// identities 0, -inf and +inf, which is what a rank without particles contributes.
#include "core/Parallel.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>

namespace mfdyn {
namespace {

// Terms whose sum depends on the order of addition in the last bits.
double term(std::size_t i) {
    return std::sin(double(i)) * std::pow(10.0, double(i % 7) - 3);
}

TEST(Parallel, GlobalEqualsLocalOnOneProcess) {
    const std::size_t n = 50000;
    EXPECT_EQ(GlobalReduce::sum<double>(n, term), LocalReduce::sum<double>(n, term));
    EXPECT_EQ(GlobalReduce::max(n, term), LocalReduce::max(n, term));
    EXPECT_EQ(GlobalReduce::min(n, term), LocalReduce::min(n, term));
    const auto a = GlobalReduce::sum<SumArray<2>>(n, [](std::size_t i) {
        SumArray<2> t;
        t.s = {term(i), 1.0};
        return t;
    });
    EXPECT_EQ(a.s[0], LocalReduce::sum<double>(n, term));
    EXPECT_EQ(a.s[1], double(n));
}

TEST(Parallel, SumsDoNotDependOnTheThreadCount) {
    const std::size_t n = 50000;  // many blocks, above the parallel threshold
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const double one = LocalReduce::sum<double>(n, term);
    omp_set_num_threads(3);
    const double three = LocalReduce::sum<double>(n, term);
    omp_set_num_threads(threads);
    EXPECT_EQ(one, three);
}

TEST(Parallel, EmptyRangesGiveTheIdentities) {
    auto never = [](std::size_t) -> double {
        ADD_FAILURE() << "term called on an empty range";
        return 0;
    };
    EXPECT_EQ(GlobalReduce::sum<double>(0, never), 0.0);
    EXPECT_EQ(LocalReduce::max(0, never), -std::numeric_limits<double>::infinity());
    EXPECT_EQ(GlobalReduce::min(0, never), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace mfdyn
