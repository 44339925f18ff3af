// Grid planning on its own (tessellate_plan.hpp): choose_grid against its curvature model on synthetic
// samples of constant curvature (where the model is exact), the offset field, and the planned and refined
// grids of real faces: a cylinder needs one interval along its straight direction and about as many around
// it as the best regular polygon straddling the circle; a sphere's latitude lines spread out towards the
// poles; creases become lines; directions closed on themselves or running pole to pole keep their minimum
// number of intervals.

#include "mesh/tessellate_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/revolve.hpp"

namespace ratbez::detail {
namespace {

const Face& surface_face(const Solid& solid) {
    for (const Face& face : solid.faces())
        if (face.kind() == Face::Kind::surface) return face;
    fail("test", "no surface face");
}

// A face on its own, as the tessellator places its points where no other face shares them: every grid
// point moved by the face's offsets (its seams take the same wish from both sides), one point for a pole.
void standalone_points(const SurfacePlan& plan, std::vector<Vec3>& out) {
    interior_grid_points(plan, plan.grid, out);
    const std::size_t nu = plan.grid.u.size(), nv = plan.grid.v.size();
    for (Side side : kSides) {
        if (!plan.sides[side_slot(side)].degenerate) continue;
        const bool row_of_u = runs_along_u(side);
        const std::size_t fixed = side == Side::v_min || side == Side::u_min ? 0 : (row_of_u ? nv : nu) - 1;
        auto at = [&](std::size_t k) -> Vec3& { return row_of_u ? out[k * nv + fixed] : out[fixed * nv + k]; };
        for (std::size_t k = 1; k < (row_of_u ? nu : nv); ++k) at(k) = at(0);
    }
}

// The planned and refined grid of a solid's (first) surface face.
SurfacePlan refined_plan(const Face& face, double tolerance, double angle_rad = 0) {
    const TessellationSettings settings{tolerance, angle_rad, 20'000'000};
    CurvatureSamples curvature;
    SurfacePlan plan = plan_face(face, settings, curvature);
    refine_grid(plan, curvature, settings, standalone_points);
    return plan;
}

// Curvature samples over [0, 1]^2 (n x n), every one with the same L, N and normal.
CurvatureSamples constant_curvature(double L, double N, std::size_t n = 17) {
    CurvatureSamples c;
    for (std::size_t k = 0; k < n; ++k) c.us.push_back(static_cast<double>(k) / static_cast<double>(n - 1));
    c.vs = c.us;
    c.L.assign(n * n, L);
    c.N.assign(n * n, N);
    c.M.assign(n * n, 0.0);
    c.k_max.assign(n * n, 0.0);
    c.normals.assign(n * n, Vec3{0, 0, 1});
    return c;
}

const std::array<std::vector<double>, 2> kNoCreases{std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, 1.0}};

std::vector<double> widths(const std::vector<double>& lines) {
    std::vector<double> w;
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) w.push_back(lines[k + 1] - lines[k]);
    return w;
}

// ---- choose_grid against its model

TEST(TessellatePlan, CurvatureInOneDirectionOnlyGivesTheFewestUniformLines) {
    // The span |L| h^2 / 8 may be twice the target (the mesh straddles the surface) with N = 0:
    // ceil(sqrt(L / (16 target))) equal intervals along u, one along v.
    const double L = 3.0, target = 1e-3;
    const ParameterGrid g = choose_grid(constant_curvature(L, 0.0), target, 0.0, {1, 1}, kNoCreases, 1e9);
    const double span = 2 * kOffsetShare * target;  // twice the largest offset
    const auto expected = static_cast<std::size_t>(std::ceil(std::sqrt(L / (8 * span))));
    ASSERT_EQ(g.u.size() - 1, expected);
    EXPECT_EQ(g.v.size(), 2u);
    for (double h : widths(g.u)) {
        EXPECT_NEAR(h, 1.0 / static_cast<double>(expected), 1e-12);
        EXPECT_LE(L * h * h / 8, span * (1 + 1e-12));
    }
    // One interval fewer would break the model.
    const double wider = 1.0 / static_cast<double>(expected - 1);
    EXPECT_GT(L * wider * wider / 8, span);
}

TEST(TessellatePlan, CellsSpanAtMostTwiceTheTarget) {
    // Whatever the signs of the curvatures (a sphere's, a saddle's), the errors of the two directions span
    // (|L| h_u^2 + |N| h_v^2) / 8 at most, which the offsets centre on the surface: twice the largest offset.
    const double target = 1e-4, span = 2 * kOffsetShare * target;
    for (const auto& [L, N] : {std::pair{2.0, 5.0}, std::pair{2.0, -5.0}, std::pair{-2.0, -5.0}}) {
        const ParameterGrid g = choose_grid(constant_curvature(L, N), target, 0.0, {1, 1}, kNoCreases, 1e9);
        ASSERT_GE(g.u.size(), 2u);
        ASSERT_GE(g.v.size(), 2u);
        for (double hu : widths(g.u))
            for (double hv : widths(g.v)) EXPECT_LE((std::abs(L) * hu * hu + std::abs(N) * hv * hv) / 8, span * (1 + 1e-12));
        // Economical: the span is not spent on one direction only (within the tried shares).
        const double hu = widths(g.u).front(), hv = widths(g.v).front();
        EXPECT_GT((std::abs(L) * hu * hu + std::abs(N) * hv * hv) / 8, target);
    }
    // The signs do not matter to the model: a saddle costs what a sphere costs.
    EXPECT_EQ(choose_grid(constant_curvature(2.0, -5.0), target, 0.0, {1, 1}, kNoCreases, 1e9).cells(),
              choose_grid(constant_curvature(2.0, 5.0), target, 0.0, {1, 1}, kNoCreases, 1e9).cells());
}

TEST(TessellatePlan, OffsetsCentreTheSpanOnTheSurface) {
    // -(c_u + c_v) / 2 with c = k h^2 / 8 on the grid's spacing: outward (positive) where the surface bends
    // away from its outward normal (k < 0), inward where it bends towards it, nothing on a flat face or a
    // balanced saddle; never beyond max_offset.
    const double target = 1e-4;
    for (const auto& [L, N] : {std::pair{-2.0, -5.0}, std::pair{2.0, 5.0}, std::pair{0.0, 0.0}, std::pair{2.0, -2.0}}) {
        const CurvatureSamples c = constant_curvature(L, N);
        const ParameterGrid g = choose_grid(c, target, 0.0, {1, 1}, kNoCreases, 1e9);
        const OffsetField field = offset_field(c, g, {}, kOffsetShare * target, target);
        const double hu = widths(g.u).front(), hv = widths(g.v).front();
        const double expected = std::clamp(-(L * hu * hu + N * hv * hv) / 16, -kOffsetShare * target, kOffsetShare * target);
        // The offsets the cells accept: those that keep the errors (on the side each curvature puts them)
        // within the target either way, and within max_offset; they hold the centre.
        const double reach = kOffsetShare * target;
        const double below = std::min(0.0, L * hu * hu / 8) + std::min(0.0, N * hv * hv / 8);
        const double above = std::max(0.0, L * hu * hu / 8) + std::max(0.0, N * hv * hv / 8);
        for (double u : {0.1, 0.5, 0.93})
            for (double v : {0.2, 0.77}) {
                EXPECT_NEAR(field.at(u, v), expected, 1e-15);
                EXPECT_NEAR(field.lowest_at(u, v), std::max(-target - below, -reach), 1e-15);
                EXPECT_NEAR(field.highest_at(u, v), std::min(target - above, reach), 1e-15);
                EXPECT_LE(field.lowest_at(u, v), field.at(u, v));
                EXPECT_GE(field.highest_at(u, v), field.at(u, v));
            }
        if (L < 0) {
            EXPECT_GT(expected, 0.4 * target);
        }
        if (L > 0 && N > 0) {
            EXPECT_LT(expected, -0.4 * target);
        }
    }
    // An inscribed face keeps its vertices on the surface, and accepts the offsets its span leaves.
    const CurvatureSamples convex = constant_curvature(-2.0, -5.0);
    const ParameterGrid inscribed = choose_grid(convex, target, 0.0, {1, 1}, kNoCreases, 1e9, false);
    const OffsetField on_surface = offset_field(convex, inscribed, {}, kOffsetShare * target, target, false);
    EXPECT_EQ(on_surface.at(0.5, 0.5), 0.0);
    EXPECT_LE(on_surface.lowest_at(0.5, 0.5), 0.0);
    EXPECT_GE(on_surface.highest_at(0.5, 0.5), 0.0);
    // Within a quarter of the radius of curvature, however large max_offset is.
    CurvatureSamples tight = constant_curvature(-2.0, -5.0);
    tight.k_max.assign(tight.L.size(), 1e6);
    const OffsetField capped = offset_field(tight, choose_grid(tight, 1.0, 0.0, {1, 1}, kNoCreases, 1e9), {}, kOffsetShare, 1.0);
    EXPECT_LE(capped.at(0.5, 0.5), 0.25e-6 * (1 + 1e-12));
}

TEST(TessellatePlan, TwistIsCentredAndBudgeted) {
    // A hyperbolic paraboloid's twist M s t h_u h_v: two triangles interpolate it with an error of one sign,
    // up to |M| h_u h_v / 4, which the offset M h_u h_v / 8 centres; the cells keep it within twice the
    // largest offset.
    const double M = 3.0, target = 1e-4;
    CurvatureSamples c = constant_curvature(0.0, 0.0);
    c.M.assign(c.L.size(), M);
    const ParameterGrid g = choose_grid(c, target, 0.0, {1, 1}, kNoCreases, 1e9);
    const OffsetField field = offset_field(c, g, {}, kOffsetShare * target, target);
    for (double hu : widths(g.u))
        for (double hv : widths(g.v)) EXPECT_LE(M * hu * hv / 4, 2 * kOffsetShare * target * (1 + 1e-12));
    const double hu = widths(g.u).front(), hv = widths(g.v).front();
    EXPECT_GT(M * hu * hv / 4, target);  // not much finer than needed
    EXPECT_NEAR(field.at(0.5, 0.5), M * hu * hv / 8, 1e-15);
}

TEST(TessellatePlan, MinimumSegmentsCreasesAndBudgetAreHonoured) {
    // Flat: only the floors count.
    const std::array<std::vector<double>, 2> creases{std::vector<double>{0.0, 0.25, 1.0}, std::vector<double>{0.0, 1.0}};
    const ParameterGrid g = choose_grid(constant_curvature(0.0, 0.0), 1e-3, 0.0, {3, 2}, creases, 1e9);
    EXPECT_GE(g.u.size() - 1, 3u);
    EXPECT_GE(g.v.size() - 1, 2u);
    EXPECT_NE(std::find(g.u.begin(), g.u.end(), 0.25), g.u.end());
    // Over the cell budget: no grid.
    EXPECT_TRUE(choose_grid(constant_curvature(1e6, 1e6), 1e-9, 0.0, {1, 1}, kNoCreases, 1000).u.empty());
}

// ---- planned faces

TEST(TessellatePlan, CylinderNeedsOneIntervalAlongItsAxis) {
    const double radius = 1.0, tolerance = 1e-3;
    const Solid solid = cylinder(radius, 2.0);
    const Face& face = surface_face(solid);
    const SurfacePlan plan = refined_plan(face, tolerance);
    const bool straight_u = face.surface().degree_u() == 1;
    const std::vector<double>& along_axis = straight_u ? plan.grid.u : plan.grid.v;
    const std::vector<double>& around = straight_u ? plan.grid.v : plan.grid.u;
    EXPECT_EQ(along_axis.size(), 2u);
    // Around: no fewer intervals than the regular polygon whose sagitta just meets twice the tolerance (its
    // vertices moved out by one, it straddles the circle; no polygon with fewer sides keeps within the
    // tolerance of it), and not many more.
    const double fewest = std::ceil(std::numbers::pi / std::acos(1 - 2 * tolerance / radius));
    EXPECT_GE(static_cast<double>(around.size() - 1), fewest);
    EXPECT_LE(static_cast<double>(around.size() - 1), 1.25 * fewest);
    EXPECT_EQ(plan.min_segments[straight_u ? 1 : 0], 3);  // the closed direction
}

TEST(TessellatePlan, SphereLatitudeLinesSpreadTowardThePoles) {
    const Solid solid = sphere(1.0);
    const Face& face = surface_face(solid);
    const SurfacePlan plan = refined_plan(face, 4e-4);
    // The direction from pole to pole is the one with two collapsed sides (at least two intervals).
    const bool latitude_u = plan.min_segments[0] == 2;
    ASSERT_EQ(plan.min_segments[latitude_u ? 1 : 0], 3);
    const std::vector<double>& lines = latitude_u ? plan.grid.u : plan.grid.v;
    const NurbsSurface& s = face.surface();
    const double other = latitude_u ? s.domain_v().min : s.domain_u().min;
    std::vector<double> latitude;  // of each line, in radians
    for (double t : lines) latitude.push_back(std::asin(std::clamp((latitude_u ? s.point(t, other) : s.point(other, t)).z, -1.0, 1.0)));
    std::vector<double> angle;  // of each interval
    for (std::size_t k = 0; k + 1 < latitude.size(); ++k) angle.push_back(std::abs(latitude[k + 1] - latitude[k]));
    ASSERT_GE(angle.size(), 16u);
    const double at_equator = *std::min_element(angle.begin(), angle.end());
    EXPECT_GT(angle.front(), 1.5 * at_equator);
    EXPECT_GT(angle.back(), 1.5 * at_equator);
    // From the equator towards each pole the intervals widen: the mean over each eighth of them grows
    // from the middle out (one interval to the next may wiggle by a few percent, as the curvature
    // samples fall).
    std::array<double, 8> eighth{};
    for (std::size_t k = 0; k < angle.size(); ++k) eighth[k * 8 / angle.size()] += angle[k] / static_cast<double>(angle.size());
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_GT(eighth[k], eighth[k + 1]);
        EXPECT_GT(eighth[7 - k], eighth[6 - k]);
    }
}

TEST(TessellatePlan, RefinedGridsPassTheirCheck) {
    for (const Solid& solid : {sphere(1.0), torus(3.0, 1.0), cone(1.0, 0.0, 1.5)}) {
        const Face& face = surface_face(solid);
        for (double angle : {0.0, 0.3}) {
            const SurfacePlan plan = refined_plan(face, 5e-3, angle);
            std::array<bool, 4> collapsed{};
            for (Side side : kSides) collapsed[side_slot(side)] = plan.sides[side_slot(side)].degenerate;
            std::vector<Vec3> corners;
            standalone_points(plan, corners);
            const GridCheck check = check_grid(*plan.evaluator, face.surface(), plan.grid, collapsed, plan.target, angle,
                                               std::vector<char>(plan.grid.u.size() - 1, 1),
                                               std::vector<char>(plan.grid.v.size() - 1, 1), corners);
            EXPECT_LE(check.worst_ratio, 1.0);
            EXPECT_GT(check.worst_ratio, 0.3);  // and not far finer than needed
        }
    }
}

TEST(TessellatePlan, CreasesBecomeLines) {
    // A profile with a corner inside one NURBS piece: a degree-1 polyline with an interior knot at 0.5
    // (an L from the axis out and up), closed back to the axis by a segment.
    const NurbsCurve corner(1, {0, 0, 0.5, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}});
    const Solid solid = revolve(Profile({corner, line_segment({1, 0, 1}, {0, 0, 1})}));
    // The face swept by the L: its crease lines along the profile hold the corner's knot.
    const Face* creased = nullptr;
    bool along_u = false;
    std::vector<double> lines;
    for (const Face& face : solid.faces()) {
        if (face.kind() != Face::Kind::surface) continue;
        const SurfaceEvaluator evaluator(face.surface());
        for (bool u : {true, false}) {
            std::vector<double> found = crease_lines(face.surface(), evaluator, u);
            if (found.size() > 2) creased = &face, along_u = u, lines = std::move(found);
        }
    }
    ASSERT_NE(creased, nullptr);
    const NurbsSurface& s = creased->surface();
    const Interval d = along_u ? s.domain_u() : s.domain_v();
    ASSERT_EQ(lines.size(), 3u);
    const double knot = lines[1];
    EXPECT_GT(knot, d.min);
    EXPECT_LT(knot, d.max);
    // The knot where the profile turns: its point is the corner (1, 0, 0) turned about the axis.
    const Vec3 on_corner = along_u ? s.point(knot, s.domain_v().min) : s.point(s.domain_u().min, knot);
    EXPECT_NEAR(std::hypot(on_corner.x, on_corner.y), 1.0, 1e-12);
    EXPECT_NEAR(on_corner.z, 0.0, 1e-12);
    const SurfacePlan plan = refined_plan(*creased, 1e-3);
    const std::vector<double>& grid = along_u ? plan.grid.u : plan.grid.v;
    EXPECT_NE(std::find(grid.begin(), grid.end(), knot), grid.end());
    // The rational circle's double knots are only G1: no crease on a sphere.
    const Solid round = sphere(1.0);
    const SurfaceEvaluator sphere_evaluator(surface_face(round).surface());
    for (bool u : {true, false}) EXPECT_EQ(crease_lines(surface_face(round).surface(), sphere_evaluator, u).size(), 2u);
}

// A file's B-spline may keep a knot within rounding of its end (a servo's strip: 1.6e-10 of its u range), its first
// poles one point, so that the normal there needs the surface's limit: the search for creases looked 1e-7 of the
// range either side of the knot, past the domain's end ("parameter ... is outside the domain"). A knot that near
// an end is that end.
TEST(TessellatePlan, AKnotWithinRoundingOfAnEndIsNoCrease) {
    const double knot = 1e-9;
    std::vector<std::vector<Vec3>> poles;
    for (const double x : {0.0, 0.0, 0.3, 0.6, 1.0}) poles.push_back({Vec3{x, 0, 0}, Vec3{x, 1, 0}});
    const NurbsSurface strip(3, 1, {0, 0, 0, 0, knot, 1, 1, 1, 1}, {0, 0, 1, 1}, poles);
    const SurfaceEvaluator evaluator(strip);
    EXPECT_EQ(crease_lines(strip, evaluator, true), (std::vector<double>{0.0, 1.0}));
    EXPECT_EQ(crease_lines(strip, evaluator, false), (std::vector<double>{0.0, 1.0}));
}

TEST(TessellatePlan, ClosedAndPoleToPoleDirectionsKeepTheirMinimumSegments) {
    // A tolerance larger than the solids: only the minimum numbers of intervals remain.
    const Solid ring = torus(3.0, 1.0);
    const SurfacePlan torus_plan = refined_plan(surface_face(ring), 100.0);
    EXPECT_EQ(torus_plan.min_segments, (std::array<int, 2>{3, 3}));
    EXPECT_GE(torus_plan.grid.u.size() - 1, 3u);
    EXPECT_GE(torus_plan.grid.v.size() - 1, 3u);
    const Solid ball = sphere(1.0);
    const SurfacePlan sphere_plan = refined_plan(surface_face(ball), 100.0);
    const bool latitude_u = sphere_plan.min_segments[0] == 2;
    EXPECT_EQ(sphere_plan.min_segments[latitude_u ? 1 : 0], 3);
    EXPECT_GE((latitude_u ? sphere_plan.grid.u : sphere_plan.grid.v).size() - 1, 2u);
    EXPECT_GE((latitude_u ? sphere_plan.grid.v : sphere_plan.grid.u).size() - 1, 3u);
}

}  // namespace
}  // namespace ratbez::detail
