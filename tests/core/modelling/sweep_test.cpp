// sweep.hpp and rotation_minimizing_frame.hpp: the double reflection frame against the helix's closed-form
// RMF; exact sweeps (a circle along a circle is the torus, a disc along a line the cylinder, a tube along lines
// and tangent arcs piece by piece); approximate
// sweeps within their tolerance (a tube along a helix: every point at the tube's radius from the path, the
// volume Pappus's section area x path length); refusals of corners and self-intersecting sweeps.

#include "ratbez/sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "modelling_test_support.hpp"
#include "ratbez/closest_point.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/join.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/rotation_minimizing_frame.hpp"
#include "ratbez/tessellate.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

constexpr double pi = std::numbers::pi;

// A circle of radius r around the path's start, in the plane normal to its tangent there.
Profile section_circle(const NurbsCurve& path, double r) {
    return Profile({circle(r, path.start_point(), path.derivative(path.domain().min))});
}

TEST(RotationMinimizingFrame, HelixAgainstItsClosedForm) {
    // RMF along a helix: r = cos(theta) N + sin(theta) B with theta = -tau s (tau = c / (a^2 + c^2)).
    const double a = 2.0, c = 0.5;
    const int steps = 2000;
    const double t_end = 2 * pi;
    std::vector<Vec3> points, tangents;
    for (int k = 0; k <= steps; ++k) {
        const double t = t_end * k / steps;
        points.push_back({a * std::cos(t), a * std::sin(t), c * t});
        tangents.push_back(Vec3{-a * std::sin(t), a * std::cos(t), c} / std::hypot(a, c));
    }
    auto normal = [](double t) { return Vec3{-std::cos(t), -std::sin(t), 0}; };
    auto binormal = [&](double t) { return cross(Vec3{-a * std::sin(t), a * std::cos(t), c} / std::hypot(a, c), normal(t)); };
    const std::vector<Vec3> r = rotation_minimizing_frame(points, tangents, normal(0));
    const double tau = c / (a * a + c * c), speed = std::hypot(a, c);
    for (int k = 0; k <= steps; k += 100) {
        const double t = t_end * k / steps, theta = -tau * speed * t;
        EXPECT_LE(distance(r[static_cast<std::size_t>(k)], normal(t) * std::cos(theta) + binormal(t) * std::sin(theta)), 1e-10);
        EXPECT_NEAR(dot(r[static_cast<std::size_t>(k)], tangents[static_cast<std::size_t>(k)]), 0, 1e-14);
    }
    EXPECT_ERROR_NAMING(rotation_minimizing_frame(points, {}, normal(0)), "tangents");
}

TEST(SweepExact, CircleAlongCircleIsTheTorus) {
    const double R = 2, r = 0.5;
    const NurbsCurve path = circle(R);
    const Profile tube({circle(r, {R, 0, 0}, {0, 1, 0})});
    const Sweep s = sweep_surfaces(tube.pieces(), path);
    EXPECT_EQ(s.method, SweepMethod::revolution);
    EXPECT_TRUE(s.closed);
    const Solid torus = sweep(tube, path);
    EXPECT_NEAR(enclosed_volume(torus), 2 * pi * pi * R * r * r, 1e-10);
    EXPECT_EQ(torus.faces().size(), 1u);
    // A half circle path: half the torus with two caps.
    const Solid half = sweep(tube, arc(R, 0, 180));
    EXPECT_EQ(half.faces().size(), 3u);
    EXPECT_NEAR(enclosed_volume(half), pi * pi * R * r * r, 1e-10);
    // Both are revolve()'s solids of the section about the path's axis, and recorded so (the OpenCASCADE bridge
    // hands such a solid over as its own revolution).
    for (const auto& [solid, angle] : {std::pair{&torus, 360.0}, std::pair{&half, 180.0}}) {
        const auto* turn = solid->construction().get<Construction::Revolution>();
        ASSERT_NE(turn, nullptr);
        EXPECT_LE(norm(turn->axis_point), 1e-12);
        EXPECT_LE(distance(turn->axis_dir, {0, 0, 1}), 1e-12);
        EXPECT_NEAR(turn->angle_deg, angle, 1e-9);
    }
    // A section tilted out of the planes through the axis is swept as it is, with no record.
    const Profile tilted({circle(r, {R, 0, 0}, {0, 1, 0.3})});
    const Solid leaning = sweep(tilted, arc(R, 0, 180));
    EXPECT_EQ(leaning.construction().kind(), "none");
    EXPECT_NEAR(enclosed_volume(leaning), pi * pi * R * r * r * std::cos(std::atan(0.3)), 1e-10);
}

TEST(SweepExact, DiscAlongALineIsTheCylinder) {
    const Profile disc({circle(1.0, {0, 0, 0})});
    const Solid straight = sweep(disc, line_segment({0, 0, 0}, {0, 0, 3}));
    EXPECT_NEAR(enclosed_volume(straight), 3 * pi, 1e-12);
    const Solid oblique = sweep(disc, line_segment({0, 0, 0}, {1, 2, 3}));
    EXPECT_NEAR(enclosed_volume(oblique), 3 * pi, 1e-12);  // the section stays horizontal: area x height
    // Recorded as the extrusions they are.
    EXPECT_EQ(straight.construction(), Construction(Construction::Extrusion{{0, 0, 1}, 3}));
    EXPECT_EQ(oblique.construction(), Construction(Construction::Extrusion{{1, 2, 3}, std::sqrt(14.0)}));
    // A straight path drawn as a cubic with control points along it is still a line.
    const NurbsCurve cubic_line = NurbsCurve::from_bezier(BezierCurve({{0, 0, 0}, {0, 0, 0.5}, {0, 0, 2}, {0, 0, 3}}));
    EXPECT_EQ(sweep_surfaces(disc.pieces(), cubic_line).method, SweepMethod::extrusion);
}

TEST(SweepExact, LinesAndTangentArcsAreSweptPieceByPiece) {
    // A sketch's path: a line, a tangent quarter arc, the opposite quarter arc (an S) and a line; then a 3D path
    // (up, a half turn over, down). Each is exact piece by piece: every point of the tube r from the path to
    // rounding, the volume Pappus's pi r^2 L, the end section the start one carried rigidly. It was
    // approximated (degree 5 trajectories, a face per refined interval in FreeCAD, volume 7e-9 off).
    const double r = 0.5;
    struct Case {
        NurbsCurve path;
        double length;
        std::size_t pieces;
    };
    const std::vector<Case> paths = {
        {join({line_segment({0, 0, 0}, {4, 0, 0}), arc(3.0, -90, 0, {4, 3, 0}), arc(3.0, 90, 180, {10, 3, 0}).reversed(),
               line_segment({10, 6, 0}, {14, 6, 0})}),
         4 + 3 * pi + 4, 4},
        {join({line_segment({0, 0, 0}, {0, 0, 5}), arc(4.0, 180, 360, {4, 0, 5}, {0, 1, 0}), line_segment({8, 0, 5}, {8, 0, 0})}),
         5 + 4 * pi + 5, 3},
    };
    for (const auto& [path, length, pieces] : paths) {
        const Profile section = section_circle(path, r);
        const Sweep swept = sweep_surfaces(section.pieces(), path);
        EXPECT_EQ(swept.method, SweepMethod::lines_and_arcs);
        EXPECT_EQ(swept.max_error, 0);
        const CurveProjector onto_path(path);
        const NurbsSurface& s = swept.surfaces.front();
        for (int i = 0; i <= 12; ++i)
            for (int j = 0; j <= 40; ++j) {
                const double u = s.domain_u().min + s.domain_u().width() * i / 12, v = j / 40.0;
                EXPECT_NEAR(onto_path.closest_point(s.point(u, v)).distance, r, 1e-12);
            }
        EXPECT_LE(distance(s.point(s.domain_u().min, 1.0), swept.end_frame.to_world(
                      {dot(s.point(s.domain_u().min, 0.0) - swept.start_frame.origin, swept.start_frame.x_axis),
                       dot(s.point(s.domain_u().min, 0.0) - swept.start_frame.origin, swept.start_frame.y_axis),
                       dot(s.point(s.domain_u().min, 0.0) - swept.start_frame.origin, swept.start_frame.z_axis)})),
                  1e-12);
        const Solid tube = sweep(section, path);
        EXPECT_NEAR(enclosed_volume(tube), pi * r * r * length, 1e-12 * length);
        // A face per piece of the path, as Part's Sweep makes one per path edge, each the swept surface over its
        // piece (the joints are where the pieces meet), and the caps.
        ASSERT_EQ(swept.joints.size(), pieces - 1);
        ASSERT_EQ(tube.faces().size(), pieces + 2);
        for (std::size_t b = 0; b < pieces; ++b) {
            const NurbsSurface& part = tube.faces()[b].surface();
            EXPECT_EQ(part.domain_v().min, b == 0 ? 0.0 : swept.joints[b - 1]);
            EXPECT_EQ(part.domain_v().max, b + 1 == pieces ? 1.0 : swept.joints[b]);
            for (int j = 0; j <= 4; ++j) {
                const double v = part.domain_v().min + part.domain_v().width() * j / 4;
                for (const double u : {s.domain_u().min, s.domain_u().min + 0.3 * s.domain_u().width(), s.domain_u().max})
                    EXPECT_LE(distance(part.point(u, v), s.point(u, v)), 1e-14 * length);
            }
        }
    }
    // A bend tighter than the section's reach is refused where the arc starts (path parameter 1), not at 0.
    const NurbsCurve tight = join({line_segment({0, 0, 0}, {4, 0, 0}), arc(0.5, -90, 0, {4, 0.5, 0})});
    try {
        (void)sweep(section_circle(tight, 1.0), tight);
        ADD_FAILURE() << "a bend of radius 0.5 under a section of radius 1 was swept";
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "profile");
        EXPECT_NE(std::string(e.what()).find("(at path parameter 1)"), std::string::npos) << e.what();
    }
}

TEST(SweepApproximate, TubeAlongAHelixIsWithinToleranceAndMatchesPappus) {
    const double a = 2.0, c = 0.4, r = 0.3, tolerance = 1e-6;
    const NurbsCurve path = test::helix_path(a, c, 6);
    const Profile section = section_circle(path, r);
    const Sweep swept = sweep_surfaces(section.pieces(), path, tolerance);
    EXPECT_EQ(swept.method, SweepMethod::approximation);
    EXPECT_LE(swept.max_error, tolerance);
    EXPECT_GT(swept.max_error, 0);
    // Every point of the true sweep is r from the path (the section centred on it, normal to it): ours
    // within the tolerance.
    const CurveProjector onto_path(path);
    std::mt19937_64 rng(1807);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int k = 0; k < 300; ++k) {
        const NurbsSurface& s = swept.surfaces.front();
        const double u = s.domain_u().min + unit(rng) * s.domain_u().width(), v = unit(rng);
        EXPECT_NEAR(onto_path.closest_point(s.point(u, v)).distance, r, tolerance);
    }
    // Pappus: V = pi r^2 L; the surface within the tolerance moves the volume by at most tolerance x area.
    const Solid tube = sweep(section, path, tolerance);
    const double L = test::curve_length(path);
    EXPECT_NEAR(enclosed_volume(tube), pi * r * r * L, tolerance * 2 * pi * r * L);
    const Mesh mesh = tessellate(tube, 1e-3);
    EXPECT_TRUE(mesh.is_closed());
}

TEST(SweepApproximate, ClosedSpacePathClosesTheTube) {
    // A closed, non-planar path (a "saddle" loop), smooth where it closes: the periodic cubic B-spline of
    // 8 points on (2 cos t, 2 sin t, 0.5 sin 2t), clamped by the constructor's caller (Path clamps).
    std::vector<Vec3> points;
    for (int k = 0; k < 8; ++k) {
        const double t = 2 * pi * k / 8;
        points.push_back({2 * std::cos(t), 2 * std::sin(t), 0.5 * std::sin(2 * t)});
    }
    for (int k = 0; k < 3; ++k) points.push_back(points[static_cast<std::size_t>(k)]);  // wrap for periodicity
    std::vector<double> knots;
    for (int k = 0; k < static_cast<int>(points.size()) + 4; ++k) knots.push_back(k);
    const NurbsCurve path(3, knots, points);
    const double r = 0.2;
    const Profile section = section_circle(path, r);
    const Sweep swept = sweep_surfaces(section.pieces(), path, 1e-6);
    EXPECT_TRUE(swept.closed);
    const Solid tube = sweep(section, path, 1e-6);
    EXPECT_EQ(tube.faces().size(), 1u);
    EXPECT_NEAR(enclosed_volume(tube), pi * r * r * test::curve_length(path), 1e-6 * 2 * pi * r * test::curve_length(path));
}

TEST(SweepErrors, CornersAndSelfIntersectionsAreRefused) {
    const NurbsCurve corner = join({line_segment({0, 0, 0}, {1, 0, 0}), line_segment({1, 0, 0}, {1, 1, 0})});
    EXPECT_ERROR_NAMING(sweep(Profile({circle(0.1, {0, 0, 0}, {1, 0, 0})}), corner), "path");
    // The section reaches past the bend's centre of curvature (radius 1 around an arc of radius 0.5).
    EXPECT_ERROR_NAMING(sweep(Profile({circle(1.0, {0.5, 0, 0}, {0, 1, 0})}), arc(0.5, 0, 90)), "profile");
    // A helix whose turns are closer than the tube's diameter.
    const NurbsCurve tight = test::helix_path(2.0, 0.05, 8);
    EXPECT_ERROR_NAMING(sweep(section_circle(tight, 0.3), tight), "profile");
    // A profile in a plane containing the path's tangent.
    EXPECT_ERROR_NAMING(sweep(Profile({circle(1.0, {0, 0, 0}, {1, 0, 0})}), line_segment({0, 0, 0}, {0, 0, 3})), "profile");
    EXPECT_ERROR_NAMING(sweep(Profile({circle(1.0)}), line_segment({0, 0, 0}, {0, 0, 3}), 0.0), "tolerance");
    EXPECT_ERROR_NAMING(sweep(Profile({circle(1.0)}), line_segment({0, 0, 0}, {0, 0, 3}), 1e-20), "tolerance");
}

TEST(SweepSurface, OpenCurveAlongAGeneralPathMovesRigidly) {
    const NurbsCurve path = test::helix_path(3.0, 0.5, 3);
    const NurbsCurve curve = NurbsCurve::from_bezier(BezierCurve({{3, 0, -0.2}, {3.2, 0.1, 0}, {3.1, -0.1, 0.3}}, {1, 2, 1}));
    const NurbsSurface s = sweep_surface(curve, path, 1e-7);
    // v = 0 is the curve itself; v = 1 its rigid image: distances between its points are kept.
    const Interval d = curve.domain();
    for (int i = 0; i <= 10; ++i) {
        const double u = d.min + d.width() * i / 10;
        EXPECT_LE(distance(s.point(u, 0.0), curve.point(u)), 1e-14);
        EXPECT_NEAR(distance(s.point(u, 1.0), s.point(d.min, 1.0)), distance(curve.point(u), curve.point(d.min)), 1e-12);
    }
}

}  // namespace
}  // namespace ratbez
