// section_alignment.hpp (issue 26): sections matched by normalised arc length from the start points of
// least twist. A circle lofted to itself turned by any angle is a cylinder (rulings vertical to 1e-13);
// corners and joints of every section land at the same normalised arc length on all, smooth sections run on
// their own parameter between them (issue 25); orientation, open sections, creases and the restart at a crease.

#include "modelling/section_alignment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nurbs_test_support.hpp"
#include "ratbez/arc_length.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/closest_point.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/interpolation.hpp"
#include "ratbez/join.hpp"
#include "ratbez/ruled.hpp"

namespace ratbez::detail {
namespace {

constexpr double pi = std::numbers::pi;

NurbsCurve turned_circle(double radius, double z, double degrees, const Vec3& normal = {0, 0, 1}) {
    // The circle of circle(), its start turned by `degrees` about z (its own parameterisation moves with it).
    const NurbsCurve c = circle(radius, {0, 0, z}, normal);
    std::vector<Vec4> pw = c.homogeneous_points();
    const double a = degrees * pi / 180, cs = std::cos(a), sn = std::sin(a);
    for (Vec4& q : pw) q = Vec4{cs * q.x - sn * q.y, sn * q.x + cs * q.y, q.z, q.w};
    return NurbsCurve::from_homogeneous(c.degree(), c.knots(), pw, true);
}

NurbsCurve square(double half, double z, int start_corner, bool clockwise = false) {
    std::vector<Vec3> corners{{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}};
    if (clockwise) std::reverse(corners.begin(), corners.end());
    std::vector<NurbsCurve> sides;
    for (int k = 0; k < 4; ++k) sides.push_back(line_segment(corners[(start_corner + k) % 4], corners[(start_corner + k + 1) % 4]));
    return join(sides);
}

TEST(SectionAlignment, ACircleTurnedByAnyAngleLoftsToACylinder) {
    for (const double angle : {0.0, 30.0, 90.0, 120.0, 180.0, 237.5}) {
        SCOPED_TRACE(angle);
        const AlignedSections aligned = align_sections({circle(2.0), turned_circle(2.0, 4, angle)}, "curves");
        ASSERT_TRUE(aligned.closed);
        const NurbsSurface s = ruled_surface(aligned.curves[0], aligned.curves[1], false);
        for (int i = 0; i <= 64; ++i) {
            const double u = i / 64.0;
            const Vec3 bottom = s.point(u, 0), top = s.point(u, 1), middle = s.point(u, 0.5);
            EXPECT_LE(std::hypot(top.x - bottom.x, top.y - bottom.y), 1e-13);  // a vertical ruling
            EXPECT_NEAR(std::hypot(middle.x, middle.y), 2.0, 1e-13);
        }
    }
}

TEST(SectionAlignment, BreakpointsMeetAtTheSameNormalisedArcLength) {
    // A circle (4 arcs from +x) and a square (4 sides from a corner at 225 degrees): the square's corners
    // land where the circle has travelled the same fraction of its length from its chosen start.
    const AlignedSections aligned = align_sections({circle(2.0), square(1.5, 4, 0)}, "curves");
    ASSERT_EQ(aligned.curves.size(), 2u);
    const NurbsCurve& round = aligned.curves[0];
    const NurbsCurve& square_curve = aligned.curves[1];
    EXPECT_EQ(breakpoints(round.degree(), round.knots()), breakpoints(square_curve.degree(), square_curve.knots()));
    const ArcLength circle_length(round), square_length(square_curve);
    for (const double b : aligned.breaks) {
        EXPECT_NEAR(circle_length.at(b) / circle_length.total(), b, 1e-12);
        EXPECT_NEAR(square_length.at(b) / square_length.total(), b, 1e-12);
    }
    // The least twist matches the square's corners to the circle at 45, 135, ... degrees, and the seam goes to
    // the first of them (from +x, the circle's own start): the square starts at its corner (1.5, 1.5), the circle
    // at 45 degrees, and the corners are at 0, 1/4, 1/2 and 3/4, where the circle points the same way.
    EXPECT_LE(distance(square_curve.start_point(), {1.5, 1.5, 4}), 1e-9);
    EXPECT_LE(distance(round.start_point(), {std::sqrt(2.0), std::sqrt(2.0), 0}), 1e-9);
    for (int k = 0; k < 4; ++k) {
        const double b = k / 4.0;
        const Vec3 corner = square_curve.point(b), on_circle = round.point(b);
        EXPECT_NEAR(std::abs(corner.x), 1.5, 1e-9) << k;
        EXPECT_NEAR(std::abs(corner.y), 1.5, 1e-9) << k;
        EXPECT_NEAR(std::atan2(corner.y, corner.x), std::atan2(on_circle.y, on_circle.x), 1e-9) << k;
    }
}

// A section's own joints where every other section runs on within one piece leave no break: a circle of three
// 120 degree arcs (as OpenCASCADE makes one) against a square has breaks at the square's corners only, where
// Part's Loft puts its edges, the seam at the first of them; each break still matched exactly by arc length.
// Without the merge the circle's joints at 1/3 and 2/3 were knots of the loft too, and OpenCASCADE face edges;
// with the seam at the circle's start (halfway along a side), the side faces met there in a fold.
TEST(SectionAlignment, JointsOnlyOneSectionHasLeaveNoBreak) {
    const NurbsCurve thirds = join({arc(2.0, 0, 120), arc(2.0, 120, 240), arc(2.0, 240, 360)});
    const AlignedSections aligned = align_sections({thirds, square(1.5, 4, 0)}, "curves");
    ASSERT_EQ(aligned.breaks.size(), 5u);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(aligned.breaks[static_cast<std::size_t>(k)], k / 4.0, 1e-12) << k;
    for (const NurbsCurve& c : aligned.curves) {
        EXPECT_EQ(breakpoints(c.degree(), c.knots()), aligned.breaks);
        const ArcLength length(c);
        for (const double b : aligned.breaks) EXPECT_NEAR(length.at(b) / length.total(), b, 1e-12);
    }
    // The quarter between two corners is one arc of 90 degrees, the corners' directions matched.
    const NurbsCurve& round = aligned.curves[0];
    EXPECT_NEAR(round.bezier_segments()[1].weights()[1], std::cos(pi / 4), 1e-12);
    for (int k = 0; k < 4; ++k) {
        const Vec3 on_circle = round.point(aligned.breaks[static_cast<std::size_t>(k)]);
        EXPECT_NEAR(std::atan2(on_circle.y, on_circle.x), (45 + 90 * k - (k >= 2 ? 360 : 0)) * pi / 180, 1e-9) << k;
    }
    // A break where the pieces are arcs of two different circles stays: a circle against a rounded square
    // keeps the rounded square's joints between its lines and corner arcs (8), plus the seam.
    std::vector<NurbsCurve> rounded;  // corners of radius 1 about (+-1, +-1), sides 2 long, from (2, 1)
    for (int k = 0; k < 4; ++k) {
        const double a = k * 90.0, b = (a + 90) * pi / 180;
        const Vec3 centre{(k == 0 || k == 3) ? 1.0 : -1.0, k < 2 ? 1.0 : -1.0, 2};
        const Vec3 corner_end = centre + Vec3{std::cos(b), std::sin(b), 0};
        rounded.push_back(arc(1.0, a, a + 90, centre));
        rounded.push_back(line_segment(corner_end, corner_end + Vec3{-std::sin(b), std::cos(b), 0} * 2.0));
    }
    const AlignedSections kept = align_sections({circle(3.0), join(rounded)}, "curves");
    EXPECT_EQ(kept.breaks.size(), 10u);
}

// The largest multiplicity of an interior knot: p or more is C0 in the parameter (an edge in OpenCASCADE).
int largest_inner_multiplicity(const NurbsCurve& c) {
    int largest = 0;
    for (const double u : breakpoints(c.degree(), c.knots()))
        if (u > c.domain().min && u < c.domain().max)
            largest = std::max(largest, static_cast<int>(std::count(c.knots().begin(), c.knots().end(), u)));
    return largest;
}

TEST(SectionAlignment, SmoothSectionsRunOnTheirOwnParameterBetweenCorners) {
    // The sections of examples/interpolated_loft.json: closed interpolations (centripetal cubic, chord cubic,
    // quadratic) with knots at unrelated lengths. Cut and matched by arc length at every knot, each would be C0
    // at all of them (16 side faces in OpenCASCADE; Part's Loft of the same curves has no such edges); as
    // their own parameters run, from the starts of least twist, they stay smooth: one side face.
    const std::vector<NurbsCurve> smooth{
        interpolate({{6, 0, 0}, {2, 3, 0}, {-3, 5, 0}, {-3, 0, 0}, {-3, -5, 0}, {2, -3, 0}}, 3, Parameterization::centripetal, {}, true),
        interpolate({{0, 5, 8}, {-4, 4, 8}, {-5, 0, 8}, {-4, -4, 8}, {0, -5, 8}, {4, -4, 8}, {6, 0, 8}, {4, 4, 8}}, 3,
                    Parameterization::chord, {}, true),
        interpolate({{7, 0, 16}, {0, 3, 16}, {-7, 0, 16}, {0, -3, 16}}, 2, Parameterization::chord, {}, true)};
    const AlignedSections aligned = align_sections(smooth, "curves");
    EXPECT_EQ(aligned.breaks, (std::vector<double>{0.0, 1.0}));
    for (std::size_t k = 0; k < smooth.size(); ++k) {
        SCOPED_TRACE(k);
        const NurbsCurve& c = aligned.curves[k];
        EXPECT_EQ(c.knots(), aligned.curves[0].knots());  // one knot vector
        EXPECT_LE(largest_inner_multiplicity(c), c.degree() - 1);  // C1 or better everywhere (the quadratic: C1)
        // The same curve: every point on the section, and a whole turn of it.
        for (int i = 0; i <= 50; ++i)
            EXPECT_LE(closest_point(smooth[k], c.point(i / 50.0)).distance, 1e-12);
        EXPECT_NEAR(ArcLength(c).total(), ArcLength(smooth[k]).total(), 1e-9);
    }
    // The starts of least twist are kept: each start is the point of its section nearest to the previous start
    // here (the sections are alike enough).
    EXPECT_LE(distance(aligned.curves[0].start_point(), {6, 0, 0}), 1e-12);
    // A smooth section against a square: the square's corners stay breaks, matched by arc length; between
    // them the smooth section runs on its own parameter (no knot of multiplicity p inside a side).
    const AlignedSections cornered = align_sections({square(3, 0, 0), smooth[1]}, "curves");
    ASSERT_EQ(cornered.breaks.size(), 5u);
    const NurbsCurve& ring = cornered.curves[1];
    for (const double u : breakpoints(ring.degree(), ring.knots())) {
        const auto m = std::count(ring.knots().begin(), ring.knots().end(), u);
        const bool at_break = std::find(cornered.breaks.begin(), cornered.breaks.end(), u) != cornered.breaks.end();
        EXPECT_EQ(m >= ring.degree(), at_break) << u;
    }
    const ArcLength ring_length(ring);
    for (const double b : cornered.breaks) EXPECT_NEAR(ring_length.at(b) / ring_length.total(), b, 1e-12);
}

TEST(SectionAlignment, OrientationStartAndOpenSections) {
    // A clockwise copy is turned round: the result runs as the first section does.
    const AlignedSections closed = align_sections({circle(1.0), turned_circle(1.0, 2, 40, {0, 0, -1})}, "curves");
    const Vec3 a = closed.curves[0].derivative(0.1), b = closed.curves[1].derivative(0.1);
    EXPECT_GT(dot(a, b), 0.99 * norm(a) * norm(b));
    // Open sections: matched end to end, the second reversed when its ends are nearer that way.
    const AlignedSections open = align_sections({line_segment({0, 0, 0}, {4, 0, 0}), line_segment({4, 0, 1}, {0, 0, 1})}, "curves");
    EXPECT_FALSE(open.closed);
    EXPECT_LE(distance(open.curves[1].start_point(), {0, 0, 1}), 1e-15);
    // A half circle of 2 arcs against a segment: at every break both have gone the same fraction of their
    // lengths (the arcs' joint at 90 degrees meets the segment's midpoint).
    const AlignedSections mixed = align_sections({arc(1.0, 0, 180), line_segment({1, 0, 1}, {-1, 0, 1})}, "curves");
    ASSERT_EQ(mixed.breaks.size(), 3u);
    EXPECT_LE(distance(mixed.curves[0].point(0.5), {0, 1, 0}), 1e-12);
    EXPECT_LE(distance(mixed.curves[1].point(0.5), {0, 0, 1}), 1e-12);
    // Errors: a point has no length; closed with open.
    EXPECT_ERROR_NAMING(align_sections({circle(1.0), arc(1.0, 0, 90, {0, 0, 1})}, "sections"), "sections");
}

TEST(SectionAlignment, CreasesRunThroughEverySection) {
    // Square to square: four creases; circle to square: none (the circle is one smooth run).
    const AlignedSections squares = align_sections({square(1, 0, 0), square(1, 2, 2)}, "curves");
    EXPECT_EQ(full_creases(squares.curves, true).size(), 4u);
    const AlignedSections mixed = align_sections({circle(1.5), square(1, 2, 0)}, "curves");
    EXPECT_TRUE(full_creases(mixed.curves, true).empty());
    EXPECT_TRUE(full_creases({circle(1.0), circle(2.0, {0, 0, 1})}, true).empty());
    // Restarted at a crease, the matching is kept: the same points at the same parameters, shifted.
    const std::vector<NurbsCurve> restarted = restarted_at(squares.curves, 0.25);
    for (int k = 0; k <= 20; ++k) {
        const double u = k / 20.0;
        for (std::size_t i = 0; i < 2; ++i)
            EXPECT_LE(distance(restarted[i].point(u), squares.curves[i].point(std::fmod(u + 0.25, 1.0))), 1e-14);
    }
    // A smooth curve keeps its continuity: a closed cubic interpolation restarted inside a span has simple
    // knots still, and its old start (C2) is the one knot of multiplicity 3.
    const NurbsCurve ring = interpolate({{3, 0, 0}, {0, 2, 0}, {-3, 0, 0}, {0, -2, 0}, {1, -1, 0}}, 3, Parameterization::chord, {}, true);
    const NurbsCurve turned = restarted_at({ring}, 0.3).front();
    for (const double u : breakpoints(3, turned.knots()))
        if (u > 0 && u < 1) {
            EXPECT_EQ(std::count(turned.knots().begin(), turned.knots().end(), u), u == 0.7 ? 3 : 1) << u;
        }
    for (int k = 0; k <= 20; ++k) EXPECT_LE(distance(turned.point(k / 20.0), ring.point(std::fmod(k / 20.0 + 0.3, 1.0))), 1e-14);
}

}  // namespace
}  // namespace ratbez::detail
