#include "ratbez/power_basis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "bezier_test_support.hpp"
#include "ratbez/bernstein.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"

namespace ratbez {
namespace {

using namespace test;

constexpr double kExact = 1e-14;

TEST(Horner, A11EvaluatesScalarAndVectorPolynomials) {
    // 3 - 2u + u^3 at u = 2: 3 - 4 + 8 = 7; at u = -1 (Exercise 1.9 uses [-1, 1]): 3 + 2 - 1 = 4.
    const std::vector<double> cubic = {3.0, -2.0, 0.0, 1.0};
    EXPECT_EQ(horner(cubic, 2.0), 7.0);
    EXPECT_EQ(horner(cubic, -1.0), 4.0);
    EXPECT_EQ(horner(std::vector<double>{5.0}, 0.3), 5.0);
    // Exercise 1.9: C(u) = (1 + u - 2u^2 + u^3, 1 - 2u + u^3); C(-1) = (-3, 2), C(0) = (1, 1), C(1) = (1, 0).
    const std::vector<Vec3> a = {{1, 1, 0}, {1, -2, 0}, {-2, 0, 0}, {1, 1, 0}};
    expect_near(horner(a, -1.0), {-3, 2, 0}, kExact);
    expect_near(horner(a, 0.0), {1, 1, 0}, kExact);
    expect_near(horner(a, 1.0), {1, 0, 0}, kExact);
}

TEST(PowerBasis, Exercise114MatricesForDegreesOneTwoThree) {
    // [B_{0,n} .. B_{n,n}] = [1 u .. u^n] M, column j holding the power coefficients of B_{j,n}:
    // n = 1: B_0 = 1 - u, B_1 = u.
    const std::vector<std::vector<double>> m1 = {{1, 0}, {-1, 1}};
    // n = 2: B_0 = 1 - 2u + u^2, B_1 = 2u - 2u^2, B_2 = u^2.
    const std::vector<std::vector<double>> m2 = {{1, 0, 0}, {-2, 2, 0}, {1, -2, 1}};
    // n = 3: B_0 = 1 - 3u + 3u^2 - u^3, B_1 = 3u - 6u^2 + 3u^3, B_2 = 3u^2 - 3u^3, B_3 = u^3
    // (the transpose of 003's "Matrix Notation" slide, whose first row has a sign typo: -3 for +3).
    const std::vector<std::vector<double>> m3 = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
    EXPECT_EQ(bezier_to_power_matrix(1), m1);
    EXPECT_EQ(bezier_to_power_matrix(2), m2);
    EXPECT_EQ(bezier_to_power_matrix(3), m3);
    EXPECT_EQ(bezier_to_power_matrix(0), (std::vector<std::vector<double>>{{1}}));
}

TEST(PowerBasis, MatrixReproducesTheBernsteinBasisOnRandomInput) {
    RandomInput random(11);
    for (int trial = 0; trial < 1000; ++trial) {
        const int n = random.integer(0, 10);
        const double u = random.parameter();
        const auto m = bezier_to_power_matrix(n);
        const auto basis = all_bernstein(n, u);
        for (int j = 0; j <= n; ++j) {
            std::vector<double> column;
            for (int i = 0; i <= n; ++i) column.push_back(m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
            EXPECT_NEAR(horner(column, u), basis[static_cast<std::size_t>(j)], 1e-11);
        }
    }
}

TEST(PowerBasis, Exercise112CubicInPowerForm) {
    // P = (0,6), (3,6), (6,3), (6,0): a = M P = (0,6), (9,0), (0,-9), (-3,3) — worked by hand from M for n = 3:
    // a_1 = -3 P0 + 3 P1, a_2 = 3 P0 - 6 P1 + 3 P2, a_3 = -P0 + 3 P1 - 3 P2 + P3.
    const std::vector<Vec3> p = {{0, 6, 0}, {3, 6, 0}, {6, 3, 0}, {6, 0, 0}};
    const auto a = bezier_to_power(p);
    ASSERT_EQ(a.size(), 4u);
    expect_near(a[0], {0, 6, 0}, kExact);
    expect_near(a[1], {9, 0, 0}, kExact);
    expect_near(a[2], {0, -9, 0}, kExact);
    expect_near(a[3], {-3, 3, 0}, kExact);
    // C(1/3) by Horner equals Exercise 1.12's (26/9, 46/9).
    expect_near(horner(a, 1.0 / 3.0), {26.0 / 9.0, 46.0 / 9.0, 0}, kExact);
    const auto back = power_to_bezier(a);
    for (std::size_t i = 0; i < p.size(); ++i) expect_near(back[i], p[i], kExact);
}

TEST(PowerBasis, RoundTripAndSameCurveOnRandomInput) {
    RandomInput random(12);
    for (int trial = 0; trial < 1000; ++trial) {
        const auto points = random.points(static_cast<std::size_t>(random.integer(1, 9)));
        const auto coefficients = bezier_to_power(points);
        const auto back = power_to_bezier(coefficients);
        ASSERT_EQ(back.size(), points.size());
        for (std::size_t i = 0; i < points.size(); ++i) expect_near(back[i], points[i], 1e-10);
        const double u = random.parameter();
        expect_near(horner(coefficients, u), BezierCurve(points).point(u), 1e-10);
        // The other direction too: power coefficients -> Bézier -> power.
        const auto again = bezier_to_power(power_to_bezier(coefficients));
        for (std::size_t i = 0; i < points.size(); ++i) expect_near(again[i], coefficients[i], 1e-8);
    }
}

TEST(PowerBasis, PowerCoefficientsAreTheScaledDerivativesAtZero) {
    // 000 §1.2: a_i = C^(i)(0) / i!.
    const std::vector<Vec3> p = {{1, 2, 3}, {-2, 0, 1}, {4, 4, -1}, {0, 1, 2}};
    const auto a = bezier_to_power(p);
    const auto d = BezierCurve(p).derivatives(0.0, 3);
    double factorial = 1.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (i > 0) factorial *= static_cast<double>(i);
        expect_near(a[i], d[i] / factorial, 1e-13);
    }
}

TEST(Horner2, A16PowerBasisSurfaces) {
    // The hyperbolic paraboloid S(u, v) = (u, v, u v) of Eq. 1.21 with a_10 = x, a_01 = y, a_11 = z.
    const std::vector<std::vector<Vec3>> saddle{{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {0, 0, 1}}};
    expect_near(horner(saddle, 0.5, 0.25), {0.5, 0.25, 0.125}, 0.0);
    expect_near(horner(saddle, -2.0, 3.0), {-2.0, 3.0, -6.0}, 0.0);  // any finite u, v
    // Random 3 x 4 coefficients: A1.6 equals the double sum, and the Bézier surface whose rows and columns
    // are the Ex. 1.14 conversions of them.
    std::mt19937_64 rng(1806);
    std::uniform_real_distribution<double> x(-2, 2);
    std::vector<std::vector<Vec3>> a(3, std::vector<Vec3>(4));
    for (auto& row : a)
        for (Vec3& c : row) c = {x(rng), x(rng), x(rng)};
    // P = M_n^-1 a (M_m^-1)^T: convert every row (in v), then every column (in u).
    std::vector<std::vector<Vec3>> rows;
    for (const auto& row : a) rows.push_back(power_to_bezier(row));
    std::vector<std::vector<Vec3>> net(3, std::vector<Vec3>(4));
    for (std::size_t j = 0; j < 4; ++j) {
        std::vector<Vec3> column;
        for (std::size_t i = 0; i < 3; ++i) column.push_back(rows[i][j]);
        const std::vector<Vec3> converted = power_to_bezier(column);
        for (std::size_t i = 0; i < 3; ++i) net[i][j] = converted[i];
    }
    const BezierSurface bezier(net);
    for (int k = 0; k < 50; ++k) {
        const double u = (k % 7) / 6.0, v = (k % 11) / 10.0;
        Vec3 sum{};
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 4; ++j) sum += a[i][j] * (std::pow(u, static_cast<double>(i)) * std::pow(v, static_cast<double>(j)));
        expect_near(horner(a, u, v), sum, 1e-13);
        expect_near(horner(a, u, v), bezier.point(u, v), 1e-13);
    }
    EXPECT_TRUE(starts_with(error_message([] { horner(std::vector<std::vector<Vec3>>{}, 0.5, 0.5); }), "coefficients:"));
    EXPECT_TRUE(starts_with(error_message([&] { horner(std::vector<std::vector<Vec3>>{{{0, 0, 0}}, {}}, 0.5, 0.5); }),
                            "coefficients:"));
    EXPECT_TRUE(starts_with(error_message([&] { horner(saddle, 0.5, std::numeric_limits<double>::infinity()); }), "v:"));
}

TEST(PowerBasisErrors, EmptyInputNamesTheArgument) {
    EXPECT_TRUE(starts_with(error_message([] { horner(std::vector<double>{}, 0.5); }), "coefficients:"));
    EXPECT_TRUE(starts_with(error_message([] { horner(std::vector<Vec3>{}, 0.5); }), "coefficients:"));
    EXPECT_TRUE(starts_with(error_message([] { bezier_to_power({}); }), "control_points:"));
    EXPECT_TRUE(starts_with(error_message([] { power_to_bezier({}); }), "coefficients:"));
}

TEST(PowerBasisErrors, NonFiniteInputNamesTheArgument) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(starts_with(error_message([&] { horner(std::vector<double>{1.0, nan}, 0.5); }), "coefficients:"));
    EXPECT_TRUE(starts_with(error_message([&] { horner(std::vector<double>{1.0, 2.0}, inf); }), "u:"));
    EXPECT_TRUE(starts_with(error_message([&] { horner(std::vector<Vec3>{{0, 0, 0}}, nan); }), "u:"));
    EXPECT_TRUE(starts_with(error_message([&] { bezier_to_power({{0, 0, 0}, {inf, 0, 0}}); }), "control_points:"));
    EXPECT_TRUE(starts_with(error_message([&] { power_to_bezier({{0, nan, 0}}); }), "coefficients:"));
}

TEST(PowerBasisErrors, NegativeDegreeNamesN) {
    EXPECT_TRUE(starts_with(error_message([] { bezier_to_power_matrix(-1); }), "n:"));
}

}  // namespace
}  // namespace ratbez
