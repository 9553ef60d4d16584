// linearVelocity: v(X) = v0 + G (X - X0), u = 0.
//   Lee, Gil, Greto, Karim & Bonet 2016 section 8.8 (doc/methods/tl-jst-sph.md 8.8): the bending column,
//   v = V [Y/L, 0, 0] (V = 10 m/s, L = 6 m): gradient ((0 1.6667 0) (0 0 0) (0 0 0));
//   section 8.4, the tensile cube, v = (0, V Y, 0): gradient ((0 0 0) (0 V 0) (0 0 0)).
//
//     keyword   meaning                                                   required  default
//     velocity  v0 [m/s], the velocity at the origin                      no        0
//     gradient  G = dv_i/dX_J [1/s], row by row: ((G11 G12 G13) (G21 ...) ...) yes
//               or flat (G11 G12 ... ); a 3x3 G in a 2D or 1D case must be 0
//               outside its leading Dim x Dim block
//     origin    X0 [m]                                                    no        0
#include "solver/LinearVelocity.hpp"

#include <string>

namespace mfdyn {

namespace {

// A Dim x Dim tensor from `((..) (..) (..))` or a flat list of n^2 values, n = Dim or 3.
template <int Dim>
Tensor<Dim> readTensor(const Dictionary& dict, const std::string& key) {
    const Entry& entry = dict.entry(key);
    const std::vector<Token>* items = &entry.tokens;
    if (items->size() == 1 && (*items)[0].kind == Token::Kind::list) items = &(*items)[0].list;
    std::vector<double> values;
    for (const Token& t : *items) {
        if (t.isNumber()) {
            values.push_back(t.number());
        } else if (t.kind == Token::Kind::list) {
            for (const Token& c : t.list) {
                if (!c.isNumber()) throw dict.error(key, "expected numbers, found '" + c.str() + "'");
                values.push_back(c.number());
            }
        } else {
            throw dict.error(key, "expected a tensor ((G11 G12 ..) (G21 ..) ..), found '" + t.str() + "'");
        }
    }
    int n = 0;
    for (int m = 1; m <= 3; ++m)
        if (int(values.size()) == m * m && m >= Dim) n = m;
    if (n == 0)
        throw dict.error(key, "expected " + std::to_string(Dim * Dim) + " or 9 values (a " +
                                  std::to_string(Dim) + "x" + std::to_string(Dim) +
                                  " or 3x3 tensor, row by row), found " + std::to_string(values.size()));
    Tensor<Dim> G;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double g = values[std::size_t(i * n + j)];
            if (i < Dim && j < Dim)
                G(i, j) = g;
            else if (g != 0.0)
                throw dict.error(key, "component (" + std::to_string(i + 1) + "," + std::to_string(j + 1) +
                                          ") is non-zero but the case is " + std::to_string(Dim) + "D");
        }
    return G;
}

}  // namespace

template <int Dim>
LinearVelocity<Dim>::LinearVelocity(const Dictionary& dict)
    : InitialState<Dim>(dict),
      v0_(dict.getOrDefault<Vector<Dim>>("velocity", Vector<Dim>::Zero())),
      gradient_(readTensor<Dim>(dict, "gradient")),
      origin_(dict.getOrDefault<Vector<Dim>>("origin", Vector<Dim>::Zero())) {}

template <int Dim>
Vector<Dim> LinearVelocity<Dim>::velocity(const Vector<Dim>& X) const {
    return v0_ + gradient_ * (X - origin_);
}

template class LinearVelocity<1>;
template class LinearVelocity<2>;
template class LinearVelocity<3>;

MFDYN_REGISTER_DIM(InitialState, LinearVelocity, "linearVelocity",
                   "v = v0 + G (X - origin): bending column, tensile cube (Lee et al. 2016 8.8, 8.4)");

}  // namespace mfdyn
