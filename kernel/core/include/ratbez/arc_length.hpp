#pragma once
// Arc length of NURBS curves: L(u0, u1) = integral of |C'(u)| du, and its inverse, the parameter at which a
// given length is reached. Exact where the maths is: Gauss–Legendre quadrature on every knot span (the
// speed is analytic inside a span, so the rule converges geometrically), adaptive (a span is halved until
// the 16-point rule on it and on its halves agree to 1e-14 of the control polygon's length, which bounds
// the curve's), so a length is good to about 1e-14 relative; a circle of radius r reads 2 pi r to a few
// ulps. The parameter at a length is found by Newton's method on L(u0, u) - s (its derivative is the
// speed), kept in a bracket by bisection, to the same accuracy. A span whose weights spread far (a rational
// quadratic with a middle weight 1e9 runs nearly all its length within 1e-9 of its ends' parameters) is first cut
// until each piece's weights are within 4 of each other; a span whose weights are more than 1e10 apart has no
// length in double precision and is an Error naming "curve". Coordinates of any size (the speed is held divided by
// a power of two of the curve's extent).

#include <memory>
#include <vector>

#include "ratbez/nurbs_curve.hpp"

namespace ratbez {

// A curve's span lengths computed once, for many queries.
class ArcLength {
public:
    explicit ArcLength(const NurbsCurve& curve);

    const NurbsCurve& curve() const { return curve_; }
    double total() const { return cumulative_.back() * scale_; }
    // The length from the domain's start to u (u in the domain; Error naming "u" otherwise).
    double at(double u) const;
    // The length from u0 to u1 (both in the domain; negative when u1 < u0), summed span by span so that a
    // short stretch keeps its own relative accuracy.
    double between(double u0, double u1) const;
    // The parameter u with at(u) = s, for 0 <= s <= total() (Error naming "s" otherwise). Where the curve
    // stands still over an interval of parameters (zero speed), the smallest such u.
    double parameter(double s) const;

    class Speed;  // |C'(u)| from the curve's Bézier segments (arc_length.cpp)

private:
    // The length over [a, b] inside span k, and between u0 and u1, in the speed's scale (divided by scale_).
    double integral(double a, double b) const;
    double scaled_between(double u0, double u1) const;
    NurbsCurve curve_;
    std::vector<double> breaks_;      // the span ends (breakpoints of the domain)
    std::vector<double> cumulative_;  // cumulative_[k]: the length up to breaks_[k]
    double tolerance_ = 0;            // absolute, for one span's integral (in the speed's scale)
    double scale_ = 1;                // a power of two near the curve's extent: lengths are held divided by it
    std::shared_ptr<const Speed> speed_;
};

// The length of the curve between u0 and u1 (defaults: the whole domain); u1 < u0 gives the negative.
double length(const NurbsCurve& curve);
double length(const NurbsCurve& curve, double u0, double u1);
// The parameter at arc length s from the domain's start, 0 <= s <= length(curve).
double parameter_at_length(const NurbsCurve& curve, double s);

}  // namespace ratbez
