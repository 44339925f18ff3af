// Exact line segments, circles, circular and elliptical arcs as NURBS (000 §1.4, Ex1.12–Ex1.13;
// the multi-segment construction is the NURBS book's A7.1).
#include "ratbez/curves.hpp"

#include <string>

#include "geometry_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

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
