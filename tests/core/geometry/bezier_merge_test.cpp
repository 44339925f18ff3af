// bezier_merge.hpp: two Bézier pieces that are parts of one straight segment or one conic arc become that one
// piece; anything else is left alone.

#include "geometry/bezier_merge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez::detail {
namespace {

std::vector<Vec4> homogeneous(const BezierCurve& c) { return c.homogeneous_points(); }

// The unit circle's arc from `start` through `sweep` degrees (below 180) as one rational quadratic (000 §1.4):
// the middle point where the end tangents meet, weight cos(sweep / 2).
BezierCurve unit_arc(double start, double sweep) {
    const double a = start * std::numbers::pi / 180, h = sweep * std::numbers::pi / 360;
    const Vec3 p0{std::cos(a), std::sin(a), 0}, p2{std::cos(a + 2 * h), std::sin(a + 2 * h), 0};
    const Vec3 p1 = Vec3{std::cos(a + h), std::sin(a + h), 0} / std::cos(h);
    return BezierCurve({p0, p1, p2}, {1, std::cos(h), 1});
}

// Points turned by `degrees` about the line through `origin` along the unit vector `axis` (Rodrigues).
BezierCurve turned(const BezierCurve& c, const Vec3& origin, const Vec3& axis, double degrees) {
    const double t = degrees * std::numbers::pi / 180;
    std::vector<Vec3> points;
    for (const Vec3& p : c.points()) {
        const Vec3 v = p - origin;
        points.push_back(origin + v * std::cos(t) + cross(axis, v) * std::sin(t) + axis * (dot(axis, v) * (1 - std::cos(t))));
    }
    return BezierCurve(points, c.weights());
}

// Every point of the two pieces lies on the merged curve, in order.
void expect_covers(const std::vector<Vec4>& merged, const BezierCurve& first, const BezierCurve& second) {
    const BezierCurve one = BezierCurve::from_homogeneous(merged);
    for (const BezierCurve* piece : {&first, &second})
        for (int k = 0; k <= 20; ++k) {
            const Vec3 x = piece->point(k / 20.0);
            double nearest = 1e300;
            for (int j = 0; j <= 4000; ++j) nearest = std::min(nearest, distance(one.point(j / 4000.0), x));
            EXPECT_LE(nearest, 2e-3) << k;  // the 4000-point sampling's spacing, not the curve's error
        }
}

// Ex1.13's quarter circle, P0 = (1, 0), P1 = (1, 1), P2 = (0, 1), weights 1, 1, 2, cut at u = 1/2 where
// Ex1.14 finds (3/5, 4/5): the halves merge back into the same polygon in normal form (middle weight
// 1 / sqrt 2, the weights' invariant w1 / sqrt(w0 w2)).
TEST(BezierMerge, Ex1_13QuarterCircleCutAtTheMiddleMergesBack) {
    const BezierCurve quarter({{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, 1, 2});
    const auto [first, second] = quarter.split(0.5);
    EXPECT_LE(distance(first.points().back(), {0.6, 0.8, 0}), 1e-15);
    const auto merged = merged_bezier(homogeneous(first), homogeneous(second), 1e-12);
    ASSERT_TRUE(merged.has_value());
    const BezierCurve one = BezierCurve::from_homogeneous(*merged);
    const std::vector<Vec3> p = one.points();
    EXPECT_LE(distance(p[0], {1, 0, 0}), 1e-15);
    EXPECT_LE(distance(p[1], {1, 1, 0}), 1e-14);
    EXPECT_LE(distance(p[2], {0, 1, 0}), 1e-15);
    const std::vector<double> w = one.weights();
    EXPECT_NEAR(w[1] / std::sqrt(w[0] * w[2]), 1 / std::sqrt(2.0), 1e-14);
    expect_covers(*merged, first, second);
}

// Arcs of one circle or ellipse merge, wherever they were cut and however their parameters run.
TEST(BezierMerge, ArcsOfOneConicUpTo120Degrees) {
    const BezierCurve a = arc(2.0, 10, 80, {1, 2, 3}, {0, 1, 1}).bezier_segments().front();
    const BezierCurve b = arc(2.0, 80, 130, {1, 2, 3}, {0, 1, 1}).bezier_segments().front();
    const auto merged = merged_bezier(homogeneous(a), homogeneous(b.normal_form()), 1e-12);
    ASSERT_TRUE(merged.has_value());
    EXPECT_NEAR(BezierCurve::from_homogeneous(*merged).weights()[1], std::cos(60 * std::numbers::pi / 180), 1e-13);
    expect_covers(*merged, a, b);

    const BezierCurve e1 = ellipse_arc(3, 1, 0, 50).bezier_segments().front();
    const BezierCurve e2 = ellipse_arc(3, 1, 50, 120).bezier_segments().front();
    const auto ellipse = merged_bezier(homogeneous(e1), homogeneous(e2), 1e-12);
    ASSERT_TRUE(ellipse.has_value());
    expect_covers(*ellipse, e1, e2);

    // Up to 120 degrees (middle weight 1/2, OpenCASCADE's arcs of a circle); not beyond, where the middle point
    // heads for infinity, nor past a half turn.
    EXPECT_TRUE(merged_bezier(homogeneous(unit_arc(0, 70)), homogeneous(unit_arc(70, 50)), 1e-12).has_value());
    EXPECT_FALSE(merged_bezier(homogeneous(unit_arc(0, 70)), homogeneous(unit_arc(70, 55)), 1e-12).has_value());
    EXPECT_FALSE(merged_bezier(homogeneous(unit_arc(0, 120)), homogeneous(unit_arc(120, 120)), 1e-12).has_value());
}

// Tangent-continuous arcs of two different circles, an arc beside a line, and arcs meeting at a corner
// are not one conic.
TEST(BezierMerge, DifferentConicsAndCornersStayApart) {
    const BezierCurve small = arc(1.0, 0, 45).bezier_segments().front();
    const BezierCurve large = arc(2.0, 45, 90, {-std::cos(std::numbers::pi / 4), -std::sin(std::numbers::pi / 4), 0})
                                  .bezier_segments()
                                  .front();  // tangent to `small` where they meet, twice its radius
    ASSERT_LE(distance(small.points().back(), large.points().front()), 1e-15);
    EXPECT_FALSE(merged_bezier(homogeneous(small), homogeneous(large), 1e-9).has_value());
    const BezierCurve along = BezierCurve({small.points().back(), small.points().back() + Vec3{-1, 1, 0}}).elevate();
    EXPECT_FALSE(merged_bezier(homogeneous(small), homogeneous(along), 1e-9).has_value());
    // The circle's next arc turned out of its plane about the tangent at the joint: tangent-continuous still.
    const BezierCurve next = unit_arc(45, 45);
    const Vec3 joint = next.points().front(), tangent = Vec3{-1, 1, 0} / std::sqrt(2.0);
    EXPECT_TRUE(merged_bezier(homogeneous(small), homogeneous(next), 1e-9).has_value());
    EXPECT_FALSE(merged_bezier(homogeneous(small), homogeneous(turned(next, joint, tangent, 20)), 1e-9).has_value());
}

// Straight pieces of any degree and parameterisation merge into the segment, evenly spaced; a piece that
// turns back, or a corner, does not.
TEST(BezierMerge, StraightPiecesMergeIntoTheSegment) {
    const BezierCurve a({{0, 0, 0}, {1, 1, 1}});
    const BezierCurve b({{1, 1, 1}, {3, 3, 3}});
    const auto line = merged_bezier(homogeneous(a), homogeneous(b), 1e-12);
    ASSERT_TRUE(line.has_value());
    ASSERT_EQ(line->size(), 2u);
    EXPECT_LE(distance(project((*line)[1]), {3, 3, 3}), 1e-15);

    const BezierCurve c({{0, 0, 0}, {0.2, 0, 0}, {1, 0, 0}}, {1, 3, 1});  // rational, uneven speed
    const BezierCurve d({{1, 0, 0}, {1.1, 0, 0}, {2, 0, 0}});
    const auto quadratic = merged_bezier(homogeneous(c), homogeneous(d), 1e-12);
    ASSERT_TRUE(quadratic.has_value());
    EXPECT_LE(distance(project((*quadratic)[1]), {1, 0, 0}), 1e-15);
    EXPECT_EQ((*quadratic)[1].w, 1.0);

    const BezierCurve back({{1, 0, 0}, {0.5, 0, 0}, {2, 0, 0}});  // runs back before going on: not a segment once
    EXPECT_FALSE(merged_bezier(homogeneous(c), homogeneous(back), 1e-12).has_value());
    const BezierCurve corner({{1, 0, 0}, {1, 0.5, 0}, {1, 1, 0}});
    EXPECT_FALSE(merged_bezier(homogeneous(c), homogeneous(corner), 1e-12).has_value());
}

}  // namespace
}  // namespace ratbez::detail
