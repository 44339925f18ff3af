#pragma once
// Exact curves built as NURBS: line segments, circles, circular and elliptical arcs.
// Circles and arcs are piecewise rational quadratics, no segment wider than 90 degrees, with the weights
// the rational Bézier quarter circle of 000 §1.4 (Ex1.13) generalises to: for a segment of sweep 2θ the
// middle control point sits at the tangents' intersection with weight cos θ, the end points weight 1.
// Their parameter runs over [0, 1] (each segment an equal share of it).

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

NurbsCurve line_segment(const Vec3& start, const Vec3& end);

// Full circle in the plane through `center` normal to `normal`, counterclockwise about `normal`,
// starting on the frame's x axis (frame_from_axis(center, normal)).
NurbsCurve circle(double radius, const Vec3& center = {}, const Vec3& normal = {0, 0, 1});
// Arc from start_deg to end_deg (end_deg > start_deg, sweep at most 360), angles measured from the frame's x axis.
NurbsCurve arc(double radius, double start_deg, double end_deg, const Vec3& center = {},
               const Vec3& normal = {0, 0, 1});
// Elliptical arc with semi-axes a (along the frame's x axis) and b (y axis), same angle convention
// (the parametric angle of the ellipse).
NurbsCurve ellipse_arc(double a, double b, double start_deg, double end_deg, const Vec3& center = {},
                       const Vec3& normal = {0, 0, 1});

}  // namespace ratbez
