#include "ratbez/construction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <string_view>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

double relative(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

// The solid's record is of `kind` and equals `expected`.
void expect_record(const Solid& solid, std::string_view kind, const Construction& expected) {
    EXPECT_EQ(solid.construction().kind(), kind);
    EXPECT_TRUE(solid.construction() == expected) << kind;
}

// The closed forms against the adaptive cubature of properties.cpp on the exact faces: two independent
// computations of the same numbers (the cubature knows nothing of the record).
TEST(Construction, ClosedFormsAgreeWithTheCubatureOfEveryPrimitive) {
    const Vec3 c{3, -2, 5}, axis{1, 2, -0.5};
    const struct {
        std::string name;
        Solid solid;
    } cases[] = {
        {"cylinder", cylinder(1.7, 2.3, c, axis)},
        {"frustum", cone(1.7, 0.6, 2.3, c, axis)},
        {"apex cone", cone(1.7, 0, 2.3, c, axis)},
        {"apex at the base", cone(0, 1.7, 2.3, c, axis)},
        {"cone of equal radii", cone(1.1, 1.1, 0.4, c, axis)},
        {"sphere", sphere(1.7, c)},
        {"torus", torus(4.1, 1.7, c, axis)},
        {"thin torus", torus(6, 0.5, c, axis)},
    };
    double worst = 0;
    for (const auto& [name, solid] : cases) {
        const auto volume = solid.construction().exact_volume();
        const auto area = solid.construction().exact_area();
        ASSERT_TRUE(volume.has_value()) << name;
        ASSERT_TRUE(area.has_value()) << name;
        const double volume_error = relative(solid.volume(), *volume), area_error = relative(solid.area(), *area);
        EXPECT_LT(volume_error, 1e-12) << name;
        EXPECT_LT(area_error, 1e-12) << name;
        worst = std::max({worst, volume_error, area_error});
    }
    std::cout << "[ measured ] closed forms vs cubature: largest relative difference " << worst << "\n";
}

TEST(Construction, PrimitivesRecordTheirArguments) {
    const Vec3 c{1, 2, -1}, axis{1, -1, 2};
    const Vec3 unit = frame_from_axis({}, axis).z_axis;  // records hold unit axes
    EXPECT_NEAR(norm(unit), 1.0, 1e-15);
    EXPECT_NEAR(norm(cross(unit, axis)), 0.0, 1e-15);
    expect_record(cylinder(2, 5, c, axis), "cylinder", Construction::Cylinder{c, unit, 2, 5});
    expect_record(cone(2, 0.5, 3, c, axis), "cone", Construction::Cone{c, unit, 2, 0.5, 3});
    expect_record(cone(0, 1.5, 3, c, axis), "cone", Construction::Cone{c, unit, 0, 1.5, 3});
    expect_record(sphere(2.5, {3, 1, -2}), "sphere", Construction::Sphere{{3, 1, -2}, 2.5});
    expect_record(torus(4, 1, c, axis), "torus", Construction::Torus{c, unit, 4, 1});
    // A record of another kind, or other numbers, is not equal.
    EXPECT_EQ(cylinder(2, 5, c, axis).construction().get<Construction::Sphere>(), nullptr);
    EXPECT_FALSE(cylinder(2, 5, c, axis).construction() == Construction(Construction::Cylinder{c, unit, 2, 5.5}));
    EXPECT_FALSE(cone(2, 2, 5, c, axis).construction() == Construction(Construction::Cylinder{c, unit, 2, 5}));
}

TEST(Construction, SweepsRecordTheirParametersAndHaveNoClosedForm) {
    const Profile square = Profile::from_beziers({BezierCurve({{1, 0, 0}, {2, 0, 0}}),
                                                  BezierCurve({{2, 0, 0}, {2, 0, 1}}),
                                                  BezierCurve({{2, 0, 1}, {1, 0, 1}}),
                                                  BezierCurve({{1, 0, 1}, {1, 0, 0}})});
    const Solid turned = revolve(square, {0, 0, 0}, {0, 0, 3}, 270);
    expect_record(turned, "revolution", Construction::Revolution{{0, 0, 0}, {0, 0, 1}, 270});
    const Solid prism = extrude(square, {0, 2, 0}, 1.5);
    expect_record(prism, "extrusion", Construction::Extrusion{{0, 1, 0}, 1.5});
    for (const Solid& solid : {turned, prism}) {
        EXPECT_FALSE(solid.construction().exact_volume().has_value());
        EXPECT_FALSE(solid.construction().exact_area().has_value());
    }
}

TEST(Construction, SolidsAssembledFromFacesAreOfKindNone) {
    const Solid ball = sphere(1);
    const Solid faces_only(ball.faces());
    EXPECT_EQ(faces_only.construction().kind(), "none");
    EXPECT_TRUE(std::holds_alternative<std::monostate>(faces_only.construction().parameters()));
    EXPECT_FALSE(faces_only.construction().exact_volume().has_value());
    EXPECT_FALSE(faces_only.construction().exact_area().has_value());
    const Solid copy = ball;  // a copy keeps the record
    EXPECT_EQ(copy.construction().kind(), "sphere");
}

TEST(Construction, RecordsAreValidatedNamingTheField) {
    EXPECT_ERROR_NAMING(Construction(Construction::Sphere{{}, -1}), "construction.radius");
    EXPECT_ERROR_NAMING(Construction(Construction::Sphere{{nan_value, 0, 0}, 1}), "construction.center");
    EXPECT_ERROR_NAMING(Construction(Construction::Cylinder{{}, {0, 0, 0}, 1, 1}), "construction.axis");
    EXPECT_ERROR_NAMING(Construction(Construction::Cylinder{{}, {0, 0, 1}, 1, inf_value}), "construction.height");
    EXPECT_ERROR_NAMING(Construction(Construction::Cone{{}, {0, 0, 1}, 0, 0, 1}), "construction.radius1");
    EXPECT_ERROR_NAMING(Construction(Construction::Cone{{}, {0, 0, 1}, 1, -1, 1}), "construction.radius2");
    EXPECT_ERROR_NAMING(Construction(Construction::Torus{{}, {0, 0, 1}, 1, 2}), "construction.minor_radius");
    EXPECT_ERROR_NAMING(Construction(Construction::Revolution{{}, {0, 0, 1}, 0}), "construction.angle_deg");
    EXPECT_ERROR_NAMING(Construction(Construction::Revolution{{}, {0, 0, 1}, 361}), "construction.angle_deg");
    EXPECT_ERROR_NAMING(Construction(Construction::Extrusion{{0, 0, 0}, 1}), "construction.direction");
    EXPECT_ERROR_NAMING(Construction(Construction::Extrusion{{0, 0, 1}, 0}), "construction.distance");
    // A valid record's axis is normalised.
    const Construction tilted = Construction::Torus{{}, {0, 0, 4}, 2, 1};
    EXPECT_EQ(tilted.get<Construction::Torus>()->axis, (Vec3{0, 0, 1}));
}

}  // namespace
}  // namespace ratbez
