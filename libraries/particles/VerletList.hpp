#pragma once
// A neighbour list with a skin, rebuilt only when it may have lost a neighbour.
//
// The list holds the pairs of the chosen criterion for radii r_i + skin at the last build. Let
// D_i be particle i's displacement since (minimum image in periodic directions) and G_i = r_i -
// r_i(build) the growth of its radius. A pair missing from row i was then at d0 >= r_i(build) +
// skin (for the criterion either also d0 >= r_j(build) + skin), so it is no neighbour now as
// long as D_i + D_j <= skin - G_i (and <= skin - G_j): d >= d0 - D_i - D_j >= r_i. Two
// policies keep that true:
//
// - displacement (the classic one): rebuild once 2 max D + max(max G, 0) > skin, so with
//   constant radii once some particle has moved more than half the skin;
// - checked: particles with D_i <= skin / 2 and D_i + skin / 2 <= skin - G_i ("slow") need no
//   test among themselves. The others ("fast": the free end of a gas expanding into vacuum, the
//   particles a strong shock has just swept, a radius that grew) are tested directly: every
//   particle within reach of a fast one now, found through the cells of the last build, must be
//   in its row (and it in theirs). The list is rebuilt only when a pair is missing or when the
//   tests would cost more than a rebuild (too many fast particles). In a strong-shock tube the
//   classic policy rebuilt at almost every step because of a few particles at the free ends.
//
// Either way the list gives candidates: the caller keeps those with d < r. The check is exact
// (it compares the separations the search itself uses) and does not depend on the number of
// threads. A caller that reorders its particles (NeighbourSearch::applyOrder through search())
// calls invalidate(): the stored positions refer to the old order.
#include "particles/NeighbourSearch.hpp"

namespace mfdyn {

enum class VerletPolicy { displacement, checked };

template <int Dim>
class VerletList {
public:
    explicit VerletList(double skin, NeighbourDomain<Dim> domain = {}, NeighbourSearchOptions options = {},
                        VerletPolicy policy = VerletPolicy::displacement);

    // Returns whether the list was rebuilt.
    bool update(const std::vector<Vector<Dim>>& positions, const std::vector<double>& supportRadius);
    bool update(const std::vector<Vector<Dim>>& positions, double supportRadius);
    void invalidate() { built_ = false; }
    // Called with the particles' FieldStore::topologyVersion() before update(): after particles
    // were appended, removed or reordered the stored positions belong to other particles (even
    // when their number is the same), so the next update() rebuilds.
    void track(std::uint64_t topologyVersion) {
        if (topologyVersion != trackedVersion_) built_ = false;
        trackedVersion_ = topologyVersion;
    }

    const NeighbourList& candidates() const { return candidates_; }
    // After every rebuild, order each row by key (NeighbourList::sortRowsBy; the vector is read
    // at each rebuild, so it may grow with ghosts): sums over rows then do not depend on how the
    // particles are numbered or when the list was built. nullptr: cell order (the default).
    void orderRowsBy(const std::vector<std::int64_t>* key) { rowKey_ = key; }
    double skin() const { return skin_; }
    VerletPolicy policy() const { return policy_; }
    std::size_t rebuildCount() const { return rebuilds_; }
    // Updates of the checked policy that kept the list after testing the fast particles, and
    // the number of fast particles the last update found (0 after a rebuild).
    std::size_t checkedCount() const { return checked_; }
    std::size_t fastCount() const { return fast_; }
    // The largest displacement since the last build (0 before the first).
    double maxDisplacement(const std::vector<Vector<Dim>>& positions) const;
    const NeighbourSearch<Dim>& search() const { return search_; }

private:
    bool needsRebuild(const std::vector<Vector<Dim>>& positions, const double* radius, bool constantRadius);
    // The checked policy: false when every pair that is a neighbour now is in the list.
    bool fastPairsMissing(const std::vector<Vector<Dim>>& positions, const double* radius,
                          bool constantRadius);
    void rebuild(const std::vector<Vector<Dim>>& positions, const double* radius, bool constantRadius);

    double skin_;
    VerletPolicy policy_;
    NeighbourSearch<Dim> search_;
    NeighbourList candidates_;
    bool built_ = false;
    std::size_t rebuilds_ = 0, checked_ = 0, fast_ = 0;
    std::vector<Vector<Dim>> builtPosition_;
    std::vector<double> builtRadius_;
    double builtMaxRadius_ = 0.0;
    std::uint64_t trackedVersion_ = 0;  // see track()
    const std::vector<std::int64_t>* rowKey_ = nullptr;  // see orderRowsBy()
    // Scratch of the checked policy, kept between updates.
    std::vector<double> displacement_;
    std::vector<NeighbourList::Index> fastParticles_;
    std::vector<std::uint32_t> mark_;
    std::uint32_t tag_ = 0;
};

}  // namespace mfdyn
