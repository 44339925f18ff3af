#include "ratbez/profile.hpp"

#include <gtest/gtest.h>

#include "ratbez/curves.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

TEST(Profile, JoinsPiecesAndDetectsClosure) {
    const Profile open({line_segment({1, 0, 0}, {2, 0, 0}), arc(1.0, 0, 90, {1, 0, 0}, {0, -1, 0})});
    EXPECT_FALSE(open.is_closed());
    EXPECT_EQ(open.start_point(), (Vec3{1, 0, 0}));
    EXPECT_NEAR(distance(open.end_point(), Vec3{1, 0, 1}), 0, 1e-15);

    const Profile triangle({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {0, 1, 0}),
                            line_segment({0, 1, 0}, {0, 0, 0})});
    EXPECT_TRUE(triangle.is_closed());
    EXPECT_TRUE(Profile({circle(1.0)}).is_closed());
    EXPECT_NEAR(triangle.size(), std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(triangle.tolerance(), 1e-9 * std::sqrt(2.0), 1e-24);
}

TEST(Profile, SnapsJointsWithinToleranceExactly) {
    const Profile p({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1 + 1e-12, 0, 0}, {1, 1, 0}),
                     line_segment({1, 1, 0}, {0, 1e-12, 0})});
    EXPECT_EQ(p.pieces()[1].start_point(), p.pieces()[0].end_point());
    EXPECT_TRUE(p.is_closed());
    EXPECT_EQ(p.pieces()[2].end_point(), p.pieces()[0].start_point());
}

TEST(Profile, ClampsUnclampedPiecesWithoutChangingThem) {
    // A uniform (unclamped) quadratic B-spline: its domain [2, 3] and its points are kept.
    const NurbsCurve uniform(2, {0, 1, 2, 3, 4, 5}, {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}});
    const Profile p({uniform});
    for (double t : {2.0, 2.25, 2.5, 3.0}) EXPECT_NEAR(distance(p.pieces()[0].point(t), uniform.point(t)), 0, 1e-15);
    EXPECT_EQ(p.pieces()[0].points().front(), uniform.point(2.0));
}

TEST(Profile, PutsPiecesWithUnevenSpanWeightsInNormalForm) {
    // End weights 1 and 0.01 crowd the parameter of this quadratic towards its start (round-trip seed
    // 20264282 had 2.4e-3 against 23): Profile keeps the curve and its domain, not that parameterisation.
    const NurbsCurve crowded(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {2, 1, 0}, {1, 2, 0}}, {1, 3, 0.01});
    const Profile p({crowded, line_segment({1, 2, 0}, {1, 0, 0})});
    const NurbsCurve& piece = p.pieces()[0];
    EXPECT_EQ(piece.weights().front(), 1.0);
    EXPECT_EQ(piece.weights().back(), 1.0);
    EXPECT_EQ(piece.domain().min, 0.0);
    EXPECT_EQ(piece.domain().max, 1.0);
    // The same curve: rho = (1 / 0.01)^(1/2) = 10 maps s to t = 10 s / ((1 - s) + 10 s).
    for (double s : {0.1, 0.5, 0.9})
        EXPECT_NEAR(distance(piece.point(s), crowded.point(10 * s / ((1 - s) + 10 * s))), 0, 1e-15);
    // Its midpoint in parameter is now far from the start; it was within 0.07 of (2, 1, 0)'s side.
    EXPECT_GT(distance(piece.point(0.5), crowded.point(0.0)), distance(crowded.point(0.5), crowded.point(0.0)));

    // End weights within 4x of each other, and polynomial pieces, keep their parameterisation.
    const NurbsCurve mild(2, {0, 0, 0, 0.5, 1, 1, 1}, {{1, 0, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}}, {1, 1.5, 1.2, 0.6});
    const Profile q({mild, line_segment({1, 2, 0}, {1, 0, 0})});
    EXPECT_EQ(q.pieces()[0].knots(), mild.knots());
    EXPECT_EQ(q.pieces()[0].weights(), mild.weights());
}

TEST(Profile, ReversedRunsBackwards) {
    const Profile p({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {1, 1, 0})});
    const Profile r = p.reversed();
    EXPECT_EQ(r.start_point(), p.end_point());
    EXPECT_EQ(r.end_point(), p.start_point());
}

TEST(Profile, RejectsEmptyAndDisjointPiecesNamingProfile) {
    EXPECT_ERROR_NAMING(Profile(std::vector<NurbsCurve>{}), "profile");
    EXPECT_ERROR_NAMING(Profile({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1.001, 0, 0}, {2, 0, 0})}), "profile");
    const std::string message = test::error_message(
        [] { Profile({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1.5, 0, 0}, {2, 0, 0})}); });
    EXPECT_NE(message.find("piece 1"), std::string::npos) << message;
    EXPECT_ERROR_NAMING(Profile({NurbsCurve(1, {0, 0, 1, 1}, {{1, 1, 1}, {1, 1, 1}})}), "profile");
}

}  // namespace
}  // namespace ratbez
