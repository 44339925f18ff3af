#pragma once
// The local shape of a curve at a parameter from its derivatives, limits included (curvature.hpp explains
// the rule): the unit tangent in the direction of motion, the curvature and the curvature vector. Shared
// by curvature() and continuity(). Defined in curvature.cpp. Not installed, not part of the public API.

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

struct CurveShape {
    Vec3 tangent;           // unit; zero when the curve does not move near u
    double curvature = 0;   // >= 0, infinite at a cusp
    Vec3 curvature_vector;  // curvature times the unit principal normal (zero where the curvature is 0)
};

// `arriving`: the curve's shape as it arrives at u from smaller parameters (the end of a piece), else as
// it leaves u. The derivatives are those NurbsCurve::derivatives gives at u (the span on the right, except
// at the domain's end).
CurveShape curve_shape(const NurbsCurve& curve, double u, bool arriving);

}  // namespace ratbez::detail
