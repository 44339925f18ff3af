// is_convex (convexity.hpp): convex primitives, revolutions and extrusions, and the ways a solid fails to be
// convex: a curved face bending inward, a concave corner inside a face (a revolved polyline's knot), a
// concave edge between faces.

#include "ratbez/convexity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/solid_transform.hpp"

namespace ratbez {
namespace {

// A degree-1 NURBS through the points in the xz half-plane: one piece, its corners at interior knots.
NurbsCurve polyline(const std::vector<Vec3>& points) {
    std::vector<double> knots{0, 0};
    for (std::size_t k = 1; k + 1 < points.size(); ++k) knots.push_back(static_cast<double>(k));
    knots.push_back(static_cast<double>(points.size() - 1));
    knots.push_back(static_cast<double>(points.size() - 1));
    return NurbsCurve(1, knots, points);
}

// A closed polygon in the xy plane as a profile of line segments.
Profile polygon(const std::vector<Vec3>& corners) {
    std::vector<NurbsCurve> sides;
    for (std::size_t k = 0; k < corners.size(); ++k) sides.push_back(line_segment(corners[k], corners[(k + 1) % corners.size()]));
    return Profile(sides);
}

// The same faces without the construction record: judged from the surfaces, not taken on the record's word.
Solid faces_only(const Solid& solid) { return Solid(solid.faces()); }

TEST(Convexity, PrimitivesThatAreConvexAre) {
    for (const Solid& solid : {sphere(3, {1, -2, 5}), cylinder(2, 7, {0, 0, 0}, {1, 1, 0}), cone(2, 1, 3),
                               cone(2, 0, 3) /* an apex: a pole of the lateral face */,
                               transformed(sphere(1), AffineMap::scaling(1e-4, {}))}) {
        SCOPED_TRACE(std::string(solid.construction().kind()));
        EXPECT_TRUE(is_convex(solid));
        EXPECT_TRUE(is_convex(faces_only(solid)));
    }
    EXPECT_FALSE(is_convex(torus(10, 3)));  // its inner half bends inward
}

TEST(Convexity, RevolutionsFollowTheirProfile) {
    // A bicone: a polyline with one convex corner inside the face (at an interior knot).
    EXPECT_TRUE(is_convex(revolve(Profile({polyline({{0, 0, -1}, {1, 0, 0}, {0, 0, 1}})}))));
    // A waist: the same with a concave corner, and a smooth peanut whose middle bends inward.
    EXPECT_FALSE(is_convex(revolve(Profile({polyline({{0, 0, -1}, {1, 0, -0.5}, {0.5, 0, 0}, {1, 0, 0.5}, {0, 0, 1}})}))));
    // An hourglass: its waist, a revolved cubic between two flat ends, bends inward.
    const NurbsCurve waist = NurbsCurve::from_bezier(BezierCurve({{2, 0, -1}, {0.5, 0, -0.3}, {0.5, 0, 0.3}, {2, 0, 1}}));
    EXPECT_FALSE(is_convex(revolve(Profile({line_segment({0, 0, -1}, {2, 0, -1}), waist, line_segment({2, 0, 1}, {0, 0, 1})}))));
    // A lens of one cubic: convex; the exact rational circle's double knots are no corner.
    EXPECT_TRUE(is_convex(revolve(Profile({NurbsCurve::from_bezier(BezierCurve({{0, 0, -2}, {3, 0, -2}, {3, 0, 2}, {0, 0, 2}}))}))));
}

TEST(Convexity, ExtrusionsFollowTheirProfile) {
    EXPECT_TRUE(is_convex(extrude(polygon({{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}}), {0, 0, 1}, 4)));
    // An L: one concave edge between two planar faces.
    EXPECT_FALSE(is_convex(extrude(polygon({{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}}), {0, 0, 1}, 4)));
    // A D: a half disc, its arc meeting the flat side at two convex edges.
    EXPECT_TRUE(is_convex(extrude(Profile({arc(2.0, -90.0, 90.0), line_segment({0, 2, 0}, {0, -2, 0})}), {0, 0, 1}, 1)));
    // A square whose left side bulges in: a face that bends inward.
    const double half_angle = std::atan2(1.5, 2.0) * 180 / std::numbers::pi;
    EXPECT_FALSE(is_convex(extrude(Profile({line_segment({0, 0, 0}, {3, 0, 0}), line_segment({3, 0, 0}, {3, 3, 0}),
                                            line_segment({3, 3, 0}, {0, 3, 0}),
                                            arc(2.5, -half_angle, half_angle, {-2, 1.5, 0}).reversed()}),
                                   {0, 0, 1}, 1)));
}

}  // namespace
}  // namespace ratbez
