#include "ratbez/bezier_surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bezier_test_support.hpp"
#include "ratbez/bernstein.hpp"

namespace ratbez {
namespace {

using namespace test;

constexpr double kExact = 1e-14;

// Every way the surface can evaluate a point must give `expected`.
void expect_all_evaluations(const BezierSurface& s, double u, double v, const Vec3& expected, double tolerance) {
    expect_near(s.point(u, v), expected, tolerance, "point");
    expect_near(s.point_basis(u, v), expected, tolerance, "basis (A1.3 per direction)");
    expect_near(s.point_u_first(u, v), expected, tolerance, "A1.7 u first");
    expect_near(s.point_v_first(u, v), expected, tolerance, "A1.7 v first");
    expect_near(s.point_one_step(u, v), expected, tolerance, "one-step");
}

// Ex1.15: the cylindrical patch, net[i][j] with P^w_{i,0} = (1,1,0,1), (1,1,1,1), (2,0,2,2) and
// P^w_{i,1} = (-1,1,0,1), (-1,1,1,1), (-2,0,2,2); Euclidean P_{i,0} = (1,1,0), (1,1,1), (1,0,1), w = 1, 1, 2.
BezierSurface cylinder_patch() {
    return BezierSurface({{{1, 1, 0}, {-1, 1, 0}}, {{1, 1, 1}, {-1, 1, 1}}, {{1, 0, 1}, {-1, 0, 1}}},
                         {{1, 1}, {1, 1}, {2, 2}});
}

// ---------------------------------------------------------------------------------------------------------
// Worked examples and exercises

TEST(BezierSurfaceExamples, Ex115CylinderPointByEveryAlgorithm) {
    const BezierSurface s = cylinder_patch();
    EXPECT_EQ(s.degree_u(), 2);
    EXPECT_EQ(s.degree_v(), 1);
    EXPECT_TRUE(s.is_rational());
    EXPECT_EQ(s.homogeneous_point(2, 1), (Vec4{-2, 0, 2, 2}));
    // S(1/2, 1/2) = H{(0, 3/4, 1, 5/4)} = (0, 3/5, 4/5).
    expect_all_evaluations(s, 0.5, 0.5, {0, 0.6, 0.8}, kExact);
    // The text's A1.7 run (n > m, v first): Q^w_i(1/2) = (0,1,0,1), (0,1,1,1), (0,0,2,2) — the arc in the yz plane.
    const BezierCurve arc = s.isocurve_v(0.5);
    ASSERT_EQ(arc.degree(), 2);
    expect_near(arc.homogeneous_points()[0], {0, 1, 0, 1}, kExact);
    expect_near(arc.homogeneous_points()[1], {0, 1, 1, 1}, kExact);
    expect_near(arc.homogeneous_points()[2], {0, 0, 2, 2}, kExact);
    expect_near(arc.homogeneous_point(0.5), {0, 0.75, 1, 1.25}, kExact);
    // Everywhere on the patch: x = 1 - 2v and y^2 + z^2 = 1 with (y, z) the arc of Eq. 1.2.
    for (int a = 0; a <= 8; ++a)
        for (int b = 0; b <= 8; ++b) {
            const double u = a / 8.0, v = b / 8.0;
            expect_all_evaluations(s, u, v, {1 - 2 * v, (1 - u * u) / (1 + u * u), 2 * u / (1 + u * u)}, kExact);
        }
}

TEST(BezierSurfaceExamples, Exercise122IsocurveOfTheCylinderAtOneThird) {
    // Q^w_j(1/3) = sum_i B_{i,2}(1/3) P^w_{i,j} with B = 4/9, 4/9, 1/9:
    // Q^w_0 = 4/9 (1,1,0,1) + 4/9 (1,1,1,1) + 1/9 (2,0,2,2) = (10/9, 8/9, 2/3, 10/9), Q^w_1 = (-10/9, 8/9, 2/3, 10/9);
    // projected: (1, 4/5, 3/5) and (-1, 4/5, 3/5) — a segment parallel to x on the cylinder.
    const BezierCurve line = cylinder_patch().isocurve_u(1.0 / 3.0);
    ASSERT_EQ(line.degree(), 1);
    EXPECT_TRUE(line.is_rational());
    expect_near(line.homogeneous_points()[0], {10.0 / 9, 8.0 / 9, 2.0 / 3, 10.0 / 9}, kExact);
    expect_near(line.homogeneous_points()[1], {-10.0 / 9, 8.0 / 9, 2.0 / 3, 10.0 / 9}, kExact);
    expect_near(line.points()[0], {1, 0.8, 0.6}, kExact);
    expect_near(line.points()[1], {-1, 0.8, 0.6}, kExact);
    // The exact oracle agrees.
    const std::vector<std::vector<RationalPoint>> net = {
        {homogeneous(1, 1, 0, 1), homogeneous(-1, 1, 0, 1)},
        {homogeneous(1, 1, 1, 1), homogeneous(-1, 1, 1, 1)},
        {homogeneous(1, 0, 1, 2), homogeneous(-1, 0, 1, 2)}};
    expect_near(line.homogeneous_points()[0], bezier_surface_exact(net, Rational(1, 3), Rational(0)).to_vec4(), kExact);
    expect_near(line.homogeneous_points()[1], bezier_surface_exact(net, Rational(1, 3), Rational(1)).to_vec4(), kExact);
}

TEST(BezierSurfaceExamples, Exercise123NonrationalCubicByQuadratic) {
    // n = 3, m = 2; the text lists {P_{i,j}} for fixed j, so net[i][j] = that list's i-th point.
    const std::vector<std::vector<Vec3>> net = {{{0, 0, 0}, {0, 2, 2}, {0, 4, 0}},
                                                {{3, 0, 3}, {3, 2, 5}, {3, 4, 3}},
                                                {{6, 0, 3}, {6, 2, 5}, {6, 4, 3}},
                                                {{9, 0, 0}, {9, 2, 2}, {9, 4, 0}}};
    const BezierSurface s(net);
    EXPECT_FALSE(s.is_rational());
    EXPECT_EQ(s.degree_u(), 3);
    EXPECT_EQ(s.degree_v(), 2);
    // b. S(1/3, 1/2): x = 9u = 3, y = 4v = 2 (both linear), and z_{i,j} = h_i + c_j with h = 0,3,3,0, c = 0,2,0:
    // z = (12*3 + 6*3)/27 + (1/2)*2 = 2 + 1 = 3. So S(1/3, 1/2) = (3, 2, 3).
    expect_all_evaluations(s, 1.0 / 3.0, 0.5, {3, 2, 3}, kExact);
    // c. C_{u0=1/2}(v): Q_j = sum_i B_{i,3}(1/2) P_{i,j}, B = 1/8, 3/8, 3/8, 1/8:
    // Q_0 = (9/2, 0, 9/4), Q_1 = (9/2, 2, 17/4), Q_2 = (9/2, 4, 9/4).
    const BezierCurve c = s.isocurve_u(0.5);
    ASSERT_EQ(c.degree(), 2);
    EXPECT_FALSE(c.is_rational());
    expect_near(c.points()[0], {4.5, 0, 2.25}, kExact);
    expect_near(c.points()[1], {4.5, 2, 4.25}, kExact);
    expect_near(c.points()[2], {4.5, 4, 2.25}, kExact);
}

TEST(BezierSurfaceExamples, Course002Exercise1TwoStepUFirst) {
    // u = v = 1/2, B_2 = 1/4, 1/2, 1/4. u first, column by column (by hand):
    //   Q_0 = (9/4, 3/4, 1/2), Q_1 = (2, 9/4, 5/2), Q_2 = (9/4, 15/4, 1);
    // then v: (9/16 + 1 + 9/16, 3/16 + 9/8 + 15/16, 1/8 + 5/4 + 1/4) = (17/8, 9/4, 13/8).
    const BezierSurface s({{{1, 0, 2}, {1, 2, 4}, {1, 3, 2}},
                           {{2, 1, 0}, {2, 2, 2}, {2, 4, 0}},
                           {{4, 1, 0}, {3, 3, 2}, {4, 4, 2}}});
    const BezierCurve q = s.isocurve_u(0.5);
    expect_near(q.points()[0], {9.0 / 4, 3.0 / 4, 1.0 / 2}, kExact);
    expect_near(q.points()[1], {2, 9.0 / 4, 5.0 / 2}, kExact);
    expect_near(q.points()[2], {9.0 / 4, 15.0 / 4, 1}, kExact);
    expect_all_evaluations(s, 0.5, 0.5, {17.0 / 8, 9.0 / 4, 13.0 / 8}, kExact);
}

TEST(BezierSurfaceExamples, Course002Exercise2OneStep) {
    // u = v = 1/4, B_2(1/4) = 9/16, 6/16, 1/16. x_{i,j} = 2i and y_{i,j} = 2j give x = 4u = 1, y = 4v = 1;
    // z is non-zero at (0,0), (0,1), (1,1) (value 4) and (2,2) (value 8):
    // z = (81*4 + 54*4 + 36*4 + 1*8) / 256 = 692/256 = 173/64.
    // First bilinear step by hand: p^1_{0,0} = (9/16)(0,0,4) + (3/16)(0,2,4) + (3/16)(2,0,0) + (1/16)(2,2,4) = (1/2, 1/2, 13/4).
    const BezierSurface s({{{0, 0, 4}, {0, 2, 4}, {0, 4, 0}},
                           {{2, 0, 0}, {2, 2, 4}, {2, 4, 0}},
                           {{4, 0, 0}, {4, 2, 0}, {4, 4, 8}}});
    expect_near(s.point_one_step(0.25, 0.25), {1, 1, 173.0 / 64}, kExact);
    expect_all_evaluations(s, 0.25, 0.25, {1, 1, 173.0 / 64}, kExact);
    // The 1x1 corner sub-net evaluates to p^1_{0,0} (a single bilinear step).
    const BezierSurface corner({{{0, 0, 4}, {0, 2, 4}}, {{2, 0, 0}, {2, 2, 4}}});
    expect_near(corner.point_one_step(0.25, 0.25), {0.5, 0.5, 3.25}, kExact);
}

TEST(BezierSurfaceExamples, Course002Exercise3BicubicAllThreeFormsAgree) {
    // A bicubic integer net; the exact oracle (Eq. 1.23 in fractions) gives the value every form must hit.
    std::vector<std::vector<Vec3>> net(4, std::vector<Vec3>(4));
    std::vector<std::vector<RationalPoint>> exact(4, std::vector<RationalPoint>(4));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const int x = 3 * i + (j % 2), y = 2 * j - (i * j) % 3, z = (i * i + 3 * j * j + i * j) % 7 - 3;
            net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = {double(x), double(y), double(z)};
            exact[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = {x, y, z};
        }
    const BezierSurface s(net);
    for (const auto& [u, v] : std::vector<std::pair<Rational, Rational>>{
             {Rational(1, 2), Rational(1, 2)}, {Rational(1, 3), Rational(3, 4)}, {Rational(5, 8), Rational(1, 5)}}) {
        expect_all_evaluations(s, u.to_double(), v.to_double(), bezier_surface_exact(exact, u, v).to_vec3(), kExact);
    }
}

TEST(BezierSurfaceExamples, CylinderDerivativesAndInwardNormal) {
    // S = (1 - 2v, y(u), z(u)) with (y, z) the arc of Eq. 1.2: S_u = (0, -4u/(1+u^2)^2, 2(1-u^2)/(1+u^2)^2),
    // S_v = (-2, 0, 0), all v-derivatives of order >= 2 and all mixed ones vanish; S_uu as for Ex1.13's x'', y''.
    // S_u x S_v = (0, -2 z_u, 2 y_u) points to the axis: N = -(0, y, z).
    const BezierSurface s = cylinder_patch();
    for (int a = 0; a <= 6; ++a)
        for (int b = 0; b <= 6; ++b) {
            const double u = a / 6.0, v = b / 6.0, q = 1 + u * u;
            const auto d = s.derivatives(u, v, 2);
            expect_near(d[1][0], {0, -4 * u / (q * q), 2 * (1 - u * u) / (q * q)}, 1e-13);
            expect_near(d[0][1], {-2, 0, 0}, 1e-13);
            expect_near(d[1][1], {0, 0, 0}, 1e-13);
            expect_near(d[0][2], {0, 0, 0}, 1e-13);
            expect_near(d[2][0], {0, (12 * u * u - 4) / (q * q * q), 4 * u * (u * u - 3) / (q * q * q)}, 1e-13);
            expect_near(s.derivative(u, v, 1, 0), d[1][0], 0.0);
            expect_near(s.normal(u, v), {0, -(1 - u * u) / q, -2 * u / q}, 1e-14);
        }
}

// Exercise 1.24 on Ex1.15: P_{i,0} = (1, 0, 0) with w = 1, 1, 2 collapses the edge v = 0 to the point (1, 0, 0):
// S(u, v) = (1 - v)(1, 0, 0) + v(-1, y(u), z(u)), a cone with apex (1,0,0) over the unit circle in x = -1.
// S_u = v C'(u) vanishes along v = 0, so Eq. 1.4 fails on the whole edge. The analytic normal along the ruling
// through (-1, y, z), oriented as S_u x S_v for v > 0: C'(u) x (C(u) - apex) ∝ (0, -z, y) x (-2, y, z)
// = (-1, -2y, -2z), i.e. N = -(1, 2y, 2z)/sqrt5, the same along the whole ruling.
BezierSurface cone_patch() {
    return BezierSurface({{{1, 0, 0}, {-1, 1, 0}}, {{1, 0, 0}, {-1, 1, 1}}, {{1, 0, 0}, {-1, 0, 1}}},
                         {{1, 1}, {1, 1}, {2, 2}});
}

Vec3 cone_normal(double u) {
    const double q = 1 + u * u, y = (1 - u * u) / q, z = 2 * u / q;
    return Vec3{-1, -2 * y, -2 * z} / std::sqrt(5.0);
}

TEST(BezierSurfaceNormal, Exercise124ConeApexEdgeUsesTheLimitDirection) {
    const BezierSurface cone = cone_patch();
    for (int a = 0; a <= 8; ++a) {
        const double u = a / 8.0;
        expect_near(cone.point(u, 0.0), {1, 0, 0}, kExact);
        expect_near(cone.derivative(u, 0.0, 1, 0), {0, 0, 0}, 1e-14);
        expect_near(cone.normal(u, 0.0), cone_normal(u), 1e-12, "apex edge, u = " + std::to_string(u));
        for (double v : {0.25, 0.5, 1.0}) expect_near(cone.normal(u, v), cone_normal(u), 1e-12);
        // Just off the edge Eq. 1.4 still applies, but S_u ~ 1e-6 carries the rounding of the quotient rule
        // (absolute ~1e-16), so the direct normal is only good to ~1e-10 there — the limit is the better value.
        expect_near(cone.normal(u, 1e-6), cone_normal(u), 1e-9);
    }
}

TEST(BezierSurfaceNormal, CollapsedEdgeOnEverySideKeepsTheOrientation) {
    // Reparameterise the cone so the apex edge lies on each side of the domain in turn; the normal must be the
    // analytic one, with the sign S_u x S_v has just inside the patch.
    const BezierSurface cone = cone_patch();
    const auto& pw = cone.homogeneous_points();  // 3 rows x 2 columns
    auto at = [&](int i, int j) { return pw[static_cast<std::size_t>(i * 2 + j)]; };
    // Swapped parameters (apex edge at u = 0): S'(u, v) = S(v, u), so N' = -N.
    std::vector<Vec4> swapped;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) swapped.push_back(at(i, j));
    const BezierSurface apex_at_u0 = BezierSurface::from_homogeneous(2, 3, swapped);
    // Reversed v (apex edge at v = 1): S'(u, v) = S(u, 1 - v), so N' = -N.
    std::vector<Vec4> reversed_v;
    for (int i = 0; i < 3; ++i)
        for (int j = 1; j >= 0; --j) reversed_v.push_back(at(i, j));
    const BezierSurface apex_at_v1 = BezierSurface::from_homogeneous(3, 2, reversed_v);
    // Swapped and reversed (apex edge at u = 1): S'(u, v) = S(v, 1 - u), so N' = N.
    std::vector<Vec4> swapped_reversed;
    for (int j = 1; j >= 0; --j)
        for (int i = 0; i < 3; ++i) swapped_reversed.push_back(at(i, j));
    const BezierSurface apex_at_u1 = BezierSurface::from_homogeneous(2, 3, swapped_reversed);

    for (int a = 0; a <= 8; ++a) {
        const double t = a / 8.0;
        expect_near(apex_at_u0.normal(0.0, t), -1.0 * cone_normal(t), 1e-12, "apex at u = 0");
        expect_near(apex_at_v1.normal(t, 1.0), -1.0 * cone_normal(t), 1e-12, "apex at v = 1");
        expect_near(apex_at_u1.normal(1.0, t), cone_normal(t), 1e-12, "apex at u = 1");
        // And continuity with the interior, where Eq. 1.4 applies.
        expect_near(apex_at_v1.normal(t, 1.0), apex_at_v1.normal(t, 1.0 - 1e-7), 1e-9);
        expect_near(apex_at_u0.normal(0.0, t), apex_at_u0.normal(1e-7, t), 1e-9);
    }
}

TEST(BezierSurfaceNormal, HemispherePoleFromARevolvedQuarterCircle) {
    // The octant of the unit sphere: profile (x, z) quarter arc (1,0) -> (1,1) -> (0,1), w = 1, s, 1 with
    // s = sqrt2/2 (Exercise 1.20's symmetric arc), rotated about z by the same quarter arc in (x, y).
    // Net[i][j]: i along the profile (u), j along the rotation (v); P_{i,j} = (r_i c_j, r_i s_j, z_i), w = w_i w_j.
    // The edge u = 1 is the north pole (r = 0), where S_v vanishes; the normal there is (0, 0, 1), outward.
    const double s = std::sqrt(2.0) / 2;
    const std::array<double, 3> r = {1, 1, 0}, z = {0, 1, 1}, wu = {1, s, 1};
    const std::array<double, 3> c = {1, 1, 0}, sn = {0, 1, 1}, wv = {1, s, 1};
    std::vector<std::vector<Vec3>> net(3, std::vector<Vec3>(3));
    std::vector<std::vector<double>> weights(3, std::vector<double>(3));
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            net[i][j] = {r[i] * c[j], r[i] * sn[j], z[i]};
            weights[i][j] = wu[i] * wv[j];
        }
    const BezierSurface octant(net, weights);
    // S_u x S_v points inward for this orientation (u climbs to the pole, v turns counterclockwise): N = -S.
    for (int a = 0; a <= 6; ++a)
        for (int b = 0; b <= 6; ++b) {
            const double u = a / 6.0, v = b / 6.0;
            const Vec3 p = octant.point(u, v);
            EXPECT_NEAR(norm(p), 1.0, kExact);
            expect_near(octant.normal(u, v), -1.0 * p, 1e-12, "u = " + std::to_string(u) + " v = " + std::to_string(v));
        }
    expect_near(octant.derivative(1.0, 0.3, 0, 1), {0, 0, 0}, 1e-14);
    expect_near(octant.normal(1.0, 0.0), {0, 0, -1}, 1e-12);
    expect_near(octant.normal(1.0, 1.0), {0, 0, -1}, 1e-12);
}

TEST(BezierSurfaceNormal, FullyDegenerateSurfaceThrowsNamingUV) {
    const BezierSurface point_patch({{{1, 2, 3}, {1, 2, 3}}, {{1, 2, 3}, {1, 2, 3}}});
    const std::string message = error_message([&] { point_patch.normal(0.5, 0.5); });
    EXPECT_TRUE(starts_with(message, "(u, v):")) << message;
}

// ---------------------------------------------------------------------------------------------------------
// Properties on random input (fixed seed)

struct RandomSurface {
    BezierSurface surface;
    std::vector<std::vector<Vec3>> net;
    std::vector<std::vector<double>> weights;
};

RandomSurface random_surface(RandomInput& random, bool rational, int max_degree = 5) {
    const auto rows = static_cast<std::size_t>(random.integer(0, max_degree) + 1);
    const auto columns = static_cast<std::size_t>(random.integer(0, max_degree) + 1);
    std::vector<std::vector<Vec3>> net(rows);
    std::vector<std::vector<double>> weights(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        net[i] = random.points(columns);
        weights[i] = rational ? random.weights(columns, 0.5, 2.0) : std::vector<double>(columns, 1.0);
    }
    return {rational ? BezierSurface(net, weights) : BezierSurface(net), net, weights};
}

TEST(BezierSurfaceProperties, RationalBasisIsAPartitionOfUnityAndNonNegative) {
    // R_{i,j}(u, v) of Eq. 1.28, read off the surface whose only non-zero control point is P_{i,j} = (1, 0, 0).
    RandomInput random(41);
    int evaluated = 0;
    while (evaluated < 1000) {
        const int n = random.integer(0, 3), m = random.integer(0, 3);
        std::vector<std::vector<double>> weights(static_cast<std::size_t>(n + 1));
        for (auto& row : weights) row = random.weights(static_cast<std::size_t>(m + 1));
        const double u = random.parameter(), v = random.parameter();
        double sum = 0.0;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= m; ++j) {
                std::vector<std::vector<Vec3>> net(static_cast<std::size_t>(n + 1),
                                                   std::vector<Vec3>(static_cast<std::size_t>(m + 1)));
                net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)].x = 1.0;
                const double value = BezierSurface(net, weights).point(u, v).x;
                EXPECT_GE(value, 0.0);
                sum += value;
                ++evaluated;
            }
        EXPECT_NEAR(sum, 1.0, 1e-14);
    }
}

TEST(BezierSurfaceProperties, CornerInterpolationAndBoundaryCurves) {
    RandomInput random(42);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 2 == 1);
        const auto& net = s.net;
        expect_near(s.surface.point(0, 0), net.front().front(), 1e-12);
        expect_near(s.surface.point(0, 1), net.front().back(), 1e-12);
        expect_near(s.surface.point(1, 0), net.back().front(), 1e-12);
        expect_near(s.surface.point(1, 1), net.back().back(), 1e-12);
        // The boundary curve v = 0 is the Bézier curve of the first column (002 §25.5).
        std::vector<Vec3> first_column;
        std::vector<double> first_weights;
        for (std::size_t i = 0; i < net.size(); ++i) {
            first_column.push_back(net[i].front());
            first_weights.push_back(s.weights[i].front());
        }
        const double t = random.parameter();
        expect_near(s.surface.point(t, 0.0), BezierCurve(first_column, first_weights).point(t), 1e-11);
    }
}

TEST(BezierSurfaceProperties, AllFourEvaluationAlgorithmsAgree) {
    // u first = v first = one-step = basis form (002 exercise 3, for every degree pair, rational too).
    RandomInput random(43);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 2 == 1, 6);
        const double u = random.parameter(), v = random.parameter();
        expect_all_evaluations(s.surface, u, v, s.surface.point_basis(u, v), 1e-11);
    }
}

TEST(BezierSurfaceProperties, ConvexHullBoundingBox) {
    RandomInput random(44);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 2 == 1);
        Vec3 low = s.net[0][0], high = low;
        for (const auto& row : s.net)
            for (const Vec3& p : row) {
                low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
                high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
            }
        const Vec3 q = s.surface.point(random.parameter(), random.parameter());
        const double slack = 1e-12;
        EXPECT_TRUE(q.x >= low.x - slack && q.x <= high.x + slack && q.y >= low.y - slack && q.y <= high.y + slack &&
                    q.z >= low.z - slack && q.z <= high.z + slack);
    }
}

TEST(BezierSurfaceProperties, AffineInvarianceRationalToo) {
    RandomInput random(45);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 2 == 1);
        const std::array<Vec3, 3> rows{random.point(2.0), random.point(2.0), random.point(2.0)};
        const Vec3 shift = random.point(5.0);
        auto map = [&](const Vec3& p) { return Vec3{dot(rows[0], p), dot(rows[1], p), dot(rows[2], p)} + shift; };
        auto moved = s.net;
        for (auto& row : moved)
            for (auto& p : row) p = map(p);
        const BezierSurface image = s.surface.is_rational() ? BezierSurface(moved, s.weights) : BezierSurface(moved);
        const double u = random.parameter(), v = random.parameter();
        expect_near(image.point(u, v), map(s.surface.point(u, v)), 1e-10);
    }
}

TEST(BezierSurfaceProperties, IsocurvesLieOnTheSurface) {
    RandomInput random(46);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 2 == 1);
        const double u = random.parameter(), v = random.parameter();
        const BezierCurve in_v = s.surface.isocurve_u(u), in_u = s.surface.isocurve_v(v);
        EXPECT_EQ(in_v.degree(), s.surface.degree_v());
        EXPECT_EQ(in_u.degree(), s.surface.degree_u());
        expect_near(in_v.point(v), s.surface.point(u, v), 1e-11);
        expect_near(in_u.point(u), s.surface.point(u, v), 1e-11);
        // S_u = C'_{v0}(u0) and S_v = C'_{u0}(v0) (000 §1.5).
        const double scale = 1e-9 * (1 + norm(s.surface.derivative(u, v, 1, 0)) + norm(s.surface.derivative(u, v, 0, 1)));
        expect_near(in_u.derivative(u), s.surface.derivative(u, v, 1, 0), scale);
        expect_near(in_v.derivative(v), s.surface.derivative(u, v, 0, 1), scale);
    }
}

TEST(BezierSurfaceProperties, DerivativesUpToOrderThreeMatchCentralDifferences) {
    RandomInput random(47);
    const double h = 1e-4;
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 4 != 0, 4);
        const double u = random.uniform(h, 1.0 - h), v = random.uniform(h, 1.0 - h);
        const auto at = s.surface.derivatives(u, v, 3);
        const auto u_plus = s.surface.derivatives(u + h, v, 2), u_minus = s.surface.derivatives(u - h, v, 2);
        const auto v_plus = s.surface.derivatives(u, v + h, 2), v_minus = s.surface.derivatives(u, v - h, 2);
        for (std::size_t k = 0; k <= 3; ++k)
            for (std::size_t l = 0; k + l <= 3; ++l) {
                if (k + l == 0) continue;
                const std::string what = "SKL[" + std::to_string(k) + "][" + std::to_string(l) + "] trial " + std::to_string(trial);
                if (k >= 1) {  // d/du of SKL[k-1][l]
                    const Vec3 difference = (u_plus[k - 1][l] - u_minus[k - 1][l]) / (2 * h);
                    expect_near(at[k][l], difference, 1e-5 * (1 + norm(at[k][l]) + norm(at[k - 1][l])), what + " (u)");
                }
                if (l >= 1) {  // d/dv of SKL[k][l-1]
                    const Vec3 difference = (v_plus[k][l - 1] - v_minus[k][l - 1]) / (2 * h);
                    expect_near(at[k][l], difference, 1e-5 * (1 + norm(at[k][l]) + norm(at[k][l - 1])), what + " (v)");
                }
                expect_near(s.surface.derivative(u, v, static_cast<int>(k), static_cast<int>(l)), at[k][l], 0.0, what);
            }
    }
}

TEST(BezierSurfaceProperties, NormalIsUnitAndPerpendicularToBothPartials) {
    RandomInput random(48);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto s = random_surface(random, trial % 2 == 1, 4);
        if (s.surface.degree_u() == 0 || s.surface.degree_v() == 0) continue;
        const double u = random.parameter(), v = random.parameter();
        const Vec3 su = s.surface.derivative(u, v, 1, 0), sv = s.surface.derivative(u, v, 0, 1);
        const Vec3 n = s.surface.normal(u, v);
        EXPECT_NEAR(norm(n), 1.0, 1e-14);
        EXPECT_NEAR(dot(n, su), 0.0, 1e-10 * (1 + norm(su)));
        EXPECT_NEAR(dot(n, sv), 0.0, 1e-10 * (1 + norm(sv)));
        EXPECT_GT(dot(n, cross(su, sv)), 0.0);
    }
}

// ---------------------------------------------------------------------------------------------------------
// Bad input

TEST(BezierSurfaceErrors, EmptyNetNamesNet) {
    const std::string m1 = error_message([] { BezierSurface(std::vector<std::vector<Vec3>>{}); });
    const std::string m2 = error_message([] { BezierSurface(std::vector<std::vector<Vec3>>{{}}); });
    EXPECT_TRUE(starts_with(m1, "net:")) << m1;
    EXPECT_TRUE(starts_with(m2, "net:")) << m2;
}

TEST(BezierSurfaceErrors, RaggedNetNamesNet) {
    const std::string message = error_message([] { BezierSurface({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}}}); });
    EXPECT_TRUE(starts_with(message, "net:")) << message;
    EXPECT_NE(message.find("row 1"), std::string::npos) << message;
}

TEST(BezierSurfaceErrors, MismatchedOrRaggedWeightsNameWeights) {
    const std::vector<std::vector<Vec3>> net = {{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}};
    const std::string m1 = error_message([&] { BezierSurface(net, {{1, 1}}); });
    const std::string m2 = error_message([&] { BezierSurface(net, {{1, 1}, {1}}); });
    const std::string m3 = error_message([&] { BezierSurface(net, {}); });
    EXPECT_TRUE(starts_with(m1, "weights:")) << m1;
    EXPECT_TRUE(starts_with(m2, "weights:")) << m2;
    EXPECT_TRUE(starts_with(m3, "weights:")) << m3;
}

TEST(BezierSurfaceErrors, NonFiniteCoordinatesNameNet) {
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        const std::string message = error_message([&] { BezierSurface({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, bad}, {1, 1, 0}}}); });
        EXPECT_TRUE(starts_with(message, "net:")) << message;
        EXPECT_NE(message.find("[1][0]"), std::string::npos) << message;
    }
}

TEST(BezierSurfaceErrors, NonPositiveOrNaNWeightsNameWeights) {
    const std::vector<std::vector<Vec3>> net = {{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}};
    for (double bad : {0.0, -2.0, std::numeric_limits<double>::quiet_NaN()}) {
        const std::string message = error_message([&] { BezierSurface(net, {{1, 1}, {bad, 1}}); });
        EXPECT_TRUE(starts_with(message, "weights:")) << message;
    }
}

TEST(BezierSurfaceErrors, FromHomogeneousValidatesShapeAndWeights) {
    EXPECT_TRUE(starts_with(error_message([] { BezierSurface::from_homogeneous(0, 1, {}); }), "rows:"));
    EXPECT_TRUE(starts_with(error_message([] { BezierSurface::from_homogeneous(1, -1, {}); }), "columns:"));
    EXPECT_TRUE(starts_with(error_message([] { BezierSurface::from_homogeneous(2, 2, {{0, 0, 0, 1}}); }),
                            "homogeneous_points:"));
    EXPECT_TRUE(starts_with(error_message([] { BezierSurface::from_homogeneous(1, 1, {{0, 0, 0, 0}}); }),
                            "homogeneous_points:"));
}

TEST(BezierSurfaceErrors, ParametersOutsideTheDomainOrNaNNameUAndV) {
    const BezierSurface s = cylinder_patch();
    for (double bad : {-0.1, 1.1, std::numeric_limits<double>::quiet_NaN()}) {
        for (const std::string& message :
             {error_message([&] { s.point(bad, 0.5); }), error_message([&] { s.point_basis(bad, 0.5); }),
              error_message([&] { s.point_u_first(bad, 0.5); }), error_message([&] { s.point_v_first(bad, 0.5); }),
              error_message([&] { s.point_one_step(bad, 0.5); }), error_message([&] { s.derivatives(bad, 0.5, 1); }),
              error_message([&] { s.normal(bad, 0.5); }), error_message([&] { s.isocurve_u(bad); })})
            EXPECT_TRUE(starts_with(message, "u:")) << message;
        for (const std::string& message :
             {error_message([&] { s.point(0.5, bad); }), error_message([&] { s.point_basis(0.5, bad); }),
              error_message([&] { s.point_u_first(0.5, bad); }), error_message([&] { s.point_v_first(0.5, bad); }),
              error_message([&] { s.point_one_step(0.5, bad); }), error_message([&] { s.derivatives(0.5, bad, 1); }),
              error_message([&] { s.normal(0.5, bad); }), error_message([&] { s.isocurve_v(bad); })})
            EXPECT_TRUE(starts_with(message, "v:")) << message;
    }
}

TEST(BezierSurfaceErrors, NegativeDerivativeOrdersNameTheirArgument) {
    const BezierSurface s = cylinder_patch();
    EXPECT_TRUE(starts_with(error_message([&] { s.derivatives(0.5, 0.5, -1); }), "order:"));
    EXPECT_TRUE(starts_with(error_message([&] { s.derivative(0.5, 0.5, -1, 0); }), "du:"));
    EXPECT_TRUE(starts_with(error_message([&] { s.derivative(0.5, 0.5, 0, -1); }), "dv:"));
}

}  // namespace
}  // namespace ratbez
