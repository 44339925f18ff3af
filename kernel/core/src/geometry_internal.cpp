// Private helpers: exact degree trigonometry, the A7.1 arc layout, Gauss–Legendre rules, control
// boxes and knot-vector clamping. See geometry_internal.hpp.
#include "geometry_internal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "ratbez/error.hpp"

namespace ratbez::detail {

namespace {

// (cos, sin) of an angle in degrees. The angle is reduced to [0, 360) by fmod (exact), the nearest
// quadrant q is taken off, and only the remainder t in [-45, 45] goes through the radian conversion,
// so multiples of 90 degrees give exactly 0 and ±1 (the ends of every rational quarter circle).
std::pair<double, double> cos_sin_deg(double degrees) {
    double reduced = std::fmod(degrees, 360.0);
    if (reduced < 0) reduced += 360.0;
    const long quadrant = std::lround(reduced / 90.0);
    const double remainder = reduced - 90.0 * static_cast<double>(quadrant);
    double c = 1.0, s = 0.0;
    if (remainder != 0.0) {
        const double radians = remainder * (std::numbers::pi / 180.0);
        c = std::cos(radians);
        s = std::sin(radians);
    }
    switch (quadrant % 4) {
        case 0: return {c, s};
        case 1: return {-s, c};
        case 2: return {-c, -s};
        default: return {s, -c};
    }
}

}  // namespace

double cos_deg(double degrees) { return cos_sin_deg(degrees).first; }
double sin_deg(double degrees) { return cos_sin_deg(degrees).second; }

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

const GaussRule& gauss_legendre(int points) {
    constexpr int max_points = 32;
    static const std::array<GaussRule, max_points + 1> rules = [] {
        std::array<GaussRule, max_points + 1> all{};
        for (int n = 1; n <= max_points; ++n) {
            GaussRule& rule = all[static_cast<std::size_t>(n)];
            // P_n(x) by its three-term recurrence and P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1).
            const auto legendre = [n](double x) {
                double p0 = 1.0, p1 = x;
                for (int k = 2; k <= n; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                if (n == 1) p0 = 1.0;
                return std::pair<double, double>{p1, n * (x * p1 - p0) / (x * x - 1.0)};
            };
            for (int i = 0; i < n; ++i) {
                // Newton's method on P_n from the classical initial guess.
                double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
                for (int iteration = 0; iteration < 100; ++iteration) {
                    const auto [value, slope] = legendre(x);
                    const double step = value / slope;
                    x -= step;
                    if (std::abs(step) < 1e-16) break;
                }
                const double derivative = legendre(x).second;
                rule.nodes.push_back((1.0 - x) / 2.0);
                rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));  // 2/(...) halved for [0, 1]
            }
        }
        return all;
    }();
    require(points >= 1 && points <= max_points, "points", "Gauss–Legendre rules exist here for 1..32 points");
    return rules[static_cast<std::size_t>(points)];
}

std::vector<double> breakpoints(int degree, const std::vector<double>& knots) {
    const std::size_t first = static_cast<std::size_t>(degree);
    const std::size_t last = knots.size() - 1 - static_cast<std::size_t>(degree);
    std::vector<double> values;
    for (std::size_t i = first; i <= last; ++i)
        if (values.empty() || knots[i] > values.back()) values.push_back(knots[i]);
    return values;
}

void Box::add(const Vec3& p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}
void Box::add(const Box& b) {
    if (b.empty()) return;
    add(b.min);
    add(b.max);
}

Box control_box(const NurbsCurve& curve) {
    Box box;
    for (const Vec4& p : curve.homogeneous_points()) box.add(project(p));
    return box;
}

Box control_box(const NurbsSurface& surface) {
    Box box;
    for (const Vec4& p : surface.homogeneous_points()) box.add(project(p));
    return box;
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

NurbsCurve with_end_point(const NurbsCurve& curve, bool at_end, const Vec3& point) {
    std::vector<Vec4> pw = curve.homogeneous_points();
    Vec4& target = at_end ? pw.back() : pw.front();
    target = homogenize(point, target.w);
    return NurbsCurve::from_homogeneous(curve.degree(), curve.knots(), std::move(pw), curve.is_rational());
}

std::vector<double> weight_cuts(const std::vector<std::vector<double>>& lines, int max_halvings) {
    std::vector<double> cuts{0.0};
    for_each_certified_piece(lines, [](double w) { return w; }, max_halvings,
                             [&](const std::vector<std::vector<double>>&, double, double b) { cuts.push_back(b); });
    return cuts;
}

std::string format_point(const Vec3& p) {
    std::ostringstream out;
    out.precision(9);
    out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
    return out.str();
}

}  // namespace ratbez::detail
