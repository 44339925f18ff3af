// interpolation.hpp: A9.1 curves pass through their points to 1e-12 and equal the textbook construction
// computed independently here (Eq. 9.5 / 9.6 / 9.3 parameters, Eq. 9.8 knots, the dense collocation system
// from Cox–de Boor, Gaussian elimination); end tangents (§9.2.2), closed curves C^{p-1} at the seam, and
// A9.4 surfaces through their grids.

#include "ratbez/interpolation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nurbs_test_support.hpp"
#include "ratbez/bspline_basis.hpp"

namespace ratbez {
namespace {

using test::Rng;
constexpr double pi = std::numbers::pi;

std::vector<Vec3> random_walk(Rng& rng, int count) {
    std::vector<Vec3> points{test::random_point(rng)};
    for (int k = 1; k < count; ++k) points.push_back(points.back() + test::random_point(rng));
    return points;
}

// The book's construction, written out independently of the library's solver: parameters, knots by
// Eq. 9.8, the dense (n+1) x (n+1) matrix N_{j,p}(t_k) by Cox–de Boor (bspline_basis), Gaussian elimination.
std::vector<Vec3> textbook_a91(const std::vector<Vec3>& q, int p, double exponent, std::vector<double>& knots) {
    const std::size_t n1 = q.size();
    std::vector<double> t(n1, 0.0);
    double total = 0;
    for (std::size_t k = 1; k < n1; ++k) total += std::pow(distance(q[k], q[k - 1]), exponent);
    for (std::size_t k = 1; k < n1; ++k) t[k] = t[k - 1] + std::pow(distance(q[k], q[k - 1]), exponent) / total;
    t.back() = 1;
    knots.assign(static_cast<std::size_t>(p + 1), 0.0);
    for (std::size_t j = 1; j + p < n1; ++j) {
        double sum = 0;
        for (std::size_t i = j; i < j + static_cast<std::size_t>(p); ++i) sum += t[i];
        knots.push_back(sum / p);
    }
    knots.insert(knots.end(), static_cast<std::size_t>(p + 1), 1.0);
    std::vector<std::vector<double>> a(n1, std::vector<double>(n1));
    for (std::size_t k = 0; k < n1; ++k)
        for (std::size_t j = 0; j < n1; ++j) a[k][j] = bspline_basis(static_cast<int>(j), p, knots, t[k]);
    std::vector<Vec3> x = q;
    for (std::size_t c = 0; c < n1; ++c) {
        std::size_t pivot = c;
        for (std::size_t r = c + 1; r < n1; ++r)
            if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
        std::swap(a[c], a[pivot]);
        std::swap(x[c], x[pivot]);
        for (std::size_t r = c + 1; r < n1; ++r) {
            const double f = a[r][c] / a[c][c];
            for (std::size_t j = c; j < n1; ++j) a[r][j] -= f * a[c][j];
            x[r] -= f * x[c];
        }
    }
    for (std::size_t c = n1; c-- > 0;) {
        for (std::size_t j = c + 1; j < n1; ++j) x[c] -= a[c][j] * x[j];
        x[c] = x[c] / a[c][c];
    }
    return x;
}

TEST(Interpolate, PassesThroughItsPointsAndEqualsTheTextbookA91) {
    Rng rng(2601);
    const std::pair<Parameterization, double> kinds[] = {
        {Parameterization::chord, 1.0}, {Parameterization::centripetal, 0.5}, {Parameterization::uniform, 0.0}};
    for (int trial = 0; trial < 60; ++trial) {
        const int degree = test::uniform_int(rng, 1, 5);
        const auto [kind, exponent] = kinds[trial % 3];
        const std::vector<Vec3> q = random_walk(rng, test::uniform_int(rng, degree + 1, 30));
        const NurbsCurve c = interpolate(q, degree, kind);
        EXPECT_EQ(c.degree(), degree);
        EXPECT_FALSE(c.is_rational());
        const std::vector<double> t = interpolation_parameters(q, kind);
        double size = 0;
        for (const Vec3& p : q) size = std::max(size, norm(p));
        for (std::size_t k = 0; k < q.size(); ++k) ASSERT_LE(distance(c.point(t[k]), q[k]), 1e-12 * size) << trial;
        std::vector<double> knots;
        const std::vector<Vec3> expected = textbook_a91(q, degree, exponent, knots);
        ASSERT_EQ(c.knots().size(), knots.size());
        for (std::size_t i = 0; i < knots.size(); ++i) EXPECT_NEAR(c.knots()[i], knots[i], 1e-15);
        const std::vector<Vec3> control = c.points();
        ASSERT_EQ(control.size(), expected.size());
        for (std::size_t i = 0; i < control.size(); ++i) EXPECT_LE(distance(control[i], expected[i]), 1e-12 * size) << trial;
    }
}

TEST(Interpolate, ParametersFollowEquations93To96) {
    const std::vector<Vec3> q{{0, 0, 0}, {1, 0, 0}, {1, 4, 0}, {1, 4, 4}};  // chords 1, 4, 4
    const std::vector<double> chord = interpolation_parameters(q, Parameterization::chord);
    EXPECT_DOUBLE_EQ(chord[1], 1.0 / 9);
    EXPECT_DOUBLE_EQ(chord[2], 5.0 / 9);
    const std::vector<double> centripetal = interpolation_parameters(q, Parameterization::centripetal);
    EXPECT_DOUBLE_EQ(centripetal[1], 1.0 / 5);  // square roots 1, 2, 2
    EXPECT_DOUBLE_EQ(centripetal[2], 3.0 / 5);
    const std::vector<double> uniform = interpolation_parameters(q, Parameterization::uniform);
    EXPECT_DOUBLE_EQ(uniform[1], 1.0 / 3);
    EXPECT_DOUBLE_EQ(uniform[3], 1.0);
    EXPECT_EQ(parse_parameterization("centripetal"), Parameterization::centripetal);
    EXPECT_ERROR_NAMING(parse_parameterization("arc"), "parameterization");
}

TEST(Interpolate, ReproducesAPolynomialCurveOfItsDegree) {
    // Points of a cubic sampled at its own uniform parameters, interpolated with uniform parameters and
    // degree 3: a cubic is in the spline space, so the interpolant is that cubic.
    auto cubic = [](double t) { return Vec3{t, 2 * t * t - t, t * t * t - 0.5 * t}; };
    std::vector<Vec3> q;
    for (int k = 0; k <= 9; ++k) q.push_back(cubic(k / 9.0));
    const NurbsCurve c = interpolate(q, 3, Parameterization::uniform);
    for (int k = 0; k <= 100; ++k) EXPECT_LE(distance(c.point(k / 100.0), cubic(k / 100.0)), 1e-13);
}

TEST(Interpolate, EndTangentsSetTheEndDerivatives) {
    Rng rng(2602);
    for (int trial = 0; trial < 30; ++trial) {
        const int degree = test::uniform_int(rng, 2, 5);
        const std::vector<Vec3> q = random_walk(rng, test::uniform_int(rng, std::max(2, degree - 1), 12));
        double chord = 0;
        for (std::size_t k = 1; k < q.size(); ++k) chord += distance(q[k], q[k - 1]);
        const Vec3 t0 = test::random_point(rng), t1 = test::random_point(rng);
        EndTangents tangents{t0, t1};
        if (trial % 3 == 1) tangents.end.reset();
        if (trial % 3 == 2) tangents.start.reset();
        const std::size_t conditions = q.size() + (tangents.start ? 1 : 0) + (tangents.end ? 1 : 0);
        if (conditions < static_cast<std::size_t>(degree + 1)) {
            EXPECT_ERROR_NAMING(interpolate(q, degree, Parameterization::chord, tangents), "points");
            continue;
        }
        const NurbsCurve c = interpolate(q, degree, Parameterization::chord, tangents);
        EXPECT_EQ(c.points().size(), conditions);
        const std::vector<double> t = interpolation_parameters(q);
        for (std::size_t k = 0; k < q.size(); ++k) EXPECT_LE(distance(c.point(t[k]), q[k]), 1e-12 * (1 + norm(q[k])));
        // C'(0) = d T/|T| (§9.2.2 with the total chord d as the magnitude).
        if (tangents.start) {
            EXPECT_LE(distance(c.derivative(0.0), chord * t0 / norm(t0)), 1e-10 * chord);
        }
        if (tangents.end) {
            EXPECT_LE(distance(c.derivative(1.0), chord * t1 / norm(t1)), 1e-10 * chord);
        }
    }
    // Both ends given: the knots are Eq. 9.22's (the averages of t_0..t_{p-1}, ...).
    const std::vector<Vec3> q{{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}};
    const NurbsCurve c = interpolate(q, 3, Parameterization::uniform, {Vec3{1, 0, 0}, Vec3{1, 0, 0}});
    const std::vector<double> expected{0, 0, 0, 0, 1.0 / 3, 2.0 / 3, 1, 1, 1, 1};  // (0+1/3+2/3)/3, (1/3+2/3+1)/3
    ASSERT_EQ(c.knots().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(c.knots()[i], expected[i], 1e-15);
}

TEST(Interpolate, ClosedCurvesArePeriodicThroughTheirPoints) {
    Rng rng(2603);
    for (int trial = 0; trial < 40; ++trial) {
        const int degree = test::uniform_int(rng, 1, 5);
        const int count = test::uniform_int(rng, degree + 1, 20);
        std::vector<Vec3> q;
        for (int k = 0; k < count; ++k) {
            const double a = 2 * pi * (k + test::uniform(rng, -0.3, 0.3)) / count;
            const double r = test::uniform(rng, 1, 2);
            q.push_back({r * std::cos(a), r * std::sin(a), test::uniform(rng, -0.5, 0.5)});
        }
        const auto kind = static_cast<Parameterization>(trial % 3);
        const NurbsCurve c = interpolate(q, degree, kind, {}, true);
        const std::vector<double> t = interpolation_parameters(q, kind, true);
        ASSERT_EQ(t.size(), q.size());
        for (std::size_t k = 0; k < q.size(); ++k) ASSERT_LE(distance(c.point(t[k]), q[k]), 1e-12 * 3) << trial;
        EXPECT_EQ(c.points().front(), q.front());  // closed exactly, at Q_0
        EXPECT_EQ(c.points().back(), q.front());
        // C^{p-1} across the seam: the derivatives at 0 and 1 agree up to order p - 1.
        for (int order = 1; order < degree; ++order) {
            const Vec3 d0 = c.derivative(0.0, order), d1 = c.derivative(1.0, order);
            // (High derivatives at the seam come from spans that the cut at Q_0 left short: rounding in
            // their control points is divided by the span width to the order'th power.)
            EXPECT_LE(distance(d0, d1), 1e-6 * (1 + norm(d0))) << "trial " << trial << " order " << order;
        }
    }
    // A repeated closing point is the same as none.
    const std::vector<Vec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<Vec3> repeated = square;
    repeated.push_back(square.front());
    const NurbsCurve once = interpolate(square, 3, Parameterization::chord, {}, true);
    const NurbsCurve twice = interpolate(repeated, 3, Parameterization::chord, {}, true);
    EXPECT_EQ(once.knots(), twice.knots());
    EXPECT_EQ(once.points(), twice.points());
}

TEST(Interpolate, ManyPointsSolveInTheBand) {
    // 20,000 points on a helix: the banded solve (O(n p^2)) handles them; the curve passes through all.
    std::vector<Vec3> q;
    for (int k = 0; k < 20000; ++k) q.push_back({std::cos(k * 0.01), std::sin(k * 0.01), k * 1e-3});
    const NurbsCurve c = interpolate(q, 3, Parameterization::centripetal);
    const std::vector<double> t = interpolation_parameters(q, Parameterization::centripetal);
    for (std::size_t k = 0; k < q.size(); k += 997) EXPECT_LE(distance(c.point(t[k]), q[k]), 1e-12 * 20);
}

TEST(Interpolate, ErrorsNameTheArgument) {
    const std::vector<Vec3> q{{0, 0, 0}, {1, 0, 0}, {2, 1, 0}};
    EXPECT_ERROR_NAMING(interpolate(q, 3), "points");                        // 3 points for degree 3
    EXPECT_ERROR_NAMING(interpolate(q, 0), "degree");
    EXPECT_ERROR_NAMING(interpolate(q, 26), "degree");
    EXPECT_ERROR_NAMING(interpolate({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}, 1), "points");  // coincident
    EXPECT_ERROR_NAMING(interpolate({{0, 0, 0}}, 1), "points");
    EXPECT_ERROR_NAMING(interpolate({{0, 0, 0}, {NAN, 0, 0}}, 1), "points");
    EXPECT_ERROR_NAMING(interpolate(q, 2, Parameterization::chord, {Vec3{}, std::nullopt}), "tangents");
    EXPECT_ERROR_NAMING(interpolate(q, 2, Parameterization::chord, {Vec3{1, 0, 0}, std::nullopt}, true), "tangents");
    EXPECT_ERROR_NAMING(interpolate(q, 1, Parameterization::chord, {Vec3{1, 0, 0}, std::nullopt}), "tangents");
    EXPECT_ERROR_NAMING(interpolate(q, 3, Parameterization::chord, {}, true), "points");  // 3 points, closed cubic
    EXPECT_NO_THROW(interpolate(q, 2, Parameterization::chord, {}, true));
}

TEST(InterpolateSurface, PassesThroughItsGrid) {
    Rng rng(2604);
    for (int trial = 0; trial < 20; ++trial) {
        const int p = test::uniform_int(rng, 1, 4), q = test::uniform_int(rng, 1, 4);
        const int rows = test::uniform_int(rng, p + 1, 9), columns = test::uniform_int(rng, q + 1, 9);
        std::vector<std::vector<Vec3>> grid(static_cast<std::size_t>(rows));
        for (int i = 0; i < rows; ++i)
            for (int j = 0; j < columns; ++j)
                grid[static_cast<std::size_t>(i)].push_back(
                    {i + test::uniform(rng, -0.3, 0.3), j + test::uniform(rng, -0.3, 0.3), test::uniform(rng, -1, 1)});
        const NurbsSurface s = interpolate_surface(grid, p, q);
        EXPECT_EQ(s.degree_u(), p);
        EXPECT_EQ(s.degree_v(), q);
        // The parameters: the averaged chord parameters of the columns (u) and rows (v), which the curve
        // parameters of one column or row need not be; find them by matching the knots' construction.
        std::vector<double> u(static_cast<std::size_t>(rows), 0.0), v(static_cast<std::size_t>(columns), 0.0);
        for (int j = 0; j < columns; ++j) {
            std::vector<Vec3> column;
            for (int i = 0; i < rows; ++i) column.push_back(grid[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
            const std::vector<double> t = interpolation_parameters(column);
            for (int i = 0; i < rows; ++i) u[static_cast<std::size_t>(i)] += t[static_cast<std::size_t>(i)] / columns;
        }
        for (int i = 0; i < rows; ++i) {
            const std::vector<double> t = interpolation_parameters(grid[static_cast<std::size_t>(i)]);
            for (int j = 0; j < columns; ++j) v[static_cast<std::size_t>(j)] += t[static_cast<std::size_t>(j)] / rows;
        }
        u.back() = v.back() = 1.0;
        for (int i = 0; i < rows; ++i)
            for (int j = 0; j < columns; ++j)
                ASSERT_LE(distance(s.point(u[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(j)]),
                                   grid[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]),
                          1e-11)
                    << trial << " " << i << " " << j;
    }
}

TEST(InterpolateSurface, ErrorsNameTheArgument) {
    std::vector<std::vector<Vec3>> grid(4, std::vector<Vec3>(4));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) grid[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = {double(i), double(j), 0};
    EXPECT_NO_THROW(interpolate_surface(grid));
    EXPECT_ERROR_NAMING(interpolate_surface(grid, 4, 3), "grid");
    EXPECT_ERROR_NAMING(interpolate_surface(grid, 0, 3), "degree_u");
    EXPECT_ERROR_NAMING(interpolate_surface(grid, 3, 30), "degree_v");
    auto ragged = grid;
    ragged[2].pop_back();
    EXPECT_ERROR_NAMING(interpolate_surface(ragged, 2, 2), "grid");
    auto doubled = grid;
    doubled[2] = doubled[1];  // two rows the same
    EXPECT_ERROR_NAMING(interpolate_surface(doubled, 2, 2), "grid");
}

}  // namespace
}  // namespace ratbez
