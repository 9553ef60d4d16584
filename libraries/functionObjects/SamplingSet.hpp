#pragma once
// A named set of sample points, from one entry of sampleDict's `sets`:
//
//     centreline { type line; start (0 0.5 0); end (1 0.5 0); nPoints 101; }
//     gauges     { type points; points ((0.1 0.5 0) (0.9 0.5 0)); }
//
//     keyword  meaning                                          required
//     type     line (evenly spaced, ends included) | points     yes
//     start    line: first point [m]                            line
//     end      line: last point [m]                             line
//     nPoints  line: number of points, at least 2               line
//     points   points: list of points [m]                       points
//
// Points have three coordinates; the ones beyond the particle dimension are ignored.
#include "core/Dictionary.hpp"
#include "functionObjects/Interpolation.hpp"

#include <string>
#include <vector>

namespace mfdyn {

class SamplingSet {
public:
    enum class Type { line, points };

    // Throws InputError naming the entry on a bad type or a malformed point.
    SamplingSet(const Dictionary& dict, std::string name);

    const std::string& name() const { return name_; }
    Type type() const { return type_; }
    const std::vector<SamplePoint>& points() const { return points_; }
    // Distance of each point from `start` (line) or its index (points): the first CSV column.
    const std::vector<double>& coordinate() const { return coordinate_; }
    // "distance" or "index".
    std::string coordinateName() const { return type_ == Type::line ? "distance" : "index"; }

    // A list of points `((x y z) ...)` under `key` (also used by probes); 1 to 3 numbers each,
    // missing ones zero.
    static std::vector<SamplePoint> readPoints(const Dictionary& dict, const std::string& key);

private:
    std::string name_;
    Type type_;
    std::vector<SamplePoint> points_;
    std::vector<double> coordinate_;
};

}  // namespace mfdyn
