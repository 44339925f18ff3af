#include "ratbez/frame.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "solid_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

TEST(Frame, IsRightHandedOrthonormalWithZAlongTheAxis) {
    for (int k = 0; k < 1000; ++k) {
        const Vec3 axis = random_point(10.0);
        const Frame f = frame_from_axis(random_point(5.0), axis);
        EXPECT_NEAR(norm(f.x_axis), 1.0, 1e-15);
        EXPECT_NEAR(norm(f.y_axis), 1.0, 1e-15);
        EXPECT_NEAR(dot(f.x_axis, f.y_axis), 0.0, 1e-15);
        // Each component of the cross product rounds twice on top of the axes' own rounding: about 20 ulp.
        EXPECT_NEAR(distance(cross(f.x_axis, f.y_axis), f.z_axis), 0.0, 1e-14);
        EXPECT_NEAR(distance(f.z_axis, axis / norm(axis)), 0.0, 1e-15);
    }
}

TEST(Frame, XIsTheGlobalXProjectedOrGlobalYNearTheXAxis) {
    const Frame z = frame_from_axis({1, 2, 3}, {0, 0, 5});
    EXPECT_EQ(z.x_axis, (Vec3{1, 0, 0}));
    EXPECT_EQ(z.y_axis, (Vec3{0, 1, 0}));
    EXPECT_EQ(z.origin, (Vec3{1, 2, 3}));
    const Frame tilted = frame_from_axis({}, {1, 0, 1});
    EXPECT_NEAR(tilted.x_axis.x, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(tilted.x_axis.z, -std::sqrt(0.5), 1e-15);
    const Frame along_x = frame_from_axis({}, {2, 0, 0});
    EXPECT_EQ(along_x.x_axis, (Vec3{0, 1, 0}));
    EXPECT_EQ(along_x.y_axis, (Vec3{0, 0, 1}));
    const Frame to_world = frame_from_axis({1, 1, 1}, {0, 0, 1});
    EXPECT_EQ(to_world.to_world({1, 2, 3}), (Vec3{2, 3, 4}));
}

TEST(Frame, RejectsZeroAndNonFiniteAxesNamingTheArgument) {
    EXPECT_ERROR_NAMING(frame_from_axis({}, {0, 0, 0}), "axis");
    EXPECT_ERROR_NAMING(frame_from_axis({}, {0, std::numeric_limits<double>::quiet_NaN(), 1}), "axis");
    EXPECT_ERROR_NAMING(frame_from_axis({}, {0, 0, 0}, "direction"), "direction");
    EXPECT_ERROR_NAMING(frame_from_axis({std::numeric_limits<double>::infinity(), 0, 0}, {0, 0, 1}), "origin");
}

}  // namespace
}  // namespace ratbez
