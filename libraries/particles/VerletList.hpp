#pragma once
// A neighbour list with a skin, rebuilt only when it may have lost a neighbour.
//
// The list holds the pairs of the chosen criterion for radii r_i + skin at the last build. A pair
// that is a neighbour now (d < r) was then at d0 <= d + 2 D, with D the largest displacement
// since (minimum image in periodic directions); with G the largest growth of a radius, it is a
// candidate as long as 2 D + G <= skin. update() rebuilds past that, so with constant radii a
// rebuild happens once some particle has moved more than half the skin. The list gives
// candidates: the caller keeps those with d < r.
//
// A caller that reorders its particles (NeighbourSearch::applyOrder through search()) calls
// invalidate(): the stored positions refer to the old order.
#include "particles/NeighbourSearch.hpp"

namespace mfdyn {

template <int Dim>
class VerletList {
public:
    explicit VerletList(double skin, NeighbourDomain<Dim> domain = {}, NeighbourSearchOptions options = {});

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
    double skin() const { return skin_; }
    std::size_t rebuildCount() const { return rebuilds_; }
    // The largest displacement since the last build (0 before the first).
    double maxDisplacement(const std::vector<Vector<Dim>>& positions) const;
    const NeighbourSearch<Dim>& search() const { return search_; }

private:
    bool needsRebuild(const std::vector<Vector<Dim>>& positions, const double* radius,
                      bool constantRadius) const;
    void rebuild(const std::vector<Vector<Dim>>& positions, const double* radius, bool constantRadius);

    double skin_;
    NeighbourSearch<Dim> search_;
    NeighbourList candidates_;
    bool built_ = false;
    std::size_t rebuilds_ = 0;
    std::vector<Vector<Dim>> builtPosition_;
    std::vector<double> builtRadius_;
    std::uint64_t trackedVersion_ = 0;  // see track()
};

}  // namespace mfdyn
