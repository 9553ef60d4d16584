#include "particles/NeighbourReferenceList.hpp"

namespace mfdyn {

template <int Dim>
NeighbourReferenceList<Dim>::NeighbourReferenceList(const std::vector<Vector<Dim>>& referencePositions,
                                                    const std::vector<double>& supportRadius,
                                                    NeighbourDomain<Dim> domain,
                                                    NeighbourSearchOptions options)
    : domain_(domain), referencePosition_(referencePositions) {
    NeighbourSearch<Dim> search(std::move(domain), options);
    list_ = search.build(referencePositions, supportRadius);
}

template <int Dim>
NeighbourReferenceList<Dim>::NeighbourReferenceList(const std::vector<Vector<Dim>>& referencePositions,
                                                    double supportRadius, NeighbourDomain<Dim> domain,
                                                    NeighbourSearchOptions options)
    : domain_(domain), referencePosition_(referencePositions) {
    NeighbourSearch<Dim> search(std::move(domain), options);
    list_ = search.build(referencePositions, supportRadius);
}

template class NeighbourReferenceList<1>;
template class NeighbourReferenceList<2>;
template class NeighbourReferenceList<3>;

}  // namespace mfdyn
