// ExactSum (core/Parallel.hpp): the correctly rounded sum whatever the order of the terms, the cut
// into blocks or the thread count. References: hand-computed sums (cancellations, ties, subnormals,
// overflow), sums of a few terms that long double holds exactly, and Shewchuk's exact summation as
// CPython's math.fsum does it (Shewchuk 1997, "Adaptive precision floating-point arithmetic and
// fast robust geometric predicates"; Modules/mathmodule.c, math_fsum): an independent algorithm
// (error-free transformations, no fixed point) that is correctly rounded while no partial overflows.
#include "core/Parallel.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace mfdyn {
namespace {

static_assert(std::is_trivially_copyable_v<ExactSum>, "globalSum gathers it as bytes");
static_assert(std::is_trivially_copyable_v<ExactSums<9>>);

double exact(std::initializer_list<double> terms) {
    ExactSum s;
    for (double t : terms) s += t;
    return s.value();
}

// CPython's math.fsum without its overflow handling (the tests keep every partial finite).
double fsum(const std::vector<double>& values) {
    std::vector<double> partials;
    for (double x : values) {
        std::size_t i = 0;
        for (double y : partials) {
            if (std::abs(x) < std::abs(y)) std::swap(x, y);
            const double hi = x + y, lo = y - (hi - x);
            if (lo != 0) partials[i++] = lo;
            x = hi;
        }
        partials.resize(i);
        partials.push_back(x);
    }
    std::size_t n = partials.size();
    double hi = 0, lo = 0;
    if (n > 0) {
        hi = partials[--n];
        while (n > 0) {
            const double x = hi, y = partials[--n];
            hi = x + y;
            lo = y - (hi - x);
            if (lo != 0) break;
        }
        // Half-way cases: the partial below decides the direction of the rounding.
        if (n > 0 && ((lo < 0 && partials[n - 1] < 0) || (lo > 0 && partials[n - 1] > 0))) {
            const double y = lo * 2, x = hi + y;
            if (y == x - hi) hi = x;
        }
    }
    return hi;
}

TEST(ExactSum, CancellationsAreExactInEveryOrder) {
    std::vector<double> t{1e16, 1.0, -1e16};
    std::sort(t.begin(), t.end());
    do {
        ExactSum s;
        for (double x : t) s += x;
        EXPECT_EQ(s.value(), 1.0);
    } while (std::next_permutation(t.begin(), t.end()));
    EXPECT_EQ(exact({1e308, 1e308, -1e308}), 1e308);  // naively inf
    const double big = std::ldexp(1.0, 1023), tiny = std::ldexp(1.0, -1074);
    EXPECT_EQ(exact({big, big, tiny, -big, -big}), tiny);
    EXPECT_EQ(exact({0.1, 0.2, 0.3, -0.6}), fsum({0.1, 0.2, 0.3, -0.6}));
    EXPECT_EQ(exact({}), 0.0);
    EXPECT_EQ(exact({-2.5}), -2.5);
}

TEST(ExactSum, RoundsToNearestWithTiesToEven) {
    const double u = std::ldexp(1.0, -52), tiny = std::ldexp(1.0, -1074);
    EXPECT_EQ(exact({1.0, u / 2}), 1.0);                                  // tie, 1 even: down
    EXPECT_EQ(exact({1.0, u / 2, tiny}), 1.0 + u);                        // just above the tie
    EXPECT_EQ(exact({1.0, u / 2, -tiny}), 1.0);                           // just below
    EXPECT_EQ(exact({1.0 + u, u / 2}), 1.0 + 2 * u);                      // tie, odd: up
    EXPECT_EQ(exact({-1.0, -u / 2, -tiny}), -1.0 - u);                    // the mirror image
    const double a = std::ldexp(1.0, 1000), half = std::ldexp(1.0, 947);  // ulp(a) = 2^948
    EXPECT_EQ(exact({a, half}), a);
    EXPECT_EQ(exact({a, half, tiny}), a + 2 * half);  // a sticky bit 2021 binades below
    EXPECT_EQ(exact({tiny, a, half}), a + 2 * half);
    EXPECT_EQ(exact({a, 3 * half, -tiny}), a + 2 * half);
}

TEST(ExactSum, SubnormalsAndTheEndsOfTheRange) {
    const double tiny = std::ldexp(1.0, -1074);
    EXPECT_EQ(exact({tiny, tiny, tiny}), 3 * tiny);
    EXPECT_EQ(exact({DBL_MIN, -tiny}), std::nextafter(DBL_MIN, 0.0));
    EXPECT_EQ(exact({-DBL_MIN, DBL_MIN / 4}), -0.75 * DBL_MIN);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(exact({DBL_MAX, DBL_MAX}), inf);
    EXPECT_EQ(exact({DBL_MAX, DBL_MAX, -DBL_MAX}), DBL_MAX);
    EXPECT_EQ(exact({-DBL_MAX, -DBL_MAX, DBL_MAX}), -DBL_MAX);
    EXPECT_EQ(exact({DBL_MAX, std::ldexp(1.0, 969)}), DBL_MAX);  // below half an ulp (2^970)
    EXPECT_EQ(exact({DBL_MAX, std::ldexp(1.0, 970)}), inf);      // the tie, odd mantissa: up
    EXPECT_EQ(exact({inf, 1.0}), inf);
    EXPECT_EQ(exact({1.0, -inf, 2.0}), -inf);
    EXPECT_TRUE(std::isnan(exact({inf, -inf})));
    EXPECT_TRUE(std::isnan(exact({1.0, std::numeric_limits<double>::quiet_NaN()})));
    EXPECT_FALSE(std::signbit(exact({1.0, -1.0})));
}

TEST(ExactSum, FewTermsAgreeWithLongDouble) {
    // Three terms of magnitude in [2^(e-8), 2^(e+1)): their exact sum has its bits between 2^(e-60)
    // and 2^(e+2), at most 63 of them, which long double (x87, 64-bit significand) holds, so
    // rounding it once to double is the correctly rounded sum; e across the range.
    static_assert(std::numeric_limits<long double>::digits >= 64);
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(1.0, 2.0);
    std::uniform_int_distribution<int> near(0, 8), scale(-960, 960), sign(0, 1);
    auto draw = [&](int e) {
        return (sign(random) ? -1.0 : 1.0) * std::ldexp(unit(random), e - near(random));
    };
    for (int trial = 0; trial < 20000; ++trial) {
        const int e = scale(random);
        const double a = draw(e), b = draw(e), c = draw(e);
        const long double reference = (long double)a + (long double)b + (long double)c;
        ASSERT_EQ(exact({a, b, c}), double(reference)) << a << " + " << b << " + " << c;
        ASSERT_EQ(exact({c, a, b}), double(reference));
    }
}

// Values of both signs over 600 decades (and some subnormals), with their negatives for heavy
// cancellation, against fsum; then shuffled and cut into blocks added in another order.
std::vector<double> wideValues(std::mt19937_64& random, std::size_t n) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> binade(-1000, 1000), pick(0, 9);
    std::vector<double> v;
    for (std::size_t i = 0; i < n; ++i) {
        const int kind = pick(random);
        const double x =
            kind == 0 ? std::ldexp(unit(random), -1060) : std::ldexp(unit(random), binade(random));
        v.push_back(x);
        if (kind <= 3) v.push_back(-x * (kind == 1 ? 1.0 : 1.0 + 1e-15));
    }
    return v;
}

TEST(ExactSum, WideRandomSumsAreCorrectlyRoundedWhateverTheOrderAndTheBlocks) {
    std::mt19937_64 random(42);
    for (int set = 0; set < 20; ++set) {
        auto v = wideValues(random, 500);
        const double reference = fsum(v);
        for (int order = 0; order < 10; ++order) {
            std::shuffle(v.begin(), v.end(), random);
            ExactSum whole;
            for (double x : v) whole += x;
            ASSERT_EQ(whole.value(), reference) << "set " << set << ", order " << order;
            // Blocks of random lengths, each summed apart, then added in reverse order.
            std::vector<ExactSum> blocks;
            std::uniform_int_distribution<std::size_t> length(1, 97);
            for (std::size_t i = 0; i < v.size();) {
                ExactSum b;
                for (std::size_t end = std::min(v.size(), i + length(random)); i < end; ++i) b += v[i];
                blocks.push_back(b);
            }
            ExactSum merged;
            for (auto b = blocks.rbegin(); b != blocks.rend(); ++b) merged += *b;
            ASSERT_EQ(merged.value(), reference);
            // The same through the chunked path (ExactSum::add, padded with zeros) and LocalReduce.
            ExactSum chunked;
            for (std::size_t i = 0; i < v.size(); i += ExactSum::chunk) {
                std::vector<double> c(v.begin() + long(i),
                                      v.begin() + long(std::min(v.size(), i + ExactSum::chunk)));
                c.resize((c.size() + 3) / 4 * 4, 0.0);
                chunked.add(c.data(), c.size());
            }
            ASSERT_EQ(chunked.value(), reference);
            ASSERT_EQ(LocalReduce::exactSum<double>(v.size(), [&](std::size_t i) { return v[i]; }),
                      reference);
        }
    }
}

TEST(ExactSum, TheBinnedPathKeepsWhatLiesFarBelowTheLargestTerm) {
    // ExactSum::add splits each term over three bins below the largest of its chunk; terms more
    // than 2^82 below it keep a remainder, added term by term; all of it exactly.
    const double tiny = std::ldexp(1.0, -1074);
    auto chunked = [](std::vector<double> v) {
        v.resize((v.size() + 3) / 4 * 4, 0.0);
        ExactSum s;
        s.add(v.data(), v.size());
        return s.value();
    };
    EXPECT_EQ(chunked({1e16, 1.0, -1e16}), 1.0);
    EXPECT_EQ(chunked({1.0, std::ldexp(1.0, -53), std::ldexp(1.0, -100)}), 1.0 + std::ldexp(1.0, -52));
    EXPECT_EQ(chunked({1.0, std::ldexp(1.0, -53), -std::ldexp(1.0, -200)}), 1.0);
    EXPECT_EQ(chunked({std::ldexp(1.0, 899), 1.0, -std::ldexp(1.0, 899)}), 1.0);
    EXPECT_EQ(chunked({1e300, 1e300, -1e300, -1e300, tiny}), tiny);  // beyond 2^900: term by term
    EXPECT_EQ(chunked({tiny, tiny, -tiny, 3 * tiny}), 4 * tiny);     // below 2^-900 too
    EXPECT_EQ(chunked({1.0, std::numeric_limits<double>::infinity()}),
              std::numeric_limits<double>::infinity());
    EXPECT_EQ(chunked({0.0, -0.0}), 0.0);
    std::vector<double> v;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 256; ++i) v.push_back(std::ldexp(unit(random), i % 3 == 0 ? -120 : 0));
    EXPECT_EQ(chunked(v), fsum(v));
}

TEST(ExactSum, CarriesAreTakenBeforeALimbOverflows) {
    // A mantissa of 53 ones on the top of its first limb (shift 31) fills three limbs; doubling
    // the accumulator 62 times by adding it to itself would overflow a 64-bit limb after 31 had
    // the carries not been propagated on the way (the count of terms reaches 2^30).
    const double x = -std::ldexp(double((std::uint64_t(1) << 53) - 1), -1043);
    ExactSum s;
    s += x;
    for (int k = 0; k < 62; ++k) s += ExactSum(s);
    EXPECT_EQ(s.value(), std::ldexp(x, 62));
}

double term(std::size_t i) {
    return std::sin(double(i)) * std::pow(10.0, double(i % 41) - 20);
}

TEST(ExactSum, ReductionsDoNotDependOnTheThreadCount) {
    const std::size_t n = 50000;  // above the parallel threshold
    std::vector<double> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = term(i);
    const double reference = fsum(all);
    const int threads = omp_get_max_threads();
    for (int t : {1, 2, 3, 7}) {
        omp_set_num_threads(t);
        EXPECT_EQ(LocalReduce::exactSum<double>(n, term), reference) << t << " threads";
        const auto a = GlobalReduce::exactSum<SumArray<2>>(n, [](std::size_t i) {
            SumArray<2> s;
            s.s = {term(i), -2 * term(i)};
            return s;
        });
        EXPECT_EQ(a.s[0], reference);
        EXPECT_EQ(a.s[1], -2 * reference);
    }
    omp_set_num_threads(threads);
    EXPECT_EQ(GlobalReduce::exactSum<double>(0, term), 0.0);
}

}  // namespace
}  // namespace mfdyn
