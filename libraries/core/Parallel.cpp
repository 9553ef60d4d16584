#include "core/Parallel.hpp"

#include <omp.h>

#include <algorithm>
#include <cstring>

namespace mfdyn {

int threadCount() {
    return omp_get_max_threads();
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
        for (const auto& part :
             Communicator::allGatherVariable(std::vector<char>(bytes, bytes + local.size() * sizeof(double)))) {
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
    for (const auto& part :
         Communicator::allGatherVariable(std::vector<char>(bytes, bytes + local.size() * sizeof(std::int64_t)))) {
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
