// Bézier curves, polynomial and rational (000 §1.3–1.4). Every algorithm runs on the homogeneous control
// points P^w_i (Eq. 1.17) and projects at the end with H (Eq. 1.16), so the polynomial curve is simply the
// case w_i = 1 and needs no code path of its own.

#include "ratbez/bezier_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "math/rational_derivatives.hpp"
#include "math/weights_internal.hpp"
#include "ratbez/bernstein.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

void validate_points(const std::vector<Vec3>& points) {
    require(!points.empty(), "points", "a Bézier curve needs at least one control point");
    limits::require_bezier_count(points.size(), "points");
    for (std::size_t i = 0; i < points.size(); ++i)
        require(is_finite(points[i]), "points",
                [&] { return "control point " + std::to_string(i) + " has a non-finite coordinate"; });
}

// The messages are built only on failure: from_homogeneous runs for every Bézier piece a tessellation
// or evaluator extracts.
void validate_weight(double weight, std::size_t index, const std::string& argument) {
    require(std::isfinite(weight), argument, [&] { return "weight " + std::to_string(index) + " is not a finite number"; });
    require(weight > 0.0, argument,
            [&] { return "weight " + std::to_string(index) + " is " + exact_number(weight) + " but must be > 0"; });
}

// P^w_i = (2^k w_i P_i, 2^k w_i): the weights scaled first, so that w P cannot overflow (weights_internal.hpp).
std::vector<Vec4> homogenize_all(const std::vector<Vec3>& points, const std::vector<double>& weights, int exponent) {
    std::vector<Vec4> pw(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) pw[i] = homogenize(points[i], std::ldexp(weights[i], exponent));
    return pw;
}

// A1.5 / Eq. 1.19 on a copy of the points: repeated linear interpolation down the triangle of Table 1.3.
Vec4 de_casteljau(std::vector<Vec4> q, double u) {
    for (std::size_t k = 1; k < q.size(); ++k)
        for (std::size_t i = 0; i + k < q.size(); ++i) q[i] = lerp(q[i], q[i + 1], u);
    return q.front();
}

}  // namespace

BezierCurve::BezierCurve(std::vector<Vec4> homogeneous_points, bool rational, int weight_exponent)
    : ControlPolygon(std::move(homogeneous_points), rational, weight_exponent) {}

BezierCurve::BezierCurve(std::vector<Vec3> points) {
    validate_points(points);
    pw_ = homogenize_all(points, std::vector<double>(points.size(), 1.0), 0);
    rational_ = false;
}

BezierCurve::BezierCurve(std::vector<Vec3> points, std::vector<double> weights) {
    validate_points(points);
    require(weights.size() == points.size(), "weights", [&] {
        return "got " + std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) +
               " control points; there must be exactly one weight per control point";
    });
    for (std::size_t i = 0; i < weights.size(); ++i) validate_weight(weights[i], i, "weights");
    weight_exponent_ = detail::weight_scale_exponent_of(weights, detail::products_finite(points, weights));
    pw_ = homogenize_all(points, weights, weight_exponent_);
    rational_ = true;
}

BezierCurve BezierCurve::from_homogeneous(std::vector<Vec4> homogeneous_points, bool rational) {
    require(!homogeneous_points.empty(), "homogeneous_points", "a Bézier curve needs at least one control point");
    limits::require_bezier_count(homogeneous_points.size(), "homogeneous_points");
    for (std::size_t i = 0; i < homogeneous_points.size(); ++i) {
        const Vec4& p = homogeneous_points[i];
        require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "homogeneous_points",
                [&] { return "control point " + std::to_string(i) + " has a non-finite coordinate"; });
        validate_weight(p.w, i, "homogeneous_points");
    }
    std::vector<double> weights(homogeneous_points.size());
    for (std::size_t i = 0; i < weights.size(); ++i) weights[i] = homogeneous_points[i].w;
    const int exponent = detail::weight_scale_exponent_of(weights);
    detail::scale_homogeneous(homogeneous_points, exponent);
    return BezierCurve(std::move(homogeneous_points), rational, exponent);
}

Vec4 BezierCurve::homogeneous_point(double u) const {
    // A1.4 on P^w: the Bernstein values of A1.3 times the homogeneous control points (Eq. 1.17).
    const std::vector<double> basis = all_bernstein(degree(), u);  // validates u
    Vec4 sum;
    for (std::size_t i = 0; i < pw_.size(); ++i) sum += basis[i] * pw_[i];
    return sum;
}

Vec3 BezierCurve::point(double u) const { return detail::require_finite_point(project(homogeneous_point(u)), u); }

Vec3 BezierCurve::point_de_casteljau(double u) const {
    require_in_domain(u, 0.0, 1.0, "u");
    return detail::require_finite_point(project(de_casteljau(pw_, u)), u);  // Eq. 1.19, then H
}

std::vector<std::vector<Vec4>> BezierCurve::de_casteljau_table(double u) const {
    require_in_domain(u, 0.0, 1.0, "u");
    // rows[k][i] = P^w_{k,i}(u) of Eq. 1.19; row 0 is the control polygon, row n the single point C^w(u).
    std::vector<std::vector<Vec4>> rows;
    rows.reserve(pw_.size());
    rows.push_back(pw_);
    for (std::size_t k = 1; k < pw_.size(); ++k) {
        const std::vector<Vec4>& previous = rows.back();
        std::vector<Vec4> next(previous.size() - 1);
        for (std::size_t i = 0; i < next.size(); ++i) next[i] = lerp(previous[i], previous[i + 1], u);
        rows.push_back(std::move(next));
    }
    return rows;
}

std::vector<Vec3> BezierCurve::derivatives(double u, int order) const {
    require_in_domain(u, 0.0, 1.0, "u");
    limits::require_derivative_order(order, "order");
    const auto count = static_cast<std::size_t>(order) + 1;

    // Derivatives of the homogeneous curve C^w = (A, w): Eq. 1.9 says the derivative of a degree-n Bézier
    // curve is the degree n-1 Bézier curve on n (P_{i+1} - P_i); apply it k times and evaluate by A1.5.
    // Above degree n the homogeneous derivatives vanish (the rational ones, in general, do not).
    std::vector<Vec4> homogeneous(count);
    std::vector<Vec4> differences = pw_;
    double factor = 1.0;  // n (n-1) ... (n-k+1)
    for (std::size_t k = 0; k < count && !differences.empty(); ++k) {
        homogeneous[k] = factor * de_casteljau(differences, u);
        factor *= static_cast<double>(differences.size() - 1);
        for (std::size_t i = 0; i + 1 < differences.size(); ++i) differences[i] = differences[i + 1] - differences[i];
        differences.pop_back();
    }

    // Quotient rule on A = w C (A4.2): A^(k) = sum_i C(k,i) w^(i) C^(k-i), solved for C^(k).
    // w > 0 on [0,1] because all w_i > 0.
    std::vector<Vec3> result(count);
    detail::rational_curve_derivatives(homogeneous, result);
    detail::require_finite_derivatives(result, u);
    return result;
}

Vec3 BezierCurve::derivative(double u, int order) const { return derivatives(u, order).back(); }

std::pair<BezierCurve, BezierCurve> BezierCurve::split(double u) const {
    require(std::isfinite(u) && u > 0.0 && u < 1.0, "u",
            [&] { return "the split parameter must lie strictly inside (0, 1), got " + exact_number(u); });
    // deCasteljau subdivision: the left half's control points run down the top edge of the triangle
    // (P^w_{k,0}), the right half's up its bottom edge (P^w_{n-k,k}).
    const auto table = de_casteljau_table(u);
    const std::size_t n = pw_.size() - 1;
    std::vector<Vec4> left(n + 1), right(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        left[k] = table[k][0];
        right[k] = table[n - k][k];
    }
    return {BezierCurve(std::move(left), rational_, weight_exponent_),
            BezierCurve(std::move(right), rational_, weight_exponent_)};
}

BezierCurve BezierCurve::elevate() const {
    require(degree() < limits::max_degree, "curve", [&] {
        return "elevating degree " + std::to_string(degree()) + " would give " + std::to_string(degree() + 1) +
               ", above the degree limit " + std::to_string(limits::max_degree);
    });
    // Degree elevation on P^w: Q_i = (i/(n+1)) P_{i-1} + (1 - i/(n+1)) P_i, i = 0..n+1 (both end points kept).
    const std::size_t n = pw_.size() - 1;
    std::vector<Vec4> elevated(n + 2);
    elevated.front() = pw_.front();
    elevated.back() = pw_.back();
    for (std::size_t i = 1; i <= n; ++i) {
        const double alpha = static_cast<double>(i) / static_cast<double>(n + 1);
        elevated[i] = lerp(pw_[i], pw_[i - 1], alpha);
    }
    return BezierCurve(std::move(elevated), rational_, weight_exponent_);
}

BezierCurve BezierCurve::reversed() const {
    // Exercise 1.11: B_{i,n}(1-u) = B_{n-i,n}(u) (symmetry P1.5), so reversing the control points (and their
    // weights with them) gives C_2(u) = C_1(1-u).
    std::vector<Vec4> backwards(pw_.rbegin(), pw_.rend());
    return BezierCurve(std::move(backwards), rational_, weight_exponent_);
}

BezierCurve BezierCurve::normal_form() const {
    // With t = rho s / D, 1 - t = (1 - s) / D and D = (1 - s) + rho s, every Bernstein polynomial becomes
    // B_{i,n}(t) = rho^i B_{i,n}(s) / D^n. The common factor 1 / D^n cancels between the numerator and
    // the denominator of the rational curve, so C(t(s)) is the curve with the same points and weights
    // w_i rho^i. Dividing by w_0 leaves w_0 = 1 and w_n = w_n rho^n / w_0 = 1. The factors are taken
    // through logarithms so that weights such as 1e-300 and 1e300 do not overflow on the way.
    const std::size_t n = pw_.size() - 1;
    if (!rational_ || n == 0) return *this;
    const double log_first = std::log(pw_.front().w);
    const double log_rho = (log_first - std::log(pw_.back().w)) / static_cast<double>(n);
    std::vector<Vec4> normal(pw_.size());
    for (std::size_t i = 0; i <= n; ++i) {
        const double factor = std::exp(static_cast<double>(i) * log_rho - log_first);
        normal[i] = pw_[i] * factor;
        if (!(normal[i].w > 0) || !std::isfinite(normal[i].w) || !std::isfinite(normal[i].x) ||
            !std::isfinite(normal[i].y) || !std::isfinite(normal[i].z))
            return *this;
    }
    // The end points exactly as before (C(0) = H(P^w_0) is one division either way), whatever the rounding.
    for (const std::size_t end : {std::size_t{0}, n}) normal[end] = homogenize(project(pw_[end]), 1.0);
    return BezierCurve(std::move(normal), true, 0);
}

}  // namespace ratbez
