#pragma once
// Smoothing kernels: the family `kernel`.
//
// Form (doc/methods/sph-impact.md §1.1, Zisis 2017 Eqs. 2.3-2.10): every kernel is a unit-support shape
// w(u), u = r/H, zero for u >= 1, scaled to the support radius H = kappa h:
//
//     W(r, h) = c_d H^-d w(r/H),    c_d^-1 = integral of w over the unit ball in d dimensions,
//     dW/dr   = c_d H^-(d+1) w'(u),  grad_i W_ij = (x_ij/r) dW/dr  (so rhat . grad W <= 0),
//     dW/dh   = -(1/h) c_d H^-d [d w(u) + u w'(u)].
//
// The smoothing length h convention. The note (and the thesis) take h = H, the support radius.
// Solvers and most of the literature use a smaller h, with H = kappa h; mfdyn follows the common
// one by default and offers the note's with `hConvention supportRadius;`:
//
//     type            kappa = H/h (hConvention standard)   reference for that h
//     cubicSpline     2                                    Monaghan 1992, M4 with support 2h
//     quinticSpline   3                                    Monaghan 2005 / Price 2012, M6 with support 3h
//     wendlandC2      2                                    common SPH use (e.g. Dehnen & Aly 2012 H = 2h)
//     wendlandC4      2                                    as C2
//     wendlandC6      2                                    as C2
//     gaussian        cutoff (default 3)                   W ~ exp(-(r/h)^2) cut at r = cutoff h (note 1.3)
//     mollifier       1                                    the thesis's bump, support h (note silent)
//
//     hConvention supportRadius: kappa = 1 for every type (the note's h = H; the gaussian is then
//     exp(-(cutoff r/h)^2), i.e. the note's exp(-9q^2) for cutoff 3).
//
// Dimension. A kernel is built once from its dictionary and holds c_d, the second moment and its
// tables for d = 1, 2, 3 (computed by quadrature at construction, so user kernels need only give
// w). The exact members below take the dimension as an argument and make virtual calls: use them
// for set-up, tests and utilities. Particle loops use evaluator<Dim>() (KernelEvaluator.hpp), a
// branch-free, inlinable table lookup; the choice is explained there.
//
// Usage (constant/<method>Properties):
//
//     kernel { type wendlandC2; }                       // H = 2h
//     kernel { type gaussian; cutoff 3; }               // exp(-(r/h)^2) cut at 3h, renormalised
//     kernel { type cubicSpline; hConvention supportRadius; }   // h = H as in the note
//
// Keywords: every type has `hConvention` (commonKeywords); a type adds its own in its
// `static KeywordSchema keywords()` (the gaussian's `cutoff`), listed by `-describe kernel` and in
// doc/models/kernel/.
//
// Resolution matching (note 1.2): sigma^2 = integral |x|^2 W = (s_d h)^2; two kernels resolve
// alike when their sigma agree, h2 = h1 s_d(1)/s_d(2) (matchedSmoothingLength).
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"
#include "core/Tensor.hpp"
#include "kernels/KernelEvaluator.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class Kernel {
public:
    static constexpr const char* familyName = "kernel";
    using Selector = Registry<Kernel, const Dictionary&>;
    static std::unique_ptr<Kernel> New(const Dictionary& dict) { return Selector::New(dict); }

    // The keywords every kernel type has (hConvention): a type's keywords() starts from them.
    static KeywordSchema commonKeywords(const std::string& type);

    // Cells of the evaluator table; a multiple of 6 so that knots at 1/2, 1/3, 2/3 are cell edges.
    static constexpr int tableCells = 6144;

    virtual ~Kernel() = default;
    Kernel(const Kernel&) = delete;
    Kernel& operator=(const Kernel&) = delete;

    const std::string& type() const { return type_; }
    // H/h for this kernel and convention.
    double kappa() const { return kappa_; }
    double supportRadius(double h) const { return kappa_ * h; }

    // The unit-support shape w(u) and w'(u), called for 0 <= u <= 1 only; at u = 1 they return the
    // limit from inside (non-zero for the truncated gaussian). The shape may depend on the dimension
    // (the Wendland functions do).
    virtual double shape(double u, int dim) const = 0;
    virtual double shapeDerivative(double u, int dim) const = 0;
    // Points of (0, 1) where a derivative of w jumps (spline knots): quadrature panels and table
    // cells are aligned to them.
    virtual std::vector<double> knots() const { return {}; }
    // Mass that truncation removed, as a fraction of the untruncated kernel (0 for compact kernels).
    // A truncated kernel's spectrum can dip below zero by at most m/(1-m) (KernelSpectrum).
    virtual double truncatedMass(int /*dim*/) const { return 0.0; }

    // c_d for the unit-support shape (note 1.1 table), by quadrature.
    double normalisation(int dim) const { return norm_.at(index(dim)); }
    // s_d with sigma = s_d h for this kernel's h (the note tabulates s_d/kappa, i.e. for h = H).
    double secondMoment(int dim) const { return kappa_ * momentUnit_.at(index(dim)); }

    double W(double r, double h, int dim) const;
    double dWdr(double r, double h, int dim) const;
    double dWdh(double r, double h, int dim) const;
    template <int Dim>
    Vector<Dim> gradW(const Vector<Dim>& rij, double h) const {
        const double r = rij.norm();
        return r > 0.0 ? Vector<Dim>(rij * (dWdr(r, h, Dim) / r)) : Vector<Dim>::Zero();
    }

    template <int Dim>
    KernelEvaluator<Dim> evaluator() const {
        return {tables_[Dim - 1].data(), tableCells, 1.0 / kappa_, norm_[Dim - 1]};
    }

protected:
    // Reads `type` and `hConvention`; `standardKappa` is H/h under the standard convention.
    Kernel(const Dictionary& dict, double standardKappa);
    // The same with `values` read through the type's own schema (which includes commonKeywords).
    Kernel(const Dictionary& dict, const KeywordValues& values, double standardKappa);
    // Computes c_d, moments and tables; called at the end of every concrete constructor, when the
    // shape is complete.
    void initialise();

private:
    static int index(int dim);

    std::string type_;
    double kappa_ = 1.0;
    std::array<double, 3> norm_{};
    std::array<double, 3> momentUnit_{};
    std::array<std::vector<double>, 3> tables_;
};

// The smoothing length for `to` whose standard deviation equals that of `from` at hFrom in `dim`
// dimensions (note 1.2: h2 = h1 s_d(from)/s_d(to)).
double matchedSmoothingLength(const Kernel& from, double hFrom, const Kernel& to, int dim);

}  // namespace mfdyn
