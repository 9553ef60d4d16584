#pragma once
// contact `multiField` (Contact.hpp): a node field per body, and the contact law between them where
// two bodies have mass at a node (MultiFieldContact.cpp for the equations and their sources).
//
//     contact          multiField;
//     multiFieldCoeffs { friction 0; separation 0.667; volumeFraction 1; surfaceGap no;
//                        normal averaged; pairs { ... } }
#include "mpm/contact/Contact.hpp"
#include "mpm/contact/HalfSpaceProfile.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class MultiFieldContact final : public Contact<Dim> {
public:
    static KeywordSchema keywords();
    explicit MultiFieldContact(const Dictionary& dict);
    bool multiField() const override { return true; }
    void bind(const std::vector<std::string>& bodies) override;
    std::size_t pairs() const override { return bodies_ < 2 ? 0 : bodies_ * (bodies_ - 1) / 2; }
    std::vector<Vector<Dim>> correct(ContactNodes<Dim>& nodes, double dt) const override;
    std::string describe() const override;

private:
    struct Pair {
        std::vector<std::string> bodies;
        double friction = 0;
        const Dictionary* dict = nullptr;  // the case's mpmProperties, alive for the run
    };
    double friction_ = 0;
    double separation_ = std::numeric_limits<double>::infinity();
    double volumeFraction_ = 0;    // the volume check's f; 0: off
    bool largerGradient_ = false;  // `normal largerGradient`: one body's normal, not the average
    bool surfaceGap_ = false;      // the surface-gap check
    std::vector<Pair> pairs_;
    std::size_t bodies_ = 0;
    std::vector<double> mu_;                           // bodies x bodies
    mutable std::vector<std::uint8_t> shared_;         // scratch of correct(): kept, so a run allocates once
    mutable std::optional<HalfSpaceProfile> profile_;  // the surface-gap check's, on the first call
};

}  // namespace mfdyn
