#pragma once
// The index of a named particle region of the run, for function objects that act on one body
// (bodyMomentum, bodyExtents, lowestPoint: in MPM each particleGen region is a body).
#include "core/Dictionary.hpp"
#include "functionObjects/RunContext.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mfdyn {

// The run's region names (empty when its particles name none).
std::vector<std::string> runRegionNames(const RunContext& context);

// The index of region `name` among the run's regions; an InputError at `keyword` of `dict`
// listing the regions there are when the run has no such region.
std::int64_t regionIndex(const Dictionary& dict, const std::string& keyword, const std::string& name,
                         const RunContext& context);

}  // namespace mfdyn
