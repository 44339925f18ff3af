// Curvature of curves and principal curvatures of surfaces; see curvature.hpp.
#include "ratbez/curvature.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/curve_shape.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"

namespace ratbez {

namespace {

// The highest derivative order the curve test looks at: enough for a vanishing first and second derivative.
constexpr int kHighestOrder = 6;

Vec3 normal_part(const Vec3& a, const Vec3& unit_direction) { return a - unit_direction * dot(a, unit_direction); }

double factorial(int n) {
    double f = 1;
    for (int i = 2; i <= n; ++i) f *= i;
    return f;
}

// The width of the knot span around u: the parameter scale of the curve's derivatives there.
double span_width(int degree, const std::vector<double>& knots, double u) {
    const std::vector<double> breaks = breakpoints(degree, knots);
    const auto above = std::upper_bound(breaks.begin(), breaks.end(), u);
    const std::size_t k = above == breaks.end() ? breaks.size() - 1 : static_cast<std::size_t>(above - breaks.begin());
    return breaks[k] - breaks[k - 1];
}

PrincipalCurvatures regular_curvatures(const NurbsSurface& surface, double u, double v, const Vec3& normal,
                                       bool* degenerate) {
    const std::vector<std::vector<Vec3>> d = surface.derivatives(u, v, 2);
    const Vec3 su = d[1][0], sv = d[0][1];
    const double e = dot(su, su), f = dot(su, sv), g = dot(sv, sv);
    const double det = e * g - f * f;
    *degenerate = !(det > 1e-20 * (e + g) * (e + g)) || e == 0;
    PrincipalCurvatures out;
    out.normal = normal;
    if (*degenerate) return out;
    const double l = dot(d[2][0], normal), m = dot(d[1][1], normal), n = dot(d[0][2], normal);
    // II in the orthonormal tangent basis (e1, e2): the parameter coordinates (a, b) of a tangent vector x
    // solve [E F; F G](a, b) = (x . S_u, x . S_v), and II(x, y) = L a a' + M (a b' + b a') + N b b'.
    const Vec3 e1 = su / std::sqrt(e), e2 = cross(normal, e1);
    auto coordinates = [&](const Vec3& x) {
        const double p = dot(x, su), q = dot(x, sv);
        return std::pair<double, double>{(g * p - f * q) / det, (e * q - f * p) / det};
    };
    const auto [a1, b1] = coordinates(e1);
    const auto [a2, b2] = coordinates(e2);
    const double b11 = l * a1 * a1 + 2 * m * a1 * b1 + n * b1 * b1;
    const double b12 = l * a1 * a2 + m * (a1 * b2 + b1 * a2) + n * b1 * b2;
    const double b22 = l * a2 * a2 + 2 * m * a2 * b2 + n * b2 * b2;
    // The symmetric 2x2 eigenproblem by one Jacobi rotation: theta puts the larger eigenvalue first.
    const double theta = 0.5 * std::atan2(2 * b12, b11 - b22);
    const double mean = 0.5 * (b11 + b22), radius = std::hypot(0.5 * (b11 - b22), b12);
    out.k1 = mean + radius;
    out.k2 = mean - radius;
    out.dir1 = e1 * std::cos(theta) + e2 * std::sin(theta);
    out.dir2 = cross(normal, out.dir1);
    return out;
}

}  // namespace

detail::CurveShape detail::curve_shape(const NurbsCurve& curve, double u, bool arriving) {
    const std::vector<Vec3> d = curve.derivatives(u, kHighestOrder);  // validates u
    const double h = span_width(curve.degree(), curve.knots(), u);
    const double floor = 1e-12 * curve.control_box().diagonal();
    auto at = [&](int order) { return d[static_cast<std::size_t>(order)]; };
    auto term = [&](const Vec3& derivative, int order) { return norm(derivative) * std::pow(h, order) / factorial(order); };
    CurveShape shape;
    int k = 1;
    while (k <= kHighestOrder && term(at(k), k) <= floor) ++k;
    if (k > kHighestOrder) return shape;  // the curve does not move near u: no direction, no bending
    // C(u + s) - C(u) ~ C^(k) s^k / k!: leaving, the curve moves along C^(k); arriving (s < 0) along
    // (-1)^(k+1) C^(k).
    const Vec3 direction = at(k) / norm(at(k));
    shape.tangent = arriving && k % 2 == 0 ? -direction : direction;
    int l = k + 1;
    while (l <= kHighestOrder && term(normal_part(at(l), direction), l) <= floor) ++l;
    // Locally (a s^k, b s^l): y = b (x / a)^(l / k), whose curvature at 0 is 0, 2 b / a^2 or infinite, and
    // which bends towards +y on both sides (s^l > 0 for l = 2k).
    if (l > kHighestOrder || l > 2 * k) return shape;
    const Vec3 bend = normal_part(at(l), direction);
    if (l < 2 * k) {
        shape.curvature = std::numeric_limits<double>::infinity();
        shape.curvature_vector = bend / norm(bend) * shape.curvature;
        return shape;
    }
    const double a = norm(at(k)) / factorial(k);
    const double b = norm(bend) / factorial(l);
    shape.curvature = 2 * b / (a * a);
    shape.curvature_vector = bend / norm(bend) * shape.curvature;
    return shape;
}

double curvature(const NurbsCurve& curve, double u) { return detail::curve_shape(curve, u, false).curvature; }

PrincipalCurvatures principal_curvatures(const NurbsSurface& surface, double u, double v) {
    const Vec3 normal = surface.normal(u, v);  // validates (u, v); the limit normal at a degenerate point
    bool degenerate = false;
    PrincipalCurvatures here = regular_curvatures(surface, u, v, normal, &degenerate);
    if (!degenerate) return here;
    // The limit from inside, by extrapolation along the line towards the domain's centre, where the
    // parameterisation is regular: k(t) = k0 + a t + b t^2 + O(t^3) sampled at t = d, 2d, 4d gives
    // k0 = (8 k(d) - 6 k(2d) + k(4d)) / 3. Closer samples would lose digits: near a pole the partials come
    // out of the quotient rule with rounding errors that grow like 1 / t^2 relative to them.
    const Interval du = surface.domain_u(), dv = surface.domain_v();
    const double cu = 0.5 * (du.min + du.max) - u, cv = 0.5 * (dv.min + dv.max) - v;
    constexpr double delta = 7e-4;
    PrincipalCurvatures samples[3];
    for (int i = 0; i < 3; ++i) {
        const double t = delta * (1 << i);  // d, 2d, 4d
        const double ui = u + t * cu, vi = v + t * cv;
        bool degenerate_here = false;
        samples[i] = regular_curvatures(surface, ui, vi, surface.normal(ui, vi), &degenerate_here);
        require(!degenerate_here, "(u, v)", "the surface has no tangent plane parameterisation near this point");
    }
    const PrincipalCurvatures& near = samples[0];
    PrincipalCurvatures limit = near;
    limit.k1 = (8 * samples[0].k1 - 6 * samples[1].k1 + samples[2].k1) / 3;
    limit.k2 = (8 * samples[0].k2 - 6 * samples[1].k2 + samples[2].k2) / 3;
    limit.normal = normal;
    // The directions of the nearby point, made tangent to the limit plane.
    limit.dir1 = normal_part(near.dir1, normal);
    limit.dir1 = limit.dir1 / norm(limit.dir1);
    limit.dir2 = cross(normal, limit.dir1);
    return limit;
}

}  // namespace ratbez
