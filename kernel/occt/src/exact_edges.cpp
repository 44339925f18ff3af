// Segments, circular and elliptic arcs among the kernel's edges (see exact_edges.hpp).

#include "exact_edges.hpp"

#include <ElCLib.hxx>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ratbez/occt/geometry.hpp"
#include "smooth_arcs.hpp"

namespace ratbez::occt::detail {

double reach(const Box& box) {
    return std::max({std::abs(box.min.x), std::abs(box.min.y), std::abs(box.min.z), std::abs(box.max.x), std::abs(box.max.y),
                     std::abs(box.max.z)});
}

double exact_fit(const Solid& solid) {
    const Box box = solid.bounding_box();
    return 1e-11 * std::max({1.0, box.diagonal(), reach(box)});
}

std::optional<EdgeCircle> edge_circle(const Edge& e, double tolerance) {
    const std::optional<ArcDirection> found = find_arc(e.curve, tolerance);
    if (!found) return std::nullopt;
    const Vec3 &u = found->u_axis.front(), &v = found->v_axis.front();
    const double r = norm(u);
    if (!(r > tolerance) || std::abs(norm(v) - r) > tolerance || std::abs(dot(u, v)) > tolerance * r) return std::nullopt;
    return EdgeCircle{found->origin.front(), cross(u, v) / (r * r), u, r, found->sweep};
}

std::optional<EdgeEllipse> edge_ellipse(const Edge& e, double tolerance) {
    const std::optional<ArcDirection> found = find_arc(e.curve, tolerance);
    if (!found) return std::nullopt;
    const Vec3 &u = found->u_axis.front(), &v = found->v_axis.front();
    // |U cos t + V sin t|^2 = mean + half_difference cos 2t + product sin 2t: largest at 2 t0 = atan2(product,
    // half_difference), the major axis, and smallest a quarter turn on.
    const double mean = (dot(u, u) + dot(v, v)) / 2, half_difference = (dot(u, u) - dot(v, v)) / 2, product = dot(u, v);
    const double spread = std::hypot(half_difference, product);
    const double major = std::sqrt(mean + spread), minor = std::sqrt(std::max(0.0, mean - spread));
    const Vec3 normal = cross(u, v);
    if (!(minor > tolerance) || !(major - minor > tolerance) || !(norm(normal) > 0)) return std::nullopt;  // a circle or a line
    const double t0 = std::atan2(product, half_difference) / 2;
    return EdgeEllipse{found->origin.front(), normal / norm(normal), (u * std::cos(t0) + v * std::sin(t0)) / major, major, minor,
                       found->sweep};
}

namespace {

template <class Conic>
std::optional<std::pair<double, double>> conic_range(const Conic& conic, const gp_Pnt& start, const gp_Pnt& middle, const gp_Pnt& end,
                                                     bool closed) {
    constexpr double kTurn = 2 * std::numbers::pi;
    // A start on the conic's own start rounds to either end of [0, 2 pi): at 0, as OCCT's own arcs start there.
    double first = ElCLib::Parameter(conic, start);
    if (kTurn - first <= 1e-12 * kTurn) first = 0;
    double last = closed ? first + kTurn : ElCLib::Parameter(conic, end);
    while (last <= first) last += kTurn;
    double through = ElCLib::Parameter(conic, middle);
    while (through < first) through += kTurn;
    if (through > last) return std::nullopt;
    return std::pair{first, last};
}

template <class Conic>
std::optional<std::pair<double, double>> conic_parameters(const Conic& conic, const Edge& e, double sweep) {
    const Interval domain = e.curve.domain();
    const std::optional<std::pair<double, double>> range =
        conic_range(conic, to_occt_point(e.start->point), to_occt_point(e.curve.point(domain.min + domain.width() / 2)),
                    to_occt_point(e.end->point), e.start == e.end);
    if (!range || std::abs(range->second - range->first - sweep) > 1e-9 * 2 * std::numbers::pi) return std::nullopt;
    return range;
}

}  // namespace

std::optional<std::pair<double, double>> arc_range(const gp_Circ& circle, const gp_Pnt& start, const gp_Pnt& middle, const gp_Pnt& end,
                                    bool closed) {
    return conic_range(circle, start, middle, end, closed);
}

std::optional<std::pair<double, double>> arc_parameters(const gp_Circ& circle, const Edge& e, double sweep) {
    return conic_parameters(circle, e, sweep);
}

std::optional<std::pair<double, double>> arc_parameters(const gp_Elips& ellipse, const Edge& e, double sweep) {
    return conic_parameters(ellipse, e, sweep);
}

bool is_segment(const Edge& e, double tolerance) {
    const Vec3 a = e.start->point, d = e.end->point - a;
    const double length = norm(d);
    if (e.start == e.end || !(length > tolerance)) return false;
    for (const Vec4& h : e.curve.homogeneous_points()) {
        const Vec3 p = Vec3{h.x, h.y, h.z} / h.w - a;
        const double t = dot(p, d) / length;
        if (t < -tolerance || t > length + tolerance || norm(p - d * (t / length)) > tolerance) return false;
    }
    return true;
}

bool runs_linearly(const Edge& e, double tolerance) {
    const NurbsCurve& curve = e.curve;
    const std::vector<Vec4>& h = curve.homogeneous_points();
    const std::vector<double>& knots = curve.knots();
    const int p = curve.degree();
    const Interval domain = curve.domain();
    if (e.start == e.end || h.size() < 2 || !(domain.width() > 0)) return false;
    for (const Vec4& point : h)
        if (point.w != h.front().w) return false;
    const Vec3 a = e.start->point, b = e.end->point;
    for (std::size_t i = 0; i < h.size(); ++i) {
        double greville = 0;
        for (int k = 1; k <= p; ++k) greville += knots[i + static_cast<std::size_t>(k)];
        greville /= p;
        const Vec3 on_line = a + (b - a) * ((greville - domain.min) / domain.width());
        if (norm(Vec3{h[i].x, h[i].y, h[i].z} / h[i].w - on_line) > tolerance) return false;
    }
    return true;
}

}  // namespace ratbez::occt::detail
