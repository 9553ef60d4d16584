#pragma once
// Strang's symmetric splitting, second order. Equations in the .cpp.
#include "fpm/splitting/Splitting.hpp"

namespace mfdyn::fpm {

class StrangSplitting final : public Splitting {
public:
    explicit StrangSplitting(const Dictionary& dict);
    static KeywordSchema keywords();
    std::vector<SplitStage> stages(const std::vector<Subsystem>& parts) const override;
    int order() const override { return 2; }
};

}  // namespace mfdyn::fpm
