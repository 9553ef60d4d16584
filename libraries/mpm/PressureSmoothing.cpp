// pressureSmoothing (PressureSmoothing.hpp): `none` leaves the particles' pressure as the
// equation of state gives it at each particle's own J (the thesis).
#include "mpm/PressureSmoothing.hpp"

namespace mfdyn {

namespace {

template <int Dim>
class NoPressureSmoothing final : public PressureSmoothing<Dim> {
public:
    explicit NoPressureSmoothing(const Dictionary&) {}
    static KeywordSchema keywords() { return KeywordSchema(PressureSmoothing<Dim>::familyName, "none"); }
    bool active() const override { return false; }
    void apply(const CartesianGrid<Dim>&, PressureSmoothingFields<Dim>&) const override {}
};

}  // namespace

template class PressureSmoothing<1>;
template class PressureSmoothing<2>;
template class PressureSmoothing<3>;

MFDYN_REGISTER_DIM(PressureSmoothing, NoPressureSmoothing, "none",
                   "no smoothing: each particle's pressure from its own J (the thesis)");

}  // namespace mfdyn
