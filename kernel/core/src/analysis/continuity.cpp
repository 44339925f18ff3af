// Continuity of curves at a joint and of patches along a shared boundary; see continuity.hpp.
#include "ratbez/continuity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "geometry/curve_shape.hpp"
#include "math/vector_angle.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/closest_point.hpp"
#include "ratbez/curvature.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

constexpr double kRelative = 1e-9;      // positions, derivatives, curvatures: relative to their scale
constexpr double kAngle = 1e-9;         // radians
constexpr double kFloor = 1e-12;        // the absolute floor of derivative and curvature comparisons

using detail::angle_between;

// The tolerance of a k-th derivative comparison: relative to the larger value, with a floor from the
// shape's size over the parameter width to the k-th power (two zero derivatives agree).
double derivative_tolerance(const Vec3& x, const Vec3& y, double size, double width, int order) {
    return kRelative * std::max(norm(x), norm(y)) + kFloor * size / std::pow(width, order);
}

// The orders reached from the gaps and their tolerances, in the order position, first, second.
int order_reached(const std::array<bool, 3>& holds) {
    int order = -1;
    while (order < 2 && holds[static_cast<std::size_t>(order + 1)]) ++order;
    return order;
}

// ---- surfaces: sides of a patch

enum class Side { v_min, u_max, v_max, u_min };

struct SideView {
    Side side;
    bool along_u;        // the side runs along u (v fixed)
    double fixed;        // the fixed parameter's value
    Interval along;      // the running parameter's domain
    bool towards_larger; // the cross parameter grows towards the side (u_max, v_max)
};

SideView side_view(const NurbsSurface& s, Side side) {
    const Interval du = s.domain_u(), dv = s.domain_v();
    switch (side) {
        case Side::v_min: return {side, true, dv.min, du, false};
        case Side::u_max: return {side, false, du.max, dv, true};
        case Side::v_max: return {side, true, dv.max, du, true};
        default: return {side, false, du.min, dv, false};
    }
}

Vec3 point_on(const NurbsSurface& s, const SideView& side, double t) {
    return side.along_u ? s.point(t, side.fixed) : s.point(side.fixed, t);
}

NurbsCurve boundary(const NurbsSurface& s, const SideView& side) {
    return side.along_u ? s.isocurve_v(side.fixed) : s.isocurve_u(side.fixed);
}

// The parameter on b's side matching t on a's side (affine, possibly reversed).
double matched(const SideView& a, const SideView& b, bool reversed, double t) {
    const double f = (t - a.along.min) / a.along.width();
    return reversed ? b.along.max - f * b.along.width() : b.along.min + f * b.along.width();
}

// The k-th cross-boundary derivative at the side's point t (k = 1, 2), oriented: `towards` the side
// (a's, as a runs into the boundary) or away from it (b's).
Vec3 cross_derivative(const NurbsSurface& s, const SideView& side, double t, int k, bool towards) {
    const Vec3 d = side.along_u ? s.derivative(t, side.fixed, 0, k) : s.derivative(side.fixed, t, k, 0);
    // The cross parameter grows towards the side on u_max / v_max; a derivative of order k changes sign
    // k times when the direction is reversed.
    const bool sign_flip = (side.towards_larger != towards) && (k % 2 == 1);
    return sign_flip ? -d : d;
}

// The sample parameters along a side: the ends and three points inside every knot span, at most ~200.
std::vector<double> side_samples(const NurbsSurface& s, const SideView& side) {
    const std::vector<double> breaks =
        side.along_u ? breakpoints(s.degree_u(), s.knots_u()) : breakpoints(s.degree_v(), s.knots_v());
    const std::size_t spans = breaks.size() - 1;
    const int per_span = spans > 50 ? 1 : 4;
    std::vector<double> t;
    for (std::size_t k = 0; k < spans; ++k)
        for (int i = 0; i < per_span; ++i) t.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * i / per_span);
    t.push_back(breaks.back());
    return t;
}

// The largest difference of the second fundamental forms of a and b over unit tangent directions (the
// spectral norm of the difference of their 2x2 matrices in one orthonormal basis), b's signs taken with
// a's normal.
double form_difference(const PrincipalCurvatures& a, const PrincipalCurvatures& b) {
    const double sign = dot(a.normal, b.normal) >= 0 ? 1.0 : -1.0;
    const Vec3 e1 = a.dir1, e2 = a.dir2;
    auto form = [](const PrincipalCurvatures& p, const Vec3& x, const Vec3& y) {
        return p.k1 * dot(x, p.dir1) * dot(y, p.dir1) + p.k2 * dot(x, p.dir2) * dot(y, p.dir2);
    };
    const double d11 = form(a, e1, e1) - sign * form(b, e1, e1);
    const double d12 = form(a, e1, e2) - sign * form(b, e1, e2);
    const double d22 = form(a, e2, e2) - sign * form(b, e2, e2);
    return std::abs(0.5 * (d11 + d22)) + std::hypot(0.5 * (d11 - d22), d12);
}

}  // namespace

Continuity continuity(const NurbsCurve& a, const NurbsCurve& b) {
    Box box = a.control_box();
    box.add(b.control_box());
    const double size = box.diagonal();
    const double end = a.domain().max, start = b.domain().min;
    const std::vector<Vec3> da = a.derivatives(end, 2), db = b.derivatives(start, 2);
    const double width = 0.5 * (a.domain().width() + b.domain().width());

    Continuity out;
    out.position = distance(da[0], db[0]);
    out.derivative1 = distance(da[1], db[1]);
    out.derivative2 = distance(da[2], db[2]);
    const detail::CurveShape sa = detail::curve_shape(a, end, true), sb = detail::curve_shape(b, start, false);
    // A curve that does not move (every control point the same) has no tangent, so no angle and no order
    // of geometric continuity to report: an Error naming it, not a NaN tangent_angle (issue 29).
    require(norm(sa.tangent) > 0, "a", "is a single point (all its control points coincide): it has no tangent to compare");
    require(norm(sb.tangent) > 0, "b", "is a single point (all its control points coincide): it has no tangent to compare");
    out.tangent_angle = angle_between(sa.tangent, sb.tangent);
    out.curvature = norm(sa.curvature_vector - sb.curvature_vector);
    if (std::isnan(out.curvature)) out.curvature = std::numeric_limits<double>::infinity();  // inf - inf at cusps

    const bool meet = out.position <= kRelative * size;
    out.parametric = order_reached({meet, out.derivative1 <= derivative_tolerance(da[1], db[1], size, width, 1),
                                    out.derivative2 <= derivative_tolerance(da[2], db[2], size, width, 2)});
    const double curvature_tolerance =
        kRelative * std::max(norm(sa.curvature_vector), norm(sb.curvature_vector)) + kFloor / size;
    out.geometric = order_reached({meet, out.tangent_angle <= kAngle,
                                   std::isfinite(out.curvature) && out.curvature <= curvature_tolerance});
    return out;
}

Continuity continuity(const NurbsSurface& a, const NurbsSurface& b) {
    Box box = a.control_box();
    box.add(b.control_box());
    const double size = box.diagonal();
    const double tolerance = kRelative * size;

    // The shared boundary: the side pair and direction whose points agree best at matching parameters.
    constexpr int kProbes = 9;
    double best = std::numeric_limits<double>::infinity();
    SideView side_a{}, side_b{};
    bool reversed = false;
    for (const Side sa : {Side::v_min, Side::u_max, Side::v_max, Side::u_min})
        for (const Side sb : {Side::v_min, Side::u_max, Side::v_max, Side::u_min})
            for (const bool rev : {false, true}) {
                const SideView va = side_view(a, sa), vb = side_view(b, sb);
                double worst = 0;
                for (int k = 0; k < kProbes && worst < best; ++k) {
                    const double t = va.along.min + va.along.width() * k / (kProbes - 1);
                    worst = std::max(worst, distance(point_on(a, va, t), point_on(b, vb, matched(va, vb, rev, t))));
                }
                if (worst < best) {
                    best = worst;
                    side_a = va;
                    side_b = vb;
                    reversed = rev;
                }
            }

    // Position: the boundaries as point sets (each side's samples projected onto the other boundary), and
    // at matching parameters for the parametric orders.
    Continuity out;
    const std::vector<double> samples = side_samples(a, side_a);
    const CurveProjector onto_b(boundary(b, side_b));
    const CurveProjector onto_a(boundary(a, side_a));
    double matched_gap = 0;
    for (const double t : samples) {
        matched_gap = std::max(matched_gap, distance(point_on(a, side_a, t), point_on(b, side_b, matched(side_a, side_b, reversed, t))));
        out.position = std::max(out.position, onto_b.closest_point(point_on(a, side_a, t)).distance);
    }
    for (const double s : side_samples(b, side_b))
        out.position = std::max(out.position, onto_a.closest_point(point_on(b, side_b, s)).distance);
    const bool geometric_meet = out.position <= tolerance;
    const bool parametric_meet = matched_gap <= tolerance;
    if (!geometric_meet) return out;

    const double width_a = side_a.along_u ? a.domain_v().width() : a.domain_u().width();
    const double width_b = side_b.along_u ? b.domain_v().width() : b.domain_u().width();
    const double width = 0.5 * (width_a + width_b);
    bool c1 = parametric_meet, c2 = parametric_meet, g1 = true, g2 = true;
    for (const double t : samples) {
        const double s = matched(side_a, side_b, reversed, t);
        for (int k = 1; k <= 2 && parametric_meet; ++k) {
            const Vec3 xa = cross_derivative(a, side_a, t, k, true), xb = cross_derivative(b, side_b, s, k, false);
            const double gap = distance(xa, xb);
            double& recorded = k == 1 ? out.derivative1 : out.derivative2;
            recorded = std::max(recorded, gap);
            bool& holds = k == 1 ? c1 : c2;
            holds = holds && gap <= derivative_tolerance(xa, xb, size, width, k);
        }
        // Geometric orders at the geometrically nearest point of b's boundary.
        const Vec3 p = point_on(a, side_a, t);
        const double sb = parametric_meet ? s : onto_b.closest_point(p).u;
        const double ua = side_a.along_u ? t : side_a.fixed, va = side_a.along_u ? side_a.fixed : t;
        const double ub = side_b.along_u ? sb : side_b.fixed, vb = side_b.along_u ? side_b.fixed : sb;
        const Vec3 na = a.normal(ua, va), nb = b.normal(ub, vb);
        const double angle = std::min(angle_between(na, nb), angle_between(na, -nb));
        out.tangent_angle = std::max(out.tangent_angle, angle);
        g1 = g1 && angle <= kAngle;
        const PrincipalCurvatures ka = principal_curvatures(a, ua, va), kb = principal_curvatures(b, ub, vb);
        const double difference = form_difference(ka, kb);
        out.curvature = std::max(out.curvature, difference);
        const double scale = std::max({std::abs(ka.k1), std::abs(ka.k2), std::abs(kb.k1), std::abs(kb.k2)});
        g2 = g2 && difference <= kRelative * scale + kFloor / size;
    }
    out.parametric = order_reached({parametric_meet, c1, c2});
    out.geometric = order_reached({geometric_meet, g1, g2});
    return out;
}

}  // namespace ratbez
