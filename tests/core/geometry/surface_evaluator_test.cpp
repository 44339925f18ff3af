// The private fast evaluator (kernel/core/src/geometry/surface_evaluator.hpp) agrees with NurbsSurface's own
// point and derivatives on rational multi-span surfaces, at knots and domain ends included.

#include "geometry/surface_evaluator.hpp"

#include <gtest/gtest.h>

#include "ratbez/primitives.hpp"

namespace ratbez::detail {
namespace {

void expect_agrees(const NurbsSurface& f) {
    const SurfaceEvaluator e(f);
    const Interval du = f.domain_u(), dv = f.domain_v();
    for (double a : {0.0, 0.1, 0.25, 0.33, 0.5, 0.77, 1.0})
        for (double b : {0.0, 0.2, 0.5, 0.61, 1.0}) {
            const double u = a == 1.0 ? du.max : du.min + a * (du.max - du.min);
            const double v = b == 1.0 ? dv.max : dv.min + b * (dv.max - dv.min);
            const auto d = f.derivatives(u, v, 2);
            const SurfaceJet j = e.jet(u, v);
            const double scale = 1e-12 * (1 + norm(d[2][0]) + norm(d[0][2]) + norm(d[1][1]));
            EXPECT_LT(distance(e.point(u, v), d[0][0]), 1e-14 * (1 + norm(d[0][0])));
            EXPECT_LT(distance(j.s, d[0][0]), scale);
            EXPECT_LT(distance(j.su, d[1][0]), scale);
            EXPECT_LT(distance(j.sv, d[0][1]), scale);
            EXPECT_LT(distance(j.suu, d[2][0]), scale);
            EXPECT_LT(distance(j.suv, d[1][1]), scale);
            EXPECT_LT(distance(j.svv, d[0][2]), scale);
        }
}

TEST(SurfaceEvaluator, AgreesOnSphere) { expect_agrees(sphere(1.3, {1, 2, 3}).faces()[0].surface()); }
TEST(SurfaceEvaluator, AgreesOnTorus) { expect_agrees(torus(3, 1, {0, 0, 1}, {1, 1, 1}).faces()[0].surface()); }
TEST(SurfaceEvaluator, AgreesOnConeSide) { expect_agrees(cone(2, 0.5, 3).faces()[0].surface()); }

}  // namespace
}  // namespace ratbez::detail
