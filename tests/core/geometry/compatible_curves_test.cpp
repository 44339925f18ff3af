// Degree elevation (A5.9) and compatible knot vectors (compatible_curves.hpp): the curve never changes, the
// representation does exactly as promised (degree, multiplicities, common knots).

#include "ratbez/compatible_curves.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "nurbs_test_support.hpp"
#include "ratbez/curves.hpp"

namespace ratbez {
namespace {

using test::Rng;

// The same point set at the same (affinely mapped) parameters, to `tolerance` of the curve's size.
void expect_same_curve(const NurbsCurve& original, const NurbsCurve& changed, double tolerance = 1e-12) {
    const Interval a = original.domain(), b = changed.domain();
    const double size = original.control_box().diagonal();
    for (int k = 0; k <= 200; ++k) {
        const double f = k / 200.0;
        ASSERT_LE(distance(original.point(a.min + f * a.width()), changed.point(k == 200 ? b.max : b.min + f * b.width())),
                  tolerance * size)
            << "at fraction " << f;
    }
}

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
        expect_same_curve(curve, elevated, 1e-11);
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

TEST(MakeCompatible, CommonDegreeDomainAndKnotsSameCurves) {
    Rng rng(1802);
    for (int trial = 0; trial < 100; ++trial) {
        std::vector<NurbsCurve> curves;
        const int count = test::uniform_int(rng, 1, 4);
        for (int k = 0; k < count; ++k) curves.push_back(test::random_curve(rng, (trial + k) % 2 == 0, (trial + k) % 3 != 0, 4));
        const std::vector<NurbsCurve> compatible = make_compatible(curves);
        ASSERT_EQ(compatible.size(), curves.size());
        for (std::size_t k = 0; k < curves.size(); ++k) {
            EXPECT_EQ(compatible[k].degree(), compatible[0].degree());
            EXPECT_EQ(compatible[k].knots(), compatible[0].knots());
            EXPECT_EQ(compatible[k].domain(), (Interval{0.0, 1.0}));
            expect_same_curve(curves[k], compatible[k], 1e-11);
        }
    }
}

TEST(MakeCompatible, ALineAndACircleShareTheCirclesKnots) {
    const std::vector<NurbsCurve> c = make_compatible({line_segment({0, 0, 0}, {4, 0, 0}), circle(1.0)});
    EXPECT_EQ(c[0].degree(), 2);
    EXPECT_EQ(c[0].knots(), circle(1.0).knots());
    EXPECT_FALSE(c[0].is_rational());
    EXPECT_NEAR(c[0].point(0.25).x, 1.0, 1e-15);  // the line keeps its (uniform) parameterisation
    EXPECT_ERROR_NAMING(make_compatible({}), "curves");
}

}  // namespace
}  // namespace ratbez
