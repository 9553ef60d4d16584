#include "solver/InitialState.hpp"

#include "geometry/Shape.hpp"

#include "core/Parallel.hpp"

#include <algorithm>

namespace mfdyn {

template <int Dim>
std::unique_ptr<InitialState<Dim>> InitialState<Dim>::New(const Dictionary& dict) {
    return Selector::New(dict);
}

template <int Dim>
InitialState<Dim>::InitialState(const Dictionary& dict) : dict_(dict) {
    if (dict.found("regions")) {
        regions_ = dict.get<std::vector<std::string>>("regions");
        if (regions_.empty()) throw dict.error("regions", "the list of regions is empty");
    }
    dict.getOrDefault<std::string>("type", "");  // read by the selector
    if (const Dictionary* shapeDict = dict.findDict("shape")) shape_ = Shape::New(*shapeDict, Dim);
}

template <int Dim>
InitialState<Dim>::~InitialState() = default;

template <int Dim>
Vector<Dim> InitialState<Dim>::displacement(const Vector<Dim>&) const {
    return Vector<Dim>::Zero();
}

template <int Dim>
Tensor<Dim> InitialState<Dim>::displacementGradient(const Vector<Dim>&) const {
    return Tensor<Dim>::Zero();
}

template <int Dim>
void InitialState<Dim>::apply(ParticleSet<Dim>& particles, const std::vector<Vector<Dim>>& X) const {
    const std::size_t n = particles.size();
    if (X.size() != n)
        throw Error("initialState: " + std::to_string(X.size()) + " reference positions for " +
                    std::to_string(n) + " particles");
    std::vector<char> selected(n, regions_.empty() ? 1 : 0);
    if (!regions_.empty()) {
        const auto& known = particles.regionNames;
        std::vector<std::int64_t> ids;
        for (const auto& name : regions_) {
            const auto it = std::find(known.begin(), known.end(), name);
            if (it == known.end()) {
                std::string list;
                for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
                std::string message = "unknown region '" + name + "'";
                if (const std::string guess = closestMatch(name, known); !guess.empty())
                    message += "; did you mean '" + guess + "'?";
                throw dict_.error("regions", message + " Regions in the particle file: " +
                                                 (list.empty() ? std::string("(none)") : list));
            }
            ids.push_back(std::int64_t(it - known.begin()));
        }
        const auto& region = particles.region();
        for (std::size_t i = 0; i < n; ++i)
            selected[i] = std::find(ids.begin(), ids.end(), region[i]) != ids.end();
    }

    // `shape { ... }` narrows the selection to the particles whose reference position is inside.
    if (shape_)
        for (std::size_t i = 0; i < n; ++i) selected[i] = selected[i] && shape_->inside(X[i].data());

    auto& x = particles.position();
    auto& v = particles.vectorField("velocity");
    std::vector<Tensor<Dim>>* F = hasDisplacement() ? &particles.tensorField("deformationGradient") : nullptr;
    parallelFor(n, [&](std::size_t i) {
        if (!selected[i]) return;
        x[i] = X[i] + displacement(X[i]);
        v[i] = velocity(X[i]);
        if (F) (*F)[i] = Tensor<Dim>::Identity() + displacementGradient(X[i]);
    });
}

template class InitialState<1>;
template class InitialState<2>;
template class InitialState<3>;

}  // namespace mfdyn
