#pragma once
// Joining curves that meet end to start into one NURBS curve (001: a piecewise curve as one B-spline).
//
// Every curve is raised to the highest degree p among them (A5.9), clamped, and put on a domain that
// continues the previous one (each keeps the width of its own domain, so parametric continuity means what
// it meant for the pieces; when the widths are too far apart for doubles to hold one domain after another,
// 1 after 1e300, every curve gets width 1 instead); curve k + 1's weights are scaled so that its first weight equals curve k's
// last (the curve is unchanged, the homogeneous polygon becomes one). Concatenated, each joint is a
// knot of multiplicity p (C0). Then each joint knot is removed (A5.8, RemoveCurveKnot) as often as the
// curve stays the same within 1e-9 of its size: a joint where the pieces are C^k keeps multiplicity
// p - k, and a joint where they are pieces of one polynomial disappears. So the knot multiplicities
// reflect the continuity found (continuity.hpp's C^k of consecutive pieces). For rational curves that is
// the continuity of the homogeneous curve C^w, which can be lower than that of C itself when the pieces'
// weights are not in the same scale.

#include <vector>

#include "ratbez/nurbs_curve.hpp"

namespace ratbez {

// Throws Error naming "curves" when the list is empty, a curve has degree 0 or is a single point, or
// curve k does not start where curve k - 1 ends (within 1e-9 of the size of their control points' box;
// gaps that small are closed by moving curve k's first control point), or whose knots cannot be spread over
// a domain that continues the others'.
NurbsCurve join(const std::vector<NurbsCurve>& curves);

}  // namespace ratbez
