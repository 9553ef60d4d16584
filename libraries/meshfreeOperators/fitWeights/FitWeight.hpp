#pragma once
// Weights of the least-squares fit: the family `fitWeight` (doc/models/fitWeight/).
//
// The finite pointset method's fit (von Nida 2005, Def. 3.3-3.5; doc/methods/fpm.md §2)
// weighs neighbour x_j of the evaluation point y by W(q), q = |x_j - y| / h, with the support
// radius h itself (the note's h = H: no kernel factor kappa) and
//
//     0 <= W <= 1,  W(0) = 1,  W(q) = 0 for q > 1,  dW/dq = 0 at q = 0,
//
// so that the weight and dW/dy are continuous at the point itself (the full derivative, eq. 3.11,
// differentiates it). Unlike a smoothing kernel it has no normalisation: a least-squares fit is
// invariant to a common factor of its weights. The thesis writes W in r = q^2 and squares it in
// the functional, D = sum_j |W_j (f_j - p(x_j))|^2; `squared` (default yes) chooses that, or the
// common moving-least-squares form D = sum_j W_j (f_j - p(x_j))^2.
//
// Usage (a solver's properties, e.g. fpmProperties):
//
//     fitWeight { type truncatedGaussian; alpha 6.25; squared yes; }
//     fitWeight { type wendlandC2; squared no; }
//
// LeastSquaresOperators::rebuild(points, x, rows, h, weight) evaluates it per pair.
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace mfdyn {

class FitWeight {
public:
    static constexpr const char* familyName = "fitWeight";
    using Selector = Registry<FitWeight, const Dictionary&>;
    static std::unique_ptr<FitWeight> New(const Dictionary& dict) { return Selector::New(dict); }

    // The keywords every type has (`squared`): a type's keywords() starts from them.
    static KeywordSchema commonKeywords(const std::string& type);

    virtual ~FitWeight() = default;
    FitWeight(const FitWeight&) = delete;
    FitWeight& operator=(const FitWeight&) = delete;

    const std::string& type() const { return type_; }
    // Whether the weight is squared in the normal equations (the thesis's D = sum |W (f - p)|^2).
    bool squared() const { return squared_; }

    // The shape W(q) and dW/dq, for 0 <= q <= 1 (at q = 1 the limit from inside).
    virtual double shape(double q) const = 0;
    virtual double shapeDerivative(double q) const = 0;

    // W at distance d = |x - y| for support radius h, zero beyond h, and dW/dd.
    double W(double d, double h) const { return d > h ? 0.0 : shape(d / h); }
    double dWdd(double d, double h) const { return d > h ? 0.0 : shapeDerivative(d / h) / h; }
    // The weight of the normal equations (W^2 when squared, else W) and its derivative in d.
    double fitWeight(double d, double h) const {
        const double w = W(d, h);
        return squared_ ? w * w : w;
    }
    double fitWeightDerivative(double d, double h) const {
        return squared_ ? 2.0 * W(d, h) * dWdd(d, h) : dWdd(d, h);
    }

protected:
    FitWeight(const Dictionary& dict, const KeywordValues& values);

private:
    std::string type_;
    bool squared_ = true;
};

}  // namespace mfdyn
