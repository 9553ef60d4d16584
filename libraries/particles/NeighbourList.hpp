#pragma once
// Neighbour lists in compressed rows: the neighbours of particle i are
// indices()[offsets()[i] .. offsets()[i + 1]). Rows are what a gather loop reads, so particle i
// owns row i and a loop over i needs no atomics.
//
// Indices are 32-bit: half the memory traffic of size_t for a list that is the largest array of
// a run (50 neighbours per particle), and 4 billion particles is beyond one process anyway.
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace mfdyn {

class NeighbourList {
public:
    using Index = std::uint32_t;

    NeighbourList() : offsets_(1, 0) {}
    // offsets has one entry per row plus one; offsets.front() == 0, offsets.back() == indices.size().
    NeighbourList(std::vector<std::size_t> offsets, std::vector<Index> indices);

    std::size_t size() const { return offsets_.size() - 1; }
    std::size_t pairCount() const { return indices_.size(); }
    std::span<const Index> operator[](std::size_t i) const {
        return {indices_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]};
    }
    std::size_t rowSize(std::size_t i) const { return offsets_[i + 1] - offsets_[i]; }
    const std::vector<std::size_t>& offsets() const { return offsets_; }
    const std::vector<Index>& indices() const { return indices_; }

    std::size_t maxRowSize() const;
    // Whether j is in row i exactly when i is in row j (true for the symmetric pair criteria).
    bool symmetric() const;

    // Hands the storage over to a rebuild and leaves this list empty: refilling the same memory
    // saves the page faults and zeroing of a fresh array (200 MB per 10^6 particles at 50
    // neighbours), which cost a tenth of a build (NeighbourSearch::list).
    void releaseStorage(std::vector<std::size_t>& offsets, std::vector<Index>& indices) {
        offsets = std::move(offsets_);
        indices = std::move(indices_);
        offsets_.assign(1, 0);
        indices_.clear();
    }

    // Each row ordered by key[j], then by j where keys tie: an order that does not depend on how
    // the particles are numbered, so that sums over a row come out the same to the bit whatever
    // the numbering (key: the global ids; the decomposition over ranks numbers particles
    // otherwise than one process, and mirror images share their source's id, the tie-break by
    // index keeps a source's images in the order they were made).
    void sortRowsBy(const std::int64_t* key);

    // Exact equality of offsets and indices: the test of thread-count determinism.
    bool operator==(const NeighbourList&) const = default;

private:
    std::vector<std::size_t> offsets_;
    std::vector<Index> indices_;
};

}  // namespace mfdyn
