#include "ratbez/nurbs_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "nurbs_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;


double net_size(const NurbsCurve& c) {
    double size = 0;
    for (const Vec3& p : c.points()) size = std::max(size, norm(p));
    return size + 1;
}

// The rational quarter circle of 000 §1.4: radius 1, weights 1, sqrt(2)/2, 1.
NurbsCurve quarter_circle() {
    return NurbsCurve(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, std::sqrt(0.5), 1});
}

// ---- exact examples --------------------------------------------------------------------------------

TEST(NurbsCurve, QuarterCircleLiesOnTheUnitCircle) {
    const NurbsCurve c = quarter_circle();
    EXPECT_TRUE(c.is_rational());
    EXPECT_EQ(c.start_point(), (Vec3{1, 0, 0}));
    EXPECT_EQ(c.end_point(), (Vec3{0, 1, 0}));
    for (int k = 0; k <= 64; ++k) {
        const double u = k / 64.0;
        EXPECT_NEAR(norm(c.point(u)), 1.0, 1e-15) << u;
        // The tangent is perpendicular to the radius.
        EXPECT_NEAR(dot(c.point(u), c.derivative(u)), 0.0, 1e-14);
    }
    // C(1/2) = (sqrt(2)/2, sqrt(2)/2) by symmetry.
    EXPECT_TRUE(near(c.point(0.5), {std::sqrt(0.5), std::sqrt(0.5), 0}, 1e-15));
    // C'(0) = 2 w_1 / w_0 (P_1 - P_0) = sqrt(2) (0, 1, 0).
    EXPECT_TRUE(near(c.derivative(0.0), {0, std::sqrt(2.0), 0}, 1e-14));
}

TEST(NurbsCurve, NonuniformQuadraticAtFiveHalves) {
    // Ex2.3's knots with P_i = (i, i^2, 0): C(5/2) = (1/8) P_2 + (6/8) P_3 + (1/8) P_4 = (3, 37/4, 0).
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i) points.push_back({double(i), double(i * i), 0});
    const NurbsCurve c(2, {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, points);
    EXPECT_FALSE(c.is_rational());
    const Vec3 expected = (1.0 / 8) * points[2] + (6.0 / 8) * points[3] + (1.0 / 8) * points[4];
    EXPECT_TRUE(near(c.point(2.5), expected, 1e-14));
    EXPECT_TRUE(near(c.point(2.5), {3, 37.0 / 4, 0}, 1e-14));
    // C'(5/2) = -1/2 P_2 + 0 P_3 + 1/2 P_4, C''(5/2) = P_2 - 2 P_3 + P_4.
    EXPECT_TRUE(near(c.derivative(2.5), 0.5 * (points[4] - points[2]), 1e-14));
    EXPECT_TRUE(near(c.derivative(2.5, 2), points[2] - 2.0 * points[3] + points[4], 1e-14));
    EXPECT_EQ(c.derivative(2.5, 3), (Vec3{}));
    EXPECT_EQ(c.start_point(), points.front());
    EXPECT_EQ(c.end_point(), points.back());
}

TEST(NurbsCurve, DegreeZeroIsAConstantPiece) {
    const NurbsCurve c(0, {1, 2}, {{3, 4, 5}});
    EXPECT_EQ(c.point(1.0), (Vec3{3, 4, 5}));
    EXPECT_EQ(c.point(2.0), (Vec3{3, 4, 5}));
    EXPECT_EQ(c.derivative(1.5), (Vec3{}));
    const auto segments = c.bezier_segments();
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_EQ(segments[0].degree(), 0);
    EXPECT_EQ(segments[0].point(0.3), (Vec3{3, 4, 5}));
    EXPECT_EQ(c.reversed().point(1.25), (Vec3{3, 4, 5}));
}

// ---- properties on random curves -----------------------------------------------------------------

TEST(NurbsCurve, RationalBasisIsAPartitionOfUnityAndNonNegative) {
    // With P_k = e_x and every other point 0, x(u) = R_k(u), the k-th rational basis function.
    Rng rng(3001);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, true, trial % 2 == 0);
        const double u = test::random_parameter(rng, c.domain());
        const std::vector<double> weights = c.weights();
        double sum = 0;
        for (std::size_t k = 0; k < weights.size(); ++k) {
            std::vector<Vec3> indicator(weights.size());
            indicator[k] = {1, 0, 0};
            const NurbsCurve basis(c.degree(), c.knots(), indicator, weights);
            const double r = basis.point(u).x;
            EXPECT_GE(r, 0.0);
            EXPECT_LE(r, 1.0 + 1e-15);
            sum += r;
        }
        EXPECT_NEAR(sum, 1.0, 1e-14) << "trial " << trial;
    }
}

TEST(NurbsCurve, ClampedCurvesInterpolateTheirEndPoints) {
    Rng rng(3002);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 2 == 0, true);
        const std::vector<Vec3> points = c.points();
        EXPECT_TRUE(near(c.start_point(), points.front(), 1e-14 * net_size(c)));
        EXPECT_TRUE(near(c.end_point(), points.back(), 1e-14 * net_size(c)));
    }
}

TEST(NurbsCurve, CurveLiesInTheConvexHullOfItsSpanPoints) {
    // Strong convex hull property: C(u) for u in span k is a convex combination of P_{k-p} .. P_k, so in
    // every direction d its extent is bounded by theirs.
    Rng rng(3003);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0);
        const double u = test::random_parameter(rng, c.domain());
        const int span = find_span(c.degree(), c.knots(), u);
        const std::vector<Vec3> points = c.points();
        const Vec3 x = c.point(u);
        for (int direction = 0; direction < 8; ++direction) {
            Vec3 d = test::random_point(rng);
            if (norm(d) == 0) continue;
            d = d / norm(d);
            double highest = -1e300;
            for (int i = span - c.degree(); i <= span; ++i) highest = std::max(highest, dot(d, points[std::size_t(i)]));
            EXPECT_LE(dot(d, x), highest + 1e-13) << "trial " << trial;
        }
    }
}

TEST(NurbsCurve, DerivativesAgreeWithCentralDifferences) {
    // Orders 1..3 for rational and polynomial curves of degrees 1..5 with repeated knots, away from knots
    // (where lower continuity is allowed). Error model: h^2 |C^(k+2)| for the difference, rounding otherwise.
    Rng rng(3004);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 4 != 0, trial % 2 == 0);
        const auto where = test::random_interior_parameter(rng, c.degree(), c.knots());
        const double length = where.span_max - where.span_min;
        const double h = 1e-4 * length;
        const auto at = c.derivatives(where.value, 5);
        const auto plus = c.derivatives(where.value + h, 3);
        const auto minus = c.derivatives(where.value - h, 3);
        ASSERT_EQ(at.size(), 6u);
        EXPECT_EQ(at[0], c.point(where.value));
        for (std::size_t k = 1; k <= 3; ++k) {
            const Vec3 difference = (plus[k - 1] - minus[k - 1]) / (2 * h);
            const double tolerance = h * h * norm(at[k + 2]) + 1e-9 * (norm(at[k]) + norm(at[k - 1]) / length + 1);
            EXPECT_TRUE(near(at[k], difference, tolerance)) << "trial " << trial << " order " << k;
            EXPECT_EQ(c.derivative(where.value, static_cast<int>(k)), at[k]);
        }
    }
}

TEST(NurbsCurve, KnotInsertionKeepsTheCurve) {
    Rng rng(3005);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0);
        const Interval d = c.domain();
        // Insert at a random parameter or at an existing knot (including an unclamped domain end).
        double u = uniform(rng, d.min, d.max);
        if (trial % 3 == 0) {
            const auto breaks = test::break_points(c.degree(), c.knots());
            u = breaks[std::size_t(uniform_int(rng, 0, int(breaks.size()) - 1))];
        }
        const int multiplicity = int(std::count(c.knots().begin(), c.knots().end(), u));
        if (multiplicity >= c.degree()) continue;
        const int times = uniform_int(rng, 1, c.degree() - multiplicity);
        const NurbsCurve refined = c.insert_knot(u, times);
        EXPECT_EQ(refined.knots().size(), c.knots().size() + std::size_t(times));
        EXPECT_EQ(refined.homogeneous_points().size(), c.homogeneous_points().size() + std::size_t(times));
        EXPECT_EQ(int(std::count(refined.knots().begin(), refined.knots().end(), u)), multiplicity + times);
        EXPECT_EQ(refined.domain().min, d.min);
        EXPECT_EQ(refined.domain().max, d.max);
        EXPECT_EQ(refined.is_rational(), c.is_rational());
        for (int sample = 0; sample < 10; ++sample) {
            const double t = sample == 0 ? d.min : sample == 1 ? d.max : sample == 2 ? u : uniform(rng, d.min, d.max);
            EXPECT_TRUE(near(refined.point(t), c.point(t), 1e-12 * net_size(c))) << "trial " << trial << " t " << t;
        }
        if (!c.is_rational()) {
            for (double w : refined.weights()) EXPECT_EQ(w, 1.0);
        }
    }
}

TEST(NurbsCurve, BezierSegmentsReproduceTheCurvePiecewise) {
    Rng rng(3006);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0);
        const std::vector<double> breaks = test::break_points(c.degree(), c.knots());
        const std::vector<BezierCurve> segments = c.bezier_segments();
        ASSERT_EQ(segments.size(), breaks.size() - 1) << "trial " << trial;
        for (std::size_t s = 0; s < segments.size(); ++s) {
            ASSERT_EQ(segments[s].degree(), c.degree());
            EXPECT_EQ(segments[s].is_rational(), c.is_rational());
            const double a = breaks[s], b = breaks[s + 1];
            for (double t : {0.0, 1.0, uniform(rng, 0, 1), uniform(rng, 0, 1)}) {
                const double u = t == 1.0 ? b : a + t * (b - a);
                EXPECT_TRUE(near(segments[s].point(t), c.point(u), 1e-12 * net_size(c)))
                    << "trial " << trial << " segment " << s << " t " << t;
            }
            // The chain rule: dC/du = dB/dt / (b - a) (checked inside the segment).
            const double t = uniform(rng, 0.1, 0.9);
            EXPECT_TRUE(near(segments[s].derivative(t) / (b - a), c.derivative(a + t * (b - a)),
                             1e-9 * (norm(c.derivative(a + t * (b - a))) + 1)));
        }
    }
}

TEST(NurbsCurve, BezierKnotVectorEqualsTheBezierCurve) {
    Rng rng(3007);
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = uniform_int(rng, 0, 7);
        std::vector<Vec3> points(std::size_t(n) + 1);
        std::vector<double> weights(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            points[i] = test::random_point(rng);
            weights[i] = test::random_weight(rng);
        }
        const bool rational = trial % 2 == 0;
        const BezierCurve bezier = rational ? BezierCurve(points, weights) : BezierCurve(points);
        std::vector<double> knots(2 * std::size_t(n + 1), 0.0);
        std::fill(knots.begin() + n + 1, knots.end(), 1.0);
        const NurbsCurve nurbs = rational ? NurbsCurve(n, knots, points, weights) : NurbsCurve(n, knots, points);
        const NurbsCurve converted = NurbsCurve::from_bezier(bezier);
        EXPECT_EQ(converted.knots(), knots);
        EXPECT_EQ(converted.is_rational(), rational);
        const double u = trial % 10 == 0 ? 1.0 : uniform(rng, 0, 1);
        const auto expected = bezier.derivatives(u, 3);
        const auto actual = nurbs.derivatives(u, 3);
        const auto actual_converted = converted.derivatives(u, 3);
        for (std::size_t k = 0; k <= 3; ++k) {
            const double tolerance = 1e-11 * (norm(expected[k]) + 1);
            EXPECT_TRUE(near(actual[k], expected[k], tolerance)) << "trial " << trial << " order " << k;
            EXPECT_TRUE(near(actual_converted[k], expected[k], tolerance)) << "trial " << trial << " order " << k;
        }
    }
}

TEST(NurbsCurve, ReversedRunsTheSameCurveBackwards) {
    Rng rng(3008);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0);
        const NurbsCurve r = c.reversed();
        const Interval d = c.domain();
        EXPECT_EQ(r.domain().min, d.min);
        EXPECT_EQ(r.domain().max, d.max);
        EXPECT_TRUE(near(r.start_point(), c.end_point(), 1e-13 * net_size(c)));
        EXPECT_TRUE(near(r.end_point(), c.start_point(), 1e-13 * net_size(c)));
        const double u = uniform(rng, d.min, d.max);
        const double mirrored = std::clamp(d.min + d.max - u, d.min, d.max);
        EXPECT_TRUE(near(r.point(u), c.point(mirrored), 1e-12 * net_size(c)));
        // Away from knots the derivative flips sign.
        const auto where = test::random_interior_parameter(rng, c.degree(), c.knots());
        const double back = d.min + d.max - where.value;
        EXPECT_TRUE(near(r.derivative(back), -1.0 * c.derivative(where.value), 1e-9 * (norm(c.derivative(where.value)) + 1)));
        EXPECT_TRUE(near(r.reversed().point(u), c.point(u), 1e-12 * net_size(c)));
    }
}

TEST(NurbsCurve, ReparameterizedIsTheSameCurveOnANewDomain) {
    Rng rng(3009);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0);
        const double a = uniform(rng, -5, 5), b = a + uniform(rng, 0.5, 10);
        const NurbsCurve r = c.reparameterized(a, b);
        EXPECT_EQ(r.domain().min, a);
        EXPECT_EQ(r.domain().max, b);
        const Interval d = c.domain();
        const double scale = (d.max - d.min) / (b - a);
        EXPECT_TRUE(near(r.start_point(), c.start_point(), 1e-14 * net_size(c)));
        EXPECT_TRUE(near(r.end_point(), c.end_point(), 1e-14 * net_size(c)));
        const auto where = test::random_interior_parameter(rng, c.degree(), c.knots());
        const double t = a + (where.value - d.min) / scale;
        EXPECT_TRUE(near(r.point(t), c.point(where.value), 1e-12 * net_size(c)));
        // First and second derivatives scale by the chain rule.
        EXPECT_TRUE(near(r.derivative(t), scale * c.derivative(where.value), 1e-9 * (norm(c.derivative(where.value)) + 1)));
        EXPECT_TRUE(near(r.derivative(t, 2), scale * scale * c.derivative(where.value, 2),
                         1e-8 * (norm(c.derivative(where.value, 2)) + 1)));
    }
}

TEST(NurbsCurve, NormalFormPutsEverySpanInNormalFormOnTheSameDomain) {
    Rng rng(3010);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsCurve c = test::random_curve(rng, true, trial % 3 != 0);
        const NurbsCurve normal = c.normal_form();
        EXPECT_EQ(normal.domain().min, c.domain().min);
        EXPECT_EQ(normal.domain().max, c.domain().max);
        const std::vector<double> breaks = test::break_points(c.degree(), c.knots());
        ASSERT_EQ(test::break_points(normal.degree(), normal.knots()), breaks) << "trial " << trial;
        const std::vector<BezierCurve> spans = c.bezier_segments();
        const std::vector<BezierCurve> normal_spans = normal.bezier_segments();
        ASSERT_EQ(normal_spans.size(), spans.size());
        for (std::size_t s = 0; s < spans.size(); ++s) {
            EXPECT_NEAR(normal_spans[s].weights().front(), 1.0, 1e-15);
            EXPECT_NEAR(normal_spans[s].weights().back(), 1.0, 1e-15);
            // Span s of the normal form at local parameter t is span s of the curve at the Möbius image of t.
            const std::vector<double> w = spans[s].weights();
            const double rho = std::pow(w.front() / w.back(), 1.0 / c.degree());
            const double t = uniform(rng, 0, 1);
            const double a = breaks[s], b = breaks[s + 1];
            EXPECT_TRUE(near(normal.point(a + t * (b - a)), spans[s].point(rho * t / ((1 - t) + rho * t)),
                             1e-12 * net_size(c)))
                << "trial " << trial << " span " << s;
        }
    }
    const NurbsCurve polynomial = test::random_curve(rng, false, true);
    EXPECT_EQ(polynomial.normal_form().knots(), polynomial.knots());
}

TEST(NurbsCurve, UnclampedCurveDecomposesAfterClampingItsEnds) {
    // The uniform quadratic B-spline on {0..6} with points P_0..P_3: domain [2, 4], two segments whose
    // end points are the midpoints of the control legs (the classic uniform B-spline property).
    const std::vector<Vec3> points{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
    const NurbsCurve c(2, {0, 1, 2, 3, 4, 5, 6}, points);
    EXPECT_TRUE(near(c.start_point(), 0.5 * (points[0] + points[1]), 1e-15));
    EXPECT_TRUE(near(c.end_point(), 0.5 * (points[2] + points[3]), 1e-15));
    const auto segments = c.bezier_segments();
    ASSERT_EQ(segments.size(), 2u);
    const auto first = segments[0].points();
    EXPECT_TRUE(near(first[0], 0.5 * (points[0] + points[1]), 1e-15));
    EXPECT_TRUE(near(first[1], points[1], 1e-15));
    EXPECT_TRUE(near(first[2], 0.5 * (points[1] + points[2]), 1e-15));
    const auto second = segments[1].points();
    EXPECT_TRUE(near(second[0], 0.5 * (points[1] + points[2]), 1e-15));
    EXPECT_TRUE(near(second[1], points[2], 1e-15));
    EXPECT_TRUE(near(second[2], 0.5 * (points[2] + points[3]), 1e-15));
    // Inserting the domain end once more (multiplicity 2 = p) keeps the curve and makes P_3 of the refined
    // curve its end point.
    const NurbsCurve refined = c.insert_knot(4.0, 1);
    EXPECT_TRUE(near(refined.points()[3], c.end_point(), 1e-15));
    EXPECT_TRUE(near(refined.end_point(), c.end_point(), 1e-15));
    EXPECT_TRUE(near(refined.point(3.3), c.point(3.3), 1e-15));
}

TEST(NurbsCurve, FromHomogeneousAndAccessors) {
    const NurbsCurve c = NurbsCurve::from_homogeneous(1, {0, 0, 1, 1}, {{2, 0, 0, 2}, {0, 4, 0, 4}});
    EXPECT_TRUE(c.is_rational());
    EXPECT_EQ(c.points(), (std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}}));
    EXPECT_EQ(c.weights(), (std::vector<double>{2, 4}));
    // H{(1-u)(2,0,0,2) + u(0,4,0,4)} at u = 1/2: (1, 2, 0) / 3.
    EXPECT_TRUE(near(c.point(0.5), {1.0 / 3, 2.0 / 3, 0}, 1e-15));
    EXPECT_EQ(c.homogeneous_point(0.5), (Vec4{1, 2, 0, 3}));
    const NurbsCurve polynomial = NurbsCurve::from_homogeneous(1, {0, 0, 1, 1}, {{2, 0, 0, 1}, {0, 4, 0, 1}}, false);
    EXPECT_FALSE(polynomial.is_rational());
    EXPECT_TRUE(throws_naming([] { (void)NurbsCurve::from_homogeneous(1, {0, 0, 1, 1}, {{2, 0, 0, 2}, {0, 4, 0, 1}}, false); },
                              "homogeneous_points"));
}

// ---- bad input, one test each ---------------------------------------------------------------------

TEST(NurbsCurveErrors, EmptyPoints) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, std::vector<Vec3>{}); }, "points"));
    EXPECT_TRUE(throws_naming([] { (void)NurbsCurve::from_homogeneous(1, {0, 1}, {}); }, "homogeneous_points"));
}

TEST(NurbsCurveErrors, MismatchedWeights) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {1.0}); }, "weights"));
}

TEST(NurbsCurveErrors, NonFiniteCoordinates) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {nan_value, 0, 0}}); }, "points"));
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, {{0, inf_value, 0}, {1, 0, 0}}); }, "points"));
}

TEST(NurbsCurveErrors, WeightsMustBePositiveAndFinite) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {1.0, 0.0}); }, "weights"));
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {-1.0, 1.0}); }, "weights"));
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {nan_value, 1.0}); }, "weights"));
}

TEST(NurbsCurveErrors, DecreasingKnots) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 0.6, 0.4, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}); },
                              "knots"));
}

TEST(NurbsCurveErrors, KnotMultiplicityTooHigh) {
    // End multiplicity above degree + 1.
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}); }, "knots"));
    // Interior multiplicity above degree.
    EXPECT_TRUE(throws_naming(
        [] { NurbsCurve(1, {0, 0, 0.5, 0.5, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}); }, "knots"));
}

TEST(NurbsCurveErrors, TooFewControlPointsForTheKnotVector) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 0, 0}}); }, "points"));
    EXPECT_TRUE(throws_naming([] { NurbsCurve(1, {0, 0, 0.5, 1, 1}, {{0, 0, 0}, {1, 0, 0}}); }, "knots"));
}

TEST(NurbsCurveErrors, NegativeDegree) {
    EXPECT_TRUE(throws_naming([] { NurbsCurve(-1, {0, 1}, {{0, 0, 0}}); }, "degree"));
}

TEST(NurbsCurveErrors, ParameterOutsideTheDomain) {
    const NurbsCurve c = quarter_circle();
    EXPECT_TRUE(throws_naming([&] { (void)c.point(1.0 + 1e-12); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)c.point(-0.5); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)c.point(nan_value); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)c.derivatives(2.0, 1); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)c.insert_knot(-1.0); }, "u"));
}

TEST(NurbsCurveErrors, NegativeDerivativeOrderAndInsertionBeyondTheDegree) {
    const NurbsCurve c = quarter_circle();
    EXPECT_TRUE(throws_naming([&] { (void)c.derivative(0.5, -1); }, "order"));
    EXPECT_TRUE(throws_naming([&] { (void)c.derivatives(0.5, -2); }, "order"));
    EXPECT_TRUE(throws_naming([&] { (void)c.insert_knot(0.5, 3); }, "times"));
    EXPECT_TRUE(throws_naming([&] { (void)c.insert_knot(0.5, -1); }, "times"));
    // fuzz_geometry found: multiplicity + times overflowed int (UBSan) for times near INT_MAX.
    EXPECT_TRUE(throws_naming([&] { (void)c.insert_knot(0.5, std::numeric_limits<int>::max()); }, "times"));
    EXPECT_TRUE(throws_naming([&] { (void)c.insert_knot(0.0, 1); }, "times"));  // the clamped end has p + 1 already
    // Zero more times is a no-op anywhere, the clamped ends included (fuzz_geometry's corpus found it refused).
    EXPECT_EQ(c.insert_knot(0.0, 0).knots(), c.knots());
    EXPECT_EQ(c.insert_knot(1.0, 0).homogeneous_points(), c.homogeneous_points());
    EXPECT_TRUE(throws_naming([&] { (void)c.reparameterized(1.0, 1.0); }, "b"));
    EXPECT_TRUE(throws_naming([&] { (void)c.reparameterized(nan_value, 1.0); }, "a"));
}

}  // namespace
}  // namespace ratbez
