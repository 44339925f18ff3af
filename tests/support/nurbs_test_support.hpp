#pragma once
// Test support for the B-spline / NURBS suites (bspline_basis, nurbs_curve, nurbs_surface): seeded random
// knot vectors with multiplicities (clamped and unclamped), random curves and surfaces.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"
#include "test_support.hpp"

namespace ratbez::test {

using Rng = std::mt19937_64;

inline double uniform(Rng& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
inline int uniform_int(Rng& rng, int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

// A valid knot vector for `degree` and `count` control points. Break points lie on a grid of 1/8 (spans of
// at least 1/8, so finite differences have room) starting at `origin`; every run has a random multiplicity
// 1..degree (ends p + 1 when clamped). Unclamped vectors whose domain comes out empty are drawn again.
inline std::vector<double> random_knots(Rng& rng, int degree, int count, bool clamped, double origin = 0.0) {
    const std::size_t total = static_cast<std::size_t>(count + degree + 1);
    for (;;) {
        std::vector<double> knots;
        double x = origin;
        const std::size_t body = clamped ? total - static_cast<std::size_t>(degree + 1) : total;
        if (clamped) knots.assign(static_cast<std::size_t>(degree + 1), x);
        bool first = true;
        while (knots.size() < body) {
            if (!first || clamped) x += uniform_int(rng, 1, 3) / 8.0;
            first = false;
            const std::size_t run = std::min<std::size_t>(static_cast<std::size_t>(uniform_int(rng, 1, std::max(degree, 1))),
                                                          body - knots.size());
            knots.insert(knots.end(), run, x);
        }
        if (clamped) {
            x += uniform_int(rng, 1, 3) / 8.0;
            knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), x);
        }
        try {
            validate_knot_vector(degree, knots, count);
            return knots;
        } catch (const Error&) {
            // empty domain or too high a multiplicity at a domain end: draw again
        }
    }
}

inline Vec3 random_point(Rng& rng) { return {uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2)}; }
inline double random_weight(Rng& rng) { return uniform(rng, 0.3, 3.0); }

inline NurbsCurve random_curve(Rng& rng, bool rational, bool clamped, int max_degree = 5) {
    const int degree = uniform_int(rng, 1, max_degree);
    const int count = degree + 1 + uniform_int(rng, 0, 6);
    std::vector<Vec3> points(static_cast<std::size_t>(count));
    for (Vec3& p : points) p = random_point(rng);
    std::vector<double> knots = random_knots(rng, degree, count, clamped, uniform_int(rng, -8, 8) / 4.0);
    if (!rational) return NurbsCurve(degree, std::move(knots), std::move(points));
    std::vector<double> weights(points.size());
    for (double& w : weights) w = random_weight(rng);
    return NurbsCurve(degree, std::move(knots), std::move(points), std::move(weights));
}

inline NurbsSurface random_surface(Rng& rng, bool rational, bool clamped, int max_degree = 5) {
    const int degree_u = uniform_int(rng, 1, max_degree), degree_v = uniform_int(rng, 1, max_degree);
    const int rows = degree_u + 1 + uniform_int(rng, 0, 4), columns = degree_v + 1 + uniform_int(rng, 0, 4);
    std::vector<std::vector<Vec3>> net(static_cast<std::size_t>(rows), std::vector<Vec3>(static_cast<std::size_t>(columns)));
    std::vector<std::vector<double>> weights(net.size(), std::vector<double>(net.front().size()));
    for (std::size_t i = 0; i < net.size(); ++i)
        for (std::size_t j = 0; j < net[i].size(); ++j) {
            net[i][j] = random_point(rng);
            weights[i][j] = random_weight(rng);
        }
    std::vector<double> knots_u = random_knots(rng, degree_u, rows, clamped, uniform_int(rng, -4, 4) / 4.0);
    std::vector<double> knots_v = random_knots(rng, degree_v, columns, clamped, uniform_int(rng, -4, 4) / 4.0);
    if (!rational) return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net));
    return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net), std::move(weights));
}

inline double random_parameter(Rng& rng, const Interval& domain) { return uniform(rng, domain.min, domain.max); }

// The distinct knot values inside the domain [u_p, u_{m-p}], the break points of the non-empty spans.
inline std::vector<double> break_points(int degree, const std::vector<double>& knots) {
    const Interval d = knot_domain(degree, knots);
    std::vector<double> result;
    for (double t : knots)
        if (t >= d.min && t <= d.max && (result.empty() || result.back() != t)) result.push_back(t);
    return result;
}

// A parameter inside a random non-empty span, at least 10% of the span away from its ends, together with
// that span: a point where the curve is analytic on both sides for finite differences.
struct InteriorParameter {
    double value, span_min, span_max;
};
inline InteriorParameter random_interior_parameter(Rng& rng, int degree, const std::vector<double>& knots) {
    const std::vector<double> breaks = break_points(degree, knots);
    const std::size_t span = static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(breaks.size()) - 2));
    const double a = breaks[span], b = breaks[span + 1];
    return {a + uniform(rng, 0.1, 0.9) * (b - a), a, b};
}

// The same point set at the same (affinely mapped) parameters, to `tolerance` of the original's control-box
// size: a representation changed (degree elevation, knot merging), never the curve.
inline void expect_same_curve(const NurbsCurve& original, const NurbsCurve& changed, double tolerance = 1e-12) {
    const Interval a = original.domain(), b = changed.domain();
    const double size = original.control_box().diagonal();
    for (int k = 0; k <= 200; ++k) {
        const double f = k / 200.0;
        ASSERT_LE(distance(original.point(a.min + f * a.width()), changed.point(k == 200 ? b.max : b.min + f * b.width())),
                  tolerance * size)
            << "at fraction " << f;
    }
}

}  // namespace ratbez::test
