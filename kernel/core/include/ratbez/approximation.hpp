#pragma once
// Least-squares approximation of points by a B-spline curve within a tolerance (The NURBS Book §9.4.1, the
// curve fit that A9.7 applies to the rows and columns of a surface).
//
// For n + 1 control points (n >= p): the points Q_0..Q_m get chord-length parameters t_k (Eq. 9.5); the
// interior knots are placed so that every knot span holds data (Eq. 9.68–9.69: d = (m + 1)/(n - p + 1),
// u_{p+j} = (1 - a) t_{i-1} + a t_i with i = int(j d), a = j d - i); the end points are interpolated
// (P_0 = Q_0, P_n = Q_m) and P_1..P_{n-1} minimise sum_k |C(t_k) - Q_k|^2 (the normal equations
// N^T N P = R of Eq. 9.63–9.67, banded, solved in O(m p^2)). At n = m the curve interpolates (A9.1).
//
// The number of control points is the smallest for which every point lies within `tolerance` of the curve
// at its parameter (max_k |C(t_k) - Q_k| <= tolerance, an upper bound of each point's distance to the curve),
// found by bisection over n: the result meets the tolerance and, with one control point fewer (knots placed
// the same way), the fit does not. Errors (ratbez::Error) name "points" (fewer than degree + 1, not finite,
// consecutive points that coincide), "tolerance" (not finite or <= 0) or "degree".

#include <vector>

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

NurbsCurve approximate(const std::vector<Vec3>& points, double tolerance, int degree = 3);

// The least-squares fit above with exactly `control_points` control points (degree + 1 .. points.size()).
NurbsCurve least_squares_fit(const std::vector<Vec3>& points, int control_points, int degree = 3);

}  // namespace ratbez
