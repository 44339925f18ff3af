// Circular directions in their one-span rational form (smooth_arcs.hpp says why and how).

#include "smooth_arcs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace ratbez::occt::detail {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr int kRuleSpans = 8;  // spans of the one-span form after knot insertion (one_span_unit_arc)

// Product of two Bernstein polynomials of degrees n and m: degree n + m coefficients.
std::vector<double> bernstein_product(const std::vector<double>& a, const std::vector<double>& b) {
    const auto binomial = [](int n, int k) {
        double r = 1;
        for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
        return r;
    };
    const int n = static_cast<int>(a.size()) - 1, m = static_cast<int>(b.size()) - 1;
    std::vector<double> c(static_cast<std::size_t>(n + m + 1), 0.0);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j)
            c[static_cast<std::size_t>(i + j)] += binomial(n, i) * binomial(m, j) / binomial(n + m, i + j) *
                                                  a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)];
    return c;
}

// Degree elevation of Bernstein coefficients by one (000 §1.4).
std::vector<double> elevated(const std::vector<double>& c) {
    const std::size_t n = c.size() - 1;
    std::vector<double> e(n + 2);
    e.front() = c.front();
    e.back() = c.back();
    for (std::size_t i = 1; i <= n; ++i) {
        const double a = static_cast<double>(i) / static_cast<double>(n + 1);
        e[i] = a * c[i - 1] + (1 - a) * c[i];
    }
    return e;
}

// The quadratic (p, q) of the half-angle construction: from (1, 0) to (cos(sweep/2), sin(sweep/2)), middle
// control point k (cos(sweep/4), sin(sweep/4)).
std::array<std::array<double, 2>, 3> half_angle_controls(double sweep, double k) {
    return {{{1.0, 0.0}, {k * std::cos(sweep / 4), k * std::sin(sweep / 4)}, {std::cos(sweep / 2), std::sin(sweep / 2)}}};
}

// Angular speed of (p, q) at s (of the half angle; the arc turns twice as fast): (p q' - q p') / (p^2 + q^2).
double half_angle_speed(const std::array<std::array<double, 2>, 3>& c, double s) {
    const double b[3] = {(1 - s) * (1 - s), 2 * s * (1 - s), s * s};
    const double d[3] = {-2 * (1 - s), 2 - 4 * s, 2 * s};
    double p = 0, q = 0, dp = 0, dq = 0;
    for (int i = 0; i < 3; ++i) {
        p += b[i] * c[static_cast<std::size_t>(i)][0];
        q += b[i] * c[static_cast<std::size_t>(i)][1];
        dp += d[i] * c[static_cast<std::size_t>(i)][0];
        dq += d[i] * c[static_cast<std::size_t>(i)][1];
    }
    return (p * dq - q * dp) / (p * p + q * q);
}

// The one-span unit arc of `sweep` on `domain`, or nullopt where a weight would not be positive.
std::optional<NurbsCurve> one_span_unit_arc(double sweep, const Interval& domain) {
    // k: the speed at the ends equals the speed in the middle. At small k the ends are faster, at large k the
    // middle (for a full turn the speeds are 2k and 4/k): bisection on the sign change.
    double lo = 1e-3, hi = 1e3;
    const auto excess = [&](double k) {
        const auto c = half_angle_controls(sweep, k);
        return half_angle_speed(c, 0.0) - half_angle_speed(c, 0.5);
    };
    if (!(excess(lo) * excess(hi) < 0)) return std::nullopt;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (excess(lo) * excess(mid) <= 0 ? hi : lo) = mid;
    }
    const auto c = half_angle_controls(sweep, 0.5 * (lo + hi));
    const std::vector<double> p{c[0][0], c[1][0], c[2][0]}, q{c[0][1], c[1][1], c[2][1]};
    const std::vector<double> pp = bernstein_product(p, p), qq = bernstein_product(q, q), pq = bernstein_product(p, q);
    std::vector<double> x(pp.size()), y(pp.size()), w(pp.size());
    for (std::size_t i = 0; i < pp.size(); ++i) {
        x[i] = pp[i] - qq[i];
        y[i] = 2 * pq[i];
        w[i] = pp[i] + qq[i];
    }
    x = elevated(x), y = elevated(y), w = elevated(w);
    std::vector<Vec4> homogeneous;
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (!(w[i] > 0)) return std::nullopt;
        homogeneous.push_back(Vec4{x[i], y[i], 0.0, w[i]});
    }
    std::vector<double> knots(6, domain.min);
    knots.resize(12, domain.max);
    NurbsCurve arc = NurbsCurve::from_homogeneous(5, std::move(knots), std::move(homogeneous));
    // Simple knots (exact insertion, A5.1; C4 across them) bring the control polygon close to the arc: with one
    // span a full turn's control points lie up to 5.7 radii from the centre (weights down to 0.2), with 8 spans
    // 1.18 (the kernel's own circle: 1.41), so the convex hull and every box taken from the poles (the kernel's
    // void-in-shell test, OCCT's bounding boxes) stay tight. OCCT's rule then gets its 61-point cap.
    for (int k = 1; k < kRuleSpans; ++k) arc = arc.insert_knot(domain.min + domain.width() * k / kRuleSpans);
    return arc;
}

// The angle of a point of a unit arc of `sweep` starting at (1, 0), in [0, sweep].
double arc_angle(const Vec3& p, double sweep) {
    double a = std::atan2(p.y, p.x);
    if (a < 0) a += kTwoPi;
    if (a > sweep) a = a - sweep < kTwoPi - a ? sweep : 0.0;  // rounding across either end
    return a;
}

// Solves the 3x3 system m x = r (Cramer); false when singular.
bool solve3(const std::array<std::array<double, 3>, 3>& m, const std::array<Vec3, 3>& r, std::array<Vec3, 3>& x) {
    const auto det = [](const std::array<std::array<double, 3>, 3>& a) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det(m);
    if (!(std::abs(d) > 1e-300)) return false;
    for (std::size_t col = 0; col < 3; ++col) {
        Vec3 value{};
        for (int component = 0; component < 3; ++component) {
            auto a = m;
            for (std::size_t row = 0; row < 3; ++row) {
                const Vec3& rr = r[row];
                a[row][col] = component == 0 ? rr.x : component == 1 ? rr.y : rr.z;
            }
            (component == 0 ? value.x : component == 1 ? value.y : value.z) = det(a) / d;
        }
        x[col] = value;
    }
    return true;
}

}  // namespace

double ArcDirection::to_kernel(double t) const {
    if (t <= domain.min) return domain.min;
    if (t >= domain.max) return domain.max;
    const double target = arc_angle(new_unit.point(t), sweep);
    // The kernel's arc turns monotonically with its parameter: bisection to the last bit.
    double lo = domain.min, hi = domain.max;
    for (int i = 0; i < 80 && lo < hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (arc_angle(old_unit.point(mid), sweep) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

namespace {

// The right-hand sides of the least squares of a row's points, less `base`, against (1, x_i, y_i) of the unit arc.
std::array<Vec3, 3> normal_rhs(const std::vector<Vec4>& row, const std::vector<Vec3>& unit, const Vec3& base) {
    std::array<Vec3, 3> rhs{};
    for (std::size_t i = 0; i < row.size(); ++i) {
        const Vec3 p = project(row[i]) - base;
        rhs[0] += p;
        rhs[1] += p * unit[i].x;
        rhs[2] += p * unit[i].y;
    }
    return rhs;
}

}  // namespace

std::optional<ArcDirection> find_arc(int degree, const std::vector<double>& knots,
                                     const std::vector<std::vector<Vec4>>& rows, double tolerance, bool refined) {
    if (degree != 2 || rows.empty()) return std::nullopt;
    const std::size_t n = rows.front().size();
    if (n < 3 || n % 2 == 0 || knots.size() != n + 3) return std::nullopt;
    // Clamped, every interior knot double (one Bézier arc per span).
    if (knots[0] != knots[1] || knots[1] != knots[2] || knots[n] != knots[n + 1] || knots[n + 1] != knots[n + 2])
        return std::nullopt;
    for (std::size_t k = 3; k < n; k += 2)
        if (knots[k] != knots[k + 1] || !(knots[k] > knots[k - 1])) return std::nullopt;
    if (!(knots[n] > knots[n - 1])) return std::nullopt;

    // The unit arc from the relative weights of the first row whose weights are all positive.
    const std::vector<Vec4>& first = rows.front();
    std::vector<double> relative(n);
    for (std::size_t i = 0; i < n; ++i) {
        relative[i] = first[i].w / first[0].w;
        if (!(relative[i] > 0) || !std::isfinite(relative[i])) return std::nullopt;
    }
    std::vector<Vec3> unit(n);
    double angle = 0;
    unit[0] = {1, 0, 0};
    for (std::size_t k = 0; k + 2 < n; k += 2) {
        const double half_cos = relative[k + 1] / std::sqrt(relative[k] * relative[k + 2]);
        if (!(half_cos > 1e-3 && half_cos < 1 - 1e-12)) return std::nullopt;  // not a circular arc below 180 degrees
        const double sweep = 2 * std::acos(half_cos), middle = angle + sweep / 2;
        unit[k + 1] = Vec3{std::cos(middle), std::sin(middle), 0} / half_cos;
        angle += sweep;
        unit[k + 2] = {std::cos(angle), std::sin(angle), 0};
    }
    if (angle > kTwoPi * (1 + 1e-12)) return std::nullopt;
    if (angle > kTwoPi * (1 - 1e-12)) angle = kTwoPi;

    // Least squares O, U, V of every row against (1, x_i, y_i): the normal matrix is the same for every row.
    std::array<std::array<double, 3>, 3> normal{};
    for (std::size_t i = 0; i < n; ++i) {
        const double b[3] = {1.0, unit[i].x, unit[i].y};
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 3; ++c) normal[r][c] += b[r] * b[c];
    }
    const Interval domain{knots.front(), knots.back()};
    std::vector<Vec4> old_homogeneous;
    for (std::size_t i = 0; i < n; ++i)
        old_homogeneous.push_back(Vec4{unit[i].x * relative[i], unit[i].y * relative[i], 0.0, relative[i]});
    std::optional<NurbsCurve> new_unit = one_span_unit_arc(angle, domain);
    if (!new_unit) return std::nullopt;
    ArcDirection arc{domain, angle, NurbsCurve::from_homogeneous(2, knots, std::move(old_homogeneous)), *new_unit, {}, {}, {}, {}};
    for (const std::vector<Vec4>& row : rows) {
        if (row.size() != n || !(row[0].w > 0)) return std::nullopt;
        for (std::size_t i = 0; i < n; ++i)
            if (std::abs(row[i].w / row[0].w - relative[i]) > 1e-12 * relative[i]) return std::nullopt;
        const auto fits = [&](const std::array<Vec3, 3>& fit) {
            for (std::size_t i = 0; i < n; ++i)
                if (distance(project(row[i]), fit[0] + fit[1] * unit[i].x + fit[2] * unit[i].y) > tolerance) return false;
            return true;
        };
        std::array<Vec3, 3> fit{};
        if (!refined && !solve3(normal, normal_rhs(row, unit, Vec3{}), fit)) return std::nullopt;
        // Refined (or failing the plain fit): relative to the row's first point and refined once on the residual.
        // The normal equations square the condition of a short arc's nearly collinear unit points: a 15 degree arc
        // of a cylinder 225 units out, read from a file, fitted only to 5e-9 plainly. Not by default, so that the
        // arcs the conversion hands over keep their fit to the last bit (OCCT's BOP check flags a B-spline sphere's
        // poles or not on rounding).
        if (refined || !fits(fit)) {
            const Vec3 base = project(row[0]);
            const std::array<Vec3, 3> rhs = normal_rhs(row, unit, base);
            std::array<Vec3, 3> correction{}, residual = rhs;
            if (!solve3(normal, rhs, fit)) return std::nullopt;
            for (std::size_t r = 0; r < 3; ++r)
                for (std::size_t c = 0; c < 3; ++c) residual[r] = residual[r] - fit[c] * normal[r][c];
            if (!solve3(normal, residual, correction)) return std::nullopt;
            for (std::size_t c = 0; c < 3; ++c) fit[c] += correction[c];
            fit[0] += base;
            if (!fits(fit)) return std::nullopt;
        }
        arc.origin.push_back(fit[0]);
        arc.u_axis.push_back(fit[1]);
        arc.v_axis.push_back(fit[2]);
        arc.omega.push_back(row[0].w);
    }
    return arc;
}

std::optional<ArcDirection> find_arc(const NurbsSurface& surface, bool along_u, double tolerance, bool refined) {
    const int along = along_u ? surface.rows() : surface.columns(), across = along_u ? surface.columns() : surface.rows();
    std::vector<std::vector<Vec4>> rows(static_cast<std::size_t>(across));
    for (int j = 0; j < across; ++j)
        for (int i = 0; i < along; ++i)
            rows[static_cast<std::size_t>(j)].push_back(along_u ? surface.homogeneous_point(i, j) : surface.homogeneous_point(j, i));
    return find_arc(along_u ? surface.degree_u() : surface.degree_v(), along_u ? surface.knots_u() : surface.knots_v(),
                    rows, tolerance, refined);
}

std::optional<ArcDirection> find_arc(const NurbsCurve& curve, double tolerance, bool refined) {
    return find_arc(curve.degree(), curve.knots(), {curve.homogeneous_points()}, tolerance, refined);
}

namespace {

// The homogeneous control point k of the one-span form on row j.
Vec4 smooth_point(const ArcDirection& arc, std::size_t k, std::size_t j) {
    const Vec4& unit = arc.new_unit.homogeneous_points()[k];
    const double w = unit.w * arc.omega[j];
    const Vec3 p = arc.origin[j] + arc.u_axis[j] * (unit.x / unit.w) + arc.v_axis[j] * (unit.y / unit.w);
    return Vec4{p.x * w, p.y * w, p.z * w, w};
}

}  // namespace

NurbsSurface smooth(const NurbsSurface& surface, bool along_u, const ArcDirection& arc) {
    const std::size_t along = arc.new_unit.homogeneous_points().size(), across = arc.omega.size();
    std::vector<Vec4> net(along * across);
    for (std::size_t k = 0; k < along; ++k)
        for (std::size_t j = 0; j < across; ++j) net[along_u ? k * across + j : j * along + k] = smooth_point(arc, k, j);
    if (along_u)
        return NurbsSurface::from_homogeneous(arc.new_unit.degree(), surface.degree_v(), arc.new_unit.knots(), surface.knots_v(),
                                              std::move(net));
    return NurbsSurface::from_homogeneous(surface.degree_u(), arc.new_unit.degree(), surface.knots_u(), arc.new_unit.knots(),
                                          std::move(net));
}

NurbsCurve smooth(const NurbsCurve&, const ArcDirection& arc) {
    std::vector<Vec4> points;
    for (std::size_t k = 0; k < arc.new_unit.homogeneous_points().size(); ++k) points.push_back(smooth_point(arc, k, 0));
    return NurbsCurve::from_homogeneous(arc.new_unit.degree(), arc.new_unit.knots(), std::move(points));
}

}  // namespace ratbez::occt::detail
