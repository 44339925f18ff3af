// Hostile inputs: degree 0 and degree 40, 10^5 control points, knot spans from 1e-300 to 1e300,
// weights 1e-12 and 1e12, coordinates 1e-300 and 1e300, a tessellation tolerance of 1e-15 and absurd
// sizes. Each case either works — finite and correct results, checked against exact properties (linear
// precision, endpoint interpolation, the algorithms agree) — or throws ratbez::Error whose message names
// the argument ("name: reason"). Nothing may hang (every test has a CTest TIMEOUT), allocate without
// bound (the tessellator's budget rejects before allocating) or throw anything else.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "ratbez/bernstein.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/limits.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/occt/check.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/surface_grid.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::reliability {
namespace {

// A clear message: "argument: reason", both parts non-empty.
void expect_clear_message(const Error& e, const std::string& argument = {}) {
    const std::string message = e.what();
    const auto colon = message.find(": ");
    ASSERT_NE(colon, std::string::npos) << "no 'argument: reason' in: " << message;
    EXPECT_GT(colon, 0u) << message;
    EXPECT_GT(message.size(), colon + 2) << message;
    if (!argument.empty()) {
        // "surface" also matches "surface (degree_u)": the argument, then which part of it.
        EXPECT_EQ(message.substr(0, argument.size()), argument) << message;
    }
}

// Runs `call`; it must throw ratbez::Error naming `argument`.
template <class Call>
void expect_rejected(Call&& call, const std::string& argument, const std::string& what) {
    try {
        call();
        ADD_FAILURE() << what << ": accepted, expected ratbez::Error naming '" << argument << "'";
    } catch (const Error& e) {
        expect_clear_message(e, argument);
    }
}

// Runs `call`; either it works and `check` holds for the result, or it throws a clear ratbez::Error.
// Returns true when it worked.
template <class Call, class Check>
bool works_or_rejects(Call&& call, Check&& check, const std::string& what) {
    try {
        auto result = call();
        SCOPED_TRACE(what);
        check(result);
        return true;
    } catch (const Error& e) {
        SCOPED_TRACE(what);
        expect_clear_message(e);
        return false;
    }
}

bool finite(const Vec3& p) { return is_finite(p); }

// --------------------------------------------------------------------------------------------- degree 0

TEST(HostileDegree, DegreeZeroCurvesAreConstant) {
    const Vec3 p{1.5, -2, 3};
    const BezierCurve bezier({p});
    EXPECT_EQ(bezier.degree(), 0);
    for (double u : {0.0, 0.3, 1.0}) {
        EXPECT_EQ(bezier.point(u), p);
        EXPECT_EQ(bezier.point_de_casteljau(u), p);
        EXPECT_EQ(bezier.derivative(u, 1), Vec3{});
        EXPECT_EQ(bezier.derivative(u, 3), Vec3{});
    }
    const BezierCurve elevated = bezier.elevate();
    EXPECT_EQ(elevated.degree(), 1);
    EXPECT_EQ(elevated.point(0.7), p);
    const auto [left, right] = bezier.split(0.25);
    EXPECT_EQ(left.point(0.5), p);
    EXPECT_EQ(right.point(0.5), p);

    const NurbsCurve nurbs(0, {0.0, 2.0}, {p});
    for (double u : {0.0, 1.0, 2.0}) EXPECT_EQ(nurbs.point(u), p);
    EXPECT_EQ(nurbs.derivative(1.0), Vec3{});
    ASSERT_EQ(nurbs.bezier_segments().size(), 1u);
    works_or_rejects([&] { return nurbs.insert_knot(1.0); }, [&](const NurbsCurve& c) { EXPECT_EQ(c.point(1.5), p); },
                     "degree-0 knot insertion");
    // OpenCASCADE holds degree >= 1 only, and a profile piece must not be a point.
    expect_rejected([&] { (void)occt::to_occt(nurbs); }, "curve", "degree 0 to OCCT");
    expect_rejected([&] { (void)Profile({nurbs}); }, "profile", "degree-0 profile piece");
}

TEST(HostileDegree, DegreeZeroSurfacesHaveNoNormal) {
    const Vec3 p{1, 2, 3};
    const BezierSurface bezier({{p}});
    EXPECT_EQ(bezier.point(0.5, 0.5), p);
    EXPECT_EQ(bezier.derivative(0.5, 0.5, 1, 0), Vec3{});
    expect_rejected([&] { (void)bezier.normal(0.5, 0.5); }, "(u, v)", "normal of a point");
    const NurbsSurface nurbs(0, 0, {0, 1}, {0, 1}, {{p}});
    EXPECT_EQ(nurbs.point(0.2, 0.9), p);
    EXPECT_THROW((void)nurbs.normal(0.5, 0.5), Error);
}

// ------------------------------------------------------------------------ degree 25, the limit everywhere

// P_i = (i/n, y_i, z_i): by linear precision x(u) = u for any y and z.
std::vector<Vec3> linear_x_points(int n) {
    std::vector<Vec3> points;
    for (int i = 0; i <= n; ++i)
        points.push_back({static_cast<double>(i) / n, std::sin(1.7 * i), std::cos(0.3 * i * i)});
    return points;
}

// Degree 25 is the one limit of the kernel and OpenCASCADE alike (ratbez/limits.hpp): exact there, and a
// degree above it refused with the limit named, before anything is built (issue 14, item 9).
TEST(HostileDegree, DegreeTwentyFiveCurvesAreExact) {
    constexpr int n = limits::max_degree;
    const BezierCurve curve(linear_x_points(n));
    std::vector<double> weights;
    for (int i = 0; i <= n; ++i) weights.push_back(std::pow(10.0, std::sin(1.3 * i)));  // 0.1 .. 10
    const BezierCurve rational(linear_x_points(n), weights);
    for (double u : {0.0, 1e-9, 0.1, 0.5, 0.77, 1 - 1e-9, 1.0}) {
        const Vec3 a = curve.point(u), b = curve.point_de_casteljau(u);
        EXPECT_NEAR(a.x, u, 1e-14);
        EXPECT_NEAR(distance(a, b), 0, 1e-13);
        const Vec3 d = curve.derivative(u, 1);
        EXPECT_NEAR(d.x, 1.0, 1e-11);
        for (const Vec3& k : curve.derivatives(u, 5)) EXPECT_TRUE(finite(k));
        const Vec3 r = rational.point(u), s = rational.point_de_casteljau(u);
        EXPECT_TRUE(finite(r));
        EXPECT_NEAR(distance(r, s), 0, 1e-12);
        EXPECT_GE(r.x, -1e-15);
        EXPECT_LE(r.x, 1 + 1e-15);
    }
    EXPECT_EQ(curve.point(0.0), curve.points().front());
    EXPECT_EQ(curve.point(1.0), curve.points().back());
    const auto [left, right] = rational.split(0.4);
    EXPECT_NEAR(distance(left.point(0.5), rational.point(0.2)), 0, 1e-12);
    EXPECT_NEAR(distance(right.point(0.5), rational.point(0.7)), 0, 1e-12);
    expect_rejected([&] { (void)rational.elevate(); }, "curve", "elevating degree 25");
    expect_rejected([&] { (void)BezierCurve(linear_x_points(n + 1)); }, "points", "a degree 26 curve");

    // OpenCASCADE takes degree 25 too: the same curve there.
    const NurbsCurve nurbs = NurbsCurve::from_bezier(rational);
    EXPECT_NEAR(distance(nurbs.point(0.6), rational.point(0.6)), 0, 1e-12);
    const Handle(Geom_BSplineCurve) occt_curve = occt::to_occt(nurbs);
    const gp_Pnt q = occt_curve->Value(0.6);
    EXPECT_NEAR(distance(Vec3{q.X(), q.Y(), q.Z()}, rational.point(0.6)), 0, 1e-12);
}

TEST(HostileDegree, DegreeTwentyFiveSurfacesAgreeAcrossAlgorithms) {
    constexpr int n = limits::max_degree;
    std::vector<std::vector<Vec3>> net(n + 1, std::vector<Vec3>(n + 1));
    std::vector<std::vector<double>> weights(n + 1, std::vector<double>(n + 1));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            net[i][j] = {static_cast<double>(i) / n, static_cast<double>(j) / n, std::sin(0.4 * i) * std::cos(0.7 * j)};
            weights[i][j] = std::pow(10.0, 0.5 * std::sin(0.3 * i + 0.2 * j));
        }
    const BezierSurface polynomial(net);
    const BezierSurface rational(net, weights);
    for (double u : {0.0, 0.31, 1.0})
        for (double v : {0.0, 0.62, 1.0}) {
            const Vec3 p = polynomial.point(u, v);
            EXPECT_NEAR(p.x, u, 1e-14);
            EXPECT_NEAR(p.y, v, 1e-14);
            const Vec3 r = rational.point_basis(u, v);
            EXPECT_NEAR(distance(r, rational.point_u_first(u, v)), 0, 1e-12);
            EXPECT_NEAR(distance(r, rational.point_v_first(u, v)), 0, 1e-12);
            EXPECT_NEAR(distance(r, rational.point_one_step(u, v)), 0, 1e-12);
            EXPECT_NEAR(norm(polynomial.normal(u, v)), 1.0, 1e-12);
        }
    const NurbsSurface nurbs = NurbsSurface::from_bezier(rational);
    EXPECT_NEAR(distance(nurbs.point(0.4, 0.45), rational.point(0.4, 0.45)), 0, 1e-12);
    const Handle(Geom_BSplineSurface) occt_surface = occt::to_occt(nurbs);
    const gp_Pnt q = occt_surface->Value(0.4, 0.45);
    EXPECT_NEAR(distance(Vec3{q.X(), q.Y(), q.Z()}, rational.point(0.4, 0.45)), 0, 1e-12);
    net.push_back(net.back());
    expect_rejected([&] { (void)BezierSurface(net); }, "net", "a degree 26 surface");
}

// --------------------------------------------------------------------------------- 10^5 control points

// Degree-3 B-spline with n + 1 = 100,000 control points at the Greville abscissae in x: x(u) = u.
TEST(HostileSize, HundredThousandControlPoints) {
    const int count = 100'000, p = 3;
    std::vector<double> knots(p + 1, 0.0);
    const int spans = count - p;
    for (int k = 1; k < spans; ++k) knots.push_back(static_cast<double>(k) / spans);
    knots.insert(knots.end(), p + 1, 1.0);
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) {
        const double greville = (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
        points.push_back({greville, std::sin(0.001 * i), 1.0 + 0.5 * std::cos(0.002 * i)});
    }
    const NurbsCurve curve(p, knots, points);
    for (int k = 0; k <= 1000; ++k) {
        const double u = k / 1000.0;
        ASSERT_NEAR(curve.point(u).x, u, 1e-12);
    }
    EXPECT_NEAR(curve.derivative(0.123456).x, 1.0, 1e-8);
    const auto segments = curve.bezier_segments();
    EXPECT_EQ(segments.size(), static_cast<std::size_t>(spans));
    const NurbsCurve refined = curve.insert_knot(0.5 + 0.3 / spans, 2);
    EXPECT_NEAR(distance(refined.point(0.5), curve.point(0.5)), 0, 1e-12);

    // A surface with 1,000 x 100 control points.
    std::vector<std::vector<Vec3>> net(1000, std::vector<Vec3>(100));
    for (int i = 0; i < 1000; ++i)
        for (int j = 0; j < 100; ++j) net[i][j] = {i * 1e-3, j * 1e-2, std::sin(0.01 * i * j)};
    std::vector<double> ku(4, 0.0), kv(4, 0.0);
    for (int k = 1; k < 997; ++k) ku.push_back(k / 997.0);
    for (int k = 1; k < 97; ++k) kv.push_back(k / 97.0);
    ku.insert(ku.end(), 4, 1.0);
    kv.insert(kv.end(), 4, 1.0);
    const NurbsSurface surface(3, 3, ku, kv, net);
    const SurfaceGrid grid = evaluate_grid(surface, 40, 40, GridOutput::normals);
    for (std::size_t k = 0; k < grid.points.size(); ++k) ASSERT_TRUE(finite(grid.points[k]));
    EXPECT_NEAR(distance(grid.point(13, 27), surface.point(13 / 39.0, 27 / 39.0)), 0, 1e-12);
}

// A closed polygon of 100,000 control points (99,999 sides) on the unit circle about (3, 0, 0) in the
// xz plane, as one degree-1 NURBS curve.
NurbsCurve polygonal_ring() {
    const int count = 100'000, p = 1;
    std::vector<double> knots(p + 1, 0.0);
    for (int k = 1; k < count - p; ++k) knots.push_back(static_cast<double>(k) / (count - p));
    knots.insert(knots.end(), p + 1, 1.0);
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) {
        const double t = 2 * std::numbers::pi * i / (count - 1);
        points.push_back({3 + std::cos(t), 0, std::sin(t)});
    }
    points.back() = points.front();
    return NurbsCurve(p, knots, points);
}

// The ring revolved: 4 x 10^5 patches. The tessellator's curvature sampling alone would need more
// samples than the triangle budget, so it is refused before sampling (it used to sample for about 14 s
// and then reject the grid).
TEST(HostileSize, RevolvedLargeProfileRespectsTheBudget) {
    const Solid solid = revolve(Profile({polygonal_ring()}));
    TessellationOptions options;
    options.tolerance = 1e-3;
    options.max_triangles = 50'000;
    expect_rejected([&] { (void)tessellate(solid, options); }, "max_triangles", "100k-point ring, 50k-triangle budget");
}

// The ring extruded: a side face of 99,999 spans and two caps bounded by it. Its volume is the polygon's
// area (n/2) sin(2π/n) times the height, to the measurements' 1e-14: the polynomial faces are integrated
// exactly patch by patch in each patch's own parameters. (Solid's orientation check integrates on the
// knot spans instead, where a node inside a span of 1e-5 is placed to about 1e-11 of the span, and the
// sum drifts by 4e-13: fine for a sign, not for a measurement.)
TEST(HostileSize, ExtrudedLargeProfileIsMeasuredExactly) {
    const double height = 2.5, sides = 99'999;
    const Solid solid = extrude(Profile({polygonal_ring()}), {0, 1, 0}, height);
    const double exact = sides / 2 * std::sin(2 * std::numbers::pi / sides) * height;
    EXPECT_NEAR(solid.volume(), exact, 1e-14 * exact);
}

// ---------------------------------------------------------------------------------------- knot spans

TEST(HostileKnots, TinyAndHugeSpans) {
    const std::vector<Vec3> points{{0, 0, 0}, {1, 2, 0}, {3, 2, 1}, {4, 0, 0}};
    // A span of 1e-300 beside one of 1: points stay in the convex hull; derivatives of a span 1e-300
    // wide reach 1e300 and beyond (the second one overflows): finite values or an Error, never inf.
    const NurbsCurve tiny(2, {0, 0, 0, 1e-300, 1, 1, 1}, points);
    for (double u : {0.0, 5e-301, 1e-300, 0.5, 1.0}) {
        const Vec3 c = tiny.point(u);
        ASSERT_TRUE(finite(c)) << u;
        EXPECT_GE(c.x, 0);
        EXPECT_LE(c.x, 4);
        works_or_rejects([&] { return tiny.derivatives(u, 2); },
                         [&](const std::vector<Vec3>& d) {
                             for (const Vec3& k : d) EXPECT_TRUE(finite(k)) << "u = " << u;
                         },
                         "derivatives across a 1e-300 span");
    }
    // A domain 2e300 wide: linear precision still holds.
    const NurbsCurve huge(1, {-1e300, -1e300, 1e300, 1e300}, {{-1, 0, 0}, {1, 0, 0}});
    EXPECT_NEAR(huge.point(0).x, 0, 1e-15);
    EXPECT_NEAR(huge.point(5e299).x, 0.5, 1e-15);
    EXPECT_NEAR(huge.derivative(0).x, 1e-300, 1e-315);
    // A domain whose width overflows to infinity cannot be evaluated: rejected at construction, or
    // evaluated correctly.
    works_or_rejects([&] { return NurbsCurve(1, {-1e308, -1e308, 1e308, 1e308}, {{-1, 0, 0}, {1, 0, 0}}); },
                     [](const NurbsCurve& c) { EXPECT_NEAR(c.point(0).x, 0, 1e-15); }, "a domain of width 2e308");
    // Knots spanning 1e-300 .. 1e300 in one vector.
    const NurbsCurve mixed(3, {1e-300, 1e-300, 1e-300, 1e-300, 1e-200, 1e-100, 1, 1e100, 1e300, 1e300, 1e300, 1e300},
                           {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}, {4, 1, 0}, {5, 1, 0}, {6, 0, 0}, {7, 0, 0}});
    for (double u : {1e-300, 1e-250, 1e-150, 1e-50, 10.0, 1e200, 1e300}) {
        const Vec3 c = mixed.point(u);
        ASSERT_TRUE(finite(c)) << u;
        EXPECT_GE(c.x, 0);
        EXPECT_LE(c.x, 7);
    }
    EXPECT_EQ(mixed.point(1e300), (Vec3{7, 0, 0}));
    expect_rejected([&] { (void)NurbsCurve(1, {0, 0, std::nan(""), 1}, {{0, 0, 0}, {1, 0, 0}}); }, "knots", "NaN knot");
    expect_rejected([&] { (void)NurbsCurve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}).point(1 + 1e-12); }, "u",
                    "parameter past the domain");
}

// -------------------------------------------------------------------------------------------- weights

TEST(HostileWeights, ExtremeWeightsStayExact) {
    const std::vector<Vec3> points{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    const BezierCurve heavy(points, {1, 1e12, 1});
    EXPECT_NEAR(distance(heavy.point(0.5), points[1]), 0, 1e-11);
    EXPECT_EQ(heavy.point(0), points[0]);
    EXPECT_EQ(heavy.point(1), points[2]);
    const BezierCurve light(points, {1, 1e-12, 1});
    EXPECT_NEAR(light.point(0.5).y, 0, 1e-11);
    const BezierCurve light_ends(points, {1e-12, 1, 1e-12});
    EXPECT_EQ(light_ends.point(0), points[0]);
    EXPECT_NEAR(distance(light_ends.point(0.5), points[1]), 0, 1e-11);
    // C'(0) = n w1/w0 (P1 - P0): 2e12 (1, 1, 0), large but finite.
    const Vec3 d = light_ends.derivative(0);
    EXPECT_NEAR(d.x / 2e12, 1, 1e-9);
    for (const BezierCurve* c : {&heavy, &light, &light_ends})
        for (double u : {0.0, 1e-6, 0.5, 1.0})
            for (const Vec3& k : c->derivatives(u, 3)) EXPECT_TRUE(finite(k));
    expect_rejected([&] { (void)BezierCurve(points, {1, 0, 1}); }, "weights", "zero weight");
    expect_rejected([&] { (void)BezierCurve(points, {1, -1e-12, 1}); }, "weights", "negative weight");
}

// A closed ring profile: a rational quadratic with a 1e12 middle weight (almost the control polygon's
// corner), one with 1e-12 (almost its chord), and two lines. Revolved fully and partially, it must
// check valid in OpenCASCADE and mesh closed within the tolerance.
std::vector<NurbsCurve> extreme_weight_ring(double bottom_weight, std::vector<double> top_weights) {
    const Vec3 a{2, 0, 0}, b{4, 0, 0}, c{4, 0, 2}, e{2, 0, 2};
    return {
        NurbsCurve::from_bezier(BezierCurve({a, {3, 0, -1}, b}, {1, bottom_weight, 1})),
        NurbsCurve::from_bezier(BezierCurve({b, c})),
        NurbsCurve::from_bezier(BezierCurve({c, {3, 0, 3}, e}, std::move(top_weights))),
        NurbsCurve::from_bezier(BezierCurve({e, a})),
    };
}

void expect_meshes_within_tolerance(const Solid& solid, const std::string& what) {
    const double tolerance = 2e-3;
    const Mesh mesh = tessellate(solid, tolerance);
    EXPECT_TRUE(mesh.is_closed()) << what;
    EXPECT_LE(max_deviation(solid, mesh), tolerance * (1 + 1e-9)) << what;
    EXPECT_NEAR(mesh.volume(), solid.volume(), tolerance * solid.area()) << what;
}

TEST(HostileWeights, RevolvedProfileWithExtremeWeightsBuildsAndMeshesClosedOrRejects) {
    for (double w : {1e6, 1e12})
        for (double angle : {360.0, 123.0}) {
            const std::string what = "weights " + std::to_string(w) + ", angle " + std::to_string(angle);
            const Solid solid = revolve(Profile(extreme_weight_ring(w, {1, 1 / w, 1})), {}, {0, 0, 1}, angle);
            works_or_rejects([&] { return tessellate(solid, 2e-3); },
                             [&](const Mesh& mesh) { EXPECT_TRUE(mesh.is_closed()) << what; }, what);
        }
    // End weights 1e-12 beside a middle weight 1: the curve rushes to the middle control point and
    // all but stops there (its speed drops by 1e12), so the surface has no usable tangent plane along
    // those parameters. Meshing it works or says where the tangent plane is missing.
    const Solid stalled = revolve(Profile(extreme_weight_ring(1, {1e-12, 1, 1e-12})));
    works_or_rejects([&] { return tessellate(stalled, 2e-3); }, [](const Mesh& mesh) { EXPECT_TRUE(mesh.is_closed()); },
                     "end weights 1e-12");
}

// The area between the chord and a rational quadratic with weights 1, w, 1, as a fraction of its
// control triangle's area (∫ y dx of the conic through (-1, 0), (0, 1), (1, 0) in closed form; f(cos θ)
// is the circular segment, f -> 2/3 at w = 1, Archimedes' parabola). Divided through by w^2 for w > 1.
double conic_segment_fraction(double w) {
    if (w > 1) {
        const double q = 1 - 1 / (w * w);
        return 1 / q - std::acosh(w) / (w * w) / std::pow(q, 1.5);
    }
    return w * w / (w * w - 1) + w * std::acos(w) / std::pow(1 - w * w, 1.5);
}

// Solid::volume and Solid::area of the extreme-weight ring against Pappus and OpenCASCADE's BRepGProp on
// the converted B-rep. The ring's profile is the square [2, 4] x [0, 2] plus two conic segments (control
// triangles of area 1, symmetric about ρ = 3): profile area A = 4 + f(w) + f(1/w) and
// V = 2π · 3 · A · angle / 360. A fixed Gauss rule was 1e-4 off at w = 1e3 and 33% at 1e6; the
// adaptive quadrature of properties.cpp must be exact. The partial ring's area is the full ring's
// lateral area times angle / 360 plus its two planar caps of area A: surface and planar (Green) faces
// checked against each other. BRepGProp at its default accuracy agrees at w = 1e3 only (6e-9 measured,
// 1e-7 asserted); it measured 9e-4 off at 1e6 and 17% at 1e12, where the converted B-rep is not valid
// either: beyond 1e3 it is not run (it was printed, and took most of the test's time).
TEST(HostileWeights, ExtremeWeightsGiveExactVolume) {
    for (double w : {1e3, 1e6, 1e12}) {
        const double profile_area = 4 + conic_segment_fraction(w) + conic_segment_fraction(1 / w);
        const double full_area = revolve(Profile(extreme_weight_ring(w, {1, 1 / w, 1}))).area();
        for (double angle : {360.0, 123.0}) {
            const std::string what = "weights " + std::to_string(w) + ", angle " + std::to_string(angle);
            const Solid solid = revolve(Profile(extreme_weight_ring(w, {1, 1 / w, 1})), {}, {0, 0, 1}, angle);
            const double pappus = 2 * std::numbers::pi * 3 * profile_area * angle / 360;
            const double area = full_area * angle / 360 + (angle < 360 ? 2 * profile_area : 0.0);
            EXPECT_NEAR(solid.volume(), pappus, 1e-10 * pappus) << what;
            EXPECT_NEAR(solid.area(), area, 1e-10 * area) << what;
            // OpenCASCADE's side up to 1e3 only: beyond (where the B-rep is not valid either) its measures, asked
            // again at 1e-11 and 1e-13 as they disagree, and its BOP analysis walking the crowded conic took most of
            // this test's time, and nothing of them is asserted there.
            if (w > 1e3) continue;
            occt::CheckOptions options;
            options.grid = 15;
            const occt::CheckReport report = occt::check(solid, options);
            EXPECT_TRUE(report.valid) << what << "\n" << occt::format_report(report);
            EXPECT_NEAR(report.occt_volume, report.volume, 1e-7 * pappus) << what << "\n" << occt::format_report(report);
            EXPECT_NEAR(report.occt_area, report.area, 1e-7 * area) << what << "\n" << occt::format_report(report);
            std::cout << "[ measured ] " << what << ": relative to Pappus, volume " << report.volume / pappus - 1
                      << ", OCCT volume " << report.occt_volume / pappus - 1 << "; OCCT area relative to ours "
                      << report.occt_area / report.area - 1 << "\n";
        }
    }
}

// With a middle weight of 1e3 and beyond the mesh once missed its tolerance and volume (the volume part
// is ExtremeWeightsGiveExactVolume above, fixed by the adaptive quadrature of properties.cpp;
// max_deviation's seeds missed the crowded conic and overestimated). Under the sanitizers the partial ring only
// (the full ring runs the same code, and took 47 s there).
TEST(HostileWeights, ExtremeWeightsGiveExactMesh) {
#if defined(__SANITIZE_ADDRESS__)
    const std::vector<double> angles{123.0};
#else
    const std::vector<double> angles{360.0, 123.0};
#endif
    for (double w : {1e3, 1e6})
        for (double angle : angles) {
            const std::string what = "weights " + std::to_string(w) + ", angle " + std::to_string(angle);
            const Solid solid = revolve(Profile(extreme_weight_ring(w, {1, 1 / w, 1})), {}, {0, 0, 1}, angle);
            expect_meshes_within_tolerance(solid, what);
        }
}

// ---------------------------------------------------------------------------------------- coordinates

TEST(HostileCoordinates, HugeAndTinyCurves) {
    for (double s : {1e-300, 1e300}) {
        const std::vector<Vec3> points{{0, 0, 0}, {s, s, 0}, {2 * s, 0, s}};
        const BezierCurve curve(points, {1, 2, 1});
        const Vec3 m = curve.point(0.5);
        ASSERT_TRUE(finite(m)) << s;
        EXPECT_NEAR(m.x / s, 1.0, 1e-14) << s;
        EXPECT_NEAR(m.y / s, 2.0 / 3.0, 1e-14) << s;
        for (const Vec3& k : curve.derivatives(0.3, 2)) EXPECT_TRUE(finite(k)) << s;
        const NurbsCurve nurbs = NurbsCurve::from_bezier(curve);
        EXPECT_NEAR(nurbs.point(0.5).x / s, 1.0, 1e-14);
    }
    expect_rejected([&] { (void)BezierCurve({{0, 0, 0}, {std::numeric_limits<double>::infinity(), 0, 0}}); }, "points",
                    "infinite coordinate");
}

// Solids of size 1e-300 and 1e300: built and measured correctly, or rejected with a clear Error —
// never an infinite volume or a mesh with NaN vertices.
TEST(HostileCoordinates, HugeAndTinySolids) {
    for (double s : {1e-300, 1e-150, 1e150, 1e300}) {
        works_or_rejects([&] { return sphere(s, {s, -s, 0}); },
                         [&](const Solid& solid) {
                             const double exact = 4.0 / 3.0 * std::numbers::pi;  // in units of s^3
                             works_or_rejects([&] { return solid.volume(); },
                                              [&](double v) {
                                                  ASSERT_TRUE(std::isfinite(v)) << s;
                                                  ASSERT_GT(v, 0) << s;
                                                  EXPECT_NEAR(v / (s * s * s), exact, 1e-6 * exact) << s;
                                              },
                                              "sphere volume, radius " + std::to_string(s));
                             works_or_rejects([&] { return tessellate(solid, default_tolerance(solid)); },
                                              [&](const Mesh& mesh) {
                                                  EXPECT_TRUE(mesh.is_closed()) << s;
                                                  for (const Vec3& v : mesh.vertices) ASSERT_TRUE(finite(v)) << s;
                                              },
                                              "sphere mesh, radius " + std::to_string(s));
                         },
                         "sphere of radius " + std::to_string(s));
    }
}

// ------------------------------------------------------------------------------------- tessellation

TEST(HostileTessellation, TooFineToleranceIsRejectedByTheBudget) {
    const Solid ball = sphere(1);
    try {
        (void)tessellate(ball, 1e-15);
        ADD_FAILURE() << "a 1e-15 tolerance was accepted";
    } catch (const Error& e) {
        expect_clear_message(e, "tolerance");
        EXPECT_NE(std::string(e.what()).find("max_triangles"), std::string::npos) << e.what();
    }
    TessellationOptions tight{1e-2, std::nullopt, 50, {}};
    expect_rejected([&] { (void)tessellate(ball, tight); }, "tolerance", "50-triangle budget");
    // The message gives an estimate of what the tolerance needs, not the budget plus one.
    const std::size_t needed = tessellate(ball, 1e-3).triangles.size();
    try {
        (void)tessellate(ball, TessellationOptions{1e-3, std::nullopt, 1000, {}});
        ADD_FAILURE() << "a 1000-triangle budget was enough";
    } catch (const TooFine& e) {
        EXPECT_EQ(e.max_triangles(), 1000u);
        EXPECT_GT(e.estimated_triangles(), 0.5 * static_cast<double>(needed)) << needed;
        EXPECT_LT(e.estimated_triangles(), 2.0 * static_cast<double>(needed)) << needed;
        EXPECT_NE(std::string(e.what()).find("more than max_triangles = 1000 allows"), std::string::npos) << e.what();
    }
    TessellationOptions angle{1.0, 1e-9, 1'000'000, {}};
    expect_rejected([&] { (void)tessellate(ball, angle); }, "tolerance", "1e-9 degree angle");
    for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
        expect_rejected([&] { (void)tessellate(ball, bad); }, "tolerance", "tolerance " + std::to_string(bad));
    TessellationOptions no_budget{1e-2, std::nullopt, 0, {}};
    expect_rejected([&] { (void)tessellate(ball, no_budget); }, "max_triangles", "zero budget");
    // A huge tolerance still gives a valid closed mesh.
    const Mesh coarse = tessellate(ball, 1e6);
    EXPECT_TRUE(coarse.is_closed());
    EXPECT_GT(coarse.volume(), 0);
}

// ------------------------------------------------------------------------------------- absurd sizes

TEST(HostileSize, AbsurdSizesAreRejectedNotAllocated) {
    constexpr int big = std::numeric_limits<int>::max();
    expect_rejected([&] { (void)NurbsCurve(big, {0, 1}, {{0, 0, 0}}); }, "degree", "degree INT_MAX");
    expect_rejected([&] { (void)NurbsCurve(-1, {0, 1}, {{0, 0, 0}}); }, "degree", "degree -1");
    // The degree limit is checked first (cheap checks before expensive ones): INT_MAX rows is degree INT_MAX - 1.
    expect_rejected([&] { (void)BezierSurface::from_homogeneous(big, big, {Vec4{0, 0, 0, 1}}); }, "rows",
                    "INT_MAX x INT_MAX Bézier surface");
    expect_rejected([&] { (void)BezierSurface::from_homogeneous(-3, 2, {Vec4{0, 0, 0, 1}}); }, "rows", "negative rows");
    expect_rejected([&] { (void)NurbsSurface::from_homogeneous(big, 1, {0, 1}, {0, 0, 1, 1}, {Vec4{0, 0, 0, 1}}); },
                    "degree_u", "NURBS surface of degree INT_MAX");
    expect_rejected([&] { (void)all_bernstein(-1, 0.5); }, "n", "Bernstein degree -1");
    const NurbsSurface plane(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}});
    expect_rejected([&] { (void)evaluate_grid(plane, std::numeric_limits<std::size_t>::max(), 2); }, "count",
                    "grid of SIZE_MAX x 2");
    expect_rejected([&] { (void)uniform_parameters({0, 1}, std::numeric_limits<std::size_t>::max()); }, "count",
                    "SIZE_MAX uniform parameters");
    const Solid cube_like = cylinder(1, 1);
    DeviationOptions deviation;
    deviation.samples_per_edge = big;
    expect_rejected([&] { (void)max_deviation(cube_like, tessellate(cube_like, 0.1), deviation); },
                    "options.samples_per_edge", "samples_per_edge INT_MAX");
    occt::CheckOptions check;
    check.grid = big;
    expect_rejected([&] { (void)occt::check(cube_like, check); }, "options.grid", "OCCT check grid INT_MAX");
}

}  // namespace
}  // namespace ratbez::reliability
