// Sample point sets. A line of n points from a to b holds x_k = a + k/(n-1) (b - a),
// k = 0..n-1, so both ends are sampled; its first column is the distance |x_k - a|.
#include "functionObjects/SamplingSet.hpp"

#include "core/Tensor.hpp"

#include <cmath>

namespace mfdyn {

SamplingSet::SamplingSet(const Dictionary& dict, std::string name) : name_(std::move(name)) {
    const std::string type = dict.get<std::string>("type");
    if (type == "line") {
        type_ = Type::line;
        const Vector<3> a = dict.get<Vector<3>>("start"), b = dict.get<Vector<3>>("end");
        const int n = dict.get<int>("nPoints");
        if (n < 2) throw dict.error("nPoints", "a line needs at least 2 points, not " + std::to_string(n));
        for (int k = 0; k < n; ++k) {
            const Vector<3> x = a + (double(k) / (n - 1)) * (b - a);
            points_.push_back({x(0), x(1), x(2)});
            coordinate_.push_back((x - a).norm());
        }
    } else if (type == "points") {
        type_ = Type::points;
        points_ = readPoints(dict, "points");
        for (std::size_t k = 0; k < points_.size(); ++k) coordinate_.push_back(double(k));
    } else {
        throw dict.error(
            "type", "set '" + name_ + "': '" + type + "' is not a set type; valid choices: line | points");
    }
}

std::vector<SamplePoint> SamplingSet::readPoints(const Dictionary& dict, const std::string& key) {
    const Entry& entry = dict.entry(key);
    const auto bad = [&](const std::string& what) {
        return dict.error(key, "expected a list of points ((x y z) ...): " + what);
    };
    if (entry.tokens.size() != 1 || entry.tokens[0].kind != Token::Kind::list) throw bad("not a list");
    std::vector<SamplePoint> points;
    for (const Token& t : entry.tokens[0].list) {
        if (t.kind != Token::Kind::list || t.list.empty() || t.list.size() > 3)
            throw bad("'" + t.str() + "' is not a point of 1 to 3 numbers");
        SamplePoint x{0.0, 0.0, 0.0};
        for (std::size_t c = 0; c < t.list.size(); ++c) {
            if (!t.list[c].isNumber()) throw bad("'" + t.str() + "' holds a non-number");
            x[c] = t.list[c].number();
        }
        points.push_back(x);
    }
    if (points.empty()) throw bad("the list is empty");
    return points;
}

}  // namespace mfdyn
