#pragma once
// Knot removal (The NURBS Book A5.8, RemoveCurveKnot) on a homogeneous control polygon, in place: what join()
// uses to give a joint the multiplicity its continuity allows, and the sweep to turn Bezier pieces that join
// with known continuity into one B-spline. Defined in knot_removal.cpp. Not installed, not part of the
// public API.

#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// Removes the interior knot u (present in `knots`) up to `num` times from the degree-p curve (knots, pw),
// each time only if the curve moves by at most `tolerance` in homogeneous space (A5.8's test; an infinite
// tolerance removes unconditionally, for data known to have the continuity). Returns how many times it was
// removed; knots and pw shrink accordingly.
int remove_knot(int p, std::vector<double>& knots, std::vector<Vec4>& pw, double u, int num, double tolerance);

}  // namespace ratbez::detail
