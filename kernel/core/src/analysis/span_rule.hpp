#pragma once
// A tensor Gauss–Legendre rule straight on the knot spans of a NURBS curve or surface: the integral of
// f(S, S_u, S_v) du dv over the domain, n_u x n_v nodes on every non-empty span pair. Equivalent to the
// same rule on each rational Bézier patch (a span is a patch, A5.7), but without extracting them: the
// basis functions and their derivatives (A2.3) are evaluated once per node and direction, each control
// row is summed in v once per v node, and the homogeneous sums give S and its partials by the quotient
// rule. Linear in the number of spans, with no allocation per span; the orientation check of a Solid
// runs it over faces of 10^5 spans.
//
// The rule converges geometrically only where the weight function has no pole near the span; the
// caller decides that (see control_weight_ratio). Its nodes are global parameters u = u_k + x (u_{k+1} -
// u_k), so in a span of width Δ a node's place is known to about ε |u| / Δ of the span: in 10^5 spans of
// [0, 1] the sum drifts by some 1e-13 of itself. Plenty for a sign (Solid's orientation check); the
// measurements, which promise 1e-14, integrate the extracted patches in their own [0, 1] instead.
// Not installed, not part of the public API.

#include <functional>
#include <span>

#include "geometry/surface_evaluator.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// A curve or a surface as one homogeneous tensor net, row-major (i along u, `columns` entries per row).
// A curve is a net of one column, of degree 0 in v over [0, 1]: S_v = 0.
struct SpanNet {
    int degree_u = 0, degree_v = 0;
    std::span<const double> knots_u, knots_v;
    std::span<const Vec4> points;
    int columns = 1;
};
SpanNet span_net(const NurbsSurface& surface);
SpanNet span_net(const NurbsCurve& curve);

// max w / min w over the control points (weights are positive). Every Bézier patch's weights are convex
// combinations of these (knot insertion), so they vary by no more than this factor either.
double control_weight_ratio(std::span<const Vec4> points);

using SpanIntegrand = std::function<double(const SurfaceFirstDerivatives&)>;

// Σ over the non-empty spans of the points_u x points_v Gauss–Legendre rule of f(S, S_u, S_v) on the span,
// in the net's own parameters (the rule's weights carry the span lengths).
double span_rule(const SpanNet& net, int points_u, int points_v, const SpanIntegrand& f);

}  // namespace ratbez::detail
