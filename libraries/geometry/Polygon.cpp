// polygon: a simple polygon of the plane (2D cases only), the triangle of the material point
// method's float example (doc/methods/mpm.md section 4.7: side 0.2, apex up) being the polygon of
// three vertices. Vertices in order, clockwise or anticlockwise, at least 3, no two consecutive
// ones equal, no edge crossing another (a self-intersecting outline has no single inside).
// Inside: the even-odd (crossing number) rule with half-open edges, so that of two polygons
// sharing an edge exactly one holds a point on it, for horizontal edges as well.
// Volume: the exact area |sum (x_i y_{i+1} - x_{i+1} y_i)| / 2 (the shoelace formula).
//     shape { type polygon; vertices ((0 0) (0.2 0) (0.1 0.173205080757)); }
#include "geometry/Polygon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace mfdyn {

namespace {

std::string format(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

double cross(const std::array<double, 2>& o, const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Closed segments ab and cd share a point.
bool segmentsMeet(const std::array<double, 2>& a, const std::array<double, 2>& b,
                  const std::array<double, 2>& c, const std::array<double, 2>& d) {
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    const auto onSegment = [](const std::array<double, 2>& p, const std::array<double, 2>& q,
                              const std::array<double, 2>& r) {  // r on pq, given collinear
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] &&
               r[1] <= std::max(p[1], q[1]);
    };
    return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) ||
           (d3 == 0 && onSegment(a, b, c)) || (d4 == 0 && onSegment(a, b, d));
}

}  // namespace

Polygon::Polygon(const Dictionary& dict, int dimension) : Shape(dict, dimension) {
    if (dimension != 2)
        throw dict.error("type",
                         "a polygon is a 2D shape, and this case is " + std::to_string(dimension) +
                             "D (valid shapes there: box, sphere" +
                             (dimension == 3 ? std::string(", cylinder, stlSurface") : std::string()) +
                             ", and their union, intersection, difference)");
    const Entry& entry = dict.entry("vertices");
    const auto bad = [&](const std::string& what) {
        return dict.error("vertices", "expected a list of at least 3 points ((x y) ...): " + what);
    };
    if (entry.tokens.size() != 1 || entry.tokens[0].kind != Token::Kind::list) throw bad("not a list");
    for (const Token& t : entry.tokens[0].list) {
        if (t.kind != Token::Kind::list || t.list.size() < 2 || t.list.size() > 3)
            throw bad("'" + t.str() + "' is not a point of 2 numbers");
        std::array<double, 2> v{0, 0};
        for (std::size_t c = 0; c < t.list.size(); ++c) {
            if (!t.list[c].isNumber()) throw bad("'" + t.str() + "' holds a non-number");
            const double x = t.list[c].number();
            if (!(std::abs(x) <= maxCoordinate))
                throw dict.error("vertices", "vertex '" + t.str() +
                                                 "': coordinates must be finite and within "
                                                 "+-1e150 m");
            if (c < 2)
                v[c] = x;
            else if (x != 0)
                throw dict.error("vertices",
                                 "vertex '" + t.str() + "' has a non-zero third component in a 2D case");
        }
        vertices_.push_back(v);
    }
    const std::size_t n = vertices_.size();
    if (n < 3) throw bad("found " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i)
        if (vertices_[i] == vertices_[(i + 1) % n])
            throw dict.error("vertices", "vertices " + std::to_string(i + 1) + " and " +
                                             std::to_string((i + 1) % n + 1) + " are the same point");
    // Edges i and j (not neighbours) must not meet: the outline is simple.
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
            if (segmentsMeet(vertices_[i], vertices_[(i + 1) % n], vertices_[j], vertices_[(j + 1) % n]))
                throw dict.error("vertices", "edge " + std::to_string(i + 1) + " (vertex " +
                                                 std::to_string(i + 1) + " to " +
                                                 std::to_string((i + 1) % n + 1) + ") meets edge " +
                                                 std::to_string(j + 1) +
                                                 ": the polygon must be simple (vertices in order along the "
                                                 "outline, no crossing)");
        }
    double twice = 0;
    box_.min = {vertices_[0][0], vertices_[0][1], 0};
    box_.max = box_.min;
    for (std::size_t i = 0; i < n; ++i) {
        const auto& a = vertices_[i];
        const auto& b = vertices_[(i + 1) % n];
        twice += a[0] * b[1] - b[0] * a[1];
        for (int d = 0; d < 2; ++d) {
            box_.min[d] = std::min(box_.min[d], a[d]);
            box_.max[d] = std::max(box_.max[d], a[d]);
        }
    }
    area_ = 0.5 * std::abs(twice);
    if (!(area_ > 0) || !std::isfinite(area_))
        throw dict.error("vertices", "the polygon's area is " + format(area_) +
                                         ": the vertices must span a region of positive finite area");
    checkBounds(dict, "vertices");
}

bool Polygon::inside(const double* x) const {
    // Crossing number: edges with one end strictly above the horizontal line through x and the
    // other at or below it, crossed to the right of x.
    bool in = false;
    const std::size_t n = vertices_.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const auto& a = vertices_[i];
        const auto& b = vertices_[j];
        if ((a[1] > x[1]) != (b[1] > x[1])) {
            const double xCross = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if (x[0] < xCross) in = !in;
        }
    }
    return in;
}

MFDYN_REGISTER(Shape, Polygon, "polygon", "2D simple polygon of the given vertices (a triangle: 3)");

}  // namespace mfdyn
