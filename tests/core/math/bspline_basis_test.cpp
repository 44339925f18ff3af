#include "ratbez/bspline_basis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "nurbs_test_support.hpp"
#include "ratbez/bernstein.hpp"

namespace ratbez {
namespace {

using namespace test;


std::vector<double> all_basis(int degree, const std::vector<double>& knots, double u) {
    std::vector<double> values(static_cast<std::size_t>(degree) + 1);
    basis_functions(find_span(degree, knots, u), u, degree, knots, values);
    return values;
}

// ---- 001's worked example: U = {0,0,0,1,1,1}, the whole triangle of degrees 0, 1, 2 ------------------

TEST(BsplineBasis, WorkedExampleOf001DegreeZeroAndOne) {
    const std::vector<double> knots{0, 0, 0, 1, 1, 1};
    for (double u : {0.0, 0.125, 0.3, 0.5, 0.875, 1.0}) {
        // N_{0,0} = N_{1,0} = N_{3,0} = N_{4,0} = 0 everywhere; N_{2,0} = 1 on [0, 1] (closed at 1 in 001).
        EXPECT_EQ(bspline_basis(0, 0, knots, u), 0.0);
        EXPECT_EQ(bspline_basis(1, 0, knots, u), 0.0);
        EXPECT_EQ(bspline_basis(2, 0, knots, u), 1.0) << u;
        EXPECT_EQ(bspline_basis(3, 0, knots, u), 0.0);
        EXPECT_EQ(bspline_basis(4, 0, knots, u), 0.0);
        // N_{0,1} = 0, N_{1,1} = 1 - u, N_{2,1} = u, N_{3,1} = 0 (the 0/0 := 0 rule at work).
        EXPECT_EQ(bspline_basis(0, 1, knots, u), 0.0);
        EXPECT_DOUBLE_EQ(bspline_basis(1, 1, knots, u), 1 - u);
        EXPECT_DOUBLE_EQ(bspline_basis(2, 1, knots, u), u);
        EXPECT_EQ(bspline_basis(3, 1, knots, u), 0.0);
    }
    // Outside [0, 1] every function vanishes.
    for (int i = 0; i <= 2; ++i) {
        EXPECT_EQ(bspline_basis(i, 2, knots, -0.5), 0.0);
        EXPECT_EQ(bspline_basis(i, 2, knots, 1.5), 0.0);
    }
}

TEST(BsplineBasis, WorkedExampleOf001DegreeTwoIsBernstein) {
    // 001 derives N_{0,2} = (1-u)^2, N_{1,2} = 2u(1-u), N_{2,2} = u^2 on [0, 1]. (The text prints N_{1,2} as
    // 2(1-u), dropping the factor u; the recursion it shows, u N_{1,1} + (1-u) N_{2,1}, gives 2u(1-u), and
    // only that sums to 1 with the other two.)
    const std::vector<double> knots{0, 0, 0, 1, 1, 1};
    for (double u : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        EXPECT_DOUBLE_EQ(bspline_basis(0, 2, knots, u), (1 - u) * (1 - u));
        EXPECT_DOUBLE_EQ(bspline_basis(1, 2, knots, u), 2 * u * (1 - u));
        EXPECT_DOUBLE_EQ(bspline_basis(2, 2, knots, u), u * u);
    }
    EXPECT_EQ(bspline_basis(1, 2, knots, 0.5), 0.5);
    EXPECT_EQ(bspline_basis(0, 2, knots, 0.5), 0.25);
}

TEST(BsplineBasis, BezierKnotVectorGivesBernsteinPolynomials) {
    // 001: {0 (p+1 times), 1 (p+1 times)} makes N_{i,p} = B_{i,p}, for every degree, at many u.
    Rng rng(2001);
    for (int p = 0; p <= 7; ++p) {
        std::vector<double> knots(static_cast<std::size_t>(2 * p + 2), 0.0);
        std::fill(knots.begin() + p + 1, knots.end(), 1.0);
        for (int sample = 0; sample < 200; ++sample) {
            const double u = sample == 0 ? 0.0 : sample == 1 ? 1.0 : uniform(rng, 0.0, 1.0);
            const std::vector<double> values = all_basis(p, knots, u);
            for (int i = 0; i <= p; ++i) {
                EXPECT_NEAR(bspline_basis(i, p, knots, u), bernstein(i, p, u), 1e-14) << "p=" << p << " u=" << u;
                EXPECT_NEAR(values[static_cast<std::size_t>(i)], bernstein(i, p, u), 1e-14);
            }
        }
    }
}

// ---- the classic nonuniform example (Ex2.3 / Ex2.4 of the NURBS book) ----------------------------------

TEST(BsplineBasis, NonuniformExampleValuesAtFiveHalves) {
    const std::vector<double> knots{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
    const int p = 2;
    EXPECT_EQ(find_span(p, knots, 2.5), 4);
    const std::vector<double> values = all_basis(p, knots, 2.5);  // N_{2,2}, N_{3,2}, N_{4,2}
    EXPECT_DOUBLE_EQ(values[0], 1.0 / 8);
    EXPECT_DOUBLE_EQ(values[1], 6.0 / 8);
    EXPECT_DOUBLE_EQ(values[2], 1.0 / 8);
    EXPECT_DOUBLE_EQ(bspline_basis(2, p, knots, 2.5), 1.0 / 8);
    EXPECT_DOUBLE_EQ(bspline_basis(3, p, knots, 2.5), 6.0 / 8);
    EXPECT_DOUBLE_EQ(bspline_basis(4, p, knots, 2.5), 1.0 / 8);
    for (int i : {0, 1, 5, 6, 7}) EXPECT_EQ(bspline_basis(i, p, knots, 2.5), 0.0) << i;
}

TEST(BsplineBasis, NonuniformExampleDerivativesAtFiveHalves) {
    // On [2, 3): N_{2,2} = (3-u)^2/2, N_{3,2} = -11/2 + 5u - u^2, N_{4,2} = (u-2)^2/2, so at u = 5/2 the first
    // derivatives are -1/2, 0, 1/2, the second 1, -2, 1, and the third vanish (degree 2).
    const std::vector<double> knots{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
    const auto ders = basis_function_derivatives(4, 2.5, 2, knots, 3);
    ASSERT_EQ(ders.size(), 4u);
    const std::vector<std::vector<double>> expected{{0.125, 0.75, 0.125}, {-0.5, 0, 0.5}, {1, -2, 1}, {0, 0, 0}};
    for (std::size_t k = 0; k < 4; ++k) {
        ASSERT_EQ(ders[k].size(), 3u);
        for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(ders[k][j], expected[k][j], 1e-15) << k << "," << j;
    }
    // The allocation-free form writes the same rows.
    std::vector<double> flat(4 * 3, -7.0);
    basis_function_derivatives(4, 2.5, 2, knots, 3, flat);
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(flat[k * 3 + j], ders[k][j]);
}

TEST(BsplineBasis, SpansOfTheNonuniformExample) {
    const std::vector<double> knots{0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5};
    EXPECT_EQ(find_span(2, knots, 0.0), 2);
    EXPECT_EQ(find_span(2, knots, 0.5), 2);
    EXPECT_EQ(find_span(2, knots, 1.0), 3);
    EXPECT_EQ(find_span(2, knots, 3.999), 5);
    EXPECT_EQ(find_span(2, knots, 4.0), 7);  // the double knot 4: span [u_7, u_8) = [4, 5)
    EXPECT_EQ(find_span(2, knots, 5.0), 7);  // the right end closes the last span
    const Interval d = knot_domain(2, knots);
    EXPECT_EQ(d.min, 0.0);
    EXPECT_EQ(d.max, 5.0);
    // At the right end of a clamped vector the last function is 1 (endpoint interpolation).
    EXPECT_EQ(bspline_basis(7, 2, knots, 5.0), 1.0);
    EXPECT_EQ(all_basis(2, knots, 5.0)[2], 1.0);
}

TEST(BsplineBasis, UnclampedUniformVector) {
    // Uniform quadratic B-spline on {0..6}: domain [2, 4]; at the integer knots the values are 1/2, 1/2, 0.
    const std::vector<double> knots{0, 1, 2, 3, 4, 5, 6};
    const Interval d = knot_domain(2, knots);
    EXPECT_EQ(d.min, 2.0);
    EXPECT_EQ(d.max, 4.0);
    EXPECT_EQ(find_span(2, knots, 4.0), 3);
    const std::vector<double> at_end = all_basis(2, knots, 4.0);  // N_{1,2}, N_{2,2}, N_{3,2}
    EXPECT_DOUBLE_EQ(at_end[0], 0.0);
    EXPECT_DOUBLE_EQ(at_end[1], 0.5);
    EXPECT_DOUBLE_EQ(at_end[2], 0.5);
    EXPECT_DOUBLE_EQ(bspline_basis(3, 2, knots, 4.0), 0.5);
    // At 2.5: the middle of N_{1,2}'s hump (3/4) and the tails of N_{0,2} and N_{2,2} (1/8 each).
    EXPECT_DOUBLE_EQ(bspline_basis(0, 2, knots, 2.5), 0.125);
    EXPECT_DOUBLE_EQ(bspline_basis(1, 2, knots, 2.5), 0.75);
    EXPECT_DOUBLE_EQ(bspline_basis(2, 2, knots, 2.5), 0.125);
    EXPECT_THROW(find_span(2, knots, 1.5), Error);
    EXPECT_THROW(find_span(2, knots, 4.5), Error);
}

// ---- properties on random knot vectors ---------------------------------------------------------------

TEST(BsplineBasis, PartitionOfUnityAndNonNegativityOnRandomKnots) {
    Rng rng(2002);
    for (int trial = 0; trial < 1000; ++trial) {
        const int p = uniform_int(rng, 0, 5);
        const int count = p + 1 + (p == 0 ? 0 : uniform_int(rng, 0, 8));
        const bool clamped = trial % 2 == 0;
        const std::vector<double> knots = test::random_knots(rng, p, count, clamped);
        const Interval d = knot_domain(p, knots);
        const double u = trial % 7 == 0 ? d.max : trial % 7 == 1 ? d.min : uniform(rng, d.min, d.max);
        const std::vector<double> values = all_basis(p, knots, u);
        double sum = 0;
        for (double n : values) {
            EXPECT_GE(n, 0.0);
            sum += n;
        }
        EXPECT_NEAR(sum, 1.0, 1e-14) << "trial " << trial;
        // All n + 1 functions by A2.4, each >= 0, summing to 1 as well.
        double sum_all = 0;
        for (int i = 0; i < count; ++i) {
            const double n = bspline_basis(i, p, knots, u);
            EXPECT_GE(n, 0.0);
            sum_all += n;
        }
        EXPECT_NEAR(sum_all, 1.0, 1e-14) << "trial " << trial;
    }
}

TEST(BsplineBasis, OneBasisFunctionAgreesWithAllBasisFunctions) {
    // A2.4 (Cox–de Boor one function at a time) against A2.2 (the non-vanishing triangle), including ends
    // and knots, on clamped and unclamped vectors; functions outside the span are 0 by A2.4.
    Rng rng(2003);
    for (int trial = 0; trial < 1000; ++trial) {
        const int p = uniform_int(rng, 1, 5);
        const int count = p + 1 + uniform_int(rng, 0, 8);
        const std::vector<double> knots = test::random_knots(rng, p, count, trial % 2 == 0);
        const Interval d = knot_domain(p, knots);
        double u = uniform(rng, d.min, d.max);
        if (trial % 5 == 0) u = knots[static_cast<std::size_t>(uniform_int(rng, p, count))];  // a knot in the domain
        if (trial % 11 == 0) u = d.max;
        const int span = find_span(p, knots, u);
        const std::vector<double> values = all_basis(p, knots, u);
        for (int i = 0; i < count; ++i) {
            const double expected = i >= span - p && i <= span ? values[static_cast<std::size_t>(i - span + p)] : 0.0;
            EXPECT_NEAR(bspline_basis(i, p, knots, u), expected, 1e-14) << "trial " << trial << " i " << i;
        }
    }
}

TEST(BsplineBasis, DerivativesAgreeWithCentralDifferences) {
    Rng rng(2004);
    for (int trial = 0; trial < 1000; ++trial) {
        const int p = uniform_int(rng, 1, 5);
        const int count = p + 1 + uniform_int(rng, 0, 8);
        const std::vector<double> knots = test::random_knots(rng, p, count, trial % 2 == 0);
        const auto where = test::random_interior_parameter(rng, p, knots);
        const double u = where.value, h = 1e-4 * (where.span_max - where.span_min);
        const int span = find_span(p, knots, u);
        const auto ders = basis_function_derivatives(span, u, p, knots, p + 1);
        const auto plus = basis_function_derivatives(span, u + h, p, knots, p + 1);
        const auto minus = basis_function_derivatives(span, u - h, p, knots, p + 1);
        for (int k = 1; k <= p; ++k) {
            for (std::size_t j = 0; j <= static_cast<std::size_t>(p); ++j) {
                const double difference = (plus[static_cast<std::size_t>(k - 1)][j] - minus[static_cast<std::size_t>(k - 1)][j]) / (2 * h);
                const double scale = std::abs(ders[static_cast<std::size_t>(k)][j]) + std::abs(ders[static_cast<std::size_t>(k - 1)][j]) / (where.span_max - where.span_min) + 1;
                EXPECT_NEAR(ders[static_cast<std::size_t>(k)][j], difference, 1e-6 * scale) << "trial " << trial << " k " << k;
            }
        }
        // Derivatives of order p + 1 vanish; the derivatives of a partition of unity sum to 0.
        for (double value : ders[static_cast<std::size_t>(p + 1)]) EXPECT_EQ(value, 0.0);
        for (int k = 1; k <= p; ++k) {
            double sum = 0, magnitude = 0;
            for (double value : ders[static_cast<std::size_t>(k)]) {
                sum += value;
                magnitude += std::abs(value);
            }
            EXPECT_NEAR(sum, 0.0, 1e-12 * (1 + magnitude));
        }
    }
}

TEST(BsplineBasis, DegreeZeroIsTheIndicatorOfItsSingleSpan) {
    const std::vector<double> knots{2.0, 3.5};
    validate_knot_vector(0, knots, 1);
    EXPECT_EQ(find_span(0, knots, 2.0), 0);
    EXPECT_EQ(find_span(0, knots, 3.5), 0);
    EXPECT_EQ(all_basis(0, knots, 3.5)[0], 1.0);
    EXPECT_EQ(bspline_basis(0, 0, knots, 3.5), 1.0);
    EXPECT_EQ(bspline_basis(0, 0, knots, 4.0), 0.0);
    // A second span would need an interior knot of multiplicity 1 > 0 = degree.
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(0, std::vector<double>{0, 1, 2}, 2); }, "knots"));
}

// ---- bad input --------------------------------------------------------------------------------------

TEST(BsplineBasisErrors, KnotCountMustMatchPointsPlusDegreePlusOne) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(2, std::vector<double>{0, 0, 0, 1, 1, 1, 1}, 3); }, "knots"));
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(2, std::vector<double>{0, 0, 0, 1, 1}, 3, "knots_v"); },
                              "knots_v"));
}

TEST(BsplineBasisErrors, TooFewControlPoints) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(3, std::vector<double>{0, 0, 0, 1, 1, 1}, 2); }, "knots"));
}

TEST(BsplineBasisErrors, NonFiniteKnots) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(1, std::vector<double>{0, 0, nan_value, 1}, 2); }, "knots"));
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(1, std::vector<double>{0, 0, 1, inf_value}, 2); }, "knots"));
    EXPECT_TRUE(throws_naming([] { (void)bspline_basis(0, 1, std::vector<double>{0, nan_value, 1}, 0.5); }, "knots"));
}

TEST(BsplineBasisErrors, DecreasingKnots) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(2, std::vector<double>{0, 0, 0, 0.7, 0.5, 1, 1, 1}, 5); },
                              "knots"));
    EXPECT_TRUE(throws_naming([] { (void)bspline_basis(0, 1, std::vector<double>{0, 1, 0.5}, 0.5); }, "knots"));
}

TEST(BsplineBasisErrors, EndMultiplicityAboveDegreePlusOne) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(2, std::vector<double>{0, 0, 0, 0, 1, 1, 1}, 4); }, "knots"));
}

TEST(BsplineBasisErrors, InteriorMultiplicityAboveDegree) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(2, std::vector<double>{0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, 6); },
                              "knots"));
    // Multiplicity p inside the domain is fine.
    EXPECT_NO_THROW(validate_knot_vector(2, std::vector<double>{0, 0, 0, 0.5, 0.5, 1, 1, 1}, 5));
}

TEST(BsplineBasisErrors, EmptyDomain) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(1, std::vector<double>{0, 1, 1, 2}, 2); }, "knots"));
}

TEST(BsplineBasisErrors, NegativeDegree) {
    EXPECT_TRUE(throws_naming([] { validate_knot_vector(-1, std::vector<double>{0, 1}, 2); }, "degree"));
    EXPECT_TRUE(throws_naming([] { (void)bspline_basis(0, -1, std::vector<double>{0, 1}, 0.5); }, "p"));
}

TEST(BsplineBasisErrors, ParameterOutsideTheDomainOrNotFinite) {
    const std::vector<double> knots{0, 0, 1, 1};
    EXPECT_TRUE(throws_naming([&] { (void)find_span(1, knots, 1.5); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)find_span(1, knots, -1e-12); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)find_span(1, knots, nan_value); }, "u"));
    EXPECT_TRUE(throws_naming([&] { (void)bspline_basis(0, 1, knots, nan_value); }, "u"));
}

TEST(BsplineBasisErrors, IndexOutOfRange) {
    const std::vector<double> knots{0, 0, 0, 1, 1, 1};
    EXPECT_TRUE(throws_naming([&] { (void)bspline_basis(3, 2, knots, 0.5); }, "i"));
    EXPECT_TRUE(throws_naming([&] { (void)bspline_basis(-1, 2, knots, 0.5); }, "i"));
    std::vector<double> out(3);
    EXPECT_TRUE(throws_naming([&] { basis_functions(3, 0.5, 2, knots, out); }, "span"));
    EXPECT_TRUE(throws_naming([&] { basis_functions(1, 0.5, 2, knots, out); }, "span"));
    std::vector<double> small(2);
    EXPECT_TRUE(throws_naming([&] { basis_functions(2, 0.5, 2, knots, small); }, "out"));
    EXPECT_TRUE(throws_naming([&] { (void)basis_function_derivatives(2, 0.5, 2, knots, -1); }, "order"));
    // An empty span (zero length) would divide by zero: refused.
    const std::vector<double> doubled{0, 0, 0, 0.5, 0.5, 1, 1, 1};
    EXPECT_TRUE(throws_naming([&] { basis_functions(3, 0.5, 2, doubled, out); }, "span"));
}

}  // namespace
}  // namespace ratbez
