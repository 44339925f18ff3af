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
