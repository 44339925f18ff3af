// continuity.hpp on the seeds' worked rules: 004's control-point conditions for C1, G1 and C2 of Bézier
// curves, 001's breakpoint formula for a C1 cubic joint on unequal intervals, G2 of circular arcs, and 004's
// L1/L2 rule for Bézier patches (constant ratio: G1; the ratio m/n: C1; varying ratio: only G0).

#include "ratbez/continuity.hpp"

#include <gtest/gtest.h>

#include "ratbez/curves.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

NurbsCurve bezier(std::vector<Vec3> points) { return NurbsCurve::from_bezier(BezierCurve(std::move(points))); }

TEST(ContinuityCurves, Seed004ControlPointRules) {
    const std::vector<Vec3> p{{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}};
    const Vec3 q0 = p[3];
    // n = 3, m = 2: C1 needs q1 = q0 + (n / m)(p3 - p2).
    const Continuity c1 = continuity(bezier(p), bezier({q0, q0 + (p[3] - p[2]) * 1.5, {5, 2, 0}}));
    EXPECT_EQ(c1.parametric, 1);
    EXPECT_EQ(c1.geometric, 1);
    EXPECT_LE(c1.derivative1, 1e-14);
    // The same direction, another length: G1 (k = 2 > 0 in 004's n(p_n - p_{n-1}) = k n (q_1 - q_0)), not C1.
    const Continuity g1 = continuity(bezier(p), bezier({q0, q0 + (p[3] - p[2]) * 3.0, {5, 2, 0}}));
    EXPECT_EQ(g1.parametric, 0);
    EXPECT_EQ(g1.geometric, 1);
    EXPECT_NEAR(g1.derivative1, norm(p[3] - p[2]) * 3.0, 1e-13);  // |3 (p3 - p2) - 2 (3 (p3 - p2))|
    // The opposite direction (a cusp at the joint): G0 only, the tangents pi apart.
    const Continuity cusp = continuity(bezier(p), bezier({q0, q0 - (p[3] - p[2]), {5, 2, 0}}));
    EXPECT_EQ(cusp.geometric, 0);
    EXPECT_NEAR(cusp.tangent_angle, std::numbers::pi, 1e-12);
    // Apart.
    const Continuity apart = continuity(bezier(p), bezier({{3, 0.5, 0}, {4, 0, 0}}));
    EXPECT_EQ(apart.parametric, -1);
    EXPECT_EQ(apart.geometric, -1);
    EXPECT_NEAR(apart.position, 0.5, 1e-15);
    // C2 (004): m(m-1)(q0 - 2q1 + q2) = n(n-1)(p3 - 2p2 + p1) with m = n = 3.
    const Vec3 q1 = q0 + (p[3] - p[2]), q2 = p[1] - p[2] * 4.0 + p[3] * 4.0;
    const Continuity c2 = continuity(bezier(p), bezier({q0, q1, q2, {7, 3, 1}}));
    EXPECT_EQ(c2.parametric, 2);
    EXPECT_EQ(c2.geometric, 2);
}

TEST(ContinuityCurves, Seed001BreakpointFormulaOnUnequalIntervals) {
    // Breakpoints u0 = 0 < u1 = 1 < u2 = 3: the joint P^1_3 = ((u2 - u1) P^1_2 + (u1 - u0) P^2_1) / (u2 - u0).
    const double u0 = 0, u1 = 1, u2 = 3;
    const Vec3 p2{2, 1, 0}, next1{5, 3, 0};
    const Vec3 joint = (p2 * (u2 - u1) + next1 * (u1 - u0)) / (u2 - u0);
    const NurbsCurve first = bezier({{0, 0, 0}, {1, 1, 0}, p2, joint});
    const NurbsCurve second = bezier({joint, next1, {6, 1, 0}, {8, 2, 0}});
    // Each on its own interval: C1 in the spline's parameter.
    const Continuity on_breakpoints = continuity(first.reparameterized(u0, u1), second.reparameterized(u1, u2));
    EXPECT_EQ(on_breakpoints.parametric, 1);
    EXPECT_EQ(on_breakpoints.geometric, 1);
    // Both on [0, 1]: the velocities differ by the ratio of the intervals, so only G1.
    const Continuity unit = continuity(first, second);
    EXPECT_EQ(unit.parametric, 0);
    EXPECT_EQ(unit.geometric, 1);
}

TEST(ContinuityCurves, QuarterCirclesAreC1AndG2) {
    // Same curvature 1/r on both sides; the speed of the rational parameterisation falls towards the
    // joint on one side and rises away from it on the other (mirror images), so C'' jumps.
    const Continuity c = continuity(arc(2.0, 0, 90), arc(2.0, 90, 180));
    EXPECT_EQ(c.parametric, 1);
    EXPECT_EQ(c.geometric, 2);
    EXPECT_GT(c.derivative2, 1e-3);
    EXPECT_LE(c.curvature, 1e-12);
    // A circle of another radius: G1 only, the curvature gap is 1/2 - 1/3.
    const Continuity g1 = continuity(arc(2.0, 0, 90), arc(3.0, 90, 180, {0, -1, 0}));
    EXPECT_EQ(g1.geometric, 1);
    EXPECT_NEAR(g1.curvature, 0.5 - 1.0 / 3.0, 1e-12);
}

// Two bicubic Bézier patches sharing a's u = 1 side and b's u = 0 side. Across the boundary the collinear
// control lines p_{2j}, p_{3j} = q_{0j}, q_{1j} have lengths L1 = |p_{3j} - p_{2j}|, L2 = |q_{1j} - q_{0j}|.
NurbsSurface patch(const std::vector<std::vector<Vec3>>& net) { return NurbsSurface::from_bezier(BezierSurface(net)); }

std::vector<std::vector<Vec3>> left_net() {
    std::vector<std::vector<Vec3>> net(4, std::vector<Vec3>(4));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) net[i][j] = {static_cast<double>(i), static_cast<double>(j), 0.3 * ((i * j) % 3) + 0.1 * i * i};
    return net;
}

// b's net with its first row on a's last and its second along the same lines at L2 = ratio(j) L1.
std::vector<std::vector<Vec3>> right_net(const std::vector<std::vector<Vec3>>& a, const std::function<double(int)>& ratio) {
    std::vector<std::vector<Vec3>> net(4, std::vector<Vec3>(4));
    for (int j = 0; j < 4; ++j) {
        const Vec3 q0 = a[3][j], d = a[3][j] - a[2][j];
        net[0][j] = q0;
        net[1][j] = q0 + d * ratio(j);
        net[2][j] = q0 + d * 2.0 + Vec3{0, 0, 0.2 * j};
        net[3][j] = q0 + d * 3.0 + Vec3{0.1, 0, -0.1 * j};
    }
    return net;
}

TEST(ContinuityPatches, Seed004RatioRule) {
    const auto a = left_net();
    // Ratio 1 (= m / n for bicubics): C1, and G1.
    const Continuity c1 = continuity(patch(a), patch(right_net(a, [](int) { return 1.0; })));
    EXPECT_EQ(c1.parametric, 1);
    EXPECT_EQ(c1.geometric, 1);
    EXPECT_LE(c1.position, 1e-14);
    // A constant ratio 2: the cross derivatives are proportional, the tangent planes agree: G1, C0.
    const Continuity g1 = continuity(patch(a), patch(right_net(a, [](int) { return 2.0; })));
    EXPECT_EQ(g1.parametric, 0);
    EXPECT_EQ(g1.geometric, 1);
    // A ratio that varies along the boundary: the tangent planes turn apart between the control lines.
    const Continuity g0 = continuity(patch(a), patch(right_net(a, [](int j) { return 1.0 + 0.5 * j; })));
    EXPECT_EQ(g0.parametric, 0);
    EXPECT_EQ(g0.geometric, 0);
    EXPECT_GT(g0.tangent_angle, 1e-3);
}

TEST(ContinuityPatches, FindsTheSharedSideInAnyDirectionAndOneSurfacesSpans) {
    const auto a = left_net();
    const NurbsSurface b = patch(right_net(a, [](int) { return 1.0; }));
    // b with u reversed and u, v exchanged still shares the boundary: the sides and directions are found.
    std::vector<std::vector<Vec3>> swapped(4, std::vector<Vec3>(4));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) swapped[j][3 - i] = right_net(a, [](int) { return 1.0; })[i][j];
    const Continuity c = continuity(patch(a), patch(swapped));
    EXPECT_EQ(c.geometric, 1);
    EXPECT_LE(c.position, 1e-14);
    // The two halves of one bicubic patch split at u = 1/2 meet C2 (C-infinity) along the cut.
    const BezierSurface whole(a);
    const NurbsSurface nurbs = NurbsSurface::from_bezier(whole).insert_knot_u(0.5, 3);
    const auto halves = nurbs.bezier_patches();
    const Continuity cut = continuity(NurbsSurface::from_bezier(halves[0][0]), NurbsSurface::from_bezier(halves[1][0]));
    EXPECT_EQ(cut.parametric, 2);
    EXPECT_EQ(cut.geometric, 2);
    // Far apart: no boundary, C^-1 with the gap.
    std::vector<std::vector<Vec3>> far = a;
    for (auto& row : far)
        for (Vec3& q : row) q += Vec3{10, 0, 0};
    const Continuity apart = continuity(patch(a), patch(far));
    EXPECT_EQ(apart.parametric, -1);
    EXPECT_EQ(apart.geometric, -1);
    EXPECT_GT(apart.position, 5);
}

}  // namespace
}  // namespace ratbez
