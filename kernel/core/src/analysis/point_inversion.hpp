#pragma once
// Point inversion, the local part: from a start (u, v) inside a parameter box, the parameters of a
// nearby surface or curve point nearest to P, by Newton's method on the orthogonality conditions
// (S - P) . S_u = (S - P) . S_v = 0 (Piegl and Tiller, The NURBS Book, §6.1, Eq. 6.6–6.8); and the seed
// parameters, per weight-certified piece of each knot span, that global searches start it from.
// What closest_point.hpp (the global search), deviation.cpp (mesh-to-solid distance) and the
// tessellator's cell check (an upper bound of a chord's distance) share. Not installed, not part of the
// public API.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/surface_evaluator.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/interval.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The parameter box a point inversion is kept in: the face's domain, or one cell of it.
struct ParameterBox {
    Interval u, v;
};

// A surface point by its parameters and its distance to the point inverted.
struct ParameterFoot {
    double u = 0, v = 0, distance = std::numeric_limits<double>::infinity();
};

// F(u, v) = |S - P|^2 / 2 to first order at one (u, v): r = S - P, F's gradient (f, g) = r . (S_u, S_v)
// and the Gauss-Newton matrix [a b; b c] = the first fundamental form (Eq. 6.6-6.8 without the terms in
// the second derivatives, which Newton's method adds).
struct DistanceGradient {
    Vec3 r;
    double a, b, c, f, g;
};
inline DistanceGradient distance_gradient(const Vec3& s, const Vec3& su, const Vec3& sv, const Vec3& p) {
    const Vec3 r = s - p;
    return {r, dot(su, su), dot(su, sv), dot(sv, sv), dot(r, su), dot(r, sv)};
}

// When Newton's iteration below stops: after `max_iterations`, once the distance is at most
// `good_enough` (all the caller needs to know), or without a step that lowers the distance; with
// `at_rounding`, also once a step would move the point by less than the rounding of its coordinates,
// where the line search otherwise halves on through rounding noise (40 or 60 times, an evaluation each)
// before it gives up. deviation.cpp's results were measured without it; the foot then differs in its
// last bits.
struct NewtonStop {
    int max_iterations = 50;
    double good_enough = -1;
    bool at_rounding = false;
};

// Newton's point inversion on a surface from (u, v) (The NURBS Book §6.1, Eq. 6.6-6.8), globalised so
// that it converges to a local minimum of the distance from any start: each step is the Newton step
// where the Hessian of F is positive definite, else (or when the Newton step finds no decrease) the
// Gauss-Newton step, which is always a descent direction; it is shortened to a trust region (the foot
// is at most 2 |S - P| from the current surface point, so no step needs to move S further) and then
// halved until F decreases. A parameter on its bound with the gradient pushing out of `box` is held
// there (the active set of projected Newton). (u, v) stays in `box`.
ParameterFoot newton_foot_on_surface(const SurfaceEvaluator& s, const Vec3& p, const ParameterBox& box, double u,
                                     double v, const NewtonStop& stop);

// Newton on a curve for the nearest point to p from t, kept in `box` (the domain, or a piece of it), with
// the step halved until the distance decreases; returns the foot's parameter. (`stop.good_enough` is not
// used.) By default it stops once the step moves the curve by rounding only: at the foot, halving on for 60
// more points took a fifth of a 117-part robot arm's export in the deviation's planar regions.
double newton_foot_on_curve(const NurbsCurve& curve, const Vec3& p, const Interval& box, double t,
                            const NewtonStop& stop = {.max_iterations = 30, .at_rounding = true});

// An upper bound of the distance from p to a surface, cheap: the distance to the surface point
// `surface_point` at (u, v), improved (when above `good_enough`) by up to two plain Gauss–Newton steps
// towards the foot of p, each clamped to `box`. Every value is the distance to a point of the surface,
// so an upper bound of the distance to the surface; unlike newton_foot_on_surface there is no line
// search and no second derivative, which is what the tessellator's cell check affords per chord sample
// (a step that goes uphill only fails to lower the bound). `start()` gives S, S_u and S_v at (u, v) for
// the first step: the caller may have them from a batch; they only steer the step.
template <class Start>
double gauss_newton_bound(const SurfaceEvaluator& s, const Vec3& p, const ParameterBox& box, double u, double v,
                          const Vec3& surface_point, Start&& start, double good_enough) {
    double best = distance(surface_point, p);
    for (int step = 0; step < 2 && best > good_enough; ++step) {
        const SurfaceFirstDerivatives d = step == 0 ? start() : s.first_derivatives(u, v);
        const DistanceGradient e = distance_gradient(d.s, d.su, d.sv, p);
        const double det = e.a * e.c - e.b * e.b;
        if (!(det > 1e-30 * (e.a * e.c + 1e-300))) break;
        // The undamped solve of [a b; b c] (du, dv) = -(f, g) by Cramer's rule.
        u = std::clamp(u - (e.c * e.f - e.b * e.g) / det, box.u.min, box.u.max);
        v = std::clamp(v - (e.a * e.g - e.b * e.f) / det, box.v.min, box.v.max);
        best = std::min(best, distance(s.point(u, v), p));
    }
    return best;
}

// ---- seeds

// Weights crowd a rational span's geometry into a small part of its parameter interval (a segment with
// end weights 1e-3 and 1e3 runs almost all of its length for t within 1e-6 of one end), where seeds at
// uniform parameters do not fall: Newton then starts far from the foot and settles in another local
// minimum. So seeds go per weight-certified piece (detail::weight_cuts, geometry/subdivision.hpp), where uniform
// parameters spread over the piece's geometry. 2^-48 of a span is near the resolution of its
// parameters; a piece that small is not split further.
inline constexpr int kMaxHalvings = 48;

// Seed parameters along one direction of a surface: a few per knot span (the span's ends included once),
// so that every Bézier patch of the face has seeds of its own however short its span is in parameter (a
// rational profile piece can crowd a whole span into a sliver of the domain; with seeds spread
// uniformly over the domain it had none, and Newton from the neighbouring span's seeds settled in that
// span's local minimum, many times farther away). Within a span the seeds go per weight-certified
// piece, for the same reason one level down; the pieces of the two directions make the face's cells, in
// which point inversion is well conditioned.
struct SeedParams {
    std::vector<double> params;
    std::vector<std::uint32_t> piece;  // per parameter: the index of its piece
    std::vector<Interval> pieces;      // the weight-certified pieces, in order
    std::vector<std::uint32_t> span;   // per piece: its knot span (index of the Bézier patch row or column)
    std::vector<Interval> fraction;    // per piece: its part of the span's [0, 1], dyadic (exact halvings)
};

// `patches` are the surface's Bézier patches (A5.7), `along_u` the direction, `knots` and `degree` its.
SeedParams seed_params(const std::vector<std::vector<BezierSurface>>& patches, bool along_u,
                       const std::vector<double>& knots, int degree);

}  // namespace ratbez::detail
