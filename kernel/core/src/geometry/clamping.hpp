#pragma once
// Clamped knot vectors: whether a NURBS curve interpolates its end control points, the same curve on a
// clamped knot vector (A5.1 knot insertion at the ends), and clamped curves with a moved end point.
// Not installed, not part of the public API.

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// True when the first and the last p + 1 knots coincide (the curve interpolates its end control points).
bool is_clamped(const NurbsCurve& curve);
// The same curve on a clamped knot vector (break points of multiplicity p, ends p + 1); unchanged if clamped.
NurbsCurve clamped(const NurbsCurve& curve);
// The same curve with only its ends clamped (knot insertion A5.1 at the domain ends up to multiplicity p,
// the knots and control points outside the domain dropped): interior knots keep their multiplicities, so
// the representation keeps the curve's continuity (clamped() makes every break point C0).
NurbsCurve clamped_ends(const NurbsCurve& curve);
// The part of the curve over [a, b] (inside its domain, a < b) on a clamped knot vector over [a, b]: knots a
// and b inserted up to multiplicity p (A5.1), the knots and control points outside dropped. Same curve,
// same parameterisation there.
NurbsCurve restricted(const NurbsCurve& curve, double a, double b);
// A clamped curve with its first (at_end = false) or last control point moved to `point`, keeping its weight.
NurbsCurve with_end_point(const NurbsCurve& curve, bool at_end, const Vec3& point);

}  // namespace ratbez::detail
