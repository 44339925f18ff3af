#include "ratbez/nurbs_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "nurbs_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

const double r2 = std::sqrt(0.5);  // the weight of a quarter circle's middle control point

double net_size(const NurbsSurface& s) {
    double size = 0;
    for (const auto& row : s.points())
        for (const Vec3& p : row) size = std::max(size, norm(p));
    return size + 1;
}

// The octant of the unit sphere x, y, z >= 0 as a rational biquadratic patch: u runs along the equator's
// quarter circle (x axis to y axis), v along the meridian from the equator to the north pole. The whole
// top row collapses into the pole (0, 0, 1): S_u vanishes along v = 1. S_u x S_v points outwards.
NurbsSurface sphere_octant() {
    const std::vector<Vec3> azimuth{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<double> azimuth_weights{1, r2, 1};
    const std::vector<std::pair<double, double>> meridian{{1, 0}, {1, 1}, {0, 1}};  // (radius, height)
    const std::vector<double> meridian_weights{1, r2, 1};
    std::vector<std::vector<Vec3>> net(3, std::vector<Vec3>(3));
    std::vector<std::vector<double>> weights(3, std::vector<double>(3));
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            net[i][j] = {meridian[j].first * azimuth[i].x, meridian[j].first * azimuth[i].y, meridian[j].second};
            weights[i][j] = azimuth_weights[i] * meridian_weights[j];
        }
    return NurbsSurface(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, net, weights);
}

// The whole unit sphere as one NURBS surface: u the full circle (four rational quadratic arcs, knots
// {0,0,0,1,1,2,2,3,3,4,4,4}), v the half meridian from the south pole to the north pole (two arcs, knots
// {0,0,0,1,1,2,2,2}). Both v edges collapse into poles.
NurbsSurface unit_sphere() {
    const std::vector<Vec3> circle{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}, {-1, 0, 0},
                                   {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}, {1, 0, 0}};
    const std::vector<double> circle_weights{1, r2, 1, r2, 1, r2, 1, r2, 1};
    const std::vector<std::pair<double, double>> meridian{{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}};
    const std::vector<double> meridian_weights{1, r2, 1, r2, 1};
    std::vector<std::vector<Vec3>> net(9, std::vector<Vec3>(5));
    std::vector<std::vector<double>> weights(9, std::vector<double>(5));
    for (std::size_t i = 0; i < 9; ++i)
        for (std::size_t j = 0; j < 5; ++j) {
            net[i][j] = {meridian[j].first * circle[i].x, meridian[j].first * circle[i].y, meridian[j].second};
            weights[i][j] = circle_weights[i] * meridian_weights[j];
        }
    return NurbsSurface(2, 2, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}, {0, 0, 0, 1, 1, 2, 2, 2}, net, weights);
}

// ---- exact examples --------------------------------------------------------------------------------

TEST(NurbsSurface, SphereOctantLiesOnTheSphereWithRadialNormals) {
    const NurbsSurface s = sphere_octant();
    for (int a = 0; a <= 16; ++a)
        for (int b = 0; b <= 16; ++b) {
            const double u = a / 16.0, v = b / 16.0;
            const Vec3 p = s.point(u, v);
            EXPECT_NEAR(norm(p), 1.0, 1e-15);
            // On the unit sphere the outward normal is the point itself, on the collapsed edge v = 1 too.
            EXPECT_TRUE(near(s.normal(u, v), p, 1e-12)) << "u " << u << " v " << v;
        }
    EXPECT_EQ(s.point(0.37, 1.0), (Vec3{0, 0, 1}));
    EXPECT_TRUE(near(s.derivative(0.37, 1.0, 1, 0), {}, 1e-15));  // S_u vanishes along the pole row
}

TEST(NurbsSurface, NormalAtACollapsedEdgeInUIsTheLimitToo) {
    // The octant with u and v swapped: now S_v vanishes along u = 1 and S_u x S_v points inwards.
    const NurbsSurface octant = sphere_octant();
    std::vector<std::vector<Vec3>> net(3, std::vector<Vec3>(3));
    std::vector<std::vector<double>> weights(3, std::vector<double>(3));
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            net[i][j] = octant.points()[j][i];
            weights[i][j] = octant.weights()[j][i];
        }
    const NurbsSurface swapped(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, net, weights);
    for (double v : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        EXPECT_TRUE(near(swapped.normal(1.0, v), {0, 0, -1}, 1e-12)) << v;
        EXPECT_TRUE(near(swapped.normal(0.999, v), -1.0 * swapped.point(0.999, v), 1e-12)) << v;
    }
}

TEST(NurbsSurface, WholeSphereNormalsAtPolesSeamAndKnots) {
    const NurbsSurface s = unit_sphere();
    EXPECT_EQ(s.rows(), 9);
    EXPECT_EQ(s.columns(), 5);
    EXPECT_EQ(s.domain_u().max, 4.0);
    EXPECT_EQ(s.domain_v().max, 2.0);
    Rng rng(4001);
    for (int trial = 0; trial < 1000; ++trial) {
        double u = uniform(rng, 0, 4), v = uniform(rng, 0, 2);
        if (trial % 4 == 0) v = trial % 8 == 0 ? 0.0 : 2.0;     // the poles
        if (trial % 5 == 0) u = double(uniform_int(rng, 0, 4));  // knots and the seam
        if (trial % 7 == 0) v = 1.0;                            // the equator, a knot in v
        const Vec3 p = s.point(u, v);
        EXPECT_NEAR(norm(p), 1.0, 1e-15);
        EXPECT_TRUE(near(s.normal(u, v), p, 1e-12)) << "u " << u << " v " << v;
    }
    EXPECT_TRUE(near(s.normal(1.3, 0.0), {0, 0, -1}, 1e-12));
    EXPECT_TRUE(near(s.normal(3.9, 2.0), {0, 0, 1}, 1e-12));
}

TEST(NurbsSurface, ConeApexNormalIsTheLimitAlongTheMeridian) {
    // A quarter cone: base circle of radius 1 at z = 0 (v = 0), apex (0, 0, 1) at v = 1, linear in v.
    // Its outward normal along the meridian at azimuth phi is (cos phi, sin phi, 1) / sqrt 2, up to the apex.
    const std::vector<std::vector<Vec3>> net{{{1, 0, 0}, {0, 0, 1}}, {{1, 1, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
    const std::vector<std::vector<double>> weights{{1, 1}, {r2, r2}, {1, 1}};
    const NurbsSurface cone(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, net, weights);
    for (double u : {0.0, 0.25, 0.5, 0.8, 1.0}) {
        const Vec3 base = cone.point(u, 0.0);
        const Vec3 expected = Vec3{base.x, base.y, 1.0} / std::sqrt(2.0);
        EXPECT_TRUE(near(cone.normal(u, 0.0), expected, 1e-12)) << u;
        EXPECT_TRUE(near(cone.normal(u, 0.5), expected, 1e-12)) << u;
        EXPECT_TRUE(near(cone.normal(u, 1.0), expected, 1e-9)) << u;  // the apex, approached along the meridian
    }
}

TEST(NurbsSurface, BilinearPatchValuesAndPartials) {
    // S(u, v) = (u, v, u v) on [0, 2] x [0, 1] with a knot at u = 1: polynomial, exact everywhere.
    const std::vector<std::vector<Vec3>> net{{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 1}}, {{2, 0, 0}, {2, 1, 2}}};
    const NurbsSurface s(1, 1, {0, 0, 1, 2, 2}, {0, 0, 1, 1}, net);
    EXPECT_FALSE(s.is_rational());
    EXPECT_EQ(s.point(1.5, 0.5), (Vec3{1.5, 0.5, 0.75}));
    const auto skl = s.derivatives(1.5, 0.5, 2);
    ASSERT_EQ(skl.size(), 3u);
    ASSERT_EQ(skl[0].size(), 3u);
    ASSERT_EQ(skl[2].size(), 1u);
    EXPECT_EQ(skl[1][0], (Vec3{1, 0, 0.5}));
    EXPECT_EQ(skl[0][1], (Vec3{0, 1, 1.5}));
    EXPECT_EQ(skl[1][1], (Vec3{0, 0, 1}));
    EXPECT_EQ(skl[2][0], (Vec3{}));
    EXPECT_EQ(s.derivative(1.5, 0.5, 1, 1), (Vec3{0, 0, 1}));
    const Vec3 n = s.normal(1.5, 0.5);  // (1,0,v) x (0,1,u) = (-v, -u, 1)
    EXPECT_TRUE(near(n, Vec3{-0.5, -1.5, 1} / std::sqrt(3.5), 1e-15));
}

// ---- properties on random surfaces -----------------------------------------------------------------

TEST(NurbsSurface, RationalBasisIsAPartitionOfUnityAndNonNegative) {
    Rng rng(4002);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsSurface s = test::random_surface(rng, true, trial % 2 == 0, 3);
        const double u = test::random_parameter(rng, s.domain_u());
        const double v = test::random_parameter(rng, s.domain_v());
        // A net of e_x everywhere gives x = sum R_ij = 1; a net with e_x at (i, j) alone gives x = R_ij >= 0.
        std::vector<std::vector<Vec3>> ones(std::size_t(s.rows()), std::vector<Vec3>(std::size_t(s.columns()), {1, 0, 0}));
        const NurbsSurface unity(s.degree_u(), s.degree_v(), s.knots_u(), s.knots_v(), ones, s.weights());
        EXPECT_NEAR(unity.point(u, v).x, 1.0, 1e-14);
        const std::vector<std::vector<double>> weights = s.weights();
        auto rational_basis = [&](int i, int j) {
            std::vector<std::vector<Vec3>> indicator(std::size_t(s.rows()), std::vector<Vec3>(std::size_t(s.columns())));
            indicator[std::size_t(i)][std::size_t(j)] = {1, 0, 0};
            return NurbsSurface(s.degree_u(), s.degree_v(), s.knots_u(), s.knots_v(), indicator, weights).point(u, v).x;
        };
        // Local support: only the (p+1)(q+1) functions of the spans at (u, v) can be non-zero, so they alone
        // must sum to 1; any other one must be 0.
        const int span_u = find_span(s.degree_u(), s.knots_u(), u), span_v = find_span(s.degree_v(), s.knots_v(), v);
        double sum = 0;
        for (int i = span_u - s.degree_u(); i <= span_u; ++i)
            for (int j = span_v - s.degree_v(); j <= span_v; ++j) {
                const double r = rational_basis(i, j);
                EXPECT_GE(r, 0.0);
                sum += r;
            }
        const int far_i = uniform_int(rng, 0, s.rows() - 1), far_j = uniform_int(rng, 0, s.columns() - 1);
        const bool in_span = far_i >= span_u - s.degree_u() && far_i <= span_u && far_j >= span_v - s.degree_v() &&
                             far_j <= span_v;
        if (!in_span) {
            EXPECT_EQ(rational_basis(far_i, far_j), 0.0);
        }
        EXPECT_NEAR(sum, 1.0, 1e-13) << "trial " << trial;
    }
}

TEST(NurbsSurface, DerivativesAgreeWithCentralDifferences) {
    Rng rng(4003);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsSurface s = test::random_surface(rng, trial % 4 != 0, trial % 2 == 0);
        const auto wu = test::random_interior_parameter(rng, s.degree_u(), s.knots_u());
        const auto wv = test::random_interior_parameter(rng, s.degree_v(), s.knots_v());
        const double length_u = wu.span_max - wu.span_min, length_v = wv.span_max - wv.span_min;
        const double hu = 1e-4 * length_u, hv = 1e-4 * length_v;
        const double u = wu.value, v = wv.value;
        const auto at = s.derivatives(u, v, 5);
        std::vector<double> magnitude(6, 0.0);  // the largest partial of each total order
        for (std::size_t k = 0; k <= 5; ++k)
            for (std::size_t l = 0; k + l <= 5; ++l) magnitude[k + l] = std::max(magnitude[k + l], norm(at[k][l]));
        EXPECT_TRUE(near(at[0][0], s.point(u, v), 0.0));
        const auto u_plus = s.derivatives(u + hu, v, 2), u_minus = s.derivatives(u - hu, v, 2);
        const auto v_plus = s.derivatives(u, v + hv, 2), v_minus = s.derivatives(u, v - hv, 2);
        const double h2 = std::max(hu, hv) * std::max(hu, hv);
        const double shortest = std::min(length_u, length_v);
        for (std::size_t k = 0; k <= 3; ++k)
            for (std::size_t l = 0; k + l <= 3; ++l) {
                if (k + l == 0) continue;
                const std::size_t order = k + l;
                const Vec3 difference = k > 0 ? (u_plus[k - 1][l] - u_minus[k - 1][l]) / (2 * hu)
                                              : (v_plus[k][l - 1] - v_minus[k][l - 1]) / (2 * hv);
                const double tolerance =
                    h2 * magnitude[order + 2] + 1e-9 * (magnitude[order] + magnitude[order - 1] / shortest + 1);
                EXPECT_TRUE(near(at[k][l], difference, tolerance)) << "trial " << trial << " k " << k << " l " << l;
                EXPECT_EQ(s.derivative(u, v, int(k), int(l)), s.derivatives(u, v, int(order))[k][l]);
            }
    }
}

TEST(NurbsSurface, KnotInsertionInUAndVKeepsTheSurface) {
    Rng rng(4004);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsSurface s = test::random_surface(rng, trial % 2 == 0, trial % 3 != 0, 4);
        const bool in_u = trial % 2 == 0;
        const int degree = in_u ? s.degree_u() : s.degree_v();
        const std::vector<double>& knots = in_u ? s.knots_u() : s.knots_v();
        const Interval d = in_u ? s.domain_u() : s.domain_v();
        double t = uniform(rng, d.min, d.max);
        if (trial % 3 == 0) {
            const auto breaks = test::break_points(degree, knots);
            t = breaks[std::size_t(uniform_int(rng, 0, int(breaks.size()) - 1))];
        }
        const int multiplicity = int(std::count(knots.begin(), knots.end(), t));
        if (multiplicity >= degree) continue;
        const int times = uniform_int(rng, 1, degree - multiplicity);
        const NurbsSurface refined = in_u ? s.insert_knot_u(t, times) : s.insert_knot_v(t, times);
        EXPECT_EQ(refined.rows(), s.rows() + (in_u ? times : 0));
        EXPECT_EQ(refined.columns(), s.columns() + (in_u ? 0 : times));
        EXPECT_EQ(refined.is_rational(), s.is_rational());
        for (int sample = 0; sample < 10; ++sample) {
            const double u = uniform(rng, s.domain_u().min, s.domain_u().max);
            const double v = uniform(rng, s.domain_v().min, s.domain_v().max);
            EXPECT_TRUE(near(refined.point(u, v), s.point(u, v), 1e-12 * net_size(s))) << "trial " << trial;
        }
    }
}

TEST(NurbsSurface, BezierPatchesReproduceTheSurfacePiecewise) {
    Rng rng(4005);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsSurface s = test::random_surface(rng, trial % 2 == 0, trial % 3 != 0, 4);
        const auto breaks_u = test::break_points(s.degree_u(), s.knots_u());
        const auto breaks_v = test::break_points(s.degree_v(), s.knots_v());
        const auto patches = s.bezier_patches();
        ASSERT_EQ(patches.size(), breaks_u.size() - 1);
        for (std::size_t a = 0; a < patches.size(); ++a) {
            ASSERT_EQ(patches[a].size(), breaks_v.size() - 1);
            for (std::size_t b = 0; b < patches[a].size(); ++b) {
                const BezierSurface& patch = patches[a][b];
                ASSERT_EQ(patch.degree_u(), s.degree_u());
                ASSERT_EQ(patch.degree_v(), s.degree_v());
                const double x = uniform(rng, 0, 1), y = uniform(rng, 0, 1);
                const double u = breaks_u[a] + x * (breaks_u[a + 1] - breaks_u[a]);
                const double v = breaks_v[b] + y * (breaks_v[b + 1] - breaks_v[b]);
                EXPECT_TRUE(near(patch.point(x, y), s.point(u, v), 1e-12 * net_size(s)))
                    << "trial " << trial << " patch " << a << "," << b;
            }
        }
        // Corners of the first and last patch are the surface's corners.
        const Interval du = s.domain_u(), dv = s.domain_v();
        EXPECT_TRUE(near(patches.front().front().point(0, 0), s.point(du.min, dv.min), 1e-12 * net_size(s)));
        EXPECT_TRUE(near(patches.back().back().point(1, 1), s.point(du.max, dv.max), 1e-12 * net_size(s)));
    }
}

TEST(NurbsSurface, BezierKnotVectorsEqualTheBezierSurface) {
    Rng rng(4006);
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = uniform_int(rng, 1, 4), m = uniform_int(rng, 1, 4);
        std::vector<std::vector<Vec3>> net(std::size_t(n + 1), std::vector<Vec3>(std::size_t(m + 1)));
        std::vector<std::vector<double>> weights(net.size(), std::vector<double>(net.front().size()));
        for (auto& row : net)
            for (Vec3& p : row) p = test::random_point(rng);
        for (auto& row : weights)
            for (double& w : row) w = test::random_weight(rng);
        const bool rational = trial % 2 == 0;
        const BezierSurface bezier = rational ? BezierSurface(net, weights) : BezierSurface(net);
        auto bezier_knots = [](int degree) {
            std::vector<double> knots(2 * std::size_t(degree + 1), 0.0);
            std::fill(knots.begin() + degree + 1, knots.end(), 1.0);
            return knots;
        };
        const NurbsSurface nurbs = rational ? NurbsSurface(n, m, bezier_knots(n), bezier_knots(m), net, weights)
                                            : NurbsSurface(n, m, bezier_knots(n), bezier_knots(m), net);
        const NurbsSurface converted = NurbsSurface::from_bezier(bezier);
        EXPECT_EQ(converted.knots_u(), bezier_knots(n));
        EXPECT_EQ(converted.is_rational(), rational);
        const double u = trial % 10 == 0 ? 1.0 : uniform(rng, 0, 1), v = trial % 10 == 1 ? 0.0 : uniform(rng, 0, 1);
        const auto expected = bezier.derivatives(u, v, 2);
        const auto actual = nurbs.derivatives(u, v, 2);
        const auto actual_converted = converted.derivatives(u, v, 2);
        for (std::size_t k = 0; k <= 2; ++k)
            for (std::size_t l = 0; k + l <= 2; ++l) {
                const double tolerance = 1e-11 * (norm(expected[k][l]) + 1);
                EXPECT_TRUE(near(actual[k][l], expected[k][l], tolerance)) << "trial " << trial << " " << k << l;
                EXPECT_TRUE(near(actual_converted[k][l], expected[k][l], tolerance)) << "trial " << trial;
            }
        EXPECT_TRUE(near(nurbs.normal(u, v), bezier.normal(u, v), 1e-9)) << "trial " << trial;
    }
}

TEST(NurbsSurface, IsocurvesAreExact) {
    Rng rng(4007);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsSurface s = test::random_surface(rng, trial % 2 == 0, trial % 3 != 0);
        const double u0 = test::random_parameter(rng, s.domain_u());
        const double v0 = test::random_parameter(rng, s.domain_v());
        const NurbsCurve along_v = s.isocurve_u(u0);
        const NurbsCurve along_u = s.isocurve_v(v0);
        EXPECT_EQ(along_v.degree(), s.degree_v());
        EXPECT_EQ(along_v.knots(), s.knots_v());
        EXPECT_EQ(along_u.degree(), s.degree_u());
        EXPECT_EQ(along_u.knots(), s.knots_u());
        EXPECT_EQ(along_v.is_rational(), s.is_rational());
        const double u = test::random_parameter(rng, s.domain_u());
        const double v = test::random_parameter(rng, s.domain_v());
        EXPECT_TRUE(near(along_v.point(v), s.point(u0, v), 1e-13 * net_size(s)));
        EXPECT_TRUE(near(along_u.point(u), s.point(u, v0), 1e-13 * net_size(s)));
        EXPECT_TRUE(near(along_v.derivative(v), s.derivative(u0, v, 0, 1), 1e-11 * (norm(s.derivative(u0, v, 0, 1)) + 1)));
        EXPECT_TRUE(near(along_u.derivative(u), s.derivative(u, v0, 1, 0), 1e-11 * (norm(s.derivative(u, v0, 1, 0)) + 1)));
    }
}

TEST(NurbsSurface, NormalIsTheUnitCrossProductOnRegularPoints) {
    Rng rng(4008);
    for (int trial = 0; trial < 1000; ++trial) {
        const NurbsSurface s = test::random_surface(rng, trial % 2 == 0, trial % 2 == 0);
        const double u = test::random_parameter(rng, s.domain_u());
        const double v = test::random_parameter(rng, s.domain_v());
        const Vec3 n = cross(s.derivative(u, v, 1, 0), s.derivative(u, v, 0, 1));
        if (norm(n) < 1e-6) continue;  // a random net may fold; those points are not what this test is about
        EXPECT_TRUE(near(s.normal(u, v), n / norm(n), 1e-12)) << "trial " << trial;
    }
}

TEST(NurbsSurface, FromHomogeneousAndAccessors) {
    const NurbsSurface s = NurbsSurface::from_homogeneous(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1},
                                                          {{0, 0, 0, 1}, {0, 2, 0, 2}, {2, 0, 0, 2}, {4, 4, 4, 4}});
    EXPECT_TRUE(s.is_rational());
    EXPECT_EQ(s.rows(), 2);
    EXPECT_EQ(s.columns(), 2);
    EXPECT_EQ(s.points()[1][1], (Vec3{1, 1, 1}));
    EXPECT_EQ(s.weights()[0][1], 2.0);
    // S^w(1/2, 1/2) = (6, 6, 4, 9) / 4, so S = (2/3, 2/3, 4/9).
    EXPECT_TRUE(near(s.point(0.5, 0.5), {2.0 / 3, 2.0 / 3, 4.0 / 9}, 1e-15));
    EXPECT_TRUE(throws_naming([] { (void)NurbsSurface::from_homogeneous(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{0, 0, 0, 1}}); },
                              "homogeneous_points"));
}

// ---- bad input, one test each ---------------------------------------------------------------------

const std::vector<double> linear{0, 0, 1, 1};
const std::vector<std::vector<Vec3>> square{{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}};

TEST(NurbsSurfaceErrors, EmptyNet) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, std::vector<std::vector<Vec3>>{}); }, "net"));
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, std::vector<std::vector<Vec3>>{{}, {}}); }, "net"));
}

TEST(NurbsSurfaceErrors, RaggedNet) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}}}); }, "net"));
}

TEST(NurbsSurfaceErrors, MismatchedWeights) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, square, {{1, 1}}); }, "weights"));
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, square, {{1, 1}, {1}}); }, "weights"));
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, square, {}); }, "weights"));
}

TEST(NurbsSurfaceErrors, NonFiniteCoordinates) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, nan_value}, {1, 1, 0}}}); },
                              "net"));
}

TEST(NurbsSurfaceErrors, WeightsMustBePositive) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, square, {{1, 1}, {1, 0}}); }, "weights"));
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, linear, linear, square, {{1, -2}, {1, 1}}); }, "weights"));
}

TEST(NurbsSurfaceErrors, DecreasingKnots) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, {0, 0, 1, 0.5}, linear, square); }, "knots_u"));
}

TEST(NurbsSurfaceErrors, KnotMultiplicityTooHigh) {
    const std::vector<std::vector<Vec3>> three_columns{{{0, 0, 0}, {0, 1, 0}, {0, 2, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 2, 0}}};
    EXPECT_TRUE(throws_naming([&] { NurbsSurface(1, 1, linear, {0, 0, 0, 1, 1}, three_columns); }, "knots_v"));
    const std::vector<std::vector<Vec3>> four_columns{{{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 3, 0}},
                                                      {{1, 0, 0}, {1, 1, 0}, {1, 2, 0}, {1, 3, 0}}};
    EXPECT_TRUE(throws_naming([&] { NurbsSurface(1, 1, linear, {0, 0, 0.5, 0.5, 1, 1}, four_columns); }, "knots_v"));
}

TEST(NurbsSurfaceErrors, TooFewControlPointsForTheKnotVector) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(2, 1, {0, 0, 0, 1, 1, 1}, linear, square); }, "net"));
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, 1, {0, 0, 0.5, 1, 1}, linear, square); }, "knots_u"));
}

TEST(NurbsSurfaceErrors, ParameterOutsideTheDomain) {
    const NurbsSurface s(1, 1, linear, linear, square);
    EXPECT_TRUE(throws_naming([&] { (void)s.point(1.5, 0.5); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)s.point(0.5, -0.5); }, "v"));
    EXPECT_TRUE(throws_naming([&] { (void)s.point(0.5, nan_value); }, "v"));
    EXPECT_TRUE(throws_naming([&] { (void)s.derivatives(0.5, 2.0, 1); }, "v"));
    EXPECT_TRUE(throws_naming([&] { (void)s.normal(-1.0, 0.5); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)s.isocurve_u(1.1); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)s.isocurve_v(1.1); }, "v"));
    EXPECT_TRUE(throws_naming([&] { (void)s.insert_knot_v(3.0); }, "v"));
}

TEST(NurbsSurfaceErrors, NegativeOrdersAndInsertionBeyondTheDegree) {
    const NurbsSurface s(1, 1, linear, linear, square);
    EXPECT_TRUE(throws_naming([&] { (void)s.derivative(0.5, 0.5, -1, 0); }, "du"));
    EXPECT_TRUE(throws_naming([&] { (void)s.derivative(0.5, 0.5, 0, -1); }, "dv"));
    EXPECT_TRUE(throws_naming([&] { (void)s.derivatives(0.5, 0.5, -1); }, "order"));
    EXPECT_TRUE(throws_naming([&] { (void)s.insert_knot_u(0.5, 2); }, "times"));
    EXPECT_TRUE(throws_naming([&] { (void)s.insert_knot_v(0.5, -1); }, "times"));
    EXPECT_TRUE(throws_naming([&] { (void)s.insert_knot_u(0.5, std::numeric_limits<int>::max()); }, "times"));
    // Zero more times is a no-op anywhere, the clamped ends (multiplicity p + 1) included.
    EXPECT_EQ(s.insert_knot_u(0.0, 0).knots_u(), s.knots_u());
    EXPECT_EQ(s.insert_knot_v(1.0, 0).knots_v(), s.knots_v());
}

TEST(NurbsSurfaceErrors, NegativeDegree) {
    EXPECT_TRUE(throws_naming([] { NurbsSurface(-1, 1, linear, linear, square); }, "degree_u"));
    EXPECT_TRUE(throws_naming([] { NurbsSurface(1, -1, linear, linear, square); }, "degree_v"));
}

}  // namespace
}  // namespace ratbez
