#include "ratbez/bezier_curve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bezier_test_support.hpp"
#include "ratbez/bernstein.hpp"

namespace ratbez {
namespace {

using namespace test;

constexpr double kExact = 1e-14;

// The quarter circle of Ex1.12 / Ex1.13: P = (1,0), (1,1), (0,1), w = 1, 1, 2.
BezierCurve quarter_circle() { return BezierCurve({{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, 1, 2}); }

// ---------------------------------------------------------------------------------------------------------
// Worked examples and exercises of 000

TEST(BezierCurveExamples, Ex114PointAndEveryEntryOfTable14) {
    const BezierCurve arc = quarter_circle();
    // Ex1.13's homogeneous points (x, y, w) = (1,0,1), (1,1,1), (0,2,2), stored here as (wx, wy, wz, w).
    const auto& pw = arc.homogeneous_points();
    ASSERT_EQ(pw.size(), 3u);
    EXPECT_EQ(pw[0], (Vec4{1, 0, 0, 1}));
    EXPECT_EQ(pw[1], (Vec4{1, 1, 0, 1}));
    EXPECT_EQ(pw[2], (Vec4{0, 2, 0, 2}));

    // Table 1.4: (1,0,1) (1,1,1) (0,2,2) | (1,1/2,1) (1/2,3/2,3/2) | (3/4,1,5/4) = C^w(1/2).
    const auto table = arc.de_casteljau_table(0.5);
    ASSERT_EQ(table.size(), 3u);
    ASSERT_EQ(table[0].size(), 3u);
    ASSERT_EQ(table[1].size(), 2u);
    ASSERT_EQ(table[2].size(), 1u);
    expect_near(table[0][0], {1, 0, 0, 1}, kExact);
    expect_near(table[0][1], {1, 1, 0, 1}, kExact);
    expect_near(table[0][2], {0, 2, 0, 2}, kExact);
    expect_near(table[1][0], {1, 0.5, 0, 1}, kExact);
    expect_near(table[1][1], {0.5, 1.5, 0, 1.5}, kExact);
    expect_near(table[2][0], {0.75, 1, 0, 1.25}, kExact);

    // C(1/2) = H{(3/4, 1, 5/4)} = (3/5, 4/5) by A1.4, by Eq. 1.19, and through C^w.
    expect_near(arc.point(0.5), {0.6, 0.8, 0}, kExact);
    expect_near(arc.point_de_casteljau(0.5), {0.6, 0.8, 0}, kExact);
    expect_near(arc.homogeneous_point(0.5), {0.75, 1, 0, 1.25}, kExact);
}

TEST(BezierCurveExamples, Ex113ArcIsTheCircleOfEq12WithItsDerivatives) {
    // C(t) = ((1-t^2)/(1+t^2), 2t/(1+t^2)) of Eq. 1.2; derivatives worked by hand with f = 1/(1+t^2):
    //   x = 2f - 1: x' = -4t/(1+t^2)^2, x'' = (12t^2-4)/(1+t^2)^3, x''' = 48t(1-t^2)/(1+t^2)^4,
    //   y' = 2(1-t^2)/(1+t^2)^2, y'' = 4t(t^2-3)/(1+t^2)^3, y''' = 12(-t^4+6t^2-1)/(1+t^2)^4.
    // §1.1: C'(0) = (0, 2) and C'(1) = (-1, 0) — the starting speed is twice the ending speed.
    const BezierCurve arc = quarter_circle();
    expect_near(arc.derivative(0.0), {0, 2, 0}, kExact);
    expect_near(arc.derivative(1.0), {-1, 0, 0}, kExact);
    for (int q = 0; q <= 16; ++q) {
        const double t = q / 16.0;
        const double s = 1 + t * t;
        const auto d = arc.derivatives(t, 3);
        ASSERT_EQ(d.size(), 4u);
        expect_near(d[0], {(1 - t * t) / s, 2 * t / s, 0}, kExact);
        EXPECT_NEAR(d[0].x * d[0].x + d[0].y * d[0].y, 1.0, kExact);
        expect_near(d[1], {-4 * t / (s * s), 2 * (1 - t * t) / (s * s), 0}, 1e-13);
        expect_near(d[2], {(12 * t * t - 4) / (s * s * s), 4 * t * (t * t - 3) / (s * s * s), 0}, 1e-13);
        expect_near(d[3], {48 * t * (1 - t * t) / (s * s * s * s), 12 * (-t * t * t * t + 6 * t * t - 1) / (s * s * s * s), 0},
                    1e-12);
    }
}

TEST(BezierCurveExamples, Exercise112CubicPointByDeCasteljauAndByBasis) {
    // P = (0,6), (3,6), (6,3), (6,0) at u = 1/3; B_{i,3}(1/3) = 8/27, 12/27, 6/27, 1/27, so
    // C(1/3) = ((36 + 36 + 6)/27, (48 + 72 + 18)/27) = (26/9, 46/9). Table (by hand):
    //   row 1: (1,6), (4,5), (6,2);  row 2: (2,17/3), (14/3,4);  row 3: (26/9, 46/9).
    const BezierCurve curve({{0, 6, 0}, {3, 6, 0}, {6, 3, 0}, {6, 0, 0}});
    const Vec3 expected{26.0 / 9.0, 46.0 / 9.0, 0};
    expect_near(curve.point(1.0 / 3.0), expected, kExact);
    expect_near(curve.point_de_casteljau(1.0 / 3.0), expected, kExact);
    const auto table = curve.de_casteljau_table(1.0 / 3.0);
    expect_near(table[1][0], {1, 6, 0, 1}, kExact);
    expect_near(table[1][1], {4, 5, 0, 1}, kExact);
    expect_near(table[1][2], {6, 2, 0, 1}, kExact);
    expect_near(table[2][0], {2, 17.0 / 3.0, 0, 1}, kExact);
    expect_near(table[2][1], {14.0 / 3.0, 4, 0, 1}, kExact);
    expect_near(table[3][0], {26.0 / 9.0, 46.0 / 9.0, 0, 1}, kExact);
    // The same value from the exact oracle.
    const std::vector<RationalPoint> exact = {{0, 6, 0}, {3, 6, 0}, {6, 3, 0}, {6, 0, 0}};
    expect_near(curve.point(1.0 / 3.0), bezier_exact(exact, Rational(1, 3)).to_vec3(), kExact);
}

TEST(BezierCurveExamples, Exercise117RationalCubicByTheDeCasteljauTable) {
    // w = 4, 1, 1, 4: P^w = (0,24,4), (3,6,1), (6,3,1), (24,0,4) in (wx, wy, w). At u = 2/3 (by hand):
    //   row 1: (2,12,2), (5,4,1), (18,1,3);  row 2: (4, 20/3, 4/3), (41/3, 2, 7/3);  row 3: (94/9, 32/9, 2)
    // so C(2/3) = (47/9, 16/9).
    const BezierCurve curve({{0, 6, 0}, {3, 6, 0}, {6, 3, 0}, {6, 0, 0}}, {4, 1, 1, 4});
    const double u = 2.0 / 3.0;
    const auto table = curve.de_casteljau_table(u);
    expect_near(table[0][0], {0, 24, 0, 4}, kExact);
    expect_near(table[0][3], {24, 0, 0, 4}, kExact);
    expect_near(table[1][0], {2, 12, 0, 2}, kExact);
    expect_near(table[1][1], {5, 4, 0, 1}, kExact);
    expect_near(table[1][2], {18, 1, 0, 3}, kExact);
    expect_near(table[2][0], {4, 20.0 / 3.0, 0, 4.0 / 3.0}, kExact);
    expect_near(table[2][1], {41.0 / 3.0, 2, 0, 7.0 / 3.0}, kExact);
    expect_near(table[3][0], {94.0 / 9.0, 32.0 / 9.0, 0, 2}, kExact);
    expect_near(curve.point_de_casteljau(u), {47.0 / 9.0, 16.0 / 9.0, 0}, kExact);
    expect_near(curve.point(u), {47.0 / 9.0, 16.0 / 9.0, 0}, kExact);
    // Exact oracle, and the mirror symmetry of the data: C(1/3) = (16/9, 47/9).
    const std::vector<RationalPoint> pw = {homogeneous(0, 6, 0, 4), homogeneous(3, 6, 0, 1), homogeneous(6, 3, 0, 1),
                                           homogeneous(6, 0, 0, 4)};
    expect_near(curve.point(u), bezier_exact(pw, Rational(2, 3)).projected().to_vec3(), kExact);
    expect_near(curve.point(1.0 / 3.0), {16.0 / 9.0, 47.0 / 9.0, 0}, kExact);
}

TEST(BezierCurveExamples, Exercise119SecondQuadrantArc) {
    // Rotating Ex1.12's arc by 90 degrees, (x, y) -> (-y, x), keeps the weights: P = (0,1), (-1,1), (-1,0),
    // w = 1, 1, 2, i.e. C(u) = (-2u/(1+u^2), (1-u^2)/(1+u^2)). Check x^2 + y^2 = 1 everywhere, the formula,
    // and C(1/2) = (-4/5, 3/5).
    const BezierCurve arc({{0, 1, 0}, {-1, 1, 0}, {-1, 0, 0}}, {1, 1, 2});
    for (int q = 0; q <= 64; ++q) {
        const double u = q / 64.0;
        const Vec3 c = arc.point(u);
        EXPECT_NEAR(c.x * c.x + c.y * c.y, 1.0, kExact);
        EXPECT_LE(c.x, kExact);
        EXPECT_GE(c.y, -kExact);
        expect_near(c, {-2 * u / (1 + u * u), (1 - u * u) / (1 + u * u), 0}, kExact);
    }
    expect_near(arc.point(0.5), {-0.8, 0.6, 0}, kExact);
}

TEST(BezierCurveExamples, Exercise120SymmetricArcHasWeightOneOverRootTwo) {
    // Equating W(u) = 1 + (sqrt2 - 2)u + (2 - sqrt2)u^2 with sum B_{i,2} w_i at u = 0, 1, 1/2:
    // w0 = 1, w2 = 1, and 1/2 + sqrt2/4 = 1/4 + w1/2 + 1/4, so w1 = sqrt2/2. C(1/2) = (sqrt2/2, sqrt2/2): the
    // midpoint of the arc — this parameterisation is symmetric.
    const double r2 = std::sqrt(2.0);
    const BezierCurve arc({{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, r2 / 2, 1});
    expect_near(arc.point(0.5), {r2 / 2, r2 / 2, 0}, kExact);
    for (int q = 0; q <= 64; ++q) {
        const double u = q / 64.0;
        const double w = 1 + (r2 - 2) * u + (2 - r2) * u * u;
        const Vec3 expected{(1 + (r2 - 2) * u + (1 - r2) * u * u) / w, (r2 / 2) * u * ((r2 - 2) * u + 2) / w, 0};
        expect_near(arc.point(u), expected, kExact);
        expect_near(arc.homogeneous_point(u), {expected.x * w, expected.y * w, 0, w}, kExact);
    }
}

TEST(BezierCurveExamples, EndDerivativesOfEq110) {
    // C'(0) = n(P1 - P0), C'(1) = n(Pn - Pn-1), C''(0) = n(n-1)(P0 - 2P1 + P2), C''(1) = n(n-1)(Pn - 2Pn-1 + Pn-2).
    const BezierCurve curve({{0, 6, 0}, {3, 6, 0}, {6, 3, 0}, {6, 0, 0}});
    expect_near(curve.derivative(0.0), {9, 0, 0}, kExact);
    expect_near(curve.derivative(1.0), {0, -9, 0}, kExact);
    expect_near(curve.derivative(0.0, 2), {0, -18, 0}, kExact);
    expect_near(curve.derivative(1.0, 2), {-18, 0, 0}, kExact);
    // A cubic's third derivative is constant, 6 (P3 - 3P2 + 3P1 - P0) = (-18, 18, 0); the fourth vanishes.
    expect_near(curve.derivative(0.3, 3), {-18, 18, 0}, 1e-12);
    expect_near(curve.derivative(0.3, 4), {0, 0, 0}, 0.0);
    expect_near(curve.derivative(0.3, 0), curve.point(0.3), kExact);
}

TEST(BezierCurve, AccessorsAndDegreeZero) {
    const BezierCurve rational({{1, 2, 3}, {4, 5, 6}}, {2, 0.5});
    EXPECT_EQ(rational.degree(), 1);
    EXPECT_TRUE(rational.is_rational());
    EXPECT_EQ(rational.points(), (std::vector<Vec3>{{1, 2, 3}, {4, 5, 6}}));
    EXPECT_EQ(rational.weights(), (std::vector<double>{2, 0.5}));
    const BezierCurve single({{1, 2, 3}});
    EXPECT_EQ(single.degree(), 0);
    EXPECT_FALSE(single.is_rational());
    EXPECT_EQ(single.point(0.7), (Vec3{1, 2, 3}));
    EXPECT_EQ(single.derivative(0.7), (Vec3{0, 0, 0}));
    const BezierCurve from_pw = BezierCurve::from_homogeneous({{2, 4, 6, 2}, {0, 0, 0, 1}}, true);
    EXPECT_EQ(from_pw.points(), (std::vector<Vec3>{{1, 2, 3}, {0, 0, 0}}));
    EXPECT_TRUE(from_pw.is_rational());
}

// ---------------------------------------------------------------------------------------------------------
// Properties on random input (fixed seed)

struct RandomCurve {
    BezierCurve curve;
    std::vector<Vec3> points;
    std::vector<double> weights;
};

RandomCurve random_curve(RandomInput& random, bool rational, int max_degree = 7, bool planar = false,
                         double max_weight_ratio = 16.0) {
    auto points = random.points(static_cast<std::size_t>(random.integer(1, max_degree) + 1));
    if (planar)
        for (auto& p : points) p.z = 0;
    if (!rational) return {BezierCurve(points), points, std::vector<double>(points.size(), 1.0)};
    const double spread = std::sqrt(max_weight_ratio);
    auto weights = random.weights(points.size(), 1.0 / spread, spread);
    return {BezierCurve(points, weights), points, weights};
}

TEST(BezierCurveProperties, RationalBasisIsAPartitionOfUnityAndNonNegativeP18P19) {
    // R_{i,n}(u) = B_{i,n} w_i / sum_j B_{j,n} w_j, read off the curve whose control points are P_j = (delta_ij, 0, 0).
    RandomInput random(21);
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = random.integer(0, 8);
        const auto weights = random.weights(static_cast<std::size_t>(n + 1));
        const double u = random.parameter();
        double sum = 0.0;
        for (int i = 0; i <= n; ++i) {
            std::vector<Vec3> indicator(weights.size(), Vec3{0, 0, 0});
            indicator[static_cast<std::size_t>(i)].x = 1.0;
            const double r = BezierCurve(indicator, weights).point(u).x;
            EXPECT_GE(r, 0.0);
            const auto b = all_bernstein(n, u);
            double denominator = 0.0;
            for (int j = 0; j <= n; ++j) denominator += b[static_cast<std::size_t>(j)] * weights[static_cast<std::size_t>(j)];
            EXPECT_NEAR(r, b[static_cast<std::size_t>(i)] * weights[static_cast<std::size_t>(i)] / denominator, 1e-14);
            sum += r;
        }
        EXPECT_NEAR(sum, 1.0, 1e-14);
    }
}

TEST(BezierCurveProperties, EndpointInterpolationP116) {
    RandomInput random(22);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1);
        expect_near(c.curve.point(0.0), c.points.front(), 1e-13);
        expect_near(c.curve.point(1.0), c.points.back(), 1e-13);
        expect_near(c.curve.point_de_casteljau(0.0), c.points.front(), 1e-13);
        expect_near(c.curve.point_de_casteljau(1.0), c.points.back(), 1e-13);
    }
}

TEST(BezierCurveProperties, A14AgreesWithA15) {
    RandomInput random(23);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1, 12);
        const double u = random.parameter();
        expect_near(c.curve.point(u), c.curve.point_de_casteljau(u), 1e-12);
    }
}

TEST(BezierCurveProperties, ConvexHullP113BoundingBoxIn3D) {
    RandomInput random(24);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1);
        Vec3 low = c.points.front(), high = low;
        for (const Vec3& p : c.points) {
            low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
            high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
        }
        const double u = random.parameter();
        const Vec3 q = c.curve.point(u);
        const double slack = 1e-12;
        EXPECT_TRUE(q.x >= low.x - slack && q.x <= high.x + slack && q.y >= low.y - slack && q.y <= high.y + slack &&
                    q.z >= low.z - slack && q.z <= high.z + slack);
    }
}

// Andrew's monotone chain: the convex hull of planar points, counterclockwise.
std::vector<Vec3> convex_hull_2d(std::vector<Vec3> points) {
    std::sort(points.begin(), points.end(), [](const Vec3& a, const Vec3& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    auto turn = [](const Vec3& o, const Vec3& a, const Vec3& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
    std::vector<Vec3> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

TEST(BezierCurveProperties, ConvexHullP113ForPlanarCurves) {
    RandomInput random(25);
    int checked = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1, 7, true);
        if (c.points.size() < 3) continue;
        const auto hull = convex_hull_2d(c.points);
        ASSERT_GE(hull.size(), 3u);
        for (int s = 0; s < 5; ++s) {
            const Vec3 q = c.curve.point(random.parameter());
            for (std::size_t e = 0; e < hull.size(); ++e) {
                const Vec3& a = hull[e];
                const Vec3& b = hull[(e + 1) % hull.size()];
                const double side = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
                EXPECT_GE(side, -1e-9 * norm(b - a)) << "point outside hull edge " << e;
            }
            ++checked;
        }
    }
    EXPECT_GE(checked, 1000);
}

TEST(BezierCurveProperties, AffineInvarianceP114PolynomialAndRational) {
    RandomInput random(26);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1);
        std::array<Vec3, 3> rows{random.point(2.0), random.point(2.0), random.point(2.0)};
        const Vec3 shift = random.point(5.0);
        auto map = [&](const Vec3& p) { return Vec3{dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)} + shift; };
        std::vector<Vec3> moved(c.points.size());
        std::transform(c.points.begin(), c.points.end(), moved.begin(), map);
        const BezierCurve image = c.curve.is_rational() ? BezierCurve(moved, c.weights) : BezierCurve(moved);
        const double u = random.parameter();
        expect_near(image.point(u), map(c.curve.point(u)), 1e-11);
    }
}

TEST(BezierCurveProperties, DerivativesUpToOrderThreeMatchCentralDifferences) {
    RandomInput random(27);
    const double h = 1e-4;
    for (int trial = 0; trial < 1000; ++trial) {
        // Weights within a factor 4 keep the fifth derivative (the central difference's error term) moderate.
        const auto c = random_curve(random, trial % 4 != 0, 6, false, 4.0);
        const double u = random.uniform(h, 1.0 - h);
        const auto at = c.curve.derivatives(u, 3);
        const auto plus = c.curve.derivatives(u + h, 2);
        const auto minus = c.curve.derivatives(u - h, 2);
        for (std::size_t k = 1; k <= 3; ++k) {
            const Vec3 difference = (plus[k - 1] - minus[k - 1]) / (2 * h);
            const double tolerance = 1e-5 * (1.0 + norm(at[k]) + norm(at[k - 1]));
            expect_near(at[k], difference, tolerance, "order " + std::to_string(k) + " trial " + std::to_string(trial));
            expect_near(c.curve.derivative(u, static_cast<int>(k)), at[k], 0.0);
        }
    }
}

TEST(BezierCurveProperties, SplitHalvesReproduceTheCurve) {
    RandomInput random(28);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1);
        const double at = random.uniform(0.01, 0.99);
        const auto [left, right] = c.curve.split(at);
        EXPECT_EQ(left.degree(), c.curve.degree());
        EXPECT_EQ(right.degree(), c.curve.degree());
        EXPECT_EQ(left.is_rational(), c.curve.is_rational());
        const double t = random.parameter();
        expect_near(left.point(t), c.curve.point(at * t), 1e-11);
        expect_near(right.point(t), c.curve.point(at + (1 - at) * t), 1e-11);
        expect_near(left.point(1.0), right.point(0.0), 1e-11);
    }
}

TEST(BezierCurveProperties, ElevationKeepsTheCurve) {
    RandomInput random(29);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1);
        const BezierCurve elevated = c.curve.elevate();
        EXPECT_EQ(elevated.degree(), c.curve.degree() + 1);
        EXPECT_EQ(elevated.is_rational(), c.curve.is_rational());
        const double u = random.parameter();
        expect_near(elevated.point(u), c.curve.point(u), 1e-11);
        expect_near(elevated.derivative(u), c.curve.derivative(u), 1e-9 * (1 + norm(c.curve.derivative(u))));
    }
    // Elevating the line (0,0,0) -> (3,0,0) gives the evenly spaced (0,0,0), (1.5,0,0), (3,0,0).
    const auto elevated = BezierCurve({{0, 0, 0}, {3, 0, 0}}).elevate().points();
    EXPECT_EQ(elevated, (std::vector<Vec3>{{0, 0, 0}, {1.5, 0, 0}, {3, 0, 0}}));
}

TEST(BezierCurveProperties, ReversalExercise111) {
    RandomInput random(30);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, trial % 2 == 1);
        const BezierCurve backwards = c.curve.reversed();
        const double u = random.parameter();
        expect_near(backwards.point(u), c.curve.point(1.0 - u), 1e-12);
        // The first derivative changes sign under u -> 1 - u.
        expect_near(backwards.derivative(u), -1.0 * c.curve.derivative(1.0 - u), 1e-9 * (1 + norm(c.curve.derivative(1.0 - u))));
    }
}

// The parameter t of the original curve at parameter s of its normal form (BezierCurve::normal_form).
double moebius(const std::vector<double>& weights, double s) {
    const double rho = std::pow(weights.front() / weights.back(), 1.0 / static_cast<double>(weights.size() - 1));
    return rho * s / ((1 - s) + rho * s);
}

TEST(BezierCurveProperties, NormalFormIsTheSameCurveWithEndWeightsOne) {
    RandomInput random(31);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto c = random_curve(random, true, 7, false, 1e6);
        if (c.curve.degree() == 0) continue;
        const BezierCurve normal = c.curve.normal_form();
        ASSERT_EQ(normal.degree(), c.curve.degree());
        EXPECT_EQ(normal.weights().front(), 1.0);
        EXPECT_EQ(normal.weights().back(), 1.0);
        EXPECT_EQ(normal.points().front(), c.curve.point(0.0));  // the ends bit for bit
        EXPECT_EQ(normal.points().back(), c.curve.point(1.0));
        const double s = random.parameter();
        expect_near(normal.point(s), c.curve.point(moebius(c.weights, s)), 1e-11);
    }
}

TEST(BezierCurveProperties, NormalFormOfTheEx114ArcIsTheStandardQuarterCircle) {
    // Weights 1, 1, 2 become 1, sqrt(2)/2, 1 (Exercise 1.20's weight for the symmetric arc); the Möbius
    // map moves the midpoint of the parameter to the middle of the arc, (sqrt(2)/2, sqrt(2)/2).
    const BezierCurve normal = quarter_circle().normal_form();
    EXPECT_EQ(normal.points(), quarter_circle().points());
    EXPECT_NEAR(normal.weights()[1], std::sqrt(0.5), kExact);
    expect_near(normal.point(0.5), {std::sqrt(0.5), std::sqrt(0.5), 0}, kExact);
}

TEST(BezierCurveProperties, NormalFormKeepsPolynomialAndOutOfRangeCurves) {
    const BezierCurve cubic({{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}});
    EXPECT_FALSE(cubic.normal_form().is_rational());
    EXPECT_EQ(cubic.normal_form().homogeneous_points(), cubic.homogeneous_points());
    // Weights 1e-300 and 1e300 at the ends still have a normal form (taken through logarithms) ...
    const BezierCurve extreme({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {1e-300, 1, 1e300});
    EXPECT_EQ(extreme.normal_form().weights().front(), 1.0);
    EXPECT_TRUE(std::isfinite(extreme.normal_form().weights()[1]));
    // ... but not when the middle weight would leave the doubles: the curve comes back unchanged.
    const BezierCurve beyond({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {1e-300, 1e300, 1e-300});
    EXPECT_EQ(beyond.normal_form().homogeneous_points(), beyond.homogeneous_points());
}

// ---------------------------------------------------------------------------------------------------------
// Bad input

TEST(BezierCurveErrors, EmptyPointsNamePoints) {
    const std::string m1 = error_message([] { BezierCurve(std::vector<Vec3>{}); });
    const std::string m2 = error_message([] { BezierCurve(std::vector<Vec3>{}, std::vector<double>{}); });
    const std::string m3 = error_message([] { BezierCurve::from_homogeneous({}); });
    EXPECT_TRUE(starts_with(m1, "points:")) << m1;
    EXPECT_TRUE(starts_with(m2, "points:")) << m2;
    EXPECT_TRUE(starts_with(m3, "homogeneous_points:")) << m3;
}

TEST(BezierCurveErrors, MismatchedWeightsSizeNamesWeights) {
    const std::string message = error_message([] { BezierCurve({{0, 0, 0}, {1, 0, 0}}, {1.0}); });
    EXPECT_TRUE(starts_with(message, "weights:")) << message;
}

TEST(BezierCurveErrors, NonFiniteCoordinatesNamePoints) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double bad : {nan, inf, -inf}) {
        const std::string m1 = error_message([&] { BezierCurve({{0, 0, 0}, {1, bad, 0}}); });
        const std::string m2 = error_message([&] { BezierCurve({{0, 0, bad}}, {1.0}); });
        const std::string m3 = error_message([&] { BezierCurve::from_homogeneous({{bad, 0, 0, 1}}); });
        EXPECT_TRUE(starts_with(m1, "points:")) << m1;
        EXPECT_TRUE(starts_with(m2, "points:")) << m2;
        EXPECT_TRUE(starts_with(m3, "homogeneous_points:")) << m3;
    }
}

TEST(BezierCurveErrors, NonPositiveOrNaNWeightsNameWeights) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double bad : {0.0, -1.0, nan, std::numeric_limits<double>::infinity()}) {
        const std::string m1 = error_message([&] { BezierCurve({{0, 0, 0}, {1, 0, 0}}, {1.0, bad}); });
        const std::string m2 = error_message([&] { BezierCurve::from_homogeneous({{0, 0, 0, 1}, {0, 0, 0, bad}}); });
        EXPECT_TRUE(starts_with(m1, "weights:")) << m1;
        EXPECT_NE(m1.find("weight 1"), std::string::npos) << m1;
        EXPECT_TRUE(starts_with(m2, "homogeneous_points:")) << m2;
    }
}

TEST(BezierCurveErrors, ParameterOutsideTheDomainOrNaNNamesU) {
    const BezierCurve curve = quarter_circle();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double bad : {-1e-9, 1.0 + 1e-9, 2.0, nan, std::numeric_limits<double>::infinity()}) {
        for (const std::string& message :
             {error_message([&] { curve.point(bad); }), error_message([&] { curve.point_de_casteljau(bad); }),
              error_message([&] { curve.homogeneous_point(bad); }), error_message([&] { curve.de_casteljau_table(bad); }),
              error_message([&] { curve.derivatives(bad, 1); }), error_message([&] { curve.derivative(bad); })})
            EXPECT_TRUE(starts_with(message, "u:")) << message;
    }
}

TEST(BezierCurveErrors, NegativeDerivativeOrderNamesOrder) {
    const BezierCurve curve = quarter_circle();
    const std::string m1 = error_message([&] { curve.derivatives(0.5, -1); });
    const std::string m2 = error_message([&] { curve.derivative(0.5, -2); });
    EXPECT_TRUE(starts_with(m1, "order:")) << m1;
    EXPECT_TRUE(starts_with(m2, "order:")) << m2;
}

TEST(BezierCurveErrors, SplitAtZeroOneOrOutsideNamesU) {
    const BezierCurve curve = quarter_circle();
    for (double bad : {0.0, 1.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
        const std::string message = error_message([&] { curve.split(bad); });
        EXPECT_TRUE(starts_with(message, "u:")) << message;
    }
}

}  // namespace
}  // namespace ratbez
