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
// The weights' spread (max / min) over which a piece is cut before the rule (the kernel's certificate,
// gprop_patches.cpp's kCertifiedWeightSpread), and how deep (the spread of doubles' range, halved each time).
constexpr double kMaxWeightSpread = 4;
constexpr int kMaxWeightHalvings = 2100;
// Beyond this spread of one segment's weights the speed where the curve nearly stands is rounding (the quotient of
// weights so far apart): measured against 50-digit quadrature on (0,0), (1,1), (2,0) with the middle weight w,
// 2e-16 relative at w = 1e9 and 1e10 (the rule's nodes placed from the nearer end of the span: Speed::rule), 4e-9 at
// 1e12 and 5000 times the length at 1e20 before that. Such a curve's length is an Error.
constexpr double kMaxLengthWeightSpread = 1e10;

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
    // And divided by a power of two near the segments' extent (scale()): a curve past 1e154 would square to
    // infinity in the speed's norm, and the rule, comparing infinities (NaN), halved to its limit for ever.
    explicit Speed(const NurbsCurve& curve)
        : degree_(curve.degree()), breaks_(breakpoints(curve.degree(), curve.knots())) {
        const std::vector<BezierCurve> segments = curve.bezier_segments();
        double extent = 0;
        for (const BezierCurve& segment : segments) {
            const Vec3 origin = project(segment.homogeneous_points().front());
            for (const Vec4& p : segment.homogeneous_points()) {
                const Vec3 r = project(p) - origin;
                extent = std::max({extent, std::abs(r.x), std::abs(r.y), std::abs(r.z)});
            }
        }
        if (extent > 0 && std::isfinite(extent)) scale_ = std::ldexp(1.0, std::ilogb(extent));
        for (const BezierCurve& segment : segments) {
            const std::vector<Vec4>& pw = segment.homogeneous_points();
            const Vec3 origin = project(pw.front());
            for (const Vec4& p : pw)
                points_.push_back({(p.x - origin.x * p.w) / scale_, (p.y - origin.y * p.w) / scale_,
                                   (p.z - origin.z * p.w) / scale_, p.w});
        }
    }

    // The curve's lengths are the speed's integrals times this.
    double scale() const { return scale_; }

    // The largest max w / min w among the segments' weights.
    double largest_weight_spread() const {
        const std::size_t n = static_cast<std::size_t>(degree_) + 1;
        double spread = 1;
        for (std::size_t k = 0; k + 1 < breaks_.size(); ++k) {
            const auto [low, high] = std::minmax_element(points_.begin() + static_cast<std::ptrdiff_t>(k * n),
                                                         points_.begin() + static_cast<std::ptrdiff_t>((k + 1) * n),
                                                         [](const Vec4& a, const Vec4& b) { return a.w < b.w; });
            spread = std::max(spread, high->w / low->w);
        }
        return spread;
    }

    // max w / min w of the weights of the piece over [a, b] of the span it lies in: de Casteljau on the weights.
    double weight_spread(double a, double b) const {
        const std::size_t k = span_of(0.5 * (a + b)), n = static_cast<std::size_t>(degree_) + 1;
        const double a0 = breaks_[k], width = breaks_[k + 1] - a0;
        std::vector<double> w(n), left, right;
        for (std::size_t i = 0; i < n; ++i) w[i] = points_[k * n + i].w;
        const double ta = (a - a0) / width, tb = (b - a0) / width;
        split(w, tb, left, right);                      // [0, tb] is left
        split(left, tb > 0 ? ta / tb : 0, w, right);    // [ta, tb] is right
        const auto [low, high] = std::minmax_element(right.begin(), right.end());
        return *high / *low;
    }

    double operator()(double u) const {
        const std::size_t k = span_of(u);
        const double a = breaks_[k], b = breaks_[k + 1], t = (u - a) / (b - a);
        return at(k, t, 1 - t);
    }

    // The rule on the piece [a, b] of one span with `points` nodes in [0, 1] and their weights. Each node is
    // placed by its distance from the nearer end of the span, not as a + node (b - a): near the far end the
    // parameters crowd (1 - 1e-9 keeps 7 digits of its distance from 1), and where the speed changes within 1/w
    // of that end (a middle weight w = 1e9) a node that far off was 1e-7 wrong: the rule never agreed with its
    // halves and halved a million times (3.9 s for one length).
    double rule(double a, double b, const std::vector<double>& nodes, const std::vector<double>& weights) const {
        const std::size_t k = span_of(0.5 * (a + b));
        const double start = breaks_[k], end = breaks_[k + 1], width = end - start;
        const bool from_end = 0.5 * (a + b) > 0.5 * (start + end);
        // Distances from the nearer end: exact (Sterbenz) where they are small, which is where it matters.
        const double da = from_end ? end - a : a - start, db = from_end ? end - b : b - start;
        double sum = 0;
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const double d = (da + nodes[i] * (db - da)) / width;
            sum += weights[i] * (from_end ? at(k, 1 - d, d) : at(k, d, 1 - d));
        }
        return sum * (b - a);
    }

private:
    // The speed at t of segment k, given with 1 - t (each as precise as the caller has it).
    double at(std::size_t k, double t, double one_minus_t) const {
        const double a = breaks_[k], b = breaks_[k + 1];
        const std::size_t n = static_cast<std::size_t>(degree_) + 1;
        if (degree_ == 0) return 0.0;
        // A fixed buffer for every degree the library holds (limits.hpp), the heap beyond.
        std::array<Vec4, limits::max_degree + 1> fixed;
        std::vector<Vec4> large;
        Vec4* q = fixed.data();
        if (n > fixed.size()) large.resize(n), q = large.data();
        std::copy_n(points_.begin() + static_cast<std::ptrdiff_t>(k * n), n, q);
        for (int level = degree_; level > 1; --level)
            for (int i = 0; i < level; ++i) q[i] = q[i] * one_minus_t + q[i + 1] * t;
        const Vec4 h = q[0] * one_minus_t + q[1] * t;
        const Vec4 dh = (q[1] - q[0]) * (static_cast<double>(degree_) / (b - a));
        const Vec3 c = project(h);
        return norm((weighted_part(dh) - c * dh.w) / h.w);
    }

    std::size_t span_of(double u) const {
        return static_cast<std::size_t>(
            std::clamp<std::ptrdiff_t>(std::upper_bound(breaks_.begin(), breaks_.end(), u) - breaks_.begin() - 1, 0,
                                       static_cast<std::ptrdiff_t>(breaks_.size()) - 2));
    }
    // Bézier coefficients split at t (A1.5's triangle): the left piece's and the right piece's.
    static void split(std::vector<double> c, double t, std::vector<double>& left, std::vector<double>& right) {
        const std::size_t n = c.size();
        left.resize(n);
        right.resize(n);
        for (std::size_t level = 0; level < n; ++level) {
            left[level] = c[0];
            right[n - 1 - level] = c[n - 1 - level];
            for (std::size_t i = 0; i + 1 < n - level; ++i) c[i] = c[i] * (1 - t) + c[i + 1] * t;
        }
    }

    int degree_;
    std::vector<double> breaks_;
    std::vector<Vec4> points_;  // (degree + 1) per segment
    double scale_ = 1;
};

namespace {

double gauss(const ArcLength::Speed& speed, double a, double b) {
    const detail::GaussRule& rule = detail::gauss_legendre(kRulePoints);
    return speed.rule(a, b, rule.nodes, rule.weights);
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

// [a, b] halved while the weights of its piece spread more than kMaxWeightSpread, then the adaptive rule on each
// piece. A rational span whose middle weight is 1e12 times its ends' runs its whole length within 1e-12 of its ends'
// parameters: the rule never sampled there and read 1.19 for 2.83 (0 for a weight of 1e20). Each halving near
// such an end divides the spread by about 2, so the pieces number about 2 log2 of it; a span of moderate weights
// (an arc's: 1.4) is not cut at all.
double integral_by_weights(const ArcLength::Speed& speed, double a, double b, double tolerance, int halvings_left) {
    const double m = 0.5 * (a + b);
    if (halvings_left == 0 || !(m > a && m < b) || speed.weight_spread(a, b) <= kMaxWeightSpread)
        return adaptive(speed, a, b, gauss(speed, a, b), tolerance, kMaxHalvings);
    // Each piece keeps the whole tolerance: halved with every cut, it fell below the rounding of the speed where the
    // curve nearly stands (its quotient of weights 1e7 apart) and the rule halved to its limit there.
    return integral_by_weights(speed, a, m, tolerance, halvings_left - 1) +
           integral_by_weights(speed, m, b, tolerance, halvings_left - 1);
}

}  // namespace

ArcLength::ArcLength(const NurbsCurve& curve)
    : curve_(curve), breaks_(breakpoints(curve.degree(), curve.knots())), speed_(std::make_shared<const Speed>(curve)) {
    scale_ = speed_->scale();
    require(speed_->largest_weight_spread() <= kMaxLengthWeightSpread, "curve", [&] {
        return "has weights " + detail::number(speed_->largest_weight_spread()) +
               " times apart within one span: its length cannot be computed to double precision beyond " +
               detail::number(kMaxLengthWeightSpread);
    });
    double polygon = 0;  // in the speed's scale, as everything below
    const std::vector<Vec4>& pw = curve.homogeneous_points();
    for (std::size_t i = 1; i < pw.size(); ++i) polygon += norm((project(pw[i]) - project(pw[i - 1])) / scale_);
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
    return integral_by_weights(*speed_, a, b, tolerance_, kMaxWeightHalvings);
}

double ArcLength::at(double u) const {
    require_in_domain(u, breaks_.front(), breaks_.back(), "u");
    return between(breaks_.front(), u);
}

double ArcLength::between(double u0, double u1) const {
    require_in_domain(u0, breaks_.front(), breaks_.back(), "u0");
    require_in_domain(u1, breaks_.front(), breaks_.back(), "u1");
    return scaled_between(u0, u1) * scale_;
}

double ArcLength::scaled_between(double u0, double u1) const {
    if (u1 < u0) return -scaled_between(u1, u0);
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
    s /= scale_;  // the tables' and the speed's scale
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
