#include "ratbez/curves.hpp"

#include <gtest/gtest.h>

#include <iostream>
#include <limits>

#include "ratbez/frame.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

TEST(Curves, QuarterCircleHasTheControlPolygonOfEx1_13AndWeightCos45) {
    const NurbsCurve quarter = arc(1.0, 0.0, 90.0);
    ASSERT_EQ(quarter.degree(), 2);
    const auto points = quarter.points();
    ASSERT_EQ(points.size(), 3u);
    // Ex1.13's polygon P0 = (1, 0), P1 = (1, 1), P2 = (0, 1), exactly; symmetric weights 1, cos 45°, 1.
    EXPECT_EQ(points[0], (Vec3{1, 0, 0}));
    EXPECT_EQ(points[1], (Vec3{1, 1, 0}));
    EXPECT_EQ(points[2], (Vec3{0, 1, 0}));
    const auto weights = quarter.weights();
    EXPECT_EQ(weights[0], 1.0);
    EXPECT_NEAR(weights[1], std::sqrt(0.5), 2.3e-16);
    EXPECT_EQ(weights[2], 1.0);
    // By symmetry the middle parameter is the 45° point.
    const Vec3 middle = quarter.point(0.5);
    EXPECT_NEAR(middle.x, std::sqrt(0.5), 2.3e-16);
    EXPECT_NEAR(middle.y, std::sqrt(0.5), 2.3e-16);
}

TEST(Curves, ArcsUseSegmentsOfAtMost90DegreesWithWeightCosHalfSweep) {
    struct Case { double start, end; int segments; };
    for (const Case c : {Case{0, 90, 1}, Case{0, 120, 2}, Case{10, 190, 2}, Case{-30, 240, 3}, Case{0, 360, 4}, Case{5, 6, 1}}) {
        const NurbsCurve a = arc(2.0, c.start, c.end);
        ASSERT_EQ(a.points().size(), static_cast<std::size_t>(2 * c.segments + 1)) << c.start << " " << c.end;
        const double half = (c.end - c.start) / c.segments / 2.0 * pi / 180.0;
        const auto w = a.weights();
        for (std::size_t i = 0; i < w.size(); ++i) EXPECT_NEAR(w[i], i % 2 == 1 ? std::cos(half) : 1.0, 1e-15);
        EXPECT_NEAR(distance(a.start_point(), Vec3{2 * std::cos(c.start * pi / 180), 2 * std::sin(c.start * pi / 180), 0}), 0, 4e-15);
        EXPECT_NEAR(distance(a.end_point(), Vec3{2 * std::cos(c.end * pi / 180), 2 * std::sin(c.end * pi / 180), 0}), 0, 4e-15);
    }
}

// The angle of the point at parameter u of an arc of `sweep` degrees starting at 0: inside segment k
// (sweep 2θ each, local parameter t) the rational quadratic with weights 1, cos θ, 1 has
// tan(α / 2) = tan(θ / 2) (2t - 1) for the angle α from the segment's bisector.
double arc_angle(double sweep_deg, int segments, double u) {
    const int k = std::min(static_cast<int>(u * segments), segments - 1);
    const double t = u * segments - k;
    const double theta = sweep_deg / (2.0 * segments) * pi / 180.0;
    return (2 * k + 1) * theta + 2 * std::atan(std::tan(theta / 2) * (2 * t - 1));
}

TEST(Curves, CirclesAndArcsInAnyPlaneLieOnTheirCircleAtTheExactAngle) {
    double worst = 0;
    for (int shape = 0; shape < 10; ++shape) {
        const double radius = uniform(0.1, 100.0);
        const Vec3 center = random_point(50.0), normal = random_unit();
        const double start = uniform(-400, 400), sweep = shape == 0 ? 360.0 : uniform(1, 360);
        const NurbsCurve c = shape == 0 ? circle(radius, center, normal) : arc(radius, start, start + sweep, center, normal);
        const Frame f = frame_from_axis(center, normal);
        const double start_rad = shape == 0 ? 0.0 : start * pi / 180;
        const int segments = static_cast<int>(std::ceil(sweep / 90.0 - 1e-12));
        for (int k = 0; k < 1000; ++k) {
            const double u = uniform(0, 1);
            const Vec3 p = c.point(u);
            const double angle = start_rad + arc_angle(sweep, segments, u);
            const Vec3 expected = center + f.x_axis * (radius * std::cos(angle)) + f.y_axis * (radius * std::sin(angle));
            const double error = distance(p, expected) / radius;
            worst = std::max(worst, error);
            ASSERT_LE(error, 1e-12) << "u = " << u;
            ASSERT_LE(std::abs(distance(p, center) - radius), 1e-12 * radius);
            ASSERT_LE(std::abs(dot(p - center, f.z_axis)), 1e-12 * radius);
        }
    }
    std::cout << "[ measured ] circles/arcs: largest relative deviation from the exact point " << worst << "\n";
}

TEST(Curves, EllipseArcsLieOnTheEllipse) {
    double worst = 0;
    for (int shape = 0; shape < 10; ++shape) {
        const double a = uniform(0.5, 20), b = uniform(0.5, 20);
        const Vec3 center = random_point(10), normal = random_unit();
        const double start = uniform(-180, 180), sweep = uniform(1, 360);
        const NurbsCurve e = ellipse_arc(a, b, start, start + sweep, center, normal);
        const Frame f = frame_from_axis(center, normal);
        for (int k = 0; k < 1000; ++k) {
            const Vec3 r = e.point(uniform(0, 1)) - center;
            const double x = dot(r, f.x_axis) / a, y = dot(r, f.y_axis) / b;
            worst = std::max(worst, std::abs(x * x + y * y - 1));
            ASSERT_LE(std::abs(x * x + y * y - 1), 1e-12);
            ASSERT_LE(std::abs(dot(r, f.z_axis)), 1e-12 * std::max(a, b));
        }
        // The parametric angle convention: the ends are (a cos t, b sin t).
        const Vec3 s = e.start_point() - center;
        EXPECT_NEAR(dot(s, f.x_axis), a * std::cos(start * pi / 180), 1e-12 * a);
        EXPECT_NEAR(dot(s, f.y_axis), b * std::sin(start * pi / 180), 1e-12 * b);
    }
    std::cout << "[ measured ] ellipse arcs: largest |(x/a)^2 + (y/b)^2 - 1| " << worst << "\n";
}

TEST(Curves, FullCircleIsClosedAndCounterclockwiseAboutItsNormal) {
    const NurbsCurve c = circle(3.0, {1, 2, 3}, {0, 0, 1});
    EXPECT_EQ(c.start_point(), c.end_point());
    EXPECT_EQ(c.start_point(), (Vec3{4, 2, 3}));
    EXPECT_GT(cross(c.point(0.1) - Vec3{1, 2, 3}, c.point(0.2) - Vec3{1, 2, 3}).z, 0.0);
    const NurbsCurve line = line_segment({0, 0, 0}, {1, 2, 3});
    EXPECT_EQ(line.point(0.5), (Vec3{0.5, 1, 1.5}));
}

TEST(Curves, RejectBadInputNamingTheArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_ERROR_NAMING(circle(0.0), "radius");
    EXPECT_ERROR_NAMING(circle(-1.0), "radius");
    EXPECT_ERROR_NAMING(circle(nan), "radius");
    EXPECT_ERROR_NAMING(circle(1.0, {}, {0, 0, 0}), "normal");
    EXPECT_ERROR_NAMING(circle(1.0, {nan, 0, 0}), "center");
    EXPECT_ERROR_NAMING(arc(1.0, 10, 10), "end_deg");
    EXPECT_ERROR_NAMING(arc(1.0, 0, 361), "end_deg");
    EXPECT_ERROR_NAMING(arc(1.0, nan, 10), "start_deg");
    EXPECT_ERROR_NAMING(ellipse_arc(0.0, 1.0, 0, 90), "a");
    EXPECT_ERROR_NAMING(ellipse_arc(1.0, -2.0, 0, 90), "b");
    EXPECT_ERROR_NAMING(line_segment({1, 1, 1}, {1, 1, 1}), "end");
    EXPECT_ERROR_NAMING(line_segment({nan, 1, 1}, {1, 1, 1}), "start");
}

}  // namespace
}  // namespace ratbez
