#pragma once
// Circular and elliptic arcs as rational quadratic NURBS (A7.1): the layout of an arc on the unit circle,
// and the arc or ellipse in a frame. Defined in geometry/curves.cpp beside circle() and arc(), which are
// built on them; also used by the primitives and revolve. Not installed, not part of the public API.

#include <vector>

#include "ratbez/frame.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez::detail {

// The control structure of a circular arc of `sweep_deg` in (0, 360] starting at angle `start_deg`,
// on the unit circle of a frame (the NURBS-book construction A7.1, generalising the rational quarter
// circle of 000 §1.4 / Ex1.13): ceil(sweep / 90) segments of equal sweep 2θ, each a rational quadratic
// whose middle control point is the tangents' intersection, (P_0 + P_2) / (1 + cos 2θ), with weight
// cos θ; knots {0,0,0, 1/n,1/n, ..., 1,1,1}.
struct ArcLayout {
    std::vector<double> knots;
    std::vector<double> cos_coefficient;  // control point i = cos_coefficient[i] x + sin_coefficient[i] y
    std::vector<double> sin_coefficient;
    std::vector<double> weights;
};
ArcLayout arc_layout(double start_deg, double sweep_deg);

// The arc with centre frame.origin and the given radius (or the ellipse with semi-axes `radius_x`,
// `radius_y`: the affine image of the circular arc, P1.14) in the plane of frame.x_axis, frame.y_axis.
NurbsCurve arc_in_frame(const Frame& frame, double radius_x, double radius_y, double start_deg, double sweep_deg);

}  // namespace ratbez::detail
