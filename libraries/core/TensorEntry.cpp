// readTensor: see TensorEntry.hpp (moved here from solver/LinearVelocity.cpp, its first user).
#include "core/TensorEntry.hpp"

namespace mfdyn {

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

template Tensor<1> readTensor<1>(const Dictionary&, const std::string&);
template Tensor<2> readTensor<2>(const Dictionary&, const std::string&);
template Tensor<3> readTensor<3>(const Dictionary&, const std::string&);

}  // namespace mfdyn
