// Clamped knot vectors (clamping.hpp).
#include "geometry/clamping.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "ratbez/bspline_basis.hpp"

namespace ratbez::detail {

bool is_clamped(const NurbsCurve& curve) {
    const auto& knots = curve.knots();
    const std::size_t p = static_cast<std::size_t>(curve.degree());
    const std::size_t m = knots.size() - 1;
    for (std::size_t i = 1; i <= p; ++i)
        if (knots[i] != knots[0] || knots[m - i] != knots[m]) return false;
    return true;
}

NurbsCurve clamped(const NurbsCurve& curve) {
    if (is_clamped(curve)) return curve;
    // The Bézier segments of the spans (A5.6) joined with break points of multiplicity p: the same curve
    // with the same parameterisation, now interpolating its end control points.
    const std::vector<BezierCurve> segments = curve.bezier_segments();
    const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
    const int p = curve.degree();
    std::vector<double> knots(static_cast<std::size_t>(p + 1), breaks.front());
    for (std::size_t k = 1; k + 1 < breaks.size(); ++k) knots.insert(knots.end(), static_cast<std::size_t>(p), breaks[k]);
    knots.insert(knots.end(), static_cast<std::size_t>(p + 1), breaks.back());
    std::vector<Vec4> points;
    for (std::size_t k = 0; k < segments.size(); ++k) {
        std::vector<Vec4> pw = segments[k].homogeneous_points();
        if (k > 0) {
            // Scaling every weight of a rational segment by one factor leaves the curve unchanged; match
            // the shared junction point's weight so that the joined homogeneous polygon is consistent.
            const double factor = points.back().w / pw.front().w;
            for (Vec4& q : pw) q *= factor;
            points.insert(points.end(), pw.begin() + 1, pw.end());
        } else {
            points = pw;
        }
    }
    return NurbsCurve::from_homogeneous(p, std::move(knots), std::move(points), curve.is_rational());
}

NurbsCurve clamped_ends(const NurbsCurve& curve) {
    if (is_clamped(curve)) return curve;
    const Interval d = curve.domain();
    return restricted(curve, d.min, d.max);
}

NurbsCurve restricted(const NurbsCurve& curve, double a, double b) {
    const int p = curve.degree();
    NurbsCurve c = curve;
    for (const double end : {a, b}) {
        const int multiplicity = static_cast<int>(std::count(c.knots().begin(), c.knots().end(), end));
        if (multiplicity < p) c = c.insert_knot(end, p - multiplicity);
    }
    // Keep U[s..e]: one knot before the first a and one after the last b, set to the ends (or the end knots
    // themselves where a or b already has multiplicity p + 1). The basis function N_s (and N_{e-p-1}) only
    // reaches [a, b] through the p equal knots after U[s], so moving U[s] onto them changes nothing there;
    // the control points P_s .. P_{e-p-1} are the ones in use.
    const std::vector<double>& knots = c.knots();
    const std::size_t first = static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), a) - knots.begin());
    const std::size_t last = static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), b) - knots.begin()) - 1;
    const std::size_t s = first > 0 ? first - 1 : 0, e = last + 1 < knots.size() ? last + 1 : last;
    std::vector<double> new_knots(knots.begin() + static_cast<std::ptrdiff_t>(s), knots.begin() + static_cast<std::ptrdiff_t>(e) + 1);
    new_knots.front() = a;
    new_knots.back() = b;
    const std::vector<Vec4>& pw = c.homogeneous_points();
    std::vector<Vec4> points(pw.begin() + static_cast<std::ptrdiff_t>(s),
                             pw.begin() + static_cast<std::ptrdiff_t>(e - static_cast<std::size_t>(p)));
    return NurbsCurve::from_homogeneous(p, std::move(new_knots), std::move(points), c.is_rational());
}

NurbsCurve with_end_point(const NurbsCurve& curve, bool at_end, const Vec3& point) {
    std::vector<Vec4> pw = curve.homogeneous_points();
    Vec4& target = at_end ? pw.back() : pw.front();
    target = homogenize(point, target.w);
    return NurbsCurve::from_homogeneous(curve.degree(), curve.knots(), std::move(pw), curve.is_rational());
}

}  // namespace ratbez::detail
