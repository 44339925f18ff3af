// evaluate_grid against the point-wise evaluation it batches: NurbsSurface::point, derivative and normal
// at every grid point of random rational surfaces (degrees 0..8 in each direction, so both the unrolled
// kernels for degrees 1..7 and the generic one run; clamped and unclamped knot vectors with interior
// multiplicities up to the degree; weights over a factor 25), on random grids that include knots and the
// domain's ends, with both the portable and the AVX2 + FMA kernels. Then the edge cases and bad input.

#include "ratbez/surface_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "ratbez/error.hpp"
#include "ratbez/primitives.hpp"

namespace ratbez {
namespace {

std::mt19937_64& rng() {
    static std::mt19937_64 engine(0x5eed6121d);
    return engine;
}
double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng()); }
int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng()); }

// A valid knot vector for `degree` and `count` control points: clamped or not, interior multiplicities
// 1..degree, over a random interval.
std::vector<double> random_knots(int degree, int count, bool clamped) {
    const std::size_t size = static_cast<std::size_t>(count + degree + 1);
    for (;;) {
        const double start = uniform(-2, 2), width = uniform(0.5, 4);
        std::vector<double> knots;
        if (clamped) knots.assign(static_cast<std::size_t>(degree + 1), start);
        const std::size_t interior = clamped ? size - 2 * static_cast<std::size_t>(degree + 1) : size;
        std::vector<double> values;
        while (knots.size() < (clamped ? static_cast<std::size_t>(degree + 1) : 0) + interior) {
            const double value = clamped ? uniform(start + 0.05 * width, start + 0.95 * width) : uniform(start, start + width);
            const int multiplicity = std::max(1, integer(1, std::max(1, degree)));
            for (int k = 0; k < multiplicity && knots.size() < (clamped ? static_cast<std::size_t>(degree + 1) : 0) + interior; ++k)
                knots.push_back(value);
        }
        std::sort(knots.begin(), knots.end());
        if (clamped) knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), start + width);
        try {
            validate_knot_vector(degree, knots, count);
            return knots;
        } catch (const Error&) {
            // merged runs broke a multiplicity rule, or the domain is empty: draw again
        }
    }
}

NurbsSurface random_surface(int degree_u, int degree_v, bool rational) {
    const int rows = degree_u + integer(1, 5), columns = degree_v + integer(1, 5);
    std::vector<std::vector<Vec3>> net(static_cast<std::size_t>(rows), std::vector<Vec3>(static_cast<std::size_t>(columns)));
    std::vector<std::vector<double>> weights(net.size(), std::vector<double>(static_cast<std::size_t>(columns), 1.0));
    for (auto& row : net)
        for (Vec3& p : row) p = {uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)};
    if (rational)
        for (auto& row : weights)
            for (double& w : row) w = uniform(0.2, 5);
    // Degree 0 allows a single span only (bspline_basis.hpp): one control point in that direction.
    const int u_count = degree_u == 0 ? 1 : rows, v_count = degree_v == 0 ? 1 : columns;
    net.resize(static_cast<std::size_t>(u_count));
    weights.resize(static_cast<std::size_t>(u_count));
    for (auto& row : net) row.resize(static_cast<std::size_t>(v_count));
    for (auto& row : weights) row.resize(static_cast<std::size_t>(v_count));
    auto knots_u = random_knots(degree_u, u_count, degree_u == 0 || integer(0, 1) == 0);
    auto knots_v = random_knots(degree_v, v_count, degree_v == 0 || integer(0, 1) == 0);
    if (rational) return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net), std::move(weights));
    return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net));
}

// Sorted random parameters over the domain, with the domain's ends, some knots inside it and a repeat.
std::vector<double> random_parameters(const std::vector<double>& knots, const Interval& domain, int count) {
    std::vector<double> ts;
    for (int k = 0; k < count; ++k) ts.push_back(uniform(domain.min, domain.max));
    ts.push_back(domain.min);
    ts.push_back(domain.max);
    for (double knot : knots)
        if (knot >= domain.min && knot <= domain.max && integer(0, 2) > 0) ts.push_back(knot);
    ts.push_back(ts[static_cast<std::size_t>(integer(0, static_cast<int>(ts.size()) - 1))]);
    std::sort(ts.begin(), ts.end());
    return ts;
}

// The size of the numbers the evaluation adds up: the largest Euclidean control point, and for a first
// partial that divided by the shortest non-empty span (times the degree).
double net_scale(const NurbsSurface& s) {
    double scale = 1.0;
    for (const Vec4& p : s.homogeneous_points()) scale = std::max(scale, norm(project(p)));
    return scale;
}
double derivative_scale(const NurbsSurface& s, const std::vector<double>& knots, int degree) {
    double shortest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k < knots.size(); ++k)
        if (knots[k] > knots[k - 1]) shortest = std::min(shortest, knots[k] - knots[k - 1]);
    return net_scale(s) * std::max(1, degree) / shortest;
}

class KernelsTest : public ::testing::TestWithParam<GridKernels> {
protected:
    void SetUp() override { select_grid_kernels(GetParam()); }
    void TearDown() override { select_grid_kernels(GridKernels::best); }
};

TEST_P(KernelsTest, MatchesPointwiseEvaluationOnRandomRationalSurfaces) {
    // Rounding differs (the sums run in another order, FMA in the AVX2 kernels), so agreement is to a
    // small multiple of the unit roundoff of the magnitudes involved, far below 1e-13 of them.
    constexpr double tolerance = 1e-13;
    double worst_point = 0, worst_partial = 0, worst_normal = 0;
    for (int degree_u = 0; degree_u <= 8; ++degree_u)
        for (int degree_v = 0; degree_v <= 8; ++degree_v) {
            const bool rational = (degree_u + degree_v) % 3 != 0;
            const NurbsSurface s = random_surface(degree_u, degree_v, rational);
            const auto us = random_parameters(s.knots_u(), s.domain_u(), integer(1, 6));
            const auto vs = random_parameters(s.knots_v(), s.domain_v(), integer(1, 24));
            const double point_scale = net_scale(s);
            const double u_scale = derivative_scale(s, s.knots_u(), degree_u);
            const double v_scale = derivative_scale(s, s.knots_v(), degree_v);
            const std::string where = "degrees " + std::to_string(degree_u) + ", " + std::to_string(degree_v) +
                                      (rational ? " rational" : " polynomial");

            const SurfaceGrid points = evaluate_grid(s, us, vs, GridOutput::points);
            const SurfaceGrid partials = evaluate_grid(s, us, vs, GridOutput::partials);
            // Degree 0 in a direction has no tangent plane: normal() throws there, and so does the grid.
            const bool has_normals = degree_u > 0 && degree_v > 0;
            if (!has_normals) {
                EXPECT_THROW(evaluate_grid(s, us, vs, GridOutput::normals), Error) << where;
            }
            const SurfaceGrid normals = evaluate_grid(s, us, vs, has_normals ? GridOutput::normals : GridOutput::points);
            ASSERT_EQ(points.points.size(), us.size() * vs.size()) << where;
            ASSERT_TRUE(points.du.x.empty() && points.normals.x.empty()) << where;
            ASSERT_EQ(partials.du.size(), us.size() * vs.size()) << where;
            ASSERT_EQ(normals.normals.size(), has_normals ? us.size() * vs.size() : 0) << where;
            for (std::size_t i = 0; i < us.size(); ++i)
                for (std::size_t j = 0; j < vs.size(); ++j) {
                    const double u = us[i], v = vs[j];
                    const Vec3 p = s.point(u, v);
                    const double e0 = distance(points.point(i, j), p) / point_scale;
                    const double e1 = distance(partials.point(i, j), p) / point_scale;
                    const double e2 = distance(normals.point(i, j), p) / point_scale;
                    const double eu = distance(partials.partial_u(i, j), s.derivative(u, v, 1, 0)) / u_scale;
                    const double ev = distance(partials.partial_v(i, j), s.derivative(u, v, 0, 1)) / v_scale;
                    worst_point = std::max({worst_point, e0, e1, e2});
                    worst_partial = std::max({worst_partial, eu, ev});
                    ASSERT_LE(std::max({e0, e1, e2}), tolerance) << where << " at (" << u << ", " << v << ")";
                    ASSERT_LE(std::max(eu, ev), tolerance) << where << " at (" << u << ", " << v << ")";
                    if (!has_normals) continue;
                    const Vec3 expected = s.normal(u, v);
                    const Vec3 n = normals.normal(i, j);
                    // The normal's sensitivity to rounding grows as S_u and S_v turn parallel.
                    const Vec3 su = s.derivative(u, v, 1, 0), sv = s.derivative(u, v, 0, 1);
                    const double sine = norm(cross(su, sv)) / (norm(su) * norm(sv));
                    const double en = distance(n, expected) * std::min(1.0, sine);
                    worst_normal = std::max(worst_normal, en);
                    ASSERT_LE(en, tolerance) << where << " at (" << u << ", " << v << ")";
                    ASSERT_NEAR(norm(n), 1.0, 1e-14) << where;
                }
        }
    std::cout << "[ kernels " << grid_kernels_name() << " ] largest relative difference: points " << worst_point
              << ", partials " << worst_partial << ", normals " << worst_normal << "\n";
}

TEST_P(KernelsTest, ReusedStorageGivesTheSameGrid) {
    const NurbsSurface s = random_surface(3, 3, true);
    const auto us = random_parameters(s.knots_u(), s.domain_u(), 20);
    const auto vs = random_parameters(s.knots_v(), s.domain_v(), 30);
    SurfaceGrid grid;
    evaluate_grid(s, us, vs, GridOutput::partials, grid);
    evaluate_grid(s, us, vs, GridOutput::points, grid);  // drops the partials
    EXPECT_TRUE(grid.du.x.empty());
    const SurfaceGrid fresh = evaluate_grid(s, us, vs);
    EXPECT_EQ(grid.points.x, fresh.points.x);
    EXPECT_EQ(grid.points.y, fresh.points.y);
    EXPECT_EQ(grid.points.z, fresh.points.z);
    const std::vector<double> fewer(us.begin(), us.begin() + 3);
    evaluate_grid(s, fewer, vs, GridOutput::points, grid);
    EXPECT_EQ(grid.u_count, 3u);
    EXPECT_EQ(grid.points.size(), 3 * vs.size());
}

TEST_P(KernelsTest, BlocksOfRowsAreTheWholeGridInPieces) {
    const NurbsSurface s = random_surface(3, 2, true);
    const auto us = random_parameters(s.knots_u(), s.domain_u(), 23);
    const auto vs = random_parameters(s.knots_v(), s.domain_v(), 17);
    for (GridOutput output : {GridOutput::points, GridOutput::partials, GridOutput::normals, GridOutput::second_partials}) {
        const SurfaceGrid whole = evaluate_grid(s, us, vs, output);
        for (std::size_t rows : {std::size_t{1}, std::size_t{4}, us.size(), us.size() + 5}) {
            SurfaceGrid block;
            std::size_t expected_first = 0;
            evaluate_grid_blocks(s, us, vs, output, rows, block, [&](std::size_t first, const SurfaceGrid& b) {
                EXPECT_EQ(first, expected_first);
                EXPECT_EQ(b.u_count, std::min(rows, us.size() - first));
                EXPECT_EQ(b.v_count, vs.size());
                for (std::size_t i = 0; i < b.u_count; ++i)
                    for (std::size_t j = 0; j < vs.size(); ++j) {
                        // Bit for bit: the same arithmetic on the same bases, only delivered in pieces.
                        EXPECT_EQ(b.point(i, j), whole.point(first + i, j));
                        if (output == GridOutput::partials || output == GridOutput::second_partials) {
                            EXPECT_EQ(b.partial_u(i, j), whole.partial_u(first + i, j));
                            EXPECT_EQ(b.partial_v(i, j), whole.partial_v(first + i, j));
                        }
                        if (output == GridOutput::second_partials) {
                            EXPECT_EQ(b.partial_uv(i, j), whole.partial_uv(first + i, j));
                        }
                        if (output == GridOutput::normals) {
                            EXPECT_EQ(b.normal(i, j), whole.normal(first + i, j));
                        }
                    }
                expected_first += b.u_count;
            });
            EXPECT_EQ(expected_first, us.size());
        }
    }
    int calls = 0;
    SurfaceGrid block;
    evaluate_grid_blocks(s, {}, vs, GridOutput::points, 4, block, [&](std::size_t, const SurfaceGrid& b) {
        ++calls;
        EXPECT_EQ(b.points.size(), 0u);
    });
    EXPECT_EQ(calls, 1);
    EXPECT_THROW(evaluate_grid_blocks(s, us, vs, GridOutput::points, 0, block, [](std::size_t, const SurfaceGrid&) {}),
                 Error);
}

INSTANTIATE_TEST_SUITE_P(SurfaceGrid, KernelsTest, ::testing::Values(GridKernels::portable, GridKernels::best),
                         [](const ::testing::TestParamInfo<GridKernels>& info) {
                             return info.param == GridKernels::portable ? std::string("Portable") : std::string("Best");
                         });

TEST(SurfaceGrid, SecondPartialsMatchPointwiseDerivatives) {
    // S and every partial up to order two against NurbsSurface::derivative, relative to the size of the
    // numbers involved (net scale times degree / shortest span per differentiation), to 1e-13.
    constexpr double tolerance = 1e-13;
    double worst = 0;
    for (int degree_u = 0; degree_u <= 8; ++degree_u)
        for (int degree_v = 0; degree_v <= 8; ++degree_v) {
            const bool rational = (degree_u + degree_v) % 3 != 1;
            const NurbsSurface s = random_surface(degree_u, degree_v, rational);
            const auto us = random_parameters(s.knots_u(), s.domain_u(), integer(1, 6));
            const auto vs = random_parameters(s.knots_v(), s.domain_v(), integer(1, 12));
            const double point_scale = net_scale(s);
            const double u_scale = derivative_scale(s, s.knots_u(), degree_u) / point_scale;
            const double v_scale = derivative_scale(s, s.knots_v(), degree_v) / point_scale;
            const std::string where = "degrees " + std::to_string(degree_u) + ", " + std::to_string(degree_v) +
                                      (rational ? " rational" : " polynomial");
            const SurfaceGrid g = evaluate_grid(s, us, vs, GridOutput::second_partials);
            ASSERT_EQ(g.output, GridOutput::second_partials);
            ASSERT_EQ(g.duu.size(), us.size() * vs.size()) << where;
            ASSERT_EQ(g.duv.size(), us.size() * vs.size()) << where;
            ASSERT_EQ(g.dvv.size(), us.size() * vs.size()) << where;
            ASSERT_TRUE(g.normals.x.empty()) << where;
            for (std::size_t i = 0; i < us.size(); ++i)
                for (std::size_t j = 0; j < vs.size(); ++j) {
                    const double u = us[i], v = vs[j];
                    const auto d = s.derivatives(u, v, 2);  // d[k][l] = d^{k+l} S / du^k dv^l
                    const double errors[] = {
                        distance(g.point(i, j), d[0][0]) / point_scale,
                        distance(g.partial_u(i, j), d[1][0]) / (point_scale * u_scale),
                        distance(g.partial_v(i, j), d[0][1]) / (point_scale * v_scale),
                        distance(g.partial_uu(i, j), d[2][0]) / (point_scale * u_scale * u_scale),
                        distance(g.partial_uv(i, j), d[1][1]) / (point_scale * u_scale * v_scale),
                        distance(g.partial_vv(i, j), d[0][2]) / (point_scale * v_scale * v_scale),
                    };
                    for (double e : errors) {
                        worst = std::max(worst, e);
                        ASSERT_LE(e, tolerance) << where << " at (" << u << ", " << v << ")";
                    }
                }
        }
    std::cout << "[ second partials ] largest relative difference " << worst << "\n";
}

TEST(SurfaceGrid, SecondPartialsOfASphereAreExact) {
    // On the unit sphere |S| = 1 everywhere, so differentiating S . S = 1 twice gives S . S_uu + |S_u|^2 = 0,
    // S . S_vv + |S_v|^2 = 0 and S . S_uv + S_u . S_v = 0, poles included.
    const Solid ball = sphere(1.0);
    const NurbsSurface& s = ball.faces().front().surface();
    const SurfaceGrid g = evaluate_grid(s, 9, 17, GridOutput::second_partials);
    for (std::size_t k = 0; k < g.points.size(); ++k) {
        const Vec3 p = g.points[k], su = g.du[k], sv = g.dv[k];
        EXPECT_NEAR(norm(p), 1.0, 1e-14);
        EXPECT_NEAR(dot(p, g.duu[k]) + dot(su, su), 0.0, 1e-12);
        EXPECT_NEAR(dot(p, g.dvv[k]) + dot(sv, sv), 0.0, 1e-12);
        EXPECT_NEAR(dot(p, g.duv[k]) + dot(su, sv), 0.0, 1e-12);
    }
}

TEST(SurfaceGrid, KernelSelectionIsReported) {
    select_grid_kernels(GridKernels::portable);
    EXPECT_STREQ(grid_kernels_name(), "portable");
    select_grid_kernels(GridKernels::best);
    const std::string best = grid_kernels_name();
    EXPECT_TRUE(best == "portable" || best == "avx2+fma") << best;
}

TEST(SurfaceGrid, GridOnEveryKnotAndTheDomainEnds) {
    // A bicubic with interior knots of every multiplicity: the grid is exactly the distinct knots.
    const std::vector<double> knots_u{0, 0, 0, 0, 0.25, 0.5, 0.5, 0.75, 0.75, 0.75, 1, 1, 1, 1};
    const std::vector<double> knots_v{-1, -1, -1, -1, 0, 0, 2, 2, 2, 2};
    std::vector<std::vector<Vec3>> net(10, std::vector<Vec3>(6));
    std::vector<std::vector<double>> weights(10, std::vector<double>(6));
    for (std::size_t i = 0; i < net.size(); ++i)
        for (std::size_t j = 0; j < net[i].size(); ++j) {
            net[i][j] = {static_cast<double>(i), static_cast<double>(j), std::sin(static_cast<double>(i * j))};
            weights[i][j] = 1.0 + 0.5 * std::cos(static_cast<double>(i + 2 * j));
        }
    const NurbsSurface s(3, 3, knots_u, knots_v, net, weights);
    const std::vector<double> us{0, 0.25, 0.5, 0.75, 1}, vs{-1, 0, 2};
    const SurfaceGrid grid = evaluate_grid(s, us, vs, GridOutput::partials);
    for (std::size_t i = 0; i < us.size(); ++i)
        for (std::size_t j = 0; j < vs.size(); ++j) {
            EXPECT_LE(distance(grid.point(i, j), s.point(us[i], vs[j])), 1e-13);
            EXPECT_LE(distance(grid.partial_u(i, j), s.derivative(us[i], vs[j], 1, 0)), 1e-12);
            EXPECT_LE(distance(grid.partial_v(i, j), s.derivative(us[i], vs[j], 0, 1)), 1e-12);
        }
    // Corners interpolate the corner control points (clamped vectors).
    EXPECT_LE(distance(grid.point(0, 0), net[0][0]), 1e-14);
    EXPECT_LE(distance(grid.point(4, 2), net[9][5]), 1e-14);
}

TEST(SurfaceGrid, SingleRowSingleColumnAndEmptyGrids) {
    const NurbsSurface s = random_surface(2, 3, true);
    const Interval du = s.domain_u(), dv = s.domain_v();
    const std::vector<double> one_u{0.5 * (du.min + du.max)}, one_v{dv.max};
    const auto us = random_parameters(s.knots_u(), du, 7), vs = random_parameters(s.knots_v(), dv, 7);
    for (const auto& [a, b] : {std::pair{one_u, vs}, std::pair{us, one_v}, std::pair{one_u, one_v}}) {
        const SurfaceGrid grid = evaluate_grid(s, a, b, GridOutput::partials);
        ASSERT_EQ(grid.u_count, a.size());
        ASSERT_EQ(grid.v_count, b.size());
        for (std::size_t i = 0; i < a.size(); ++i)
            for (std::size_t j = 0; j < b.size(); ++j) {
                EXPECT_LE(distance(grid.point(i, j), s.point(a[i], b[j])), 1e-13);
                EXPECT_LE(distance(grid.partial_v(i, j), s.derivative(a[i], b[j], 0, 1)),
                          1e-13 * derivative_scale(s, s.knots_v(), 3));
            }
    }
    const SurfaceGrid empty = evaluate_grid(s, std::vector<double>{}, vs, GridOutput::normals);
    EXPECT_EQ(empty.u_count, 0u);
    EXPECT_EQ(empty.v_count, vs.size());
    EXPECT_EQ(empty.points.size(), 0u);
    EXPECT_EQ(empty.normals.size(), 0u);
}

TEST(SurfaceGrid, UniformGridCoversTheDomain) {
    const Solid ball = sphere(2.0, {1, -1, 0.5});
    const NurbsSurface& s = ball.faces()[0].surface();
    const SurfaceGrid grid = evaluate_grid(s, 33, 17);
    ASSERT_EQ(grid.u_count, 33u);
    ASSERT_EQ(grid.v_count, 17u);
    const auto us = uniform_parameters(s.domain_u(), 33), vs = uniform_parameters(s.domain_v(), 17);
    EXPECT_EQ(us.front(), s.domain_u().min);
    EXPECT_EQ(us.back(), s.domain_u().max);
    EXPECT_TRUE(std::is_sorted(us.begin(), us.end()));
    for (std::size_t i = 0; i < us.size(); ++i)
        for (std::size_t j = 0; j < vs.size(); ++j) {
            EXPECT_LE(distance(grid.point(i, j), s.point(us[i], vs[j])), 1e-14);
            EXPECT_NEAR(distance(grid.point(i, j), Vec3{1, -1, 0.5}), 2.0, 1e-14);
        }
}

TEST(SurfaceGrid, NormalsAtPolesAreTheLimitDirection) {
    // The sphere's parameter rectangle collapses to a point along two sides: S_u x S_v vanishes there and
    // the grid must hand those points to NurbsSurface::normal, which gives the radial direction.
    const Vec3 center{0.5, 0.25, -1};
    const Solid ball = sphere(1.5, center);
    const NurbsSurface& s = ball.faces()[0].surface();
    const SurfaceGrid grid = evaluate_grid(s, 9, 9, GridOutput::normals);
    for (std::size_t i = 0; i < grid.u_count; ++i)
        for (std::size_t j = 0; j < grid.v_count; ++j) {
            const Vec3 radial = (grid.point(i, j) - center) / 1.5;
            EXPECT_LE(distance(grid.normal(i, j), radial), 1e-12) << i << ", " << j;
        }
}

TEST(SurfaceGrid, RejectsBadParameters) {
    const NurbsSurface s = random_surface(2, 2, true);
    const Interval du = s.domain_u(), dv = s.domain_v();
    const std::vector<double> good_u{du.min, du.max}, good_v{dv.min, dv.max};
    auto message = [&](const std::vector<double>& us, const std::vector<double>& vs) -> std::string {
        try {
            evaluate_grid(s, us, vs);
        } catch (const Error& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_NE(message({du.max, du.min}, good_v).find("us: must be non-decreasing"), std::string::npos);
    EXPECT_NE(message(good_u, {dv.min - 1e-9}).find("vs: element 0"), std::string::npos);
    EXPECT_NE(message(good_u, {dv.min, dv.max + 1}).find("outside the domain"), std::string::npos);
    EXPECT_NE(message({du.min, std::nan("")}, good_v).find("us: element 1 is not a finite number"), std::string::npos);
    EXPECT_NE(message(good_u, {std::numeric_limits<double>::infinity()}).find("vs:"), std::string::npos);
    EXPECT_THROW(evaluate_grid(s, 1, 5), Error);
    EXPECT_THROW(evaluate_grid(s, 5, 0), Error);
    EXPECT_THROW(uniform_parameters(Interval{1, 1}, 4), Error);
    EXPECT_THROW(uniform_parameters(Interval{0, 1}, 1), Error);
}

}  // namespace
}  // namespace ratbez
