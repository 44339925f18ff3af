#include "ratbez/extrude.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "ratbez/curves.hpp"
#include "ratbez/frame.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

// A rounded rectangle (w x h, corner radius r) of lines and quarter arcs in the plane of `frame`,
// counterclockwise about frame.z_axis when ccw is true.
Profile rounded_rectangle(const Frame& f, double w, double h, double r, bool ccw = true) {
    auto at = [&](double x, double y) { return f.to_world({x, y, 0}); };
    const double x0 = -w / 2, x1 = w / 2, y0 = -h / 2, y1 = h / 2;
    const Vec3 n = f.z_axis;
    // arc() measures angles from frame_from_axis(center, n).x_axis, which is f.x_axis only for some
    // frames; build the corners from their end points instead, as rational quadratics.
    auto corner = [&](double cx, double cy, double a0) {
        const double a1 = a0 + 90;
        const Vec3 p0 = at(cx + r * std::cos(a0 * pi / 180), cy + r * std::sin(a0 * pi / 180));
        const Vec3 p2 = at(cx + r * std::cos(a1 * pi / 180), cy + r * std::sin(a1 * pi / 180));
        const Vec3 c = at(cx, cy);
        return NurbsCurve(2, {0, 0, 0, 1, 1, 1}, {p0, p0 + p2 - c, p2}, {1, std::sqrt(0.5), 1});
    };
    (void)n;
    std::vector<NurbsCurve> pieces{line_segment(at(x0 + r, y0), at(x1 - r, y0)), corner(x1 - r, y0 + r, -90),
                                   line_segment(at(x1, y0 + r), at(x1, y1 - r)), corner(x1 - r, y1 - r, 0),
                                   line_segment(at(x1 - r, y1), at(x0 + r, y1)), corner(x0 + r, y1 - r, 90),
                                   line_segment(at(x0, y1 - r), at(x0, y0 + r)), corner(x0 + r, y0 + r, 180)};
    const Profile p(pieces);
    return ccw ? p : p.reversed();
}

TEST(Extrude, SurfaceIsTheCurveTranslated) {
    const NurbsCurve c(3, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0, 0}, {4, 1, 2}},
                       {1, 0.5, 2, 1, 0.7});
    const Vec3 d{0.3, -1, 2};
    const NurbsSurface s = extrude_surface(c, d);
    for (int k = 0; k < 10000; ++k) {
        const double u = uniform(0, 1), v = uniform(0, 1);
        ASSERT_LE(distance(s.point(u, v), c.point(u) + d * v), 1e-13);
    }
    EXPECT_ERROR_NAMING(extrude_surface(c, {0, 0, 0}), "displacement");
}

TEST(Extrude, RoundedRectangleGivesAClosedOutwardPrismOfTheRightVolume) {
    const double w = 4, h = 2, r = 0.5, area = w * h - (4 - pi) * r * r, perimeter = 2 * (w + h) - 8 * r + 2 * pi * r;
    for (int trial = 0; trial < 4; ++trial) {
        const Frame f = frame_from_axis(random_point(10), random_unit());
        const Profile profile = rounded_rectangle(f, w, h, r, trial % 2 == 0);
        // Straight: volume A d and area 2A + L d; drawn clockwise or counterclockwise, swept either way.
        const double distance_ = uniform(0.5, 5);
        const Vec3 direction = f.z_axis * (trial < 2 ? 1.0 : -1.0);
        const Solid prism = extrude(profile, direction, distance_);
        EXPECT_EQ(prism.faces().size(), 10u);
        EXPECT_EQ(prism.euler_characteristic(), 2);
        EXPECT_LT(std::abs(prism.volume() - area * distance_) / (area * distance_), 1e-10);
        const double total = 2 * area + perimeter * distance_;
        EXPECT_LT(std::abs(prism.area() - total) / total, 1e-10);
        const double sign = trial < 2 ? 1.0 : -1.0;
        test::expect_outward(prism, [&](const Vec3& p) {
            const Vec3 q = p - f.origin;
            const double x = dot(q, f.x_axis), y = dot(q, f.y_axis), z = sign * dot(q, f.z_axis);
            const double dx = std::max({-w / 2 + r - x, 0.0, x - (w / 2 - r)}), dy = std::max({-h / 2 + r - y, 0.0, y - (h / 2 - r)});
            return z > 0 && z < distance_ && std::hypot(dx, dy) < r;
        }, 1e-7, 30);
        // Oblique: Cavalieri, volume = A times the height along the normal.
        const Vec3 oblique = f.z_axis * sign + f.x_axis * 0.7 - f.y_axis * 0.4;
        const Solid slanted = extrude(profile, oblique, distance_);
        const double height = distance_ / norm(oblique);
        EXPECT_LT(std::abs(slanted.volume() - area * height) / (area * height), 1e-10);
    }
}

TEST(Extrude, ExtremeWeightsDoNotHideTheProfileFromTheAreaCheck) {
    // A square whose straight edges are degree-1 rational segments with weights (w, 1/w): nearly all of
    // each edge is traversed within a parameter range of order 1/w^2, where a fixed-depth Gauss rule has
    // no nodes, so the old area check called the profile empty and the cap check rejected it.
    const double a = 3, d = 2;
    const Vec3 corners[4] = {{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}};
    for (double w : {1e12, 1e-12, 1e3}) {
        std::vector<NurbsCurve> edges;
        for (int k = 0; k < 4; ++k)
            edges.push_back(NurbsCurve::from_bezier(BezierCurve({corners[k], corners[(k + 1) % 4]}, {w, 1 / w})));
        const Profile square(edges);
        for (const Profile& profile : {square, square.reversed()}) {
            const Solid prism = extrude(profile, {0, 0, 1}, d);
            EXPECT_EQ(prism.faces().size(), 6u);
            EXPECT_LT(std::abs(prism.volume() - a * a * d) / (a * a * d), 1e-10) << w;
        }
    }
}

TEST(Extrude, HolesGoThroughThePrism) {
    // A 10 x 6 rectangle with a circular hole (radius 1.5) and a rounded-rectangle hole, in a random frame;
    // the holes drawn in either orientation, the sweep either way and oblique.
    const double w = 10, h = 6, r = 1.5;
    const double hole_area = pi * r * r + (2 * 1.2 - (4 - pi) * 0.2 * 0.2);
    for (int trial = 0; trial < 4; ++trial) {
        const Frame f = frame_from_axis(random_point(10), random_unit());
        const Profile outer = rounded_rectangle(f, w, h, 0.5, trial % 2 == 0);
        const Profile round(std::vector<NurbsCurve>{circle(r, f.to_world({-2, 0, 0}), f.z_axis * (trial < 2 ? 1.0 : -1.0))});
        const Frame shifted{f.to_world({2.5, 0, 0}), f.x_axis, f.y_axis, f.z_axis};
        const Profile slot = rounded_rectangle(shifted, 2, 1.2, 0.2, trial % 3 == 0);
        const double outer_area = w * h - (4 - pi) * 0.25;
        const double d = uniform(0.5, 4);
        const Vec3 direction = f.z_axis * (trial % 2 == 0 ? 1.0 : -1.0) + f.x_axis * (trial == 3 ? 0.5 : 0.0);
        const Solid prism = extrude(outer, direction, d, {round, slot});
        EXPECT_EQ(prism.faces().size(), 8u + 1u + 8u + 2u);
        EXPECT_EQ(prism.euler_characteristic(), -2);  // genus 2
        const double height = d * std::abs(dot(direction, f.z_axis)) / norm(direction);
        const double volume = (outer_area - hole_area) * height;
        EXPECT_LT(std::abs(prism.volume() - volume) / volume, 1e-10) << trial;
        const double sign = trial % 2 == 0 ? 1.0 : -1.0;
        if (trial < 3)
            test::expect_outward(prism, [&](const Vec3& p) {
                const Vec3 q = p - f.origin;
                const double x = dot(q, f.x_axis), y = dot(q, f.y_axis), z = sign * dot(q, f.z_axis);
                const double dx = std::max(std::abs(x) - (w / 2 - 0.5), 0.0), dy = std::max(std::abs(y) - (h / 2 - 0.5), 0.0);
                const bool in_outer = std::hypot(dx, dy) < 0.5;
                const bool in_round = std::hypot(x + 2, y) < r;
                const double sx = std::max(std::abs(x - 2.5) - 0.8, 0.0), sy = std::max(std::abs(y) - 0.4, 0.0);
                const bool in_slot = std::hypot(sx, sy) < 0.2;
                return z > 0 && z < d && in_outer && !in_round && !in_slot;
            }, 1e-7, 20);
    }
}

TEST(Extrude, RefusesHolesThatAreNotInsideApartAndPlanar) {
    const Profile square({line_segment({0, 0, 0}, {10, 0, 0}), line_segment({10, 0, 0}, {10, 6, 0}),
                          line_segment({10, 6, 0}, {0, 6, 0}), line_segment({0, 6, 0}, {0, 0, 0})});
    const auto hole = [](double radius, Vec3 centre) { return Profile(std::vector<NurbsCurve>{circle(radius, centre)}); };
    const auto message = [&](const std::vector<Profile>& holes) {
        return test::error_message([&] { extrude(square, {0, 0, 1}, 1.0, holes); });
    };
    // Crossing the outer boundary, outside it, nested in another hole, crossing another hole, off the plane, open.
    EXPECT_TRUE(test::starts_with(message({hole(1.5, {9, 3, 0})}), "holes: piece 1 of the profile and piece 0 of hole 0"))
        << message({hole(1.5, {9, 3, 0})});
    EXPECT_TRUE(test::starts_with(message({hole(1, {20, 3, 0})}), "holes[0]: must lie inside the profile"));
    EXPECT_TRUE(test::starts_with(message({hole(2, {3, 3, 0}), hole(1, {3, 3, 0})}), "holes[1]: lies inside holes[0]"));
    EXPECT_TRUE(test::starts_with(message({hole(2, {3, 3, 0}), hole(1.5, {6, 3, 0})}), "holes: piece 0 of hole 0 and piece 0 of hole 1"));
    EXPECT_TRUE(test::starts_with(message({hole(1, {3, 3, 0.5})}), "holes[0]: must be planar"));
    EXPECT_TRUE(test::starts_with(message({Profile({arc(1, 0, 180, {3, 3, 0})})}), "holes[0]: must be closed"));
    // A hole that touches the boundary in one point is refused too (the caps would not be faces).
    EXPECT_TRUE(test::starts_with(message({hole(1, {1, 3, 0})}), "holes: piece 3 of the profile and piece 0 of hole 0"))
        << message({hole(1, {1, 3, 0})});
}

TEST(Extrude, RejectsBadInputNamingTheArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Profile square({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {1, 1, 0}),
                          line_segment({1, 1, 0}, {0, 1, 0}), line_segment({0, 1, 0}, {0, 0, 0})});
    EXPECT_ERROR_NAMING(extrude(square, {0, 0, 1}, 0.0), "distance");
    EXPECT_ERROR_NAMING(extrude(square, {0, 0, 1}, -1.0), "distance");
    EXPECT_ERROR_NAMING(extrude(square, {0, 0, 1}, nan), "distance");
    EXPECT_ERROR_NAMING(extrude(square, {0, 0, 0}, 1.0), "direction");
    EXPECT_ERROR_NAMING(extrude(square, {nan, 0, 1}, 1.0), "direction");
    EXPECT_ERROR_NAMING(extrude(square, {1, 1, 0}, 1.0), "direction");  // parallel to the plane
    EXPECT_ERROR_NAMING(extrude(Profile({line_segment({0, 0, 0}, {1, 0, 0})}), {0, 0, 1}, 1.0), "profile");  // open
    const Profile skew({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {1, 1, 0.5}),
                        line_segment({1, 1, 0.5}, {0, 1, 0}), line_segment({0, 1, 0}, {0, 0, 0})});
    const std::string message = test::error_message([&] { extrude(skew, {0, 0, 1}, 1.0); });
    EXPECT_NE(message.find("planar"), std::string::npos) << message;
    EXPECT_ERROR_NAMING(extrude(Profile({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {0, 0, 0})}),
                                {0, 0, 1}, 1.0), "profile");  // encloses no area
}

}  // namespace
}  // namespace ratbez
