#include "ratbez/bernstein.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bezier_test_support.hpp"

namespace ratbez {
namespace {

using namespace test;

constexpr double kExact = 1e-14;

TEST(Bernstein, LowDegreesMatchTheClosedFormsOfP16) {
    // 000 §1.3 after P1.7: B_{0,1} = 1-u, B_{1,1} = u, B_{0,2} = (1-u)^2, B_{1,2} = 2u(1-u), B_{2,2} = u^2.
    for (double u : {0.0, 0.2, 0.5, 0.7, 1.0}) {
        EXPECT_NEAR(bernstein(0, 0, u), 1.0, kExact);
        EXPECT_NEAR(bernstein(0, 1, u), 1.0 - u, kExact);
        EXPECT_NEAR(bernstein(1, 1, u), u, kExact);
        EXPECT_NEAR(bernstein(0, 2, u), (1 - u) * (1 - u), kExact);
        EXPECT_NEAR(bernstein(1, 2, u), 2 * u * (1 - u), kExact);
        EXPECT_NEAR(bernstein(2, 2, u), u * u, kExact);
    }
}

TEST(Bernstein, A12AndA13MatchExactFractionsUpToDegree12) {
    // Table 1.1's B_{1,3} included: B_{1,3}(2/5) = 3 (2/5) (3/5)^2 = 54/125.
    EXPECT_NEAR(bernstein(1, 3, 0.4), 54.0 / 125.0, kExact);
    for (int n = 0; n <= 12; ++n)
        for (int q = 1; q <= 7; ++q) {
            const Rational u(q, 8);
            const std::vector<double> all = all_bernstein(n, u.to_double());
            ASSERT_EQ(all.size(), static_cast<std::size_t>(n + 1));
            for (int i = 0; i <= n; ++i) {
                const double exact = bernstein_exact(i, n, u).to_double();
                EXPECT_NEAR(bernstein(i, n, u.to_double()), exact, kExact) << "A1.2, i=" << i << " n=" << n;
                EXPECT_NEAR(all[static_cast<std::size_t>(i)], exact, kExact) << "A1.3, i=" << i << " n=" << n;
            }
        }
}

TEST(Bernstein, IndicesOutsideZeroToNAreZero) {
    // The convention of P1.6 and P1.7: B_{-1,n-1} = B_{n,n-1} = 0.
    EXPECT_EQ(bernstein(-1, 3, 0.3), 0.0);
    EXPECT_EQ(bernstein(4, 3, 0.3), 0.0);
}

TEST(Bernstein, EndValuesP13AndSymmetryP15) {
    for (int n = 0; n <= 15; ++n) {
        EXPECT_EQ(bernstein(0, n, 0.0), 1.0);
        EXPECT_EQ(bernstein(n, n, 1.0), 1.0);
        for (int i = 1; i <= n; ++i) EXPECT_EQ(bernstein(i, n, 0.0), 0.0);
        for (double u : {0.1, 0.35, 0.8})
            for (int i = 0; i <= n; ++i) EXPECT_NEAR(bernstein(i, n, u), bernstein(n - i, n, 1.0 - u), kExact);
    }
}

TEST(Bernstein, MaximumP14IsAtIOverN) {
    const int n = 7;
    for (int i = 0; i <= n; ++i) {
        const double peak = static_cast<double>(i) / n;
        const double at_peak = bernstein(i, n, peak);
        for (double offset : {-0.05, 0.05}) {
            const double u = peak + offset;
            if (u < 0.0 || u > 1.0) continue;
            EXPECT_LT(bernstein(i, n, u), at_peak);
        }
    }
}

TEST(Bernstein, PartitionOfUnityP12AndNonNegativityP11OnRandomInput) {
    RandomInput random(1);
    for (int trial = 0; trial < 2000; ++trial) {
        const int n = random.integer(0, 25);
        const double u = random.parameter();
        const std::vector<double> values = all_bernstein(n, u);
        double sum = 0.0;
        for (double b : values) {
            EXPECT_GE(b, 0.0);
            sum += b;
        }
        EXPECT_NEAR(sum, 1.0, 1e-14) << "n=" << n << " u=" << u;
    }
}

TEST(BernsteinDerivatives, CubicDerivativesOfExercise110) {
    // P1.7 for n = 3 worked by hand: B'_{0,3} = -3(1-u)^2, B'_{1,3} = 3(1-u)(1-3u), B'_{2,3} = 3u(2-3u), B'_{3,3} = 3u^2;
    // second derivatives 6(1-u), 6(3u-2), 6(1-3u), 6u; third -6, 18, -18, 6.
    for (double u : {0.0, 0.25, 0.6, 1.0}) {
        const auto d1 = all_bernstein_derivatives(3, 1, u);
        EXPECT_NEAR(d1[0], -3 * (1 - u) * (1 - u), kExact);
        EXPECT_NEAR(d1[1], 3 * (1 - u) * (1 - 3 * u), kExact);
        EXPECT_NEAR(d1[2], 3 * u * (2 - 3 * u), kExact);
        EXPECT_NEAR(d1[3], 3 * u * u, kExact);
        const auto d2 = all_bernstein_derivatives(3, 2, u);
        EXPECT_NEAR(d2[0], 6 * (1 - u), kExact);
        EXPECT_NEAR(d2[1], 6 * (3 * u - 2), kExact);
        EXPECT_NEAR(d2[2], 6 * (1 - 3 * u), kExact);
        EXPECT_NEAR(d2[3], 6 * u, kExact);
        const auto d3 = all_bernstein_derivatives(3, 3, u);
        EXPECT_NEAR(d3[0], -6, kExact);
        EXPECT_NEAR(d3[1], 18, kExact);
        EXPECT_NEAR(d3[2], -18, kExact);
        EXPECT_NEAR(d3[3], 6, kExact);
    }
    // Exercise 1.10 for n = 2: B'_{0,2} = -2(1-u), B'_{1,2} = 2 - 4u, B'_{2,2} = 2u.
    const auto q = all_bernstein_derivatives(2, 1, 0.3);
    EXPECT_NEAR(q[0], -1.4, kExact);
    EXPECT_NEAR(q[1], 0.8, kExact);
    EXPECT_NEAR(q[2], 0.6, kExact);
}

TEST(BernsteinDerivatives, OrderZeroIsTheBasisAndOrdersAboveNVanish) {
    const auto zero = all_bernstein_derivatives(4, 0, 0.3);
    const auto basis = all_bernstein(4, 0.3);
    for (std::size_t i = 0; i < basis.size(); ++i) EXPECT_EQ(zero[i], basis[i]);
    for (double d : all_bernstein_derivatives(4, 5, 0.3)) EXPECT_EQ(d, 0.0);
    EXPECT_EQ(all_bernstein_derivatives(4, 5, 0.3).size(), 5u);
}

TEST(BernsteinDerivatives, AgreeWithCentralDifferencesAndSumToZeroOnRandomInput) {
    RandomInput random(2);
    const double h = 1e-5;
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = random.integer(1, 12);
        const int k = random.integer(1, 3);
        const double u = random.uniform(h, 1.0 - h);
        const auto derivative = all_bernstein_derivatives(n, k, u);
        const auto below_plus = all_bernstein_derivatives(n, k - 1, u + h);
        const auto below_minus = all_bernstein_derivatives(n, k - 1, u - h);
        double sum = 0.0, scale = 1.0;
        for (int i = 0; i <= n; ++i) {
            const auto s = static_cast<std::size_t>(i);
            const double difference = (below_plus[s] - below_minus[s]) / (2 * h);
            scale = std::max(scale, std::abs(derivative[s]));
            EXPECT_NEAR(derivative[s], difference, 1e-5 * (1.0 + std::abs(derivative[s])))
                << "n=" << n << " k=" << k << " i=" << i << " u=" << u;
            sum += derivative[s];
        }
        // Differentiating P1.2: the derivatives of a partition of unity sum to zero.
        EXPECT_NEAR(sum, 0.0, 1e-12 * scale);
    }
}

TEST(BernsteinErrors, NegativeDegreeNamesN) {
    EXPECT_TRUE(starts_with(error_message([] { bernstein(0, -1, 0.5); }), "n:"));
    EXPECT_TRUE(starts_with(error_message([] { all_bernstein(-2, 0.5); }), "n:"));
    EXPECT_TRUE(starts_with(error_message([] { all_bernstein_derivatives(-1, 1, 0.5); }), "n:"));
}

TEST(BernsteinErrors, ParameterOutsideTheUnitIntervalOrNaNNamesU) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (double bad : {-0.001, 1.001, nan, inf}) {
        const std::string m1 = error_message([&] { bernstein(1, 3, bad); });
        const std::string m2 = error_message([&] { all_bernstein(3, bad); });
        const std::string m3 = error_message([&] { all_bernstein_derivatives(3, 1, bad); });
        EXPECT_TRUE(starts_with(m1, "u:")) << m1;
        EXPECT_TRUE(starts_with(m2, "u:")) << m2;
        EXPECT_TRUE(starts_with(m3, "u:")) << m3;
    }
}

TEST(BernsteinErrors, NegativeDerivativeOrderNamesK) {
    const std::string message = error_message([] { all_bernstein_derivatives(3, -1, 0.5); });
    EXPECT_TRUE(starts_with(message, "k:")) << message;
    EXPECT_NE(message.find("-1"), std::string::npos) << message;
}

}  // namespace
}  // namespace ratbez
