#pragma once
// Operator splittings of fpmSolid's step: the family `splitting` (doc/models/splitting/).
//
// The hypo-elastic system is split into the shear (S), Euler (H) and rotation (R) parts (von Nida
// 2005 §4.2; doc/methods/fpm.md §3.1), each advanced by its own scheme from the previous one's
// intermediate results. A splitting turns the parts that run, in the thesis's order
// shear -> euler -> rotation (the worst-conditioned first, the Hujeirat-Rannacher rule of §4.2.1),
// into the stages of one step: a part and the fraction of dt it advances by. Lie's splitting
// (the thesis's) is first order in dt, O(dt^2) per step; Strang's symmetric one is second order,
// O(dt^3) per step (§4.1, eq. 4.5), at the cost of a second pass through all but the last part.
//
// Usage (constant/fpmProperties): splitting { type lie; }   or   splitting { type strang; }
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn::fpm {

enum class Subsystem { shear, euler, rotation };

struct SplitStage {
    Subsystem part;
    double fraction;  // of the step
};

class Splitting {
public:
    static constexpr const char* familyName = "splitting";
    static constexpr const char* methodName = "fpmSolid";
    using Selector = Registry<Splitting, const Dictionary&>;
    static std::unique_ptr<Splitting> New(const Dictionary& dict) { return Selector::New(dict); }

    virtual ~Splitting() = default;
    Splitting(const Splitting&) = delete;
    Splitting& operator=(const Splitting&) = delete;

    const std::string& type() const { return type_; }
    // The stages of one step for the parts that run, given in the order they are applied.
    virtual std::vector<SplitStage> stages(const std::vector<Subsystem>& parts) const = 0;
    // The order in dt of the global error (1 Lie, 2 Strang).
    virtual int order() const = 0;

protected:
    explicit Splitting(const Dictionary& dict) : type_(dict.get<std::string>("type")) {}

private:
    std::string type_;
};

}  // namespace mfdyn::fpm
