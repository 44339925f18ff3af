// approximation.hpp: the least-squares fit (§9.4.1) meets its tolerance at every point with the fewest
// control points its bisection finds (one fewer misses it), interpolates the ends, and reproduces what it can.

#include "ratbez/approximation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nurbs_test_support.hpp"
#include "ratbez/interpolation.hpp"

namespace ratbez {
namespace {

constexpr double pi = std::numbers::pi;

double worst(const NurbsCurve& c, const std::vector<Vec3>& q) {
    const std::vector<double> t = interpolation_parameters(q);
    double e = 0;
    for (std::size_t k = 0; k < q.size(); ++k) e = std::max(e, distance(c.point(t[k]), q[k]));
    return e;
}

TEST(Approximate, MeetsTheToleranceWithTheFewestControlPoints) {
    std::vector<Vec3> q;
    for (int k = 0; k <= 400; ++k) {
        const double x = 4 * pi * k / 400;
        q.push_back({x, std::sin(x), 0.1 * std::cos(3 * x)});
    }
    for (const double tolerance : {1e-1, 1e-3, 1e-5}) {
        for (const int degree : {2, 3, 5}) {
            const NurbsCurve c = approximate(q, tolerance, degree);
            EXPECT_EQ(c.degree(), degree);
            EXPECT_LE(worst(c, q), tolerance);
            const int count = static_cast<int>(c.points().size());
            EXPECT_LT(count, 200) << tolerance << " " << degree;  // far fewer than the 401 points
            if (count > degree + 1) {
                EXPECT_GT(worst(least_squares_fit(q, count - 1, degree), q), tolerance) << tolerance << " " << degree;
            }
            EXPECT_EQ(c.points().front(), q.front());  // the ends interpolated (P_0 = Q_0, P_n = Q_m)
            EXPECT_EQ(c.points().back(), q.back());
        }
    }
}

TEST(Approximate, PointsOnACubicNeedFewControlPoints) {
    // Points on one cubic: a handful of control points fit them to 1e-3 (the chord-length parameters are
    // not the cubic's own, so 4 alone do not).
    auto cubic = [](double t) { return Vec3{t, t * t * (1 - t), 0}; };
    std::vector<Vec3> q;
    for (int k = 0; k <= 50; ++k) q.push_back(cubic(k / 50.0));
    const NurbsCurve c = approximate(q, 1e-3, 3);
    EXPECT_LE(static_cast<int>(c.points().size()), 8);
    EXPECT_LE(worst(c, q), 1e-3);
}

TEST(Approximate, ExactFitsAndErrors) {
    const std::vector<Vec3> q{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}};
    // With as many control points as points the fit interpolates (A9.1).
    const NurbsCurve fitted = least_squares_fit(q, 5, 3), interpolant = interpolate(q, 3);
    EXPECT_EQ(fitted.knots(), interpolant.knots());
    EXPECT_EQ(fitted.points(), interpolant.points());
    EXPECT_LE(worst(approximate(q, 1e-9, 3), q), 1e-9);
    EXPECT_ERROR_NAMING(approximate(q, 0.0), "tolerance");
    EXPECT_ERROR_NAMING(approximate(q, NAN), "tolerance");
    EXPECT_ERROR_NAMING(approximate(q, 1e-3, 0), "degree");
    EXPECT_ERROR_NAMING(approximate({{0, 0, 0}, {1, 0, 0}}, 1e-3, 3), "points");
    EXPECT_ERROR_NAMING(approximate({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, 1e-3, 3), "points");
    EXPECT_ERROR_NAMING(least_squares_fit(q, 3, 3), "control_points");
}

}  // namespace
}  // namespace ratbez
