// degree_elevation.hpp: A5.9 keeps every curve and surface (rational ones exactly), raises the degree by the
// amount asked and keeps the continuity at every knot (multiplicity s becomes s + t).

#include "ratbez/degree_elevation.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "nurbs_test_support.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/primitives.hpp"

namespace ratbez {
namespace {

using test::Rng;

int multiplicity(const std::vector<double>& knots, double u) {
    return static_cast<int>(std::count(knots.begin(), knots.end(), u));
}

TEST(ElevateDegree, RandomCurvesKeepTheirShapeAndContinuity) {
    Rng rng(1801);
    for (int trial = 0; trial < 200; ++trial) {
        const NurbsCurve curve = test::random_curve(rng, trial % 2 == 0, trial % 3 != 0);
        const int times = test::uniform_int(rng, 1, 3);
        const NurbsCurve elevated = elevate_degree(curve, times);
        ASSERT_EQ(elevated.degree(), curve.degree() + times);
        EXPECT_EQ(elevated.is_rational(), curve.is_rational());
        test::expect_same_curve(curve, elevated, 1e-11);
        // Every interior break point keeps its continuity: multiplicity s becomes s + t.
        const std::vector<double> breaks = test::break_points(curve.degree(), curve.knots());
        for (std::size_t k = 1; k + 1 < breaks.size(); ++k)
            EXPECT_EQ(multiplicity(elevated.knots(), breaks[k]), multiplicity(curve.knots(), breaks[k]) + times)
                << "trial " << trial << " knot " << breaks[k];
        // Derivatives agree too (the same parameterisation), inside a span.
        const auto at = test::random_interior_parameter(rng, curve.degree(), curve.knots());
        EXPECT_LE(distance(curve.derivative(at.value, 1), elevated.derivative(at.value, 1)),
                  1e-9 * (1 + norm(curve.derivative(at.value, 1))));
    }
}

TEST(ElevateDegree, AQuadraticCircleBecomesAnExactCubicCircle) {
    const NurbsCurve c = circle(2.0, {1, 2, 3}, {0, 1, 1});
    const NurbsCurve cubic = elevate_degree(c, 1);
    EXPECT_EQ(cubic.degree(), 3);
    for (int k = 0; k <= 100; ++k) EXPECT_NEAR(distance(cubic.point(k / 100.0), {1, 2, 3}), 2.0, 1e-14);
    EXPECT_EQ(elevate_degree(c, 0).knots(), c.knots());
    EXPECT_ERROR_NAMING(elevate_degree(c, -1), "times");
}

TEST(ElevateDegree, SurfacesKeepTheirShapeInUAndV) {
    Rng rng(2606);
    for (int trial = 0; trial < 60; ++trial) {
        const NurbsSurface s = test::random_surface(rng, trial % 2 == 0, trial % 3 != 0, 4);
        const int tu = test::uniform_int(rng, 0, 2), tv = test::uniform_int(rng, 0, 2);
        const NurbsSurface e = elevate_degree_v(elevate_degree_u(s, tu), tv);
        EXPECT_EQ(e.degree_u(), s.degree_u() + tu);
        EXPECT_EQ(e.degree_v(), s.degree_v() + tv);
        EXPECT_EQ(e.is_rational(), s.is_rational());
        const Interval du = s.domain_u(), dv = s.domain_v();
        ASSERT_EQ(e.domain_u().min, du.min);
        ASSERT_EQ(e.domain_v().max, dv.max);
        const double size = s.control_box().diagonal();
        for (int i = 0; i <= 12; ++i)
            for (int j = 0; j <= 12; ++j) {
                const double u = du.min + du.width() * i / 12, v = dv.min + dv.width() * j / 12;
                ASSERT_LE(distance(s.point(u, v), e.point(u, v)), 1e-11 * size) << trial << " " << u << " " << v;
            }
        // Interior knots keep their continuity in the elevated direction.
        const std::vector<double> breaks = test::break_points(s.degree_u(), s.knots_u());
        for (std::size_t k = 1; k + 1 < breaks.size(); ++k)
            EXPECT_EQ(multiplicity(e.knots_u(), breaks[k]), multiplicity(s.knots_u(), breaks[k]) + tu);
    }
    // A sphere's face, rational in both directions, elevated to bicubic: still on the sphere.
    const NurbsSurface sphere_face = sphere(2.0).faces().front().surface();
    const NurbsSurface cubic = elevate_degree_v(elevate_degree_u(sphere_face, 1), 1);
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const Interval du = cubic.domain_u(), dv = cubic.domain_v();
            EXPECT_NEAR(norm(cubic.point(du.min + du.width() * i / 20, dv.min + dv.width() * j / 20)), 2.0, 1e-14);
        }
    EXPECT_ERROR_NAMING(elevate_degree_u(sphere_face, -1), "times_u");
    EXPECT_ERROR_NAMING(elevate_degree_v(sphere_face, -1), "times_v");
}

}  // namespace
}  // namespace ratbez
