// Least-squares curve approximation within a tolerance (The NURBS Book §9.4.1); see approximation.hpp.
#include "ratbez/approximation.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/interpolation.hpp"
#include "math/banded_system.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/interpolation.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace {

using detail::to_size;

// The clamped knot vector for n + 1 control points fitted to data at parameters t_0..t_m (Eq. 9.68–9.69):
// every knot span holds at least one parameter, so N^T N is positive definite.
std::vector<double> fitting_knots(const std::vector<double>& t, int n, int p) {
    const int m = static_cast<int>(t.size()) - 1;
    const double d = static_cast<double>(m + 1) / (n - p + 1);
    std::vector<double> knots(to_size(p + 1), 0.0);
    for (int j = 1; j <= n - p; ++j) {
        const int i = static_cast<int>(j * d);
        const double alpha = j * d - i;
        knots.push_back((1 - alpha) * t[to_size(i - 1)] + alpha * t[to_size(i)]);
    }
    knots.insert(knots.end(), to_size(p + 1), 1.0);
    return knots;
}

// The least-squares curve with n + 1 control points through Q_0 and Q_m (Eq. 9.63–9.67).
NurbsCurve fit(const std::vector<Vec3>& q, const std::vector<double>& t, int n, int p) {
    const int m = static_cast<int>(q.size()) - 1;
    if (n == m) return interpolate(q, p);  // A9.1: the same parameters (Eq. 9.5) and knots (Eq. 9.8)
    std::vector<double> knots = fitting_knots(t, n, p);
    std::vector<Vec3> control(to_size(n + 1));
    control.front() = q.front();
    control.back() = q.back();
    const int unknowns = n - 1;  // P_1 .. P_{n-1}
    if (unknowns > 0) {
        detail::BandedMatrix normal(to_size(unknowns), to_size(p), to_size(p));
        std::vector<Vec3> rhs(to_size(unknowns));
        std::vector<double> basis(to_size(p + 1));
        for (int k = 1; k < m; ++k) {
            const int span = find_span(p, knots, t[to_size(k)]);
            basis_functions(span, t[to_size(k)], p, knots, basis);
            // R_k = Q_k - N_0(t_k) Q_0 - N_n(t_k) Q_m (Eq. 9.63), spread over the unknowns it touches.
            Vec3 r = q[to_size(k)];
            for (int j = 0; j <= p; ++j) {
                const int i = span - p + j;
                if (i == 0) r -= basis[to_size(j)] * q.front();
                if (i == n) r -= basis[to_size(j)] * q.back();
            }
            for (int a = 0; a <= p; ++a) {
                const int i = span - p + a;
                if (i < 1 || i > n - 1) continue;
                rhs[to_size(i - 1)] += basis[to_size(a)] * r;
                for (int b = 0; b <= p; ++b) {
                    const int j = span - p + b;
                    if (j < 1 || j > n - 1) continue;
                    normal.at(to_size(i - 1), to_size(j - 1)) += basis[to_size(a)] * basis[to_size(b)];
                }
            }
        }
        require(normal.factor(), "points", "the least-squares system is singular (parameters too close together)");
        normal.solve(rhs);
        std::copy(rhs.begin(), rhs.end(), control.begin() + 1);
    }
    return NurbsCurve(p, std::move(knots), std::move(control));
}

double max_error(const NurbsCurve& curve, const std::vector<Vec3>& q, const std::vector<double>& t) {
    double worst = 0;
    for (std::size_t k = 0; k < q.size(); ++k) worst = std::max(worst, distance(curve.point(t[k]), q[k]));
    return worst;
}

void require_fit_degree(int degree, std::size_t points) {
    require(degree >= 1, "degree", [&] { return "must be >= 1, got " + std::to_string(degree); });
    limits::require_degree(degree, "degree");
    require(points >= to_size(degree) + 1, "points", [&] {
        return "a degree-" + std::to_string(degree) + " fit needs at least " + std::to_string(degree + 1) +
               " points, got " + std::to_string(points) + " (lower the degree for fewer points)";
    });
}

}  // namespace

NurbsCurve least_squares_fit(const std::vector<Vec3>& points, int control_points, int degree) {
    const std::vector<double> t = interpolation_parameters(points);  // validates the points
    require_fit_degree(degree, points.size());
    require(control_points >= degree + 1 && to_size(control_points) <= points.size(), "control_points", [&] {
        return "must be from " + std::to_string(degree + 1) + " to " + std::to_string(points.size()) + ", got " +
               std::to_string(control_points);
    });
    return fit(points, t, control_points - 1, degree);
}

NurbsCurve approximate(const std::vector<Vec3>& points, double tolerance, int degree) {
    require(std::isfinite(tolerance) && tolerance > 0, "tolerance", [&] {
        return "must be a finite number > 0, got " + detail::number(tolerance);
    });
    const std::vector<double> t = interpolation_parameters(points);
    require_fit_degree(degree, points.size());
    const int p = degree, m = static_cast<int>(points.size()) - 1;
    // Bisection on n: `low` misses the tolerance, `high` meets it (n = m interpolates, error 0).
    int low = p, high = m;
    NurbsCurve best = fit(points, t, low, p);
    if (max_error(best, points, t) <= tolerance) return best;
    best = fit(points, t, high, p);
    while (high - low > 1) {
        const int mid = low + (high - low) / 2;
        NurbsCurve candidate = fit(points, t, mid, p);
        if (max_error(candidate, points, t) <= tolerance) {
            high = mid;
            best = std::move(candidate);
        } else {
            low = mid;
        }
    }
    return best;
}

}  // namespace ratbez
