// ratbez::occt::check: the report of every primitive passes with its analytic surface and closed-form
// volume; a wrong claim fails with a reason; bad options throw naming the option.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "occt_test_support.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/check.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"

namespace ratbez::occt {
namespace {

using Kind = AnalyticShape::Kind;

CheckOptions with(AnalyticShape shape, int grid = 30) {
    CheckOptions options;
    options.grid = grid;
    options.analytic = shape;
    return options;
}

void expect_passes(const Solid& solid, const CheckOptions& options, const std::string& name,
                   testing::MaxTracker& deviation, testing::MaxTracker& analytic) {
    const CheckReport report = check(solid, options);
    EXPECT_TRUE(report.passed) << name << "\n" << format_report(report);
    EXPECT_TRUE(report.valid) << name;
    EXPECT_TRUE(report.closed) << name;
    EXPECT_GT(report.size, 0);
    deviation.add(report.max_deviation / report.size);
    EXPECT_LE(report.max_deviation, 1e-12 * report.size) << name;
    if (options.analytic.kind != Kind::none) {
        ASSERT_TRUE(report.max_analytic_deviation.has_value()) << name;
        analytic.add(*report.max_analytic_deviation / report.size);
        EXPECT_LE(*report.max_analytic_deviation, 1e-10 * report.size) << name;
    }
    EXPECT_NEAR(report.occt_volume, report.volume, 1e-6 * report.volume) << name;
    EXPECT_NEAR(report.occt_area, report.area, 1e-6 * report.area) << name;
    if (report.closed_form_volume) {
        EXPECT_NEAR(*report.closed_form_volume, report.volume, 1e-6 * report.volume) << name;
    }
    EXPECT_TRUE(report.failures.empty()) << name;
}

TEST(Check, EveryPrimitivePassesAgainstItsAnalyticSurface) {
    testing::MaxTracker deviation("check: max |ours - OCCT D0| / size");
    testing::MaxTracker analytic("check: max analytic distance / size");
    const Vec3 c{1, 2, -1}, axis{1, -1, 2};
    expect_passes(cylinder(2, 5, c, axis), with({Kind::cylinder, c, axis, 2, 0, 5, {}}), "cylinder", deviation, analytic);
    expect_passes(cone(2, 0.5, 3, c, axis), with({Kind::cone, c, axis, 2, 0.5, 3, {}}), "cone", deviation, analytic);
    expect_passes(cone(0, 1.5, 3, c, axis), with({Kind::cone, c, axis, 0, 1.5, 3, {}}), "cone apex at base", deviation,
                  analytic);
    const Vec3 sphere_center{3, 1, -2};
    expect_passes(sphere(2.5, sphere_center), with({Kind::sphere, sphere_center, {0, 0, 1}, 2.5, 0, 0, {}}), "sphere",
                  deviation, analytic);
    expect_passes(torus(4, 1, c, axis), with({Kind::torus, c, axis, 4, 1, 0, {}}), "torus", deviation, analytic);
    const Profile vase = Profile::from_beziers(
        {BezierCurve({{0, 0, 0}, {4, 0, 0.5}, {0.5, 0, 3}, {0, 0, 4}}, {1, 0.5, 2, 1})});
    expect_passes(revolve(vase, {}, {0, 0, 1}, 180), with({Kind::revolution, {}, {0, 0, 1}, 0, 0, 0, {}}, 20),
                  "vase 180", deviation, analytic);
}

TEST(Check, ReportIsFormattedWithPassAndFail) {
    const CheckReport report = check(sphere(1), with({Kind::sphere, {}, {0, 0, 1}, 1, 0, 0, {}}, 10));
    const std::string text = format_report(report);
    EXPECT_NE(text.find("PASSED"), std::string::npos) << text;
    EXPECT_NE(text.find("BRepCheck valid"), std::string::npos) << text;
    EXPECT_NE(text.find("volume (closed form)"), std::string::npos) << text;
    EXPECT_EQ(text.find("FAIL"), std::string::npos) << text;
}

TEST(Check, AWrongClaimFails) {
    // The solid is a sphere of radius 1, the claim radius 1.1: the analytic distance is 0.1 and the
    // closed-form volume is off by 33%.
    const CheckReport report = check(sphere(1), with({Kind::sphere, {}, {0, 0, 1}, 1.1, 0, 0, {}}, 10));
    EXPECT_FALSE(report.passed);
    EXPECT_TRUE(report.valid);
    ASSERT_TRUE(report.max_analytic_deviation.has_value());
    EXPECT_NEAR(*report.max_analytic_deviation, 0.1, 1e-12);
    EXPECT_EQ(report.failures.size(), 2u);
    EXPECT_NE(format_report(report).find("FAIL"), std::string::npos);
}

TEST(Check, BadOptionsThrowNamingTheOption) {
    const Solid solid = sphere(1);
    CheckOptions options;
    options.grid = 1;
    try {
        (void)check(solid, options);
        FAIL() << "grid 1 must throw";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("options.grid", 0), 0u) << e.what();
    }
    options = {};
    options.analytic = {Kind::torus, {}, {0, 0, 0}, 2, 1, 0, {}};
    EXPECT_THROW((void)check(solid, options), Error);
}

}  // namespace
}  // namespace ratbez::occt
