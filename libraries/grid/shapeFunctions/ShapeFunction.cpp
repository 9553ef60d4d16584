// The family `shapeFunction`: selection by name (either dictionary form of ShapeFunction::New),
// the grid-size check every type shares, and the node list's sizing. The functions themselves are
// in TensorProductShapeFunction.hpp and one .cpp per type.
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include "core/Error.hpp"

#include <algorithm>

namespace mfdyn {

template <int Dim>
void ParticleNodeList<Dim>::resize(std::size_t n, std::size_t entriesPerParticle) {
    // std::vector keeps its capacity when shrinking or regrowing within it, so a steady run (the
    // same particle count every step) allocates nothing; evaluate() writes every entry, so what
    // resize leaves in them does not matter.
    stride = entriesPerParticle;
    count.resize(n);
    node.resize(n * entriesPerParticle);
    weight.resize(n * entriesPerParticle);
    gradient.resize(n * entriesPerParticle);
}

template <int Dim>
std::unique_ptr<ShapeFunction<Dim>> ShapeFunction<Dim>::New(const Dictionary& dict) {
    std::unique_ptr<ShapeFunction> made;
    if (dict.found("type")) {
        made = Selector::New(dict);
        made->setType(dict.get<std::string>("type"));
    } else if (dict.isDict(familyName)) {
        const Dictionary& sub = dict.subDict(familyName);
        made = Selector::New(sub);
        made->setType(sub.get<std::string>("type"));
    } else if (dict.found(familyName)) {
        // The word form `shapeFunction cubicBSpline;`: an unknown name is reported at that entry.
        const std::string type = dict.get<std::string>(familyName);
        const std::vector<std::string> names = Selector::names();
        if (std::find(names.begin(), names.end(), type) == names.end())
            throw dict.error(familyName, RegistryIndex::global().family(familyName).unknownTypeMessage(type));
        made = Selector::NewOfType(type, dict, dict);
        made->setType(type);
    } else {
        throw InputError(dict.where(), dict.scope(),
                         std::string("missing keyword '") + familyName + "' (or 'type')" +
                             RegistryIndex::global().family(familyName).validTypes());
    }
    return made;
}

template <int Dim>
std::string ShapeFunction<Dim>::gridProblem(const CartesianGrid<Dim>& grid) const {
    static constexpr const char* axisName[] = {"x", "y", "z"};
    for (int d = 0; d < Dim; ++d)
        if (grid.cells()[d] < minimumCells())
            return "shape function " + type() + " needs at least " + std::to_string(minimumCells()) +
                   " cells along each axis (its " + std::to_string(nodesPerAxis()) +
                   " nodes per axis, folded at the grid's edges); the grid has " +
                   std::to_string(grid.cells()[d]) + " along " + axisName[d];
    return {};
}

template struct ParticleNodeList<1>;
template struct ParticleNodeList<2>;
template struct ParticleNodeList<3>;
template class ShapeFunction<1>;
template class ShapeFunction<2>;
template class ShapeFunction<3>;

}  // namespace mfdyn
