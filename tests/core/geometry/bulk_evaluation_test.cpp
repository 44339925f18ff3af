// Bulk evaluation into interleaved (x, y, z) arrays against the point-wise calls: the grid in blocks and
// scattered back for unsorted parameters, curves, (u, v) pairs; then sizes and bad parameters. (The
// Python tests cover random surfaces of many degrees through the module; this is the C++ contract.)

#include "ratbez/bulk_evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/primitives.hpp"

namespace ratbez {
namespace {

Vec3 at(const std::vector<double>& out, std::size_t k) { return {out[3 * k], out[3 * k + 1], out[3 * k + 2]}; }

void expect_near(const Vec3& a, const Vec3& b, double tolerance) {
    EXPECT_LE(distance(a, b), tolerance) << a.x << " " << a.y << " " << a.z << " vs " << b.x << " " << b.y << " " << b.z;
}

TEST(BulkEvaluation, UnsortedGridMatchesPointwiseEvaluation) {
    const NurbsSurface s = torus(2.0, 0.5).faces()[0].surface();
    const Interval du = s.domain_u(), dv = s.domain_v();
    // More rows than one block holds, in descending order, with repeats and both ends.
    std::vector<double> us, vs{dv.max, dv.min, 0.3 * dv.min + 0.7 * dv.max, dv.min};
    for (int k = 0; k < 1500; ++k) us.push_back(du.max - (du.max - du.min) * (k % 700) / 699.0);
    for (auto [order_u, order_v] : {std::pair{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 1}}) {
        std::vector<double> out(3 * us.size() * vs.size());
        evaluate_surface_grid(s, us, vs, order_u, order_v, out);
        for (std::size_t i = 0; i < us.size(); i += 37)
            for (std::size_t j = 0; j < vs.size(); ++j)
                expect_near(at(out, i * vs.size() + j), s.derivative(us[i], vs[j], order_u, order_v), 1e-13);
    }
    std::vector<double> normals(3 * us.size() * vs.size());
    evaluate_surface_normals(s, us, vs, normals);
    for (std::size_t i = 0; i < us.size(); i += 37)
        for (std::size_t j = 0; j < vs.size(); ++j) expect_near(at(normals, i * vs.size() + j), s.normal(us[i], vs[j]), 1e-14);
}

TEST(BulkEvaluation, PartialsInOnePassAreTheGridsOfEachPartial) {
    const NurbsSurface s = torus(2.0, 0.5).faces()[0].surface();
    const Interval du = s.domain_u(), dv = s.domain_v();
    // Unsorted in both directions, more rows than a block.
    std::vector<double> us, vs{dv.max, dv.min, 0.3 * dv.min + 0.7 * dv.max};
    for (int k = 0; k < 1500; ++k) us.push_back(du.max - (du.max - du.min) * (k % 700) / 699.0);
    const std::vector<std::pair<int, int>> partials{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    for (const std::size_t m : {std::size_t{3}, std::size_t{6}}) {
        std::vector<double> out(3 * m * us.size() * vs.size());
        evaluate_surface_partials(s, us, vs, m == 3 ? 1 : 2, out);
        for (std::size_t k = 0; k < m; ++k) {
            std::vector<double> single(3 * us.size() * vs.size());
            evaluate_surface_grid(s, us, vs, partials[k].first, partials[k].second, single);
            for (std::size_t i = 0; i < us.size(); i += 37)
                for (std::size_t j = 0; j < vs.size(); ++j)
                    expect_near(at(out, (i * vs.size() + j) * m + k), at(single, i * vs.size() + j), 1e-13);
        }
    }
    std::vector<double> out(9);
    EXPECT_THROW(evaluate_surface_partials(s, std::vector<double>{du.min}, std::vector<double>{dv.min}, 3, out), Error);
    EXPECT_THROW(evaluate_surface_partials(s, std::vector<double>{du.min}, std::vector<double>{dv.min}, 2, out), Error);
}

TEST(BulkEvaluation, CurvesAndPairsAreTheirPointwiseValuesExactly) {
    const NurbsCurve c = circle(2.0, {1, 2, 3}, {0, 1, 1});
    const std::vector<double> us{1.0, 0.0, 0.25, 0.6, 0.25};
    std::vector<double> out(3 * us.size());
    for (int order : {0, 1, 3}) {
        evaluate_curve(c, us, order, out);
        for (std::size_t k = 0; k < us.size(); ++k)
            EXPECT_EQ(at(out, k), order == 0 ? c.point(us[k]) : c.derivative(us[k], order));
    }
    const NurbsSurface s = sphere(1.0).faces()[0].surface();
    const std::vector<double> uv{s.domain_u().min, s.domain_v().max, 0.5, 0.5};
    evaluate_surface_at(s, uv, 0, 0, std::span<double>(out).first(6));
    EXPECT_EQ(at(out, 0), s.point(uv[0], uv[1]));
    EXPECT_EQ(at(out, 1), s.point(uv[2], uv[3]));
}

TEST(BulkEvaluation, RejectsBadParametersAndSizes) {
    const NurbsSurface s = sphere(1.0).faces()[0].surface();
    std::vector<double> out(6);
    const std::vector<double> good{s.domain_u().min, s.domain_u().max};
    try {
        evaluate_surface_grid(s, good, std::vector<double>{s.domain_v().max + 1}, 0, 0, out);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "vs");
        EXPECT_NE(std::string(e.reason()).find("element 0"), std::string::npos);
    }
    EXPECT_THROW(evaluate_surface_grid(s, good, std::vector<double>{NAN}, 0, 0, out), Error);
    EXPECT_THROW(evaluate_surface_grid(s, good, std::vector<double>{0.1, 0.2}, 0, 0, out), Error);  // out too small
    EXPECT_THROW(evaluate_surface_grid(s, good, std::vector<double>{0.1}, -1, 0, out), Error);
    EXPECT_THROW(evaluate_surface_at(s, std::vector<double>{0.1, 0.2, 0.3}, 0, 0, out), Error);  // odd count
    EXPECT_THROW(evaluate_curve(circle(1.0), std::vector<double>{1.5}, 0, std::span<double>(out).first(3)), Error);
}

}  // namespace
}  // namespace ratbez
