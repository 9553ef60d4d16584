#pragma once
// The written times a post-processing utility works on, chosen on its command line as OpenFOAM's
// utilities choose them:
//
//     (none)            every time
//     -latestTime       the last
//     -time 0.25        the one equal to 0.25 (to `tolerance` relative, at least absolute)
//     -time 0.1:0.5     those in [0.1, 0.5] (to the same tolerance; either end may be left open)
//
// Shared by `sample` and `orderEstimate`, so that both read -time alike.
#include "core/Application.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace mfdyn {

// Indices into `values` (ascending times) of the chosen ones; `names` (the directories' names, as
// many as values) go into the message when nothing matches. Throws InputError on -time and
// -latestTime together, a spec that is not a number or a range of numbers, or no match (listing
// the times there are: "-time 0.9 matches no time <what>; there are: 0 0.5", what e.g. "directory").
std::vector<std::size_t> selectTimes(const Arguments& args, const std::vector<double>& values,
                                     const std::vector<std::string>& names, double tolerance,
                                     const std::string& what);

}  // namespace mfdyn
