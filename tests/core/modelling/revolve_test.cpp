#include "ratbez/revolve.hpp"

#include <gtest/gtest.h>

#include <array>
#include <iostream>
#include <limits>
#include <numbers>

#include "ratbez/curves.hpp"
#include "ratbez/frame.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

// The angle of arc parameter u for a revolution by `angle_deg` (see curves_test: inside segment k of
// sweep 2θ, tan(α / 2) = tan(θ / 2) (2t - 1) from the segment's bisector).
double rotation_angle(double angle_deg, double u) {
    const int segments = static_cast<int>(std::ceil(angle_deg / 90.0 - 1e-12));
    const int k = std::min(static_cast<int>(u * segments), segments - 1);
    const double t = u * segments - k;
    const double theta = angle_deg / (2.0 * segments) * pi / 180.0;
    return (2 * k + 1) * theta + 2 * std::atan(std::tan(theta / 2) * (2 * t - 1));
}

// The vase: an open rational cubic Bézier in the xz half-plane from the axis (bottom) to the axis (top).
BezierCurve vase_curve() {
    return BezierCurve({{0, 0, 0}, {3, 0, 0.2}, {0.2, 0, 2.5}, {0, 0, 4}}, {1, 2, 0.5, 1});
}

// π ∫ ρ² dh over the profile (the disk method), by a 64-point rule on a fine split: an independent volume.
double disk_method_volume(const BezierCurve& c) {
    double v = 0;
    const int panels = 400;
    for (int p = 0; p < panels; ++p)
        for (int q = 0; q < 4; ++q) {
            static const double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
            static const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
            const double t = (p + 0.5 * (1 + x[q])) / panels;
            const auto d = c.derivatives(t, 1);
            v += w[q] * 0.5 / panels * pi * d[0].x * d[0].x * d[1].z;
        }
    return v;
}

TEST(Revolve, SurfacePointsAreTheProfileRotatedByTheExactAngle) {
    double worst = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const Vec3 axis_point = random_point(10), axis_dir = random_unit() * uniform(0.2, 5);
        const Vec3 d = axis_dir / norm(axis_dir);
        std::vector<Vec3> points;
        std::vector<double> weights;
        for (int i = 0; i < 4; ++i) {
            points.push_back(random_point(8));
            weights.push_back(uniform(0.3, 3));
        }
        const BezierCurve profile(points, weights);  // any rational profile, anywhere (even across the axis)
        const double angle = trial == 0 ? 360.0 : uniform(1, 360);
        const NurbsSurface s = revolve_surface(NurbsCurve::from_bezier(profile), axis_point, axis_dir, angle);
        double size = 0;
        for (const Vec3& p : points) size = std::max(size, distance(p, axis_point));
        for (int k = 0; k < 10000; ++k) {
            const double u = uniform(0, 1), v = uniform(0, 1);
            const Vec3 expected = test::rotate_about(profile.point(v), axis_point, d, rotation_angle(angle, u));
            const double error = distance(s.point(u, v), expected) / size;
            worst = std::max(worst, error);
            ASSERT_LE(error, 1e-12) << "u = " << u << ", v = " << v;
        }
    }
    std::cout << "[ measured ] revolve_surface: largest deviation from the rotated profile point (relative) " << worst << "\n";
}

TEST(Revolve, VaseFromAnOpenRationalCubicWithBothEndsOnTheAxis) {
    const BezierCurve c = vase_curve();
    const Solid vase = revolve(Profile::from_beziers({c}));
    EXPECT_EQ(vase.faces().size(), 1u);
    EXPECT_EQ(vase.euler_characteristic(), 2);
    EXPECT_TRUE(vase.faces()[0].sides()[0].edge->degenerate);
    EXPECT_TRUE(vase.faces()[0].sides()[2].edge->degenerate);
    const double expected = disk_method_volume(c);
    const double error = std::abs(vase.volume() - expected) / expected;
    EXPECT_LT(error, 1e-10);
    std::cout << "[ measured ] vase: relative volume error against the disk method " << error << "\n";
    // Drawn top to bottom it is the same solid, still outward.
    const Solid flipped = revolve(Profile::from_beziers({c.reversed()}));
    EXPECT_NEAR(flipped.volume(), vase.volume(), 1e-12 * expected);
    // Normals point away from the axis on the bulge.
    const Vec3 n = vase.faces()[0].normal(0.0, 0.5), p = vase.faces()[0].point(0.0, 0.5);
    EXPECT_GT(dot(n, Vec3{p.x, p.y, 0}), 0);
}

TEST(Revolve, PartialRevolutionsHaveVolumeProportionalToTheAngle) {
    const Profile vase = Profile::from_beziers({vase_curve()});
    const Profile block({line_segment({1, 0, 0}, {2, 0, 0}), arc(0.5, -90, 90, {2, 0, 0.5}, {0, -1, 0}),
                         line_segment({2, 0, 1}, {1, 0, 1}), line_segment({1, 0, 1}, {1, 0, 0})});
    for (const Profile* profile : {&vase, &block}) {
        const double full = revolve(*profile).volume();
        for (double angle : {90.0, 180.0, 270.0, 45.5}) {
            const Solid part = revolve(*profile, {}, {0, 0, 1}, angle);
            EXPECT_EQ(part.euler_characteristic(), 2) << angle;
            EXPECT_EQ(part.faces().size(), profile->pieces().size() + 2) << angle;
            EXPECT_LT(std::abs(part.volume() - full * angle / 360) / full, 1e-10) << angle;
        }
        // Drawn the other way round the same partial solid comes out, still outward.
        const double reversed = revolve(profile->reversed(), {}, {0, 0, 1}, 270).volume();
        EXPECT_LT(std::abs(reversed - full * 0.75) / full, 1e-10);
    }
    // The 270° vase: its end faces share the axis segment, the poles are degenerate.
    const Solid part = revolve(vase, {}, {0, 0, 1}, 270.0);
    EXPECT_EQ(part.faces()[1].loops()[0].back().edge, part.faces()[2].loops()[0].back().edge);
    // The solid occupies the angles 0..270°: the start face looks to -y, the end face (the -y half-plane) to +x.
    EXPECT_NEAR(distance(part.faces()[1].plane().normal, Vec3{0, -1, 0}), 0, 1e-15);
    EXPECT_NEAR(distance(part.faces()[2].plane().normal, Vec3{1, 0, 0}), 0, 1e-15);
    EXPECT_GT(dot(part.faces()[0].normal(0.5, 0.5), Vec3{-1, 1, 0}), 0);  // the bulge at 135° looks outward
}

TEST(Revolve, RingFromAClosedProfileOfSeveralPieces) {
    // A rounded rectangle (4 lines, 4 quarter arcs) centred at distance 5 from the axis: Pappus–Guldinus
    // with the centroid (of the region and of its boundary) at the centre by symmetry.
    const double w = 2, h = 3, r = 0.5, cx = 5, cz = 1;
    const double x0 = cx - w / 2, x1 = cx + w / 2, z0 = cz - h / 2, z1 = cz + h / 2;
    const Vec3 n{0, -1, 0};  // so the frame of the xz-plane is (x, z)
    const Profile rounded({line_segment({x0 + r, 0, z0}, {x1 - r, 0, z0}), arc(r, -90, 0, {x1 - r, 0, z0 + r}, n),
                           line_segment({x1, 0, z0 + r}, {x1, 0, z1 - r}), arc(r, 0, 90, {x1 - r, 0, z1 - r}, n),
                           line_segment({x1 - r, 0, z1}, {x0 + r, 0, z1}), arc(r, 90, 180, {x0 + r, 0, z1 - r}, n),
                           line_segment({x0, 0, z1 - r}, {x0, 0, z0 + r}), arc(r, 180, 270, {x0 + r, 0, z0 + r}, n)});
    ASSERT_TRUE(rounded.is_closed());
    const Solid ring = revolve(rounded);
    EXPECT_EQ(ring.faces().size(), 8u);
    EXPECT_EQ(ring.euler_characteristic(), 0);
    const double area = w * h - (4 - pi) * r * r, perimeter = 2 * (w + h) - 8 * r + 2 * pi * r;
    EXPECT_LT(std::abs(ring.volume() - 2 * pi * cx * area) / (2 * pi * cx * area), 1e-10);
    EXPECT_LT(std::abs(ring.area() - 2 * pi * cx * perimeter) / (2 * pi * cx * perimeter), 1e-10);
    // Neighbouring faces share the circle traced by their joint.
    for (std::size_t k = 0; k < 8; ++k)
        EXPECT_EQ(ring.faces()[k].sides()[2].edge, ring.faces()[(k + 1) % 8].sides()[0].edge);
    test::expect_outward(ring, [&](const Vec3& p) {
        // Inside the rounded rectangle: within r of the inner rectangle [x0 + r, x1 - r] x [z0 + r, z1 - r].
        const double rho = std::hypot(p.x, p.y);
        const double dx = std::max({x0 + r - rho, 0.0, rho - (x1 - r)}), dz = std::max({z0 + r - p.z, 0.0, p.z - (z1 - r)});
        return std::hypot(dx, dz) < r;
    }, 1e-7, 50);
    // Partial: 270° of the ring.
    const Solid part = revolve(rounded, {}, {0, 0, 1}, 270);
    EXPECT_EQ(part.euler_characteristic(), 2);
    EXPECT_LT(std::abs(part.volume() - 0.75 * ring.volume()) / ring.volume(), 1e-10);
}

// A square [x0, x0 + a] x [0, a] in the xz half-plane whose edges (bottom, right, top, left) are
// degree-1 rational segments with the given end weights: still straight, but with weights (w0, w1) all
// but a w0/w1 share of the edge is traversed within a parameter range of order w0/w1 (or the mirror
// image), where a Gauss rule at fixed parameters has few nodes or none.
using EdgeWeights = std::array<std::array<double, 2>, 4>;
Profile crowded_square(double x0, double a, const EdgeWeights& weights) {
    const Vec3 corners[4] = {{x0, 0, 0}, {x0 + a, 0, 0}, {x0 + a, 0, a}, {x0, 0, a}};
    std::vector<NurbsCurve> edges;
    for (std::size_t k = 0; k < 4; ++k)
        edges.push_back(NurbsCurve::from_bezier(
            BezierCurve({corners[k], corners[(k + 1) % 4]}, {weights[k][0], weights[k][1]})));
    return Profile(edges);
}

TEST(Revolve, ExtremeWeightsDoNotHideTheProfileFromTheOrientationCheck) {
    // The area check of revolve once used a fixed-depth rule: with weights 1e12 / 1e-12 it found no area
    // ("encloses no area with the axis") although the square encloses a^2. Pappus: V = 2π (x0 + a/2) a^2.
    const double x0 = 2, a = 1, exact = 2 * pi * (x0 + a / 2) * a * a;
    const EdgeWeights up{{{1e12, 1e-12}, {1e12, 1e-12}, {1e12, 1e-12}, {1e12, 1e-12}}};
    const EdgeWeights mixed{{{1e-12, 1e12}, {1e6, 1e-3}, {1, 1e9}, {1e12, 1e-12}}};
    for (const EdgeWeights& weights : {up, mixed}) {
        const Profile square = crowded_square(x0, a, weights);
        for (const Profile& profile : {square, square.reversed()})
            EXPECT_LT(std::abs(revolve(profile).volume() - exact) / exact, 1e-10);
    }
}

TEST(Revolve, ExtremeWeightsPassThePlanarEndFaceCheck) {
    // A 77° revolve has two planar end faces bounded by the profile; Face::planar's counterclockwise
    // check once rejected them for weights in 1e-3 .. 1e3 ("outer loop must run counterclockwise"): its
    // fixed-depth rule lost most of the outer (right) edge and kept the inner one, which runs the other
    // way, so the loop's area came out negative.
    const double x0 = 2, a = 1, exact = 77.0 / 360.0 * 2 * pi * (x0 + a / 2) * a * a;
    const EdgeWeights first{{{0.1, 0.01}, {100, 0.01}, {1, 10}, {0.1, 0.001}}};
    const EdgeWeights second{{{0.01, 0.1}, {0.01, 100}, {1, 1000}, {1, 1000}}};
    for (const EdgeWeights& weights : {first, second}) {
        const Profile square = crowded_square(x0, a, weights);
        for (const Profile& profile : {square, square.reversed()}) {
            const Solid part = revolve(profile, {}, {0, 0, 1}, 77);
            EXPECT_EQ(part.faces().size(), 6u);
            EXPECT_LT(std::abs(part.volume() - exact) / exact, 1e-10);
        }
    }
}

TEST(Revolve, ArbitraryPlacementIsTheCanonicalSolidMovedRigidly) {
    const BezierCurve c = vase_curve();
    const Solid canonical = revolve(Profile::from_beziers({c}), {}, {0, 0, 1}, 270);
    for (int trial = 0; trial < 5; ++trial) {
        const Vec3 center = random_point(20);
        const Frame f = frame_from_axis(center, random_unit());
        std::vector<Vec3> moved;
        for (const Vec3& p : c.points()) moved.push_back(f.to_world(p));
        const Solid placed = revolve(Profile::from_beziers({BezierCurve(moved, c.weights())}), center, f.z_axis * 3.0, 270);
        ASSERT_EQ(placed.faces().size(), canonical.faces().size());
        for (int k = 0; k < 500; ++k) {
            auto [u, v] = test::random_parameter(canonical.faces()[0]);
            EXPECT_LE(distance(f.to_world(canonical.faces()[0].point(u, v)), placed.faces()[0].point(u, v)), 1e-12 * 25);
        }
        EXPECT_LT(std::abs(placed.volume() - canonical.volume()) / canonical.volume(), 1e-11);
    }
}

TEST(Revolve, RejectsBadInputNamingTheArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Profile vase = Profile::from_beziers({vase_curve()});
    EXPECT_ERROR_NAMING(revolve(vase, {}, {0, 0, 1}, 0.0), "angle_deg");
    EXPECT_ERROR_NAMING(revolve(vase, {}, {0, 0, 1}, -90.0), "angle_deg");
    EXPECT_ERROR_NAMING(revolve(vase, {}, {0, 0, 1}, 360.5), "angle_deg");
    EXPECT_ERROR_NAMING(revolve(vase, {}, {0, 0, 1}, nan), "angle_deg");
    EXPECT_ERROR_NAMING(revolve(vase, {}, {0, 0, 0}), "axis_dir");
    EXPECT_ERROR_NAMING(revolve(vase, {}, {nan, 0, 1}), "axis_dir");
    EXPECT_ERROR_NAMING(revolve(vase, {nan, 0, 0}), "axis_point");
    EXPECT_ERROR_NAMING(revolve_surface(vase.pieces()[0], {}, {0, 0, 1}, 400), "angle_deg");

    // Crossing the axis: a closed triangle with points on both sides.
    const Profile crossing({line_segment({-1, 0, 0}, {2, 0, 0}), line_segment({2, 0, 0}, {1, 0, 2}),
                            line_segment({1, 0, 2}, {-1, 0, 0})});
    const std::string crosses = test::error_message([&] { revolve(crossing); });
    EXPECT_EQ(crosses.rfind("profile:", 0), 0u) << crosses;
    EXPECT_NE(crosses.find("crosses the axis"), std::string::npos) << crosses;
    // The piece that crosses is named, not the one beyond the axis on the far side (piece 0 lies wholly
    // at x < 0; piece 1 crosses; e points to x < 0, the side of the farthest control point).
    const Profile far_side({line_segment({-3, 0, 0}, {-3, 0, 2}), line_segment({-3, 0, 2}, {1, 0, 1}),
                            line_segment({1, 0, 1}, {-3, 0, 0})});
    const std::string far = test::error_message([&] { revolve(far_side); });
    EXPECT_EQ(far, "profile: piece 1 crosses the axis (it reaches the other side of it)");
    // Touching the axis at a corner of a closed profile.
    const Profile corner({line_segment({0, 0, 0}, {2, 0, 0}), line_segment({2, 0, 0}, {1, 0, 2}),
                          line_segment({1, 0, 2}, {0, 0, 0})});
    const std::string touches = test::error_message([&] { revolve(corner); });
    EXPECT_NE(touches.find("touches the axis"), std::string::npos) << touches;
    // Touching it tangentially inside a piece: a parabola-like arc x = (2t-1)^2 between two points.
    const Profile tangent = Profile::from_beziers({BezierCurve({{1, 0, 0}, {-1, 0, 1}, {1, 0, 2}}),
                                                   BezierCurve({{1, 0, 2}, {2, 0, 1}, {1, 0, 0}})});
    const std::string tangent_message = test::error_message([&] { revolve(tangent); });
    EXPECT_NE(tangent_message.find("touches the axis"), std::string::npos) << tangent_message;
    // An open profile that touches the axis in its middle.
    const Profile middle({line_segment({0, 0, 0}, {1, 0, 1}), line_segment({1, 0, 1}, {0, 0, 2}),
                          line_segment({0, 0, 2}, {1, 0, 3}), line_segment({1, 0, 3}, {0, 0, 4})});
    EXPECT_ERROR_NAMING(revolve(middle), "profile");
    // Open with ends off the axis.
    const std::string ends = test::error_message([] { revolve(Profile({line_segment({1, 0, 0}, {1, 0, 2})})); });
    EXPECT_NE(ends.find("must start and end on the axis"), std::string::npos) << ends;
    EXPECT_ERROR_NAMING(revolve(Profile({line_segment({0, 0, 0}, {1, 0, 1}), line_segment({1, 0, 1}, {0.5, 0, 2})})), "profile");
    // Not in a plane containing the axis.
    const Profile skew({line_segment({1, 0, 0}, {2, 0.5, 0}), line_segment({2, 0.5, 0}, {1, 0, 1}),
                        line_segment({1, 0, 1}, {1, 0, 0})});
    EXPECT_ERROR_NAMING(revolve(skew), "profile");
    // A closed triangle with two sides on the axis is still refused (the rest is no single open profile).
    EXPECT_ERROR_NAMING(revolve(Profile({line_segment({0, 0, 0}, {0, 0, 1}), line_segment({0, 0, 1}, {0, 0, 2}),
                                         line_segment({0, 0, 2}, {1, 0, 1}), line_segment({1, 0, 1}, {0, 0, 0})})),
                        "profile");
    // A profile lying on the axis.
    EXPECT_ERROR_NAMING(revolve(Profile({line_segment({0, 0, 0}, {0, 0, 1})})), "profile");
}

// OpenSCAD's rotate_extrude habit: a closed polygon with one side on the axis. It is revolved as the open
// profile of its other sides: the same solid (a cone here) as the open profile gives, in either order.
TEST(Revolve, ClosedProfileWithOneSideOnTheAxisIsTheOpenProfile) {
    const Profile closed({line_segment({0, 0, 0}, {3, 0, 0}), line_segment({3, 0, 0}, {0, 0, 4}),
                          line_segment({0, 0, 4}, {0, 0, 0})});
    const Profile rotated({line_segment({0, 0, 4}, {0, 0, 0}), line_segment({0, 0, 0}, {3, 0, 0}),
                           line_segment({3, 0, 0}, {0, 0, 4})});
    const Profile open({line_segment({0, 0, 0}, {3, 0, 0}), line_segment({3, 0, 0}, {0, 0, 4})});
    const double cone = std::numbers::pi * 9 * 4 / 3;
    for (const Profile* p : {&closed, &rotated}) {
        const Solid solid = revolve(*p);
        EXPECT_NEAR(solid.volume(), cone, 1e-9 * cone);
        EXPECT_EQ(solid.faces().size(), revolve(open).faces().size());
        EXPECT_NEAR(revolve(*p, {}, {0, 0, 1}, 90).volume(), cone / 4, 1e-9 * cone);
    }
}

}  // namespace
}  // namespace ratbez
