#pragma once
// The neighbour list of a reference configuration, built once and kept: total-Lagrangian
// methods evaluate every operator over the pairs of the undeformed body, so the list must not
// follow the motion. The reference positions are kept with it because those methods need
// X_i - X_j (kernel gradients in the reference configuration) at every step.
#include "particles/NeighbourSearch.hpp"

namespace mfdyn {

template <int Dim>
class NeighbourReferenceList {
public:
    NeighbourReferenceList(const std::vector<Vector<Dim>>& referencePositions,
                           const std::vector<double>& supportRadius, NeighbourDomain<Dim> domain = {},
                           NeighbourSearchOptions options = {});
    NeighbourReferenceList(const std::vector<Vector<Dim>>& referencePositions, double supportRadius,
                           NeighbourDomain<Dim> domain = {}, NeighbourSearchOptions options = {});

    const NeighbourList& list() const { return list_; }
    std::size_t size() const { return referencePosition_.size(); }
    const std::vector<Vector<Dim>>& referencePositions() const { return referencePosition_; }
    const NeighbourDomain<Dim>& domain() const { return domain_; }
    // X_i - X_j, minimum image in periodic directions.
    Vector<Dim> referenceSeparation(std::size_t i, std::size_t j) const {
        return domain_.separation(referencePosition_[i], referencePosition_[j]);
    }

private:
    NeighbourDomain<Dim> domain_;
    std::vector<Vector<Dim>> referencePosition_;
    NeighbourList list_;
};

}  // namespace mfdyn
