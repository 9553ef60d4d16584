#pragma once
// Lie's splitting, each part once over the whole step (the thesis's). Equations in the .cpp.
#include "fpm/splitting/Splitting.hpp"

namespace mfdyn::fpm {

class LieSplitting final : public Splitting {
public:
    explicit LieSplitting(const Dictionary& dict);
    static KeywordSchema keywords();
    std::vector<SplitStage> stages(const std::vector<Subsystem>& parts) const override;
    int order() const override { return 1; }
};

}  // namespace mfdyn::fpm
