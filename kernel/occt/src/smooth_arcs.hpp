#pragma once
// Circular directions re-parameterised for OpenCASCADE: the natural conversion's answer to OCCT's fixed Gauss
// rule and to its BOP check. Internal to kernel/occt.
//
// The kernel represents an arc of a circle (circle, arc, and every direction of a revolution, cylinder, cone,
// sphere or torus that turns about the axis) as a piecewise rational quadratic: one Bézier arc per sweep below
// 180 degrees, joined at double knots (000 Ex 1.15). Across those knots the surface is only C1 in its parameter
// (the second derivative jumps), which costs twice in OpenCASCADE:
//  - BRepGProp without eps (FreeCAD's Shape.Volume, Area, CenterOfMass) integrates a face with ONE Gauss rule
//    over its whole parameter rectangle (gprop_patches.hpp says how it sizes the rule); across the joints the
//    rule converges slowly: +0.93 % on a sphere, +0.79 % on a cylinder (SETUP-NOTES);
//  - a double knot of a degree 2 B-spline is C0 by multiplicity, which "Run BOP check" (BOPAlgo_ArgumentAnalyzer's
//    ContinuityMode) reports as BOPAlgo GeomAbs_C0.
// The same arc has an exact rational form of ONE Bézier span with positive weights, degree 4 elevated to 5:
// with (p(s), q(s)) a quadratic Bézier in the plane turning through half the sweep, the point
//     (p^2 - q^2, 2 p q) / (p^2 + q^2)
// turns through the whole sweep (angle doubling, tan of the half angle = q / p), so X = p^2 - q^2, Y = 2 p q,
// W = p^2 + q^2 are quartic polynomials (Bernstein products). For a full turn the quartic weights are
// (1, 0, w, 0, 1) — two at zero, which neither the kernel nor OCCT accept — and one degree elevation makes them
// all positive (Chou, "Higher order Bézier circles", CAD 27(4), 1995). The middle control point of (p, q) is
// k (cos(sweep/4), sin(sweep/4)) with k chosen so that the angular speed is the same at the ends and in the
// middle (for a full turn k = sqrt 2, weights 1, .2, .6, .6, .2, 1). The integrand is then analytic over the
// face and OCCT's rule reads a sphere to 3e-9 (measured with FreeCAD's Shape.Volume at centres to 1e4 and
// radii 1e-3 to 1e4), and no knot is left to be C0. The span is then cut in 8 by exact knot insertion (simple
// knots, C4), which pulls the control polygon to within 1.18 radii of the centre (5.7 with one span).
//
// A direction qualifies when every row of control points across it is the same arc up to an affine map: with
// the arc's unit-circle control points (x_i, y_i) and relative weights w_i (taken from the knots and the
// weights: a Bézier arc's middle weight over the geometric mean of its ends is cos(half its angle), and its
// middle point is where the tangents at its ends meet), row j is P_ij = O_j + x_i U_j + y_i V_j with weights
// w_i omega_j. Then S(u, v) = O(v) + X(u)/W(u) U(v) + Y(u)/W(u) V(v) in homogeneous form, and replacing
// (X, Y, W) by the one-span form keeps the surface and changes only its parameter along the direction: exact.
// A pole (O_j with U_j = V_j = 0) and an ellipse (U_j, V_j not orthogonal) qualify as well.

#include <functional>
#include <optional>
#include <vector>

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::occt::detail {

// A direction of control points found to be an arc, and what it becomes.
struct ArcDirection {
    Interval domain;                   // the direction's parameter domain, kept
    double sweep = 0;                  // the arc's angle (radians), at most 2 pi
    NurbsCurve old_unit;               // the kernel's form of the unit arc on `domain` (z = 0)
    NurbsCurve new_unit;               // the one-span form on `domain`
    // Per row across the direction: P_ij = O_j + x_i U_j + y_i V_j, weight w_i omega_j.
    std::vector<Vec3> origin, u_axis, v_axis;
    std::vector<double> omega;
    // OCCT's parameter (the one-span form's) -> ours (the kernel's): the same point of the arc.
    double to_kernel(double t) const;
};

// rows[j][i]: the i-th homogeneous control point along the direction of the j-th row across it (a curve has
// one row). nullopt unless the direction is a kernel-style arc (degree 2, clamped, interior knots double) that
// every row follows to `tolerance` (absolute, in model units). `refined`: each row's centre and axes fitted to the
// last bits (relative to its first point, refined on the residual), for recognising a surface: a short arc far
// from the origin is otherwise fitted only to ~1e-10 of its distance (the plain fit, which the conversion's
// one-span forms keep, is the refined one where that one alone meets `tolerance`).
std::optional<ArcDirection> find_arc(int degree, const std::vector<double>& knots,
                                     const std::vector<std::vector<Vec4>>& rows, double tolerance, bool refined = false);

// The direction (u when along_u) of a surface, and the curve.
std::optional<ArcDirection> find_arc(const NurbsSurface& surface, bool along_u, double tolerance, bool refined = false);
std::optional<ArcDirection> find_arc(const NurbsCurve& curve, double tolerance, bool refined = false);

// The same surface / curve with the arc direction in its one-span form (exact).
NurbsSurface smooth(const NurbsSurface& surface, bool along_u, const ArcDirection& arc);
NurbsCurve smooth(const NurbsCurve& curve, const ArcDirection& arc);

}  // namespace ratbez::occt::detail
