// GlobalReduce::exactSum on three ranks (core/Parallel.hpp): each rank sums an uneven share of
// the same terms, and every rank gets the bits of the serial sum of them all, where the rounded
// per-rank partials of GlobalReduce::sum, added in rank order, differ in the last bits (issue 21).
#include "core/Communicator.hpp"
#include "core/Parallel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace mfdyn;

namespace {
// Terms over 40 decades and both signs, whose order of addition shows in the last bits.
double term(std::size_t i) {
    return std::sin(double(i)) * std::pow(10.0, double(i % 41) - 20);
}
}  // namespace

TEST(ExactSumOnRanks, EveryRankGetsTheSerialSumWhateverTheShares) {
    const std::size_t n = 10007;
    const auto rank = std::size_t(Communicator::rank()), ranks = std::size_t(Communicator::size());
    const double serial = LocalReduce::exactSum<double>(n, term);
    const auto serialPair = LocalReduce::exactSum<SumArray<2>>(n, [](std::size_t i) {
        SumArray<2> s;
        s.s = {term(i), 1.0};
        return s;
    });
    // Shares of growing size: rank r holds [begin, end).
    for (std::size_t shift : {0, 1, 4096}) {
        auto edge = [&](std::size_t r) {
            return r == 0 ? 0 : std::min(n, r * r * n / (ranks * ranks) + shift);
        };
        const std::size_t begin = edge(rank), end = rank + 1 == ranks ? n : edge(rank + 1);
        const double distributed =
            GlobalReduce::exactSum<double>(end - begin, [&](std::size_t i) { return term(begin + i); });
        EXPECT_EQ(distributed, serial) << "shift " << shift;
        const auto pair = GlobalReduce::exactSum<SumArray<2>>(end - begin, [&](std::size_t i) {
            SumArray<2> s;
            s.s = {term(begin + i), 1.0};
            return s;
        });
        EXPECT_EQ(pair.s[0], serialPair.s[0]);
        EXPECT_EQ(pair.s[1], double(n));
    }
}
