// The family `fitWeight`: the common keyword `squared` (FitWeight.hpp states the contract).
#include "meshfreeOperators/fitWeights/FitWeight.hpp"

namespace mfdyn {

KeywordSchema FitWeight::commonKeywords(const std::string& type) {
    return KeywordSchema(familyName, type)
        .flag("squared",
              "square the weight in the normal equations, D = sum |W (f - p)|^2 (von Nida 2005 eq. 3.5); "
              "no: D = sum W (f - p)^2")
        .orDefault(true);
}

FitWeight::FitWeight(const Dictionary& dict, const KeywordValues& values)
    : type_(dict.get<std::string>("type")), squared_(values.flag("squared")) {}

}  // namespace mfdyn
