// NURBS curves C(u) = H{ sum_i N_{i,p}(u) P^w_i } (001; the standard NURBS algorithms cited inline).
// Every algorithm runs on the homogeneous points P^w, so a rational curve costs the same as a polynomial
// one until the final projection H (Eq. 1.16) or the quotient rule for derivatives (A4.2).

#include "ratbez/nurbs_curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "math/numeric_internal.hpp"
#include "math/rational_derivatives.hpp"
#include "math/weights_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {
namespace {

using detail::number;
using detail::to_size;

// Basis values on the stack for degree <= 31, on the heap beyond (written by basis_functions before read).
using BasisScratch = detail::Scratch<double, 32>;

void require_weight(double w, std::size_t index, const std::string& argument) {
    require(std::isfinite(w) && w > 0.0, argument, [&] {
        return "weight " + std::to_string(index) + " is " + number(w) + "; weights must be finite and > 0";
    });
}

// A polynomial curve keeps w = 1 exactly: the convex combinations of knot insertion would otherwise leave
// weights like 0.9999999999999999 behind and make a polynomial curve look rational downstream.
void reset_polynomial_weights(std::vector<Vec4>& pw) {
    for (Vec4& p : pw) p.w = 1.0;
}

// A5.1 (CurveKnotIns, Boehm): insert u `times` times into (knots, pw) in place. The caller has checked
// that u lies in the domain and that its multiplicity s satisfies s + times <= p, so u < u_m, and the
// span k below is the half-open one with u_k <= u < u_{k+1} (for u = u_{m-p} of an unclamped vector
// that is a span past the domain, which is what the algorithm's index arithmetic requires).
void insert_knot_in_place(int degree, std::vector<double>& knots, std::vector<Vec4>& pw, double u, int times) {
    if (times <= 0) return;
    const int p = degree;
    const int k = static_cast<int>(std::upper_bound(knots.begin(), knots.end(), u) - knots.begin()) - 1;
    const int s = static_cast<int>(std::count(knots.begin(), knots.end(), u));
    const int r = times;
    const int n = static_cast<int>(pw.size()) - 1;

    std::vector<double> new_knots(knots.size() + to_size(r));
    std::copy(knots.begin(), knots.begin() + k + 1, new_knots.begin());
    std::fill(new_knots.begin() + k + 1, new_knots.begin() + k + 1 + r, u);
    std::copy(knots.begin() + k + 1, knots.end(), new_knots.begin() + k + 1 + r);

    std::vector<Vec4> q(pw.size() + to_size(r));
    for (int i = 0; i <= k - p; ++i) q[to_size(i)] = pw[to_size(i)];
    for (int i = k - s; i <= n; ++i) q[to_size(i + r)] = pw[to_size(i)];
    std::vector<Vec4> affected(to_size(p - s + 1));
    for (int i = 0; i <= p - s; ++i) affected[to_size(i)] = pw[to_size(k - p + i)];
    int left = k - p;
    for (int j = 1; j <= r; ++j) {
        left = k - p + j;
        for (int i = 0; i <= p - j - s; ++i) {
            // u_{i+k+1} >= u_{k+1} > u >= u_{left+i}: the denominator is positive.
            const double alpha = (u - knots[to_size(left + i)]) /
                                 (knots[to_size(i + k + 1)] - knots[to_size(left + i)]);
            affected[to_size(i)] = alpha * affected[to_size(i + 1)] + (1.0 - alpha) * affected[to_size(i)];
        }
        q[to_size(left)] = affected[0];
        q[to_size(k + r - j - s)] = affected[to_size(p - j - s)];
    }
    for (int i = left + 1; i < k - s; ++i) q[to_size(i)] = affected[to_size(i - left)];

    knots = std::move(new_knots);
    pw = std::move(q);
}

}  // namespace

NurbsCurve::NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec4> homogeneous_points, bool rational,
                       int weight_exponent)
    : ControlPolygon(std::move(homogeneous_points), rational, weight_exponent), degree_(degree), knots_(std::move(knots)) {}

namespace {

// The checks shared by the two public constructors; `weights` is null for a polynomial curve. The sizes
// first (cheap, and before any work grows with them), then the values.
std::vector<Vec4> validated_homogeneous_points(int degree, const std::vector<double>& knots,
                                               const std::vector<Vec3>& points, const std::vector<double>* weights,
                                               int& weight_exponent) {
    limits::require_degree(degree, "degree");
    require(!points.empty(), "points", "a NURBS curve needs at least one control point");
    limits::require_curve_points(points.size(), "points");
    for (std::size_t i = 0; i < points.size(); ++i)
        require(is_finite(points[i]), "points",
                [&] { return "control point " + std::to_string(i) + " has a non-finite coordinate"; });
    if (weights != nullptr) {
        require(weights->size() == points.size(), "weights", [&] {
            return "has " + std::to_string(weights->size()) + " entries for " + std::to_string(points.size()) +
                   " control points";
        });
        for (std::size_t i = 0; i < weights->size(); ++i) require_weight((*weights)[i], i, "weights");
    }
    require(points.size() >= to_size(degree) + 1, "points", [&] {
        return "a degree-" + std::to_string(degree) + " curve needs at least " + std::to_string(to_size(degree) + 1) +
               " control points, got " + std::to_string(points.size());
    });
    validate_knot_vector(degree, knots, static_cast<int>(points.size()), "knots");
    weight_exponent = weights ? detail::weight_scale_exponent_of(*weights, detail::products_finite(points, *weights)) : 0;
    std::vector<Vec4> pw(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        pw[i] = homogenize(points[i], weights ? std::ldexp((*weights)[i], weight_exponent) : 1.0);
    return pw;
}

}  // namespace

NurbsCurve::NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> points) : degree_(degree) {
    rational_ = false;
    pw_ = validated_homogeneous_points(degree, knots, points, nullptr, weight_exponent_);
    knots_ = std::move(knots);
}

NurbsCurve::NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> points, std::vector<double> weights)
    : degree_(degree) {
    rational_ = true;
    pw_ = validated_homogeneous_points(degree, knots, points, &weights, weight_exponent_);
    knots_ = std::move(knots);
}

NurbsCurve NurbsCurve::from_homogeneous(int degree, std::vector<double> knots, std::vector<Vec4> homogeneous_points,
                                        bool rational) {
    limits::require_degree(degree, "degree");
    require(!homogeneous_points.empty(), "homogeneous_points", "a NURBS curve needs at least one control point");
    limits::require_curve_points(homogeneous_points.size(), "homogeneous_points");
    for (std::size_t i = 0; i < homogeneous_points.size(); ++i) {
        Vec4& p = homogeneous_points[i];
        require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "homogeneous_points",
                [&] { return "control point " + std::to_string(i) + " has a non-finite coordinate"; });
        require_weight(p.w, i, "homogeneous_points");
        if (!rational) {
            // Not rational means every weight is 1; anything else would be silently a different curve.
            require(std::abs(p.w - 1.0) <= 1e-12, "homogeneous_points", [&] {
                return "weight " + std::to_string(i) + " is " + number(p.w) +
                       ", but a non-rational curve has weights 1";
            });
            p = homogenize(project(p), 1.0);
        }
    }
    require(homogeneous_points.size() >= to_size(degree) + 1, "homogeneous_points", [&] {
        return "a degree-" + std::to_string(degree) + " curve needs at least " + std::to_string(to_size(degree) + 1) +
               " control points, got " + std::to_string(homogeneous_points.size());
    });
    validate_knot_vector(degree, knots, static_cast<int>(homogeneous_points.size()), "knots");
    std::vector<double> weights(homogeneous_points.size());
    for (std::size_t i = 0; i < weights.size(); ++i) weights[i] = homogeneous_points[i].w;
    const int exponent = detail::weight_scale_exponent_of(weights);
    detail::scale_homogeneous(homogeneous_points, exponent);
    return NurbsCurve(degree, std::move(knots), std::move(homogeneous_points), rational, exponent);
}

NurbsCurve NurbsCurve::from_bezier(const BezierCurve& curve) {
    // 001: the Bézier curve of degree n is the B-spline on {0 (n+1 times), 1 (n+1 times)}.
    const int n = curve.degree();
    std::vector<double> knots(2 * to_size(n + 1), 0.0);
    std::fill(knots.begin() + n + 1, knots.end(), 1.0);
    return NurbsCurve(n, std::move(knots), curve.homogeneous_points(), curve.is_rational(), curve.weight_exponent_);
}

Interval NurbsCurve::domain() const { return knot_domain(degree_, knots_); }

Box NurbsCurve::control_box() const {
    Box box;
    for (const Vec4& p : pw_) box.add(project(p));
    return box;
}

Vec4 NurbsCurve::homogeneous_point(double u) const {
    // A3.1 on P^w: the p + 1 non-vanishing basis functions of the span (A2.1, A2.2) times P^w.
    const int span = find_span(degree_, knots_, u);  // validates u against the domain
    BasisScratch scratch(to_size(degree_) + 1);
    const std::span<double> basis = scratch.values();
    basis_functions(span, u, degree_, knots_, basis);
    Vec4 sum;
    const std::size_t first = to_size(span - degree_);
    for (std::size_t j = 0; j < basis.size(); ++j) sum += basis[j] * pw_[first + j];
    return sum;
}

Vec3 NurbsCurve::point(double u) const {
    // A4.1: A3.1 in homogeneous space, then the projection H. A polynomial curve skips H: its w is a sum of
    // basis functions, 1 only up to rounding, and dividing by it would perturb every coordinate.
    const Vec4 cw = homogeneous_point(u);
    return detail::require_finite_point(rational_ ? project(cw) : weighted_part(cw), u);
}

std::vector<Vec3> NurbsCurve::derivatives(double u, int order) const {
    limits::require_derivative_order(order, "order");
    std::vector<Vec3> result(to_size(order) + 1);
    derivatives(u, result);
    return result;
}

void NurbsCurve::derivatives(double u, std::span<Vec3> out) const {
    require(!out.empty(), "out", "must hold at least C(u)");
    const int order = static_cast<int>(out.size()) - 1;
    limits::require_derivative_order(order, "order");
    const int span = find_span(degree_, knots_, u);  // validates u against the domain
    const int highest = std::min(order, degree_);    // derivatives of C^w above p vanish
    const std::size_t width = to_size(degree_) + 1;
    // On the stack up to the orders and degrees inner loops ask (Newton's: order 2, cubic and below).
    detail::Scratch<double, 32> ders(to_size(highest + 1) * width);
    basis_function_derivatives(span, u, degree_, knots_, highest, ders.values());

    // A3.2 on P^w: CK^w[k] = sum_j N^(k)_{span-p+j,p}(u) P^w_{span-p+j}.
    detail::Scratch<Vec4, 8> ckw(out.size());
    for (std::size_t k = 0; k < out.size(); ++k) ckw[k] = Vec4{};
    const std::size_t first = to_size(span - degree_);
    for (std::size_t k = 0; k <= to_size(highest); ++k)
        for (std::size_t j = 0; j < width; ++j) ckw[k] += ders[k * width + j] * pw_[first + j];

    if (!rational_) {
        // w = 1 identically: C^(k) = A^(k) with no quotient to form.
        for (std::size_t k = 0; k < out.size(); ++k) out[k] = weighted_part(ckw[k]);
    } else {
        detail::rational_curve_derivatives(ckw.values(), out);  // A4.2
    }
    // Finite control points and knots can still give derivatives past the double range (the k-th one
    // scales like 1 / (knot span)^k: a span of 1e-300 overflows the second): an Error, not inf or NaN.
    detail::require_finite_derivatives(out, u);
}

Vec3 NurbsCurve::derivative(double u, int order) const {
    require(order >= 0, "order", [&] { return "the derivative order must be >= 0, got " + std::to_string(order); });
    return derivatives(u, order)[to_size(order)];
}

NurbsCurve NurbsCurve::insert_knot(double u, int times) const {
    require(times >= 0, "times", [&] { return "must be >= 0, got " + std::to_string(times); });
    const Interval d = domain();
    require_in_domain(u, d.min, d.max, "u");
    if (times == 0) return *this;  // even at a clamped end, whose multiplicity p + 1 exceeds the degree
    const int multiplicity = static_cast<int>(std::count(knots_.begin(), knots_.end(), u));
    require(times <= degree_ - multiplicity, "times", [&] {
        return "inserting u = " + number(u) + " (" + std::to_string(times) +
               " more times) would raise its multiplicity from " + std::to_string(multiplicity) + " to " +
               std::to_string(static_cast<long long>(multiplicity) + times) + ", more than the degree " + std::to_string(degree_);
    });
    std::vector<double> knots = knots_;
    std::vector<Vec4> pw = pw_;
    insert_knot_in_place(degree_, knots, pw, u, times);
    if (!rational_) reset_polynomial_weights(pw);
    return NurbsCurve(degree_, std::move(knots), std::move(pw), rational_, weight_exponent_);
}

std::vector<BezierCurve> NurbsCurve::bezier_segments() const {
    const int p = degree_;
    // The segments keep the curve's weight scale (the private constructor, no re-scaling): callers join the
    // homogeneous points of neighbouring segments (NurbsSurface::bezier_patches builds patches from the
    // segments of every column), which from_homogeneous's own scaling of each would make inconsistent.
    if (p == 0) return {BezierCurve({pw_.front()}, rational_, weight_exponent_)};  // one constant span

    // 1. Clamp: raise the domain ends to multiplicity p by A5.1 (a no-op for a clamped vector), drop the
    //    knots and control points outside the domain, and set the outermost knots to the ends. The first
    //    and last knots never influence the curve on its domain, so this is the same curve on a clamped
    //    vector, which is what A5.6 needs.
    std::vector<double> knots = knots_;
    std::vector<Vec4> pw = pw_;
    const Interval d = domain();
    for (const double end : {d.min, d.max}) {
        const int multiplicity = static_cast<int>(std::count(knots.begin(), knots.end(), end));
        if (multiplicity < p) insert_knot_in_place(p, knots, pw, end, p - multiplicity);
    }
    const std::size_t last_of_min = to_size(std::upper_bound(knots.begin(), knots.end(), d.min) - knots.begin()) - 1;
    const std::size_t first_of_max = to_size(std::lower_bound(knots.begin(), knots.end(), d.max) - knots.begin());
    const std::size_t start = last_of_min - to_size(p);  // last_of_min >= p because u_p = d.min
    std::vector<double> u(knots.begin() + static_cast<std::ptrdiff_t>(start),
                          knots.begin() + static_cast<std::ptrdiff_t>(first_of_max + to_size(p) + 1));
    u.front() = d.min;
    u.back() = d.max;
    const std::vector<Vec4> clamped_points(pw.begin() + static_cast<std::ptrdiff_t>(start),
                                           pw.begin() + static_cast<std::ptrdiff_t>(first_of_max));

    // 2. A5.6 (DecomposeCurve): sweep the interior break points left to right, inserting each until its
    //    multiplicity is p; the points of every finished segment are final, the overlap seeds the next.
    const std::size_t m = u.size() - 1;
    const std::size_t degree = to_size(p);
    std::vector<std::vector<Vec4>> segments(1, std::vector<Vec4>(degree + 1));
    std::copy(clamped_points.begin(), clamped_points.begin() + p + 1, segments[0].begin());
    std::vector<double> alphas(degree);
    std::size_t a = degree, b = degree + 1, nb = 0;
    while (b < m) {
        const std::size_t run_start = b;
        while (b < m && u[b + 1] == u[b]) ++b;
        const std::size_t multiplicity = b - run_start + 1;
        if (b < m && segments.size() < nb + 2) segments.emplace_back(degree + 1);
        if (multiplicity < degree) {
            const double numerator = u[b] - u[a];
            // u[a + j] >= u[a + 1] > u[a]: a is the last index of the previous break point.
            for (std::size_t j = degree; j > multiplicity; --j) alphas[j - multiplicity - 1] = numerator / (u[a + j] - u[a]);
            const std::size_t r = degree - multiplicity;
            for (std::size_t j = 1; j <= r; ++j) {
                const std::size_t save = r - j;
                const std::size_t s = multiplicity + j;
                for (std::size_t k = degree; k >= s; --k) {
                    const double alpha = alphas[k - s];
                    segments[nb][k] = alpha * segments[nb][k] + (1.0 - alpha) * segments[nb][k - 1];
                }
                if (b < m) segments[nb + 1][save] = segments[nb][degree];
            }
        }
        ++nb;
        if (b < m) {
            for (std::size_t i = degree - std::min(multiplicity, degree); i <= degree; ++i)
                segments[nb][i] = clamped_points[b - degree + i];
            a = b;
            ++b;
        }
    }

    std::vector<BezierCurve> result;
    result.reserve(segments.size());
    for (std::vector<Vec4>& points : segments) {
        if (!rational_) reset_polynomial_weights(points);
        result.push_back(BezierCurve(std::move(points), rational_, weight_exponent_));
    }
    return result;
}

NurbsCurve NurbsCurve::reversed() const {
    // C_r(u) = C(a + b - u) on the mirrored knot vector u'_i = a + b - u_{m-i} with reversed points. The
    // domain ends map to each other exactly (rounding in a + b - u could move them by an ulp).
    const Interval d = domain();
    const std::size_t m = knots_.size() - 1;
    std::vector<double> knots(knots_.size());
    for (std::size_t i = 0; i <= m; ++i) {
        const double t = knots_[m - i];
        knots[i] = t == d.max ? d.min : t == d.min ? d.max : (d.min + d.max) - t;
    }
    std::vector<Vec4> pw(pw_.rbegin(), pw_.rend());
    return NurbsCurve(degree_, std::move(knots), std::move(pw), rational_, weight_exponent_);
}

NurbsCurve NurbsCurve::reparameterized(double a, double b) const {
    require_finite(a, "a");
    require_finite(b, "b");
    require(a < b, "b", [&] { return "the new domain [" + number(a) + ", " + number(b) + "] must have a < b"; });
    require(std::isfinite(b - a), "b",
            [&] { return "the new domain [" + number(a) + ", " + number(b) + "] is too long"; });
    // The affine map of the knots u -> a + (u - u_p) (b - a) / (u_{m-p} - u_p); the control points stay.
    const Interval d = domain();
    const double scale = (b - a) / (d.max - d.min);
    std::vector<double> knots(knots_.size());
    for (std::size_t i = 0; i < knots.size(); ++i) {
        const double t = knots_[i];
        knots[i] = t == d.min ? a : t == d.max ? b : a + (t - d.min) * scale;
    }
    // A very short or very long target domain can merge or overflow knots: refuse rather than change the curve.
    validate_knot_vector(degree_, knots, static_cast<int>(pw_.size()), "b");
    return NurbsCurve(degree_, std::move(knots), pw_, rational_, weight_exponent_);
}

NurbsCurve NurbsCurve::normal_form() const {
    if (!rational_ || degree_ == 0) return *this;
    // The span breaks: the distinct knots of the domain, one more than there are Bézier segments.
    const Interval d = domain();
    std::vector<double> breaks;
    for (const double u : knots_)
        if (u >= d.min && u <= d.max && (breaks.empty() || breaks.back() != u)) breaks.push_back(u);
    const std::vector<BezierCurve> segments = bezier_segments();
    const std::size_t p = to_size(degree_);
    std::vector<double> knots(p + 1, d.min);
    std::vector<Vec4> pw;
    pw.reserve(segments.size() * p + 1);
    for (std::size_t s = 0; s < segments.size(); ++s) {
        // Neighbouring spans share their joint's control point; in normal form both give it weight 1.
        const BezierCurve normal = segments[s].normal_form();
        const std::vector<Vec4>& points = normal.homogeneous_points();
        if (points.front().w != 1 || points.back().w != 1) return *this;  // weights beyond double range
        pw.insert(pw.end(), points.begin() + (s == 0 ? 0 : 1), points.end());
        knots.insert(knots.end(), s + 1 < segments.size() ? p : p + 1, breaks[s + 1]);
    }
    return NurbsCurve(degree_, std::move(knots), std::move(pw), true, 0);
}

}  // namespace ratbez
