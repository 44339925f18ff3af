// Private helpers: the A7.1 arc layout, Gauss–Legendre rules, control
// boxes and knot-vector clamping. See geometry_internal.hpp.
#include "geometry_internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez::detail {

ArcLayout arc_layout(double start_deg, double sweep_deg) {
    // A7.1: as few segments as keep each within 90 degrees (the weight cos θ stays >= cos 45° and the
    // control polygon stays well shaped); the tiny slack keeps an exact 90k sweep at k segments.
    const int segments = std::max(1, static_cast<int>(std::ceil(sweep_deg / 90.0 - 1e-12)));
    const double segment_sweep = sweep_deg / segments;
    const double middle_weight = cos_deg(segment_sweep / 2.0);
    const double one_plus_cos = 1.0 + cos_deg(segment_sweep);

    ArcLayout layout;
    layout.knots = {0.0, 0.0, 0.0};
    for (int k = 1; k < segments; ++k) {
        const double knot = static_cast<double>(k) / segments;
        layout.knots.insert(layout.knots.end(), {knot, knot});
    }
    layout.knots.insert(layout.knots.end(), {1.0, 1.0, 1.0});

    auto angle_at = [&](int k) { return k == segments ? start_deg + sweep_deg : start_deg + sweep_deg * k / segments; };
    double c0 = cos_deg(start_deg), s0 = sin_deg(start_deg);
    layout.cos_coefficient.push_back(c0);
    layout.sin_coefficient.push_back(s0);
    layout.weights.push_back(1.0);
    for (int k = 1; k <= segments; ++k) {
        const double c2 = cos_deg(angle_at(k)), s2 = sin_deg(angle_at(k));
        // The tangents at P_0 and P_2 meet on the bisector at distance 1 / cos θ from the centre, which
        // is (P_0 + P_2) / (2 cos² θ) = (P_0 + P_2) / (1 + cos 2θ): exact (1, 1) for a quarter circle.
        layout.cos_coefficient.push_back((c0 + c2) / one_plus_cos);
        layout.sin_coefficient.push_back((s0 + s2) / one_plus_cos);
        layout.weights.push_back(middle_weight);
        layout.cos_coefficient.push_back(c2);
        layout.sin_coefficient.push_back(s2);
        layout.weights.push_back(1.0);
        c0 = c2;
        s0 = s2;
    }
    return layout;
}

NurbsCurve arc_in_frame(const Frame& frame, double radius_x, double radius_y, double start_deg, double sweep_deg) {
    const ArcLayout layout = arc_layout(start_deg, sweep_deg);
    std::vector<Vec3> points;
    points.reserve(layout.weights.size());
    for (std::size_t i = 0; i < layout.weights.size(); ++i)
        points.push_back(frame.origin + frame.x_axis * (radius_x * layout.cos_coefficient[i]) +
                         frame.y_axis * (radius_y * layout.sin_coefficient[i]));
    return NurbsCurve(2, layout.knots, std::move(points), layout.weights);
}

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
    const int p = curve.degree();
    const Interval d = curve.domain();
    NurbsCurve c = curve;
    for (const double end : {d.min, d.max}) {
        const int multiplicity = static_cast<int>(std::count(c.knots().begin(), c.knots().end(), end));
        if (multiplicity < p) c = c.insert_knot(end, p - multiplicity);
    }
    // Keep U[s..e]: one knot before the first d.min and one after the last d.max, set to the ends. The basis
    // function N_s (and N_{e-p-1}) only reaches the domain through the p equal knots after U[s], so moving
    // U[s] onto them changes nothing there; the control points P_s .. P_{e-p-1} are the ones in use.
    const std::vector<double>& knots = c.knots();
    const std::size_t first = static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), d.min) - knots.begin());
    const std::size_t last = static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), d.max) - knots.begin()) - 1;
    const std::size_t s = first - 1, e = last + 1;
    std::vector<double> new_knots(knots.begin() + static_cast<std::ptrdiff_t>(s), knots.begin() + static_cast<std::ptrdiff_t>(e) + 1);
    new_knots.front() = d.min;
    new_knots.back() = d.max;
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

void require_solid_scale(double size, double reach, std::string_view size_argument, std::string_view position_argument) {
    using limits::max_solid_coordinate, limits::min_solid_size, limits::min_relative_solid_size;
    require(std::isfinite(size) && size <= max_solid_coordinate, size_argument, [&] {
        return "gives a solid of size " + number(size) + ", above the limit " + number(max_solid_coordinate) +
               " (its area and volume must be finite numbers)";
    });
    require(std::isfinite(reach) && reach <= max_solid_coordinate, position_argument, [&] {
        return "gives a solid with coordinates up to " + number(reach) + ", above the limit " +
               number(max_solid_coordinate);
    });
    require(size >= min_solid_size, size_argument, [&] {
        return "gives a solid of size " + number(size) + ", below the limit " + number(min_solid_size) +
               " (its area and volume must be non-zero numbers)";
    });
    require(size >= min_relative_solid_size * reach, size_argument, [&] {
        return "gives a solid of size " + number(size) + " at " + number(reach) +
               " from the origin, where neighbouring doubles are " + number(reach * 0x1p-52) +
               " apart: a solid must be at least " + number(min_relative_solid_size) + " of its distance from the origin";
    });
}

double reach_of(const Box& box) {
    double reach = 0;
    for (const Vec3& corner : {box.min, box.max})
        reach = std::max({reach, std::abs(corner.x), std::abs(corner.y), std::abs(corner.z)});
    return reach;
}

std::string format_point(const Vec3& p) {
    std::ostringstream out;
    out.precision(9);
    out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
    return out.str();
}

}  // namespace ratbez::detail
