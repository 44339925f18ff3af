// self_intersection.hpp: the certificate proves embedded surfaces embedded (plane patches, a torus closed both
// ways, a twisted but embedded hyperboloid, tubes with creases) and the search finds the surfaces that meet
// themselves: rulings that cross, a pinch where every ruling passes through one point, a spindle torus (a
// circle swept round an axis nearer than its radius: the sweep whose profile is larger than the path's
// radius of curvature), a figure-eight extruded. Each found place is checked to be where the surface meets
// itself (two parameter pairs with one point) or has no tangent plane.

#include "analysis/self_intersection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nurbs_test_support.hpp"
#include "ratbez/compatible_curves.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/interpolation.hpp"
#include "ratbez/revolve.hpp"

namespace ratbez::detail {
namespace {

constexpr double pi = std::numbers::pi;

// The ruled net between two curves point u to point u (no alignment, no check): the surface ruled_surface
// would refuse.
NurbsSurface raw_ruled(const NurbsCurve& a, const NurbsCurve& b) {
    const std::vector<NurbsCurve> c = make_compatible({a, b});
    std::vector<Vec4> net;
    for (std::size_t i = 0; i < c[0].homogeneous_points().size(); ++i) {
        net.push_back(c[0].homogeneous_points()[i]);
        net.push_back(c[1].homogeneous_points()[i]);
    }
    return NurbsSurface::from_homogeneous(c[0].degree(), 1, c[0].knots(), {0, 0, 1, 1}, net, true);
}

NurbsCurve turned_circle(double radius, double z, double degrees) {
    std::vector<Vec4> pw = circle(radius, {0, 0, z}).homogeneous_points();
    const double a = degrees * pi / 180;
    for (Vec4& q : pw) q = Vec4{std::cos(a) * q.x - std::sin(a) * q.y, std::sin(a) * q.x + std::cos(a) * q.y, q.z, q.w};
    return NurbsCurve::from_homogeneous(2, circle(radius).knots(), pw, true);
}

// Where a meeting is reported, the surface is there: at a crossing the two places are one point; at a fold
// there is no tangent plane near it.
void expect_found_where_it_is(const SurfaceStrip& strip, const SelfIntersection& found) {
    ASSERT_TRUE(found.found);
    EXPECT_FALSE(found.undecided);
    const NurbsSurface& s = strip.pieces[found.piece];
    const double size = s.control_box().diagonal();
    EXPECT_LE(distance(s.point(found.u, found.v), found.point), 1e-6 * size);
    if (!found.fold) {
        EXPECT_LE(distance(strip.pieces[found.other_piece].point(found.other_u, found.other_v), found.point), 1e-6 * size);
        EXPECT_GT(std::abs(found.u - found.other_u) + std::abs(found.v - found.other_v), 1e-6);
    }
}

SelfIntersection search(const SurfaceStrip& strip) {
    double size = 0;
    for (const NurbsSurface& s : strip.pieces) size = std::max(size, s.control_box().diagonal());
    return find_self_intersection(strip, 1e-7 * size);
}

TEST(SelfIntersection, EmbeddedSurfacesAreCertified) {
    // A bilinear patch, a torus (closed round both ways), a twisted hyperboloid (circles turned 120 degrees)
    // and the same twist 170 degrees (a waist of radius 2 cos 85°, rulings nearly crossing).
    EXPECT_FALSE(search({{NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 1}}})}}).found);
    const NurbsSurface torus = revolve_surface(circle(1.0, {3, 0, 0}, {0, 1, 0}), {0, 0, 0}, {0, 0, 1}, 360);
    EXPECT_FALSE(search({{torus}, true, true}).found);
    EXPECT_FALSE(search({{raw_ruled(circle(2.0), turned_circle(2.0, 4, 120))}, true, false}).found);
    EXPECT_FALSE(search({{raw_ruled(circle(2.0), turned_circle(2.0, 4, 170))}, true, false}).found);
    // A square tube (four creases), as four pieces side by side.
    std::vector<NurbsSurface> sides;
    const Vec3 corners[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    for (int k = 0; k < 4; ++k) sides.push_back(extrude_surface(line_segment(corners[k], corners[(k + 1) % 4]), {0, 0, 1}, 3));
    EXPECT_FALSE(search({sides, true, false}).found);
    // An interpolated closed space curve swept straight up (a wavy tube).
    std::vector<Vec3> points;
    for (int k = 0; k < 12; ++k) points.push_back({std::cos(k * pi / 6) * (2 + 0.5 * std::cos(k * pi / 2)), std::sin(k * pi / 6) * 2, 0});
    EXPECT_FALSE(search({{extrude_surface(interpolate(points, 3, Parameterization::centripetal, {}, true), {0, 0.3, 1}, 2)}, true, false}).found);
}

TEST(SelfIntersection, RulingsThatCrossArePinchesAreFound) {
    // A circle ruled to the same circle run the other way: rulings from angle t and -t meet at mid height.
    const SurfaceStrip crossing{{raw_ruled(circle(2.0), circle(2.0, {0, 0, 4}, {0, 0, -1}))}, true, false};
    expect_found_where_it_is(crossing, search(crossing));
    // Turned half a turn: every ruling passes through the axis at mid height (a pinch, no tangent plane).
    const SurfaceStrip pinch{{raw_ruled(circle(2.0), turned_circle(2.0, 4, 180))}, true, false};
    const SelfIntersection found = search(pinch);
    expect_found_where_it_is(pinch, found);
    EXPECT_LE(norm(found.point - Vec3{0, 0, 2}), 1e-6);
}

TEST(SelfIntersection, ASweepLargerThanItsBendAndAFigureEightAreFound) {
    // A circle of radius 1.5 swept round an axis 1 away: the spindle torus, which passes through itself.
    const SurfaceStrip spindle{{revolve_surface(circle(1.5, {1, 0, 0}, {0, 1, 0}), {0, 0, 0}, {0, 0, 1}, 360)}, true, true};
    expect_found_where_it_is(spindle, search(spindle));
    // Half of it (a sweep along a half circle): still through itself near the axis.
    const SurfaceStrip half{{revolve_surface(circle(1.5, {1, 0, 0}, {0, 1, 0}), {0, 0, 0}, {0, 0, 1}, 180)}, true, false};
    expect_found_where_it_is(half, search(half));
    // A figure-eight (a closed curve crossing itself) extruded: the surface crosses itself along a line.
    std::vector<Vec3> eight;
    for (int k = 0; k < 16; ++k) eight.push_back({std::sin(k * pi / 8), std::sin(k * pi / 4) / 2, 0});
    const SurfaceStrip extruded{{extrude_surface(interpolate(eight, 3, Parameterization::chord, {}, true), {0, 0, 1}, 1)}, true, false};
    expect_found_where_it_is(extruded, search(extruded));
}

TEST(SelfIntersection, TheBudgetEndsUndecided) {
    const SurfaceStrip pinch{{raw_ruled(circle(2.0), turned_circle(2.0, 4, 175))}, true, false};
    const SelfIntersection result = find_self_intersection(pinch, 1e-7, 3);
    EXPECT_TRUE(result.found);
    EXPECT_TRUE(result.undecided);
}

}  // namespace
}  // namespace ratbez::detail
