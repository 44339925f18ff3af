// Exact line segments, circles, circular and elliptical arcs as NURBS (000 §1.4, Ex1.12–Ex1.13;
// the multi-segment construction is the NURBS book's A7.1).
#include "ratbez/curves.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geometry/arcs.hpp"
#include "math/degrees.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

namespace detail {

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

}  // namespace detail

namespace {

void require_positive_length(double value, const std::string& argument) {
    require_finite(value, argument);
    require(value > 0, argument, "must be greater than 0");
}

// Shared validation of the angle pair of arc() and ellipse_arc(): 0 < end - start <= 360.
double validated_sweep(double start_deg, double end_deg) {
    require_finite(start_deg, "start_deg");
    require_finite(end_deg, "end_deg");
    require(end_deg > start_deg, "end_deg", "must be greater than start_deg");
    const double sweep = end_deg - start_deg;
    require(sweep <= 360.0, "end_deg", "the sweep end_deg - start_deg must be at most 360 degrees");
    return sweep;
}

Frame validated_frame(const Vec3& center, const Vec3& normal) {
    require(is_finite(center), "center", "must have finite coordinates");
    return frame_from_axis(center, normal, "normal");
}

}  // namespace

NurbsCurve line_segment(const Vec3& start, const Vec3& end) {
    require(is_finite(start), "start", "must have finite coordinates");
    require(is_finite(end), "end", "must have finite coordinates");
    require(!(start == end), "end", "must differ from start (a segment needs a length)");
    return NurbsCurve(1, {0.0, 0.0, 1.0, 1.0}, {start, end});
}

NurbsCurve circle(double radius, const Vec3& center, const Vec3& normal) {
    require_positive_length(radius, "radius");
    const Frame frame = validated_frame(center, normal);
    // Four rational quarter circles (Ex1.13 with the symmetric weights 1, cos 45°, 1).
    return detail::arc_in_frame(frame, radius, radius, 0.0, 360.0);
}

NurbsCurve arc(double radius, double start_deg, double end_deg, const Vec3& center, const Vec3& normal) {
    require_positive_length(radius, "radius");
    const double sweep = validated_sweep(start_deg, end_deg);
    const Frame frame = validated_frame(center, normal);
    return detail::arc_in_frame(frame, radius, radius, start_deg, sweep);
}

NurbsCurve ellipse_arc(double a, double b, double start_deg, double end_deg, const Vec3& center, const Vec3& normal) {
    require_positive_length(a, "a");
    require_positive_length(b, "b");
    const double sweep = validated_sweep(start_deg, end_deg);
    const Frame frame = validated_frame(center, normal);
    // The affine image (x, y) -> (a x, b y) of the unit circular arc: rational curves are transformed by
    // transforming their control points (P1.14), weights unchanged, so the point at the circle's angle t
    // goes to (a cos t, b sin t): t is the ellipse's parametric angle.
    return detail::arc_in_frame(frame, a, b, start_deg, sweep);
}

}  // namespace ratbez
