#pragma once
// The ruled surface between two curves (The NURBS Book §8.4): the curves are made compatible (the same degree
// by A5.9, the same domain [0, 1] and the same knots by A5.4; compatible_curves.hpp) and their homogeneous
// control polygons become the two columns of a degree (p, 1) net. The surface is exact for any rational
// curves: at every u the isocurve in v is the straight segment from a(u) to b(u) (a convex combination of
// the two points, rationally parameterised when their weights differ), and S(u, 0) = a(u), S(u, 1) = b(u).
// Which point of b a point of a is ruled to: with `align` (the default) the curves are first matched by
// normalised arc length (section_alignment.hpp in the modelling sources: closed curves oriented alike and
// started at the points of least twist, open curves end to end, corners and joints of either matched exactly
// by arc length, each curve on its own parameter between them); without it, by the parameter on [0, 1], as
// given. A surface whose rulings cross or pinch is refused (Error naming "curve_b" and the place;
// analysis/self_intersection.hpp), unless a side collapses to a point (curves that share an end), which the
// certificate does not cover.

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez {

// u runs along the curves over [0, 1], v from curve_a (v = 0) to curve_b (v = 1).
NurbsSurface ruled_surface(const NurbsCurve& curve_a, const NurbsCurve& curve_b, bool align = true);

}  // namespace ratbez
