// The check that a planar profile does not cross itself (kernel/core/src/modelling/profile_crossings.hpp), and
// that revolve and extrude apply it.

#include "modelling/profile_crossings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/revolve.hpp"
#include "test_support.hpp"

namespace ratbez::detail {
namespace {

// The closed polygon through `corners` in the xy plane, one line piece per side.
Profile polygon(const std::vector<Vec3>& corners) {
    std::vector<NurbsCurve> pieces;
    for (std::size_t i = 0; i < corners.size(); ++i) pieces.push_back(line_segment(corners[i], corners[(i + 1) % corners.size()]));
    return Profile(pieces);
}

void check(const Profile& profile) { require_no_crossings(profile, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}); }

// The Error's message, which must name the profile and contain every one of `parts`.
void expect_refused(const Profile& profile, const std::vector<std::string>& parts) {
    const std::string message = test::error_message([&] { check(profile); });
    EXPECT_TRUE(test::starts_with(message, "profile:")) << message;
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(ProfileCrossings, SimpleProfilesPass) {
    check(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    check(Profile({circle(1.0)}));
    // A star: non-convex, with reflex corners.
    std::vector<Vec3> star;
    for (int k = 0; k < 10; ++k) {
        const double r = k % 2 == 0 ? 1.0 : 0.4, a = k * 0.6283185307179586;
        star.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    check(polygon(star));
    // A slot: two half circles joined tangentially to two lines.
    check(Profile({line_segment({0, -1, 0}, {2, -1, 0}), arc(1.0, -90, 90, {2, 0, 0}), line_segment({2, 1, 0}, {0, 1, 0}),
                   arc(1.0, 90, 270, {0, 0, 0})}));
    // A corner of 0.001 degrees is sharp but not a cusp; a gap of 1e-6 is far above the 1e-9 tolerance.
    check(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1.7453292519943295e-5, 0}}));
    check(polygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 1e-6, 0}, {0, 2, 0}}));
}

TEST(ProfileCrossings, ABowTieIsRefusedWhereItsSidesCross) {
    expect_refused(polygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}), {"pieces 0 and 2 cross or touch near (0.5, 0.5, 0)"});
}

TEST(ProfileCrossings, ACornerTouchingASideIsRefused) {
    // The corner (1, 0) of pieces 2 and 3 lies on piece 0: the profile touches itself there.
    expect_refused(polygon({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0, 0}, {0, 2, 0}}), {"pieces 0 and", "cross or touch near (1, "});
}

TEST(ProfileCrossings, ACubicWithALoopIsRefused) {
    // This cubic crosses itself near (0.5, 0.58); a line closes the profile.
    const NurbsCurve loop = NurbsCurve::from_bezier(BezierCurve({{0, 0, 0}, {2, 1, 0}, {-1, 1, 0}, {1, 0, 0}}));
    expect_refused(Profile({loop, line_segment({1, 0, 0}, {0, 0, 0})}), {"piece 0 crosses or touches itself"});
}

TEST(ProfileCrossings, APieceFoldingBackOverTheLastIsRefused) {
    // Piece 1 runs back along piece 0 (the fuzz finding of FuzzRegression.ProfileThatFoldsBackIsNotMeshedOpen),
    // and piece 2 starts on it.
    expect_refused(polygon({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {0, 1, 0}}), {"pieces 0 and", "cross or touch near ("});
}

TEST(ProfileCrossings, ACuspBetweenTangentCirclesIsRefused) {
    // A crescent: the outer circle counterclockwise, then the inner one clockwise, both through (0, 0)
    // with the x axis as tangent. The two sides leave (0, 0) in the same direction and stay within the
    // tolerance (1e-9 of the size) of each other for about 4e-5 beside it.
    const Profile crescent({arc(1.0, -90, 270, {0, 1, 0}), arc(0.5, -90, 270, {0, 0.5, 0}).reversed()});
    expect_refused(crescent, {"pieces 0 and 1 cross or touch near ("});
}

// The distance between segments ab and cd in the xy plane (0 when they cross).
double segment_distance(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const auto side = [](const Vec3& p, const Vec3& q, const Vec3& r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return 0;
    const auto to_segment = [](const Vec3& p, const Vec3& q, const Vec3& r) {
        const double t = std::clamp(dot(p - q, r - q) / dot(r - q, r - q), 0.0, 1.0);
        return distance(p, q + (r - q) * t);
    };
    return std::min({to_segment(a, c, d), to_segment(b, c, d), to_segment(c, a, b), to_segment(d, a, b)});
}

// Differential test against an exact oracle: random polygons, whose sides are drawn as straight rational
// quadratics with a random middle point and a middle weight in [1e-3, 1e3] (the same segment, crawling
// along it) or as straight cubics, sometimes split in two pieces. Non-adjacent sides either cross or keep
// a clear distance (cases within 1e-6 of touching are skipped); the check must agree every time.
TEST(ProfileCrossings, AgreesWithExactSegmentTestsOnRandomPolygons) {
    std::mt19937_64 random(20261201);
    const auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
    int simple = 0, crossing = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const int n = 3 + static_cast<int>(uniform(0, 6));
        std::vector<Vec3> corners;
        for (int i = 0; i < n; ++i) corners.push_back({uniform(0, 1), uniform(0, 1), 0});
        bool crosses = false, ambiguous = false;
        for (int i = 0; i < n; ++i)
            for (int j = i + 2; j < n; ++j) {
                if (i == 0 && j == n - 1) continue;  // adjacent through the closing corner
                const double gap = segment_distance(corners[i], corners[(i + 1) % n], corners[j], corners[(j + 1) % n]);
                if (gap == 0) crosses = true;
                else if (gap < 1e-6) ambiguous = true;
            }
        if (ambiguous) continue;
        std::vector<NurbsCurve> pieces;
        for (int i = 0; i < n; ++i) {
            const Vec3 a = corners[i], b = corners[(i + 1) % n];
            std::vector<Vec3> side{a};
            const int degree = 2 + static_cast<int>(uniform(0, 2));
            std::vector<double> ts;
            for (int k = 1; k < degree; ++k) ts.push_back(uniform(0.05, 0.95));
            std::sort(ts.begin(), ts.end());
            for (double t : ts) side.push_back(a + (b - a) * t);
            side.push_back(b);
            std::vector<double> weights(side.size(), 1.0);
            for (std::size_t k = 1; k + 1 < side.size(); ++k) weights[k] = std::pow(10.0, uniform(-3, 3));
            const BezierCurve curve(side, weights);
            if (uniform(0, 1) < 0.3) {
                const auto [left, right] = curve.split(uniform(0.2, 0.8));
                pieces.push_back(NurbsCurve::from_bezier(left));
                pieces.push_back(NurbsCurve::from_bezier(right));
            } else {
                pieces.push_back(NurbsCurve::from_bezier(curve));
            }
        }
        const Profile profile(pieces);
        bool refused = false;
        try {
            check(profile);
        } catch (const Error& e) {
            refused = true;
            EXPECT_NE(std::string(e.what()).find("cross or touch"), std::string::npos) << e.what();
        }
        EXPECT_EQ(refused, crosses) << "trial " << trial << " with " << n << " corners";
        ++(crosses ? crossing : simple);
    }
    std::printf("[ measured ] random polygons: %d simple, %d crossing, every one judged right\n", simple, crossing);
    // Both outcomes well represented (random polygons of up to 8 corners mostly cross).
    EXPECT_GT(simple, 300);
    EXPECT_GT(crossing, 1000);
}

TEST(ProfileCrossings, RevolveAndExtrudeRefuseACrossingProfile) {
    // The bow tie in the xz plane, away from the z axis; and in the xy plane for the extrusion.
    const Profile in_xz = polygon({{1, 0, 0}, {2, 0, 1}, {2, 0, 0}, {1, 0, 1}});
    EXPECT_NE(test::error_message([&] { (void)revolve(in_xz); }).find("cross or touch"), std::string::npos);
    const Profile in_xy = polygon({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}});
    EXPECT_ERROR_NAMING(extrude(in_xy, {0, 0, 1}, 1.0), "profile");
}

TEST(ProfileCrossings, WindingNumberCountsTurnsAboutAPoint) {
    const Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0};
    const Profile ccw(std::vector<NurbsCurve>{circle(2.0)});
    EXPECT_EQ(winding_number(ccw, {0.5, -0.3, 0}, o, x, y, "p"), 1);
    EXPECT_EQ(winding_number(ccw.reversed(), {0.5, -0.3, 0}, o, x, y, "p"), -1);
    EXPECT_EQ(winding_number(ccw, {2.5, 0, 0}, o, x, y, "p"), 0);
    // Near the curve (1e-9 inside and outside), and seen from the other side of the plane.
    EXPECT_EQ(winding_number(ccw, {2 - 1e-9, 0, 0}, o, x, y, "p"), 1);
    EXPECT_EQ(winding_number(ccw, {0, 2 + 1e-9, 0}, o, x, y, "p"), 0);
    EXPECT_EQ(winding_number(ccw, {0.1, 0.1, 0}, o, y, x, "p"), -1);
    // A non-convex star with extreme rational weights on one side: its reflex corners are outside.
    std::vector<Vec3> star;
    for (int k = 0; k < 10; ++k) {
        const double r = k % 2 == 0 ? 1.0 : 0.4, a = k * 0.6283185307179586;
        star.push_back({r * std::cos(a), r * std::sin(a), 0});
    }
    std::vector<NurbsCurve> pieces;
    for (std::size_t i = 0; i < star.size(); ++i)
        pieces.push_back(NurbsCurve::from_bezier(BezierCurve({star[i], star[(i + 1) % star.size()]}, {1e6, 1e-6})));
    const Profile spiky(pieces);
    EXPECT_EQ(winding_number(spiky, {0, 0, 0}, o, x, y, "p"), 1);
    EXPECT_EQ(winding_number(spiky, {0.6 * std::cos(0.3141592653589793), 0.6 * std::sin(0.3141592653589793), 0}, o, x, y, "p"), 0);
    EXPECT_EQ(winding_number(spiky, {0.3, 0.05, 0}, o, x, y, "p"), 1);
    // A point on the curve cannot be decided.
    EXPECT_ERROR_NAMING(winding_number(ccw, {2, 0, 0}, o, x, y, "holes"), "holes");
}

}  // namespace
}  // namespace ratbez::detail
