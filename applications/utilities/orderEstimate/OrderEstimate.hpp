#pragma once
// The numbers of the three-resolution order estimate (von Nida 2005, Lemma 7.1; equations in
// OrderEstimate.cpp): the ratio function alpha(p) of three particle counts, its inversion for the
// observed order p, the discrete norm of a difference of two sampled fields and the mean mesh
// size. Kept apart from orderEstimate.cpp, which reads the runs, so that the unit tests
// (tests/unit/orderEstimate) check them against closed forms.
#include <array>
#include <string>
#include <vector>

namespace mfdyn {

class OrderEstimate {
public:
    // The bracket the order is searched in: wider than any order a particle method shows, narrow
    // enough that alpha stays far from overflow for any particle counts a run can have.
    static constexpr double lowestOrder = -10.0;
    static constexpr double highestOrder = 20.0;

    enum class Norm { infinity, l2 };

    // What became of one inversion.
    enum class Status {
        ok,
        // The ratio is above alpha(lowestOrder): the fine run moved away more than the model
        // allows, the order is below the bracket (diverging, or not in the asymptotic range).
        belowRange,
        // The ratio is below alpha(highestOrder), e.g. 0: the two finer runs agree exactly.
        aboveRange,
        // No ratio: ||phi2 - phi1|| is zero or at round-off level, or a difference is not finite.
        undefined
    };
    struct Order {
        double value;  // NaN unless status is ok
        Status status;
    };

    // Particle counts N1 < N2 < N3 (coarse, medium, fine) in `dimension` (1, 2 or 3) dimensions;
    // std::invalid_argument otherwise (the caller says which run is wrong before this).
    OrderEstimate(const std::array<double, 3>& particleCounts, int dimension);

    // alpha(p) = ((N2/N3)^(p/d) - 1) / (1 - (N2/N1)^(p/d)), continued at p = 0 by its limit.
    double alpha(double order) const;
    // lim_{p->0} alpha(p) = ln(N3/N2) / ln(N2/N1).
    double alphaAtZeroOrder() const;
    // The p in [lowestOrder, highestOrder] with alpha(p) = ratio, by bisection (alpha is strictly
    // decreasing); a ratio outside alpha's range over the bracket gives belowRange/aboveRange.
    Order order(double ratio) const;
    // order() of ||phi3 - phi2|| / ||phi2 - phi1||. `valueMagnitude` is the size of the values
    // differenced (max |phi|): a ||phi2 - phi1|| within roundOffLevel of it is round-off, not a
    // resolution's error (a field the runs share, such as a constant), and gives undefined where
    // the ratio of two round-off values would give an arbitrary order.
    Order order(double fineDifference, double coarseDifference, double valueMagnitude = 0.0) const;
    // Relative to the values: the interpolation's round-off is cond(M) eps |phi| (mls, M the
    // scaled moment matrix, cond ~ 10-100 inside a body), ~1e-14; no three runs of a study agree
    // to 1e-10, so differences below it are taken as none.
    static constexpr double roundOffLevel = 1e-10;

    // ||a - b|| over the points: max |a_i - b_i| (infinity) or sqrt(mean (a_i - b_i)^2) (l2,
    // the root mean square, so that it does not grow with the number of points). NaN for no
    // points or sizes that differ; a non-finite difference makes the norm non-finite.
    static double differenceNorm(const std::vector<double>& a, const std::vector<double>& b, Norm norm);
    // dx = (V / N)^(1/d): the edge of the cube (square, segment) each particle stands for.
    static double meanSpacing(double totalVolume, double particleCount, int dimension);

    // "infinity", "l2"; "ok", "below -10", "above 20", "undefined".
    static std::string normName(Norm norm);
    static std::string statusText(Status status);

private:
    // ln(N2/N3)/d and ln(N2/N1)/d: alpha(p) = expm1(p a) / -expm1(p b) with these.
    double logFineRatio_;
    double logCoarseRatio_;
};

}  // namespace mfdyn
