// join.hpp: curves meeting end to start become one NURBS curve whose joint knots keep the multiplicity the
// continuity found there leaves (p - k at a C^k joint, none where the pieces are one polynomial).

#include "ratbez/join.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "nurbs_test_support.hpp"
#include "ratbez/continuity.hpp"
#include "ratbez/curves.hpp"

namespace ratbez {
namespace {

using test::Rng;

int multiplicity(const NurbsCurve& c, double u) { return static_cast<int>(std::count(c.knots().begin(), c.knots().end(), u)); }

// The joined curve runs through the pieces one after the other, each over its own domain width.
void expect_pieces(const NurbsCurve& joined, const std::vector<NurbsCurve>& pieces, double tolerance = 1e-12) {
    double start = joined.domain().min;
    double size = 0;
    for (const NurbsCurve& p : pieces) size = std::max(size, p.control_box().diagonal());
    for (const NurbsCurve& p : pieces) {
        const Interval d = p.domain();
        for (int k = 0; k <= 50; ++k) {
            const double f = k / 50.0;
            ASSERT_LE(distance(p.point(d.min + f * d.width()), joined.point(std::min(start + f * d.width(), joined.domain().max))),
                      tolerance * size);
        }
        start += d.width();
    }
    EXPECT_NEAR(start, joined.domain().max, 1e-12);
}

TEST(Join, TheBezierSegmentsOfACubicSplineGiveItsKnotsBack) {
    // Simple interior knots: C2 joints of a cubic, multiplicity 1 = 3 - 2.
    const NurbsCurve spline(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, {{0, 0}, {1, 2}, {2, -1}, {3, 3}, {4, 0}, {5, 1}});
    const std::vector<BezierCurve> segments = spline.bezier_segments();
    std::vector<NurbsCurve> pieces;
    for (const BezierCurve& s : segments) pieces.push_back(NurbsCurve::from_bezier(s));
    const NurbsCurve joined = join(pieces);
    EXPECT_EQ(joined.knots(), spline.knots());
    for (int k = 0; k <= 60; ++k) EXPECT_LE(distance(joined.point(k / 20.0), spline.point(k / 20.0)), 1e-12);
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) EXPECT_EQ(continuity(pieces[k], pieces[k + 1]).parametric, 2);
}

TEST(Join, TwoHalvesOfOneBezierAreOnePolynomialAgain) {
    const BezierCurve cubic({{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}});
    const auto [left, right] = cubic.split(0.5);
    const NurbsCurve joined = join({NurbsCurve::from_bezier(left), NurbsCurve::from_bezier(right)});
    EXPECT_EQ(joined.degree(), 3);
    EXPECT_EQ(joined.knots(), (std::vector<double>{0, 0, 0, 0, 2, 2, 2, 2}));  // the joint knot removed 3 times
    for (int k = 0; k <= 20; ++k) EXPECT_LE(distance(joined.point(k / 10.0), cubic.point(k / 20.0)), 1e-12);
}

TEST(Join, SeedRulesSetTheMultiplicities) {
    // 004: P cubic, Q cubic on [0, 1] each. C1 needs q1 = q0 + (n / m)(p3 - p2); C2 also the second rule.
    const std::vector<Vec3> p{{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
    const Vec3 q0 = p[3], q1 = q0 + (p[3] - p[2]);
    const Vec3 q2 = p[1] - p[2] * 4.0 + p[3] * 4.0;  // m(m-1)(q0 - 2q1 + q2) = n(n-1)(p3 - 2p2 + p1), n = m
    const NurbsCurve a = NurbsCurve::from_bezier(BezierCurve(p));
    const NurbsCurve c2 = NurbsCurve::from_bezier(BezierCurve({q0, q1, q2, {6, 2, 0}}));
    const NurbsCurve c1 = NurbsCurve::from_bezier(BezierCurve({q0, q1, {5, 1, 0}, {6, 2, 0}}));
    const NurbsCurve c0 = NurbsCurve::from_bezier(BezierCurve({q0, {4, 1, 0}, {5, 1, 0}, {6, 2, 0}}));
    EXPECT_EQ(continuity(a, c2).parametric, 2);
    EXPECT_EQ(continuity(a, c1).parametric, 1);
    EXPECT_EQ(continuity(a, c0).parametric, 0);
    EXPECT_EQ(multiplicity(join({a, c2}), 1.0), 1);
    EXPECT_EQ(multiplicity(join({a, c1}), 1.0), 2);
    EXPECT_EQ(multiplicity(join({a, c0}), 1.0), 3);
    expect_pieces(join({a, c1}), {a, c1});
}

TEST(Join, MixedDegreesRandomPiecesAndSmallGaps) {
    Rng rng(1803);
    for (int trial = 0; trial < 60; ++trial) {
        std::vector<NurbsCurve> pieces;
        Vec3 end{};
        for (int k = 0; k < 3; ++k) {
            NurbsCurve c = test::random_curve(rng, (trial + k) % 2 == 0, true, 4);
            // Translate the piece so that it starts 1e-12 from where the previous one ended.
            std::vector<Vec4> pw = c.homogeneous_points();
            const Vec3 shift = k == 0 ? Vec3{} : end - c.start_point() + Vec3{1e-12, 0, 0};
            for (Vec4& q : pw) q = homogenize(project(q) + shift, q.w);
            c = NurbsCurve::from_homogeneous(c.degree(), c.knots(), pw, c.is_rational());
            end = c.end_point();
            pieces.push_back(c);
        }
        const NurbsCurve joined = join(pieces);
        int highest = 0;
        for (const NurbsCurve& c : pieces) highest = std::max(highest, c.degree());
        EXPECT_EQ(joined.degree(), highest);
        expect_pieces(joined, pieces, 1e-10);
    }
}

TEST(Join, RationalArcsStayC0InHomogeneousSpace) {
    // Two quarter circles are C1 as curves but their homogeneous curves are not (w' changes sign at the
    // joint), so the joint keeps multiplicity 2 = p: the homogeneous continuity is what knots can show.
    const NurbsCurve first = arc(1.0, 0, 90), second = arc(1.0, 90, 180);
    const NurbsCurve joined = join({first, second});
    EXPECT_EQ(multiplicity(joined, 1.0), 2);
    expect_pieces(joined, {first, second});
    EXPECT_EQ(continuity(first, second).parametric, 1);
}

TEST(Join, RefusesGapsAndPoints) {
    EXPECT_ERROR_NAMING(join({}), "curves");
    EXPECT_ERROR_NAMING(join({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0.01, 0}, {2, 0, 0})}), "curves");
    EXPECT_ERROR_NAMING(join({line_segment({0, 0, 0}, {1, 0, 0}), NurbsCurve(1, {0, 0, 1, 1}, {{1, 0, 0}, {1, 0, 0}})}),
                        "curves");
}

}  // namespace
}  // namespace ratbez
