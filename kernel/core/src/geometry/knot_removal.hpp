#pragma once
// Knot removal (The NURBS Book A5.8, RemoveCurveKnot) on a homogeneous control polygon, in place: what join()
// uses to give a joint the multiplicity its continuity allows, and the sweep to turn Bezier pieces that join
// with known continuity into one B-spline. Defined in knot_removal.cpp. Not installed, not part of the
// public API.

#include <vector>

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// Removes the interior knot u (present in `knots`) up to `num` times from the degree-p curve (knots, pw),
// each time only if the curve moves by at most `tolerance` in homogeneous space (A5.8's test; an infinite
// tolerance removes unconditionally, for data known to have the continuity). Returns how many times it was
// removed; knots and pw shrink accordingly.
int remove_knot(int p, std::vector<double>& knots, std::vector<Vec4>& pw, double u, int num, double tolerance);

// A5.8's homogeneous tolerance for a Euclidean one: d w_min / (1 + |P|_max) keeps the points of the curve
// with homogeneous polygon `pw` within d of where they were (the book's Eq. 5.30).
double homogeneous_tolerance(const std::vector<Vec4>& pw, double tolerance);

// The same curve with every interior knot removed as often as it moves the curve by at most `tolerance`
// (Euclidean): a knot's multiplicity then tells the curve's continuity there, whatever made the knot
// vector (a curve cut into Bézier pieces and put together again has multiplicity p at every break).
NurbsCurve without_removable_knots(const NurbsCurve& curve, double tolerance);

}  // namespace ratbez::detail
