#include "particles/NeighbourList.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace mfdyn {

NeighbourList::NeighbourList(std::vector<std::size_t> offsets, std::vector<Index> indices)
    : offsets_(std::move(offsets)), indices_(std::move(indices)) {
    if (offsets_.empty() || offsets_.front() != 0 || offsets_.back() != indices_.size() ||
        !std::is_sorted(offsets_.begin(), offsets_.end()))
        throw Error("NeighbourList: offsets must rise from 0 to the number of indices (" +
                    std::to_string(indices_.size()) + ")");
}

std::size_t NeighbourList::maxRowSize() const {
    std::size_t m = 0;
    for (std::size_t i = 0; i < size(); ++i) m = std::max(m, rowSize(i));
    return m;
}

bool NeighbourList::symmetric() const {
    // Sorted copies of each row make the reverse look-up a binary search; rows may be stored in
    // cell order rather than index order.
    std::vector<Index> sorted = indices_;
    for (std::size_t i = 0; i < size(); ++i)
        std::sort(sorted.begin() + offsets_[i], sorted.begin() + offsets_[i + 1]);
    for (std::size_t i = 0; i < size(); ++i)
        for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
            const std::size_t j = sorted[k];
            if (j >= size() ||
                !std::binary_search(sorted.begin() + offsets_[j], sorted.begin() + offsets_[j + 1], Index(i)))
                return false;
        }
    return true;
}

void NeighbourList::sortRowsBy(const std::int64_t* key) {
    const std::size_t rows = size();
    parallelForWork(rows, indices_.size(), [&](std::size_t i) {
        std::sort(indices_.begin() + std::ptrdiff_t(offsets_[i]), indices_.begin() + std::ptrdiff_t(offsets_[i + 1]),
                  [&](Index a, Index b) { return key[a] < key[b] || (key[a] == key[b] && a < b); });
    });
}

}  // namespace mfdyn
