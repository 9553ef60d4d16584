#include "core/Parallel.hpp"

#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace mfdyn {

int threadCount() {
    return omp_get_max_threads();
}

void ExactSum::normalise() {
    std::int64_t carry = 0;
    for (int k = 0; k < limbs - 1; ++k) {
        const std::int64_t v = limb_[k] + carry;
        limb_[k] = v & 0xffffffff;
        carry = v >> 32;  // arithmetic: floor(v / 2^32)
    }
    limb_[limbs - 1] += carry;
    count_ = 1;
    high_ = limbs - 1;
}

// Four doubles side by side (GCC's vector extension): SSE2 pairs on any x86-64, one AVX2 register
// in the avx2 clone of ExactSum::add.
typedef double ExactSumLanes __attribute__((vector_size(32)));

// The avx2 clone where the target has one (x86-64 only: elsewhere the plain build).
#if defined(__x86_64__) && defined(__GNUC__)
#define MFDYN_EXACT_SUM_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MFDYN_EXACT_SUM_CLONES
#endif
MFDYN_EXACT_SUM_CLONES void ExactSum::add(double* x, std::size_t len) {
    using Lanes = ExactSumLanes;
    Lanes largest{}, special{};
    for (std::size_t i = 0; i < len; i += 4) {
        Lanes v;
        std::memcpy(&v, x + i, sizeof v);
        const Lanes magnitude = v < 0 ? -v : v;
        largest = magnitude > largest ? magnitude : largest;
        special += v * 0.0;  // NaN if any term is infinite or NaN
    }
    const double big = std::max(std::max(largest[0], largest[1]), std::max(largest[2], largest[3]));
    const double nonFinite = (special[0] + special[1]) + (special[2] + special[3]);
    if (big == 0 && nonFinite == 0) return;
    if (nonFinite != 0 || !(big < 0x1p900) || big < 0x1p-900) {
        for (std::size_t i = 0; i < len; ++i) *this += x[i];
        return;
    }
    // |x| < 2^e; bin k1 = e + 8: its unit 2^(k1-52), |x| <= 2^(k1-8), and 256 parts sum within
    // 2^(k1+1) (exactly: multiples of the unit below 2^53 units). The remainder after a bin is
    // at most half its unit, 2^(k-53): the next bin is k - 45, and after three the remainders
    // are zero for every term above 2^(e-82).
    // (Bit arithmetic rather than frexp and ldexp, library calls that cost more than a short sum.)
    const int e = int(std::bit_cast<std::uint64_t>(big) >> 52) - 1022;  // big normal, below 2^e
    auto bin = [](int k) {
        return std::bit_cast<double>(std::uint64_t(k + 1023) << 52 | std::uint64_t(1) << 51);
    };
    const double m1 = bin(e + 8), m2 = bin(e + 8 - 45), m3 = bin(e + 8 - 90);  // 1.5 x 2^k
    Lanes s1{}, s2{}, s3{}, rest{};
    for (std::size_t i = 0; i < len; i += 4) {
        Lanes v;
        std::memcpy(&v, x + i, sizeof v);
        const Lanes q1 = (m1 + v) - m1, r1 = v - q1;
        const Lanes q2 = (m2 + r1) - m2, r2 = r1 - q2;
        const Lanes q3 = (m3 + r2) - m3, r3 = r2 - q3;
        s1 += q1, s2 += q2, s3 += q3;
        const Lanes left = r3 < 0 ? -r3 : r3;
        rest = left > rest ? left : rest;
        std::memcpy(x + i, &r3, sizeof r3);
    }
    // The lanes of a bin add exactly too (multiples of its unit, within the same bound).
    for (const Lanes& bin : {s1, s2, s3}) *this += (bin[0] + bin[1]) + (bin[2] + bin[3]);
    if (std::max(std::max(rest[0], rest[1]), std::max(rest[2], rest[3])) > 0)
        for (std::size_t i = 0; i < len; ++i)
            if (x[i] != 0) *this += x[i];
}

double ExactSum::value() const {
    if (high_ < low_) return special_;
    // The carries over the limbs touched only, into the one above (signed: it may hold more than
    // 32 bits; the bits are read as a sum of the limbs, which is what they are).
    ExactSum a = *this;
    const int low = low_, last = std::min(high_ + 1, limbs - 1);
    auto carryUp = [&] {
        std::int64_t carry = 0;
        for (int k = low; k < last; ++k) {
            const std::int64_t v = a.limb_[k] + carry;
            a.limb_[k] = v & 0xffffffff;
            carry = v >> 32;  // arithmetic: floor(v / 2^32)
        }
        a.limb_[last] += carry;
    };
    carryUp();
    const bool negative = a.limb_[last] < 0;
    if (negative) {  // the magnitude: negate every limb and carry again
        for (int k = low; k <= last; ++k) a.limb_[k] = -a.limb_[k];
        carryUp();
    }
    int top = last;
    while (top >= low && a.limb_[top] == 0) --top;
    double magnitude = 0;
    if (top >= low) {
        // The highest bit set, `high`, above 2^-1074; the last bit kept, `ulp`: 53 bits from
        // `high` down, none below 2^-1074 (subnormals keep fewer).
        const int high = 32 * top + 63 - std::countl_zero(std::uint64_t(a.limb_[top]));
        const int ulp = std::max(high - 52, 0);
        auto bit = [&](int i) { return (a.limb_[i >> 5] >> (i & 31)) & 1; };
        // The bits [ulp, high] from the three limbs over ulp (at least 65 bits).
        std::uint64_t kept = 0;
        for (int j = 0; j < 3 && (ulp >> 5) + j < limbs; ++j) {
            const int k = (ulp >> 5) + j, from = 32 * k - ulp;  // bit 0 of limb k, relative to ulp
            const auto l = std::uint64_t(a.limb_[k]);
            if (from >= 0 && from < 64)
                kept |= l << from;
            else if (from < 0)
                kept |= l >> -from;
        }
        kept &= (std::uint64_t(1) << (high - ulp + 1)) - 1;
        // Round to nearest, ties to even: the half bit below ulp and whether anything lies below it.
        if (ulp > 0 && bit(ulp - 1)) {
            bool sticky = false;
            const int below = ulp - 1;  // bits [0, below)
            for (int k = 0; k < (below >> 5) && !sticky; ++k) sticky = a.limb_[k] != 0;
            if (!sticky && (below & 31))
                sticky = (a.limb_[below >> 5] & ((std::int64_t(1) << (below & 31)) - 1)) != 0;
            if (sticky || (kept & 1)) ++kept;  // 2^53 at most: exact; beyond the range: inf
        }
        magnitude = std::ldexp(double(kept), ulp - 1074);
    }
    const double finite = negative ? -magnitude : magnitude;
    return special_ != 0 ? special_ : finite;  // NaN != 0 too
}

}  // namespace mfdyn

namespace mfdyn {

namespace {

// Every rank's value, in rank order (one allGather).
std::vector<double> gatherOne(double local) {
    std::vector<double> all(std::size_t(Communicator::size()));
    Communicator::allGather(&local, sizeof local, all.data());
    return all;
}

// Every rank's values of a trivially copyable T, concatenated in rank order (allGatherVariable).
template <class T>
std::vector<T> gatherAll(const std::vector<T>& local) {
    std::vector<T> all;
    const char* bytes = reinterpret_cast<const char*>(local.data());
    for (const auto& part :
         Communicator::allGatherVariable(std::vector<char>(bytes, bytes + local.size() * sizeof(T)))) {
        const std::size_t k = part.size() / sizeof(T), at = all.size();
        all.resize(at + k);
        if (k) std::memcpy(all.data() + at, part.data(), part.size());
    }
    return all;
}

}  // namespace

double globalMax(double local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return local;
    const std::vector<double> all = gatherOne(local);
    return *std::max_element(all.begin(), all.end());
}

double globalMin(double local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return local;
    const std::vector<double> all = gatherOne(local);
    return *std::min_element(all.begin(), all.end());
}

double globalMedian(const std::vector<double>& local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    std::vector<double> all = Communicator::distributed() ? gatherAll(local) : local;
    if (all.empty()) return 0;
    std::nth_element(all.begin(), all.begin() + long(all.size() / 2), all.end());
    return all[all.size() / 2];
}

std::vector<std::int64_t> globalConcatenation(const std::vector<std::int64_t>& local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    return Communicator::distributed() ? gatherAll(local) : local;
}

std::string globalFirstMessage(std::int64_t key, std::string text) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return text;
    std::vector<std::int64_t> keys(std::size_t(Communicator::size()));
    Communicator::allGather(&key, sizeof key, keys.data());
    const int winner = int(std::min_element(keys.begin(), keys.end()) - keys.begin());
    if (keys[std::size_t(winner)] == noMessageKey) return {};
    std::uint64_t length = text.size();
    Communicator::broadcast(&length, sizeof length, winner);
    text.resize(length);
    Communicator::broadcast(text.data(), length, winner);
    return text;
}

}  // namespace mfdyn
