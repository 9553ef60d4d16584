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
}

double ExactSum::value() const {
    ExactSum a = *this;
    a.normalise();
    const bool negative = a.limb_[limbs - 1] < 0;
    if (negative) {  // the magnitude: negate every limb and carry again
        for (auto& l : a.limb_) l = -l;
        a.normalise();
    }
    int top = limbs - 1;
    while (top >= 0 && a.limb_[top] == 0) --top;
    double magnitude = 0;
    if (top >= 0) {
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

double globalMax(double local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return local;
    std::vector<double> all(std::size_t(Communicator::size()));
    Communicator::allGather(&local, sizeof local, all.data());
    return *std::max_element(all.begin(), all.end());
}

double globalMin(double local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return local;
    std::vector<double> all(std::size_t(Communicator::size()));
    Communicator::allGather(&local, sizeof local, all.data());
    return *std::min_element(all.begin(), all.end());
}

double globalMedian(const std::vector<double>& local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    std::vector<double> all;
    if (!Communicator::distributed()) {
        all = local;
    } else {
        const char* bytes = reinterpret_cast<const char*>(local.data());
        for (const auto& part : Communicator::allGatherVariable(
                 std::vector<char>(bytes, bytes + local.size() * sizeof(double)))) {
            const std::size_t k = part.size() / sizeof(double);
            const std::size_t at = all.size();
            all.resize(at + k);
            if (k) std::memcpy(all.data() + at, part.data(), part.size());
        }
    }
    if (all.empty()) return 0;
    std::nth_element(all.begin(), all.begin() + long(all.size() / 2), all.end());
    return all[all.size() / 2];
}

std::vector<std::int64_t> globalConcatenation(const std::vector<std::int64_t>& local) {
    globalReductionCount.fetch_add(1, std::memory_order_relaxed);
    if (!Communicator::distributed()) return local;
    std::vector<std::int64_t> all;
    const char* bytes = reinterpret_cast<const char*>(local.data());
    for (const auto& part : Communicator::allGatherVariable(
             std::vector<char>(bytes, bytes + local.size() * sizeof(std::int64_t)))) {
        const std::size_t k = part.size() / sizeof(std::int64_t), at = all.size();
        all.resize(at + k);
        if (k) std::memcpy(all.data() + at, part.data(), part.size());
    }
    return all;
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
