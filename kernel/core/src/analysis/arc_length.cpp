// Arc length by adaptive Gauss–Legendre quadrature on knot spans; see arc_length.hpp.
#include "ratbez/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "math/gauss_legendre.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

constexpr int kRulePoints = 16;
constexpr int kMaxHalvings = 30;

}  // namespace

// The speed |C'(u)| from the curve's rational Bézier segments, without allocating: de Casteljau (A1.5) on the
// homogeneous points to the last level's two points Q0, Q1 gives C^w = (1 - t) Q0 + t Q1 and its derivative
// p (Q1 - Q0), then the quotient rule (Eq. 1.28). The length's quadrature evaluates the speed some hundred
// thousand times for a section that a loft aligns (arc_length.hpp's users), where NurbsCurve::derivative's
// allocations were 60% of the time.
class ArcLength::Speed {
public:
    // Each segment is held relative to its first point (the speed does not see a translation): a short
    // segment far from the origin (a 0.002 mm edge at z = 1.6 in a STEP file) would otherwise lose its
    // differences to the coordinates' rounding, 3e-13 of its length, and the adaptive rule, asked for 1e-14,
    // would halve to its limit, 2^30 evaluations.
    explicit Speed(const NurbsCurve& curve)
        : degree_(curve.degree()), breaks_(breakpoints(curve.degree(), curve.knots())) {
        for (const BezierCurve& segment : curve.bezier_segments()) {
            const std::vector<Vec4>& pw = segment.homogeneous_points();
            const Vec3 origin = project(pw.front());
            for (const Vec4& p : pw) points_.push_back({p.x - origin.x * p.w, p.y - origin.y * p.w, p.z - origin.z * p.w, p.w});
        }
    }

    double operator()(double u) const {
        const auto k = static_cast<std::size_t>(
            std::clamp<std::ptrdiff_t>(std::upper_bound(breaks_.begin(), breaks_.end(), u) - breaks_.begin() - 1, 0,
                                       static_cast<std::ptrdiff_t>(breaks_.size()) - 2));
        const double a = breaks_[k], b = breaks_[k + 1], t = (u - a) / (b - a);
        const std::size_t n = static_cast<std::size_t>(degree_) + 1;
        if (degree_ == 0) return 0.0;
        // A fixed buffer for every degree the library holds (limits.hpp), the heap beyond.
        std::array<Vec4, limits::max_degree + 1> fixed;
        std::vector<Vec4> large;
        Vec4* q = fixed.data();
        if (n > fixed.size()) large.resize(n), q = large.data();
        std::copy_n(points_.begin() + static_cast<std::ptrdiff_t>(k * n), n, q);
        for (int level = degree_; level > 1; --level)
            for (int i = 0; i < level; ++i) q[i] = q[i] * (1 - t) + q[i + 1] * t;
        const Vec4 h = q[0] * (1 - t) + q[1] * t;
        const Vec4 dh = (q[1] - q[0]) * (static_cast<double>(degree_) / (b - a));
        const Vec3 c = project(h);
        return norm((weighted_part(dh) - c * dh.w) / h.w);
    }

private:
    int degree_;
    std::vector<double> breaks_;
    std::vector<Vec4> points_;  // (degree + 1) per segment
};

namespace {

double gauss(const ArcLength::Speed& speed, double a, double b) {
    const detail::GaussRule& rule = detail::gauss_legendre(kRulePoints);
    double sum = 0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * speed(a + rule.nodes[i] * (b - a));
    return sum * (b - a);
}

// The 16-point rule on [a, b] against the rule on its halves, halving where they differ by more than the
// part of the tolerance that [a, b] may use (Richardson would not help: the rule's error is not a power of
// the width for a non-polynomial integrand, but it falls geometrically).
double adaptive(const ArcLength::Speed& speed, double a, double b, double whole, double tolerance, int halvings_left) {
    const double m = 0.5 * (a + b);
    const double left = gauss(speed, a, m), right = gauss(speed, m, b);
    const double finer = left + right;
    // Below 1e-14 of the piece's own length the difference is rounding: halving further cannot help.
    if (std::abs(finer - whole) <= std::max(tolerance, 1e-14 * std::abs(finer)) || halvings_left == 0 || !(m > a && m < b))
        return finer;
    return adaptive(speed, a, m, left, 0.5 * tolerance, halvings_left - 1) +
           adaptive(speed, m, b, right, 0.5 * tolerance, halvings_left - 1);
}

}  // namespace

ArcLength::ArcLength(const NurbsCurve& curve)
    : curve_(curve), breaks_(breakpoints(curve.degree(), curve.knots())), speed_(std::make_shared<const Speed>(curve)) {
    double polygon = 0;
    const std::vector<Vec4>& pw = curve.homogeneous_points();
    for (std::size_t i = 1; i < pw.size(); ++i) polygon += distance(project(pw[i]), project(pw[i - 1]));
    tolerance_ = 1e-14 * polygon;
    detail::CompensatedSum sum;
    cumulative_.push_back(0.0);
    for (std::size_t k = 1; k < breaks_.size(); ++k) {
        sum.add(integral(breaks_[k - 1], breaks_[k]));
        cumulative_.push_back(sum.value());
    }
}

double ArcLength::integral(double a, double b) const {
    if (!(b > a)) return 0.0;
    return adaptive(*speed_, a, b, gauss(*speed_, a, b), tolerance_, kMaxHalvings);
}

double ArcLength::at(double u) const {
    require_in_domain(u, breaks_.front(), breaks_.back(), "u");
    return between(breaks_.front(), u);
}

double ArcLength::between(double u0, double u1) const {
    require_in_domain(u0, breaks_.front(), breaks_.back(), "u0");
    require_in_domain(u1, breaks_.front(), breaks_.back(), "u1");
    if (u1 < u0) return -between(u1, u0);
    auto span_of = [&](double u) {
        const auto k = static_cast<std::size_t>(std::upper_bound(breaks_.begin(), breaks_.end(), u) - breaks_.begin());
        return std::min(k, breaks_.size() - 1) - 1;
    };
    const std::size_t k0 = span_of(u0), k1 = span_of(u1);
    if (k0 == k1) return integral(u0, u1);
    // The partial spans at both ends, the whole ones between from the table.
    return integral(u0, breaks_[k0 + 1]) + (cumulative_[k1] - cumulative_[k0 + 1]) + integral(breaks_[k1], u1);
}

double ArcLength::parameter(double s) const {
    // A length from at() or between() may sum its spans in another order than total() and land an ulp past it.
    if (s > total() && s <= total() * (1 + 1e-12)) s = total();
    require(std::isfinite(s) && s >= 0 && s <= total(), "s", [&] {
        return "must be a length from 0 to the curve's length " + detail::number(total()) + ", got " + detail::number(s);
    });
    if (s == 0) return breaks_.front();
    if (s == total()) return breaks_.back();
    // The span where the length reaches s: cumulative_[k] < s <= cumulative_[k + 1].
    const std::size_t k = static_cast<std::size_t>(std::lower_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin()) - 1;
    double lo = breaks_[k], hi = breaks_[k + 1];
    const double target = s - cumulative_[k], span_length = cumulative_[k + 1] - cumulative_[k];
    if (!(span_length > 0)) return lo;
    // Newton on f(u) = L(lo_k, u) - target, f' = speed, from the linear guess; a step that leaves the
    // bracket [lo, hi] (where f changes sign) is replaced by bisection. f is carried along, each step adding
    // the length between the old and the new u (short: one rule usually suffices).
    const double a = lo;
    double u = lo + (hi - lo) * std::clamp(target / span_length, 0.0, 1.0);
    double f = integral(a, u) - target;
    for (int iteration = 0; iteration < 100; ++iteration) {
        if (std::abs(f) <= 4 * tolerance_ + 1e-15 * target) return u;
        if (f > 0) hi = u; else lo = u;
        const double v = (*speed_)(u);
        double next = v > 0 ? u - f / v : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (next == u || hi - lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi))) return next;
        f += next > u ? integral(u, next) : -integral(next, u);
        u = next;
    }
    return u;
}

double length(const NurbsCurve& curve) { return ArcLength(curve).total(); }

double length(const NurbsCurve& curve, double u0, double u1) {
    const Interval d = curve.domain();
    require_in_domain(u0, d.min, d.max, "u0");
    require_in_domain(u1, d.min, d.max, "u1");
    return ArcLength(curve).between(u0, u1);
}

double parameter_at_length(const NurbsCurve& curve, double s) { return ArcLength(curve).parameter(s); }

}  // namespace ratbez
