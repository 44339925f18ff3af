// Issue 14, items 9-11 in the core: sizes bounded before the work (limits.hpp), no silent non-finite answer
// (weights scaled, basis from ratios), messages naming the real cause and printable (text.hpp).

#include "ratbez/limits.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ratbez/bernstein.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/power_basis.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/text.hpp"

namespace ratbez {
namespace {

// The argument of the Error `call` throws ("" and a failure when none).
template <class Call>
std::string argument_of(Call call) {
    try {
        call();
    } catch (const Error& e) {
        return std::string(e.argument());
    }
    ADD_FAILURE() << "no Error";
    return "";
}

std::vector<Vec3> line_points(std::size_t n) {
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < n; ++i) points.push_back({static_cast<double>(i), 1.0, 0.0});
    return points;
}

TEST(Limits, OneDegreeLimitForBasesCurvesAndMatrices) {
    EXPECT_EQ(argument_of([] { BezierCurve(line_points(limits::max_degree + 2)); }), "points");
    EXPECT_EQ(BezierCurve(line_points(limits::max_degree + 1)).degree(), limits::max_degree);
    EXPECT_EQ(argument_of([] { BezierCurve(line_points(100000)); }), "points");  // took 57 s before the refusal
    EXPECT_EQ(argument_of([] { bezier_to_power_matrix(1100); }), "n");
    EXPECT_EQ(argument_of([] { bernstein(0, 1 << 30, 0.5); }), "n");
    EXPECT_EQ(argument_of([] { bspline_basis(0, 2147483647, std::vector<double>{0.0, 1.0}, 0.5); }), "p");
    EXPECT_EQ(argument_of([] { BezierCurve(line_points(limits::max_degree + 1)).elevate(); }), "curve");
}

TEST(Limits, CurvePointsAreBoundedBeforeAProfileIsBuilt) {
    const std::size_t n = limits::max_curve_points + 1;
    std::vector<double> knots{0.0};
    for (std::size_t i = 0; i < n; ++i) knots.push_back(static_cast<double>(i));
    knots.push_back(static_cast<double>(n - 1));
    EXPECT_EQ(argument_of([&] { NurbsCurve(1, knots, line_points(n)); }), "points");
}

TEST(Limits, ExtremeWeightsGiveTheTruePointAndComeBackExactly) {
    const BezierCurve curve({{1, 0, 0}, {1, 1, 0}}, {1e308, 1e308});  // point(0.5) was (inf, 0.5, 0)
    const Vec3 p = curve.point(0.5);
    EXPECT_DOUBLE_EQ(p.x, 1.0);
    EXPECT_DOUBLE_EQ(p.y, 0.5);
    EXPECT_EQ(curve.weights(), (std::vector<double>{1e308, 1e308}));
    const BezierCurve ordinary({{1, 0, 0}, {0, 1, 0}}, {1, 2});  // ordinary weights are stored as given
    EXPECT_EQ(ordinary.homogeneous_points()[1].w, 2.0);
}

TEST(Limits, TinyKnotSpansGiveFiniteBasisValues) {
    const NurbsCurve curve(1, {0.0, 0.0, 5e-324, 5e-324}, {{0, 0, 0}, {1, 1, 0}});  // gave NaN
    EXPECT_EQ(curve.point(0.0).x, 0.0);
    EXPECT_EQ(curve.point(5e-324).x, 1.0);
}

TEST(Limits, DerivativeOrdersAreBounded) {
    const BezierCurve arc({{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, 1, 2});
    EXPECT_EQ(argument_of([&] { arc.derivative(0.3, 200); }), "order");  // was NaN after O(k^3) work
    const Vec3 d = arc.derivative(0.3, limits::max_derivative_order);
    EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y));
}

TEST(Limits, SolidsOutsideTheScaleNameTheirSize) {
    EXPECT_EQ(argument_of([] { sphere(1e308); }), "radius");  // said "collapse to a single point"
    EXPECT_EQ(argument_of([] { sphere(1.0, {1e17, 0, 0}); }), "radius");  // said "oriented inward"
    EXPECT_EQ(argument_of([] { sphere(1e-300); }), "radius");
    const std::vector<Vec3> corners{{1, 0, 0}, {2, 0, 0}, {2, 0, 1}, {1, 0, 1}};
    std::vector<NurbsCurve> sides;
    for (std::size_t k = 0; k < 4; ++k)
        sides.push_back(NurbsCurve::from_bezier(BezierCurve({corners[k], corners[(k + 1) % 4]})));
    const Profile square(sides);
    EXPECT_NO_THROW(revolve(square, {}, {0, 0, 1}, 1e-3));
    EXPECT_EQ(argument_of([&] { revolve(square, {}, {0, 0, 1}, 1e-12); }), "angle_deg");  // a zero-thickness solid
}

TEST(Text, PrintableEscapesControlsAndKeepsText) {
    EXPECT_EQ(printable("a\nb\x1b[2J\tc"), "a\\nb\\x1b[2J\\tc");
    EXPECT_EQ(printable(std::string("cut\0here", 8)), "cut\\x00here");
    EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x80\xa8"), "caf\xc3\xa9 \\u2028");
    EXPECT_EQ(printable("\xff"), "\\xff");
    EXPECT_EQ(printable(printable("x\ny")), printable("x\ny"));
    const Error error("path", "'a\nb' is missing");  // messages carry no newline into a terminal or a log
    EXPECT_STREQ(error.what(), "path: 'a\\nb' is missing");
}

}  // namespace
}  // namespace ratbez
