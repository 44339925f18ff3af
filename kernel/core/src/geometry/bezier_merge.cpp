// Two Bézier pieces as one where they are parts of one straight segment or one conic arc; see bezier_merge.hpp.
#include "geometry/bezier_merge.hpp"

#include <array>
#include <cmath>

#include "ratbez/bezier_curve.hpp"

namespace ratbez::detail {

namespace {

constexpr std::array<double, 4> kCheckParameters{0.2, 0.4, 0.6, 0.8};
// The least middle weight of a merged arc: a circle's arc of 120 degrees (cos 60), as OpenCASCADE makes a full
// circle of three. Towards a half turn the weight goes to 0 and the middle point to infinity, which neither a
// Gauss rule nor the weight certificate of the integrals likes, and rounding grows with 1 / w.
constexpr double kLeastWeight = 0.5 - 1e-12;

std::vector<Vec3> projected(const std::vector<Vec4>& pw) {
    std::vector<Vec3> points;
    for (const Vec4& q : pw) points.push_back(project(q));
    return points;
}

// Every control point of both pieces on the segment from the first start to the second end, in order along
// it: the segment with evenly spaced control points.
std::optional<std::vector<Vec4>> merged_straight(const std::vector<Vec3>& first, const std::vector<Vec3>& second,
                                                 double tolerance) {
    const Vec3 start = first.front(), end = second.back();
    const Vec3 along = end - start;
    const double length = norm(along);
    if (length <= tolerance) return std::nullopt;
    const Vec3 unit = along / length;
    double reached = 0;
    for (const std::vector<Vec3>* piece : {&first, &second})
        for (const Vec3& p : *piece) {
            const double s = dot(p - start, unit);
            if (distance(p, start + s * unit) > tolerance || s < reached - tolerance || s > length + tolerance)
                return std::nullopt;
            reached = std::max(reached, s);
        }
    const std::size_t n = first.size() - 1;
    std::vector<Vec4> merged;
    for (std::size_t i = 0; i <= n; ++i) merged.push_back(homogenize(lerp(start, end, static_cast<double>(i) / n), 1.0));
    return merged;
}

// (a, c) of x = a p0 + b p1 + c p2 with a + b + c = 1 (least squares in the triangle's plane), and the
// distance of x from that plane's point.
struct Barycentric {
    double a = 0, b = 0, c = 0, off_plane = 0;
};
Barycentric barycentric(const Vec3& x, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 e0 = p0 - p1, e2 = p2 - p1, d = x - p1;
    const double m00 = dot(e0, e0), m02 = dot(e0, e2), m22 = dot(e2, e2);
    const double r0 = dot(e0, d), r2 = dot(e2, d);
    const double det = m00 * m22 - m02 * m02;
    Barycentric result;
    result.a = (r0 * m22 - r2 * m02) / det;
    result.c = (m00 * r2 - m02 * r0) / det;
    result.b = 1 - result.a - result.c;
    result.off_plane = distance(x, p1 + result.a * e0 + result.c * e2);
    return result;
}

// The parameter of a point of the rational quadratic (end weights 1) from its barycentric coordinates:
// a : c = (1 - t)^2 : t^2.
double conic_parameter(const Barycentric& x) { return std::sqrt(x.c) / (std::sqrt(x.a) + std::sqrt(x.c)); }

// The tangent lines at the merged arc's ends, start + s (start's neighbour - start) and end + r (end's
// neighbour - end): where they meet, if they do ahead of both ends.
std::optional<Vec3> tangent_meeting(const Vec3& start, const Vec3& start_next, const Vec3& end, const Vec3& end_previous,
                                    double tolerance) {
    const Vec3 d1 = start_next - start, d2 = end_previous - end, w = start - end;
    const double a = dot(d1, d1), b = dot(d1, d2), c = dot(d2, d2), d = dot(d1, w), e = dot(d2, w);
    const double det = a * c - b * b;
    if (!(det > 1e-24 * a * c)) return std::nullopt;  // parallel tangents: a half turn or more, or a line
    const double s = (b * e - c * d) / det, r = (a * e - b * d) / det;
    const Vec3 on_first = start + s * d1, on_second = end + r * d2;
    if (s <= 0 || r <= 0 || distance(on_first, on_second) > tolerance) return std::nullopt;
    return 0.5 * (on_first + on_second);
}

std::optional<std::vector<Vec4>> merged_conic(const std::vector<Vec4>& first, const std::vector<Vec4>& second,
                                              double tolerance) {
    const std::vector<Vec3> a = projected(first), b = projected(second);
    const std::optional<Vec3> middle = tangent_meeting(a[0], a[1], b[2], b[1], tolerance);
    if (!middle) return std::nullopt;
    const Vec3 p0 = a[0], p1 = *middle, p2 = b[2];
    const Barycentric joint = barycentric(a[2], p0, p1, p2);
    if (!(joint.a > 0 && joint.b > 0 && joint.c > 0) || joint.off_plane > tolerance) return std::nullopt;
    const double t = conic_parameter(joint);
    const double weight = (1 - t) * (1 - t) * joint.b / (2 * t * (1 - t) * joint.a);
    if (!(std::isfinite(weight) && weight >= kLeastWeight)) return std::nullopt;
    std::vector<Vec4> merged{homogenize(p0, 1.0), homogenize(p1, weight), homogenize(p2, 1.0)};

    // The pieces' own points on the merged arc, in order: the first before the joint, the second after it.
    const BezierCurve arc = BezierCurve::from_homogeneous(merged);
    for (const auto& [piece, before_joint] : {std::pair{&first, true}, std::pair{&second, false}}) {
        const BezierCurve curve = BezierCurve::from_homogeneous(*piece);
        for (const double u : kCheckParameters) {
            const Vec3 x = curve.point(u);
            const Barycentric on = barycentric(x, p0, p1, p2);
            if (!(on.a >= 0 && on.c >= 0) || on.off_plane > tolerance) return std::nullopt;
            const double s = conic_parameter(on);
            if ((s < t) != before_joint || distance(arc.point(s), x) > tolerance) return std::nullopt;
        }
    }
    return merged;
}

}  // namespace

std::optional<std::vector<Vec4>> merged_bezier(const std::vector<Vec4>& first, const std::vector<Vec4>& second,
                                               double tolerance) {
    if (first.size() != second.size() || first.size() < 2) return std::nullopt;
    if (auto straight = merged_straight(projected(first), projected(second), tolerance)) return straight;
    if (first.size() == 3) return merged_conic(first, second, tolerance);
    return std::nullopt;
}

}  // namespace ratbez::detail
