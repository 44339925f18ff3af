// hermite.hpp: 003's Hermite cubic and its Bézier form. The Bézier curve must reproduce the Hermite basis
// C(t) = (2t^3 - 3t^2 + 1) P1 + (-2t^3 + 3t^2) P4 + (t^3 - 2t^2 + t) R1 + (t^3 - t^2) R4 (003) at every t,
// and the conversion must invert.

#include "ratbez/hermite.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace ratbez {
namespace {

Vec3 hermite_basis_point(const HermiteForm& h, double t) {
    const double t2 = t * t, t3 = t2 * t;
    return h.p0 * (2 * t3 - 3 * t2 + 1) + h.p1 * (-2 * t3 + 3 * t2) + h.t0 * (t3 - 2 * t2 + t) + h.t1 * (t3 - t2);
}

TEST(Hermite, BezierFormReproducesTheSeedsHermiteBasis) {
    const HermiteForm h{{1, 2, 0}, {3, -1, 2}, {4, 0, 1}, {-2, 5, 0}};
    const BezierCurve b = hermite_to_bezier(h.p0, h.t0, h.p1, h.t1);
    ASSERT_EQ(b.degree(), 3);
    EXPECT_FALSE(b.is_rational());
    // b1 = p0 + t0 / 3, b2 = p1 - t1 / 3.
    EXPECT_EQ(b.points()[1], h.p0 + h.t0 / 3.0);
    EXPECT_EQ(b.points()[2], h.p1 - h.t1 / 3.0);
    for (int k = 0; k <= 20; ++k) EXPECT_LE(distance(b.point(k / 20.0), hermite_basis_point(h, k / 20.0)), 1e-14);
    EXPECT_LE(distance(b.derivative(0.0), h.t0), 1e-14);
    EXPECT_LE(distance(b.derivative(1.0), h.t1), 1e-14);
    const HermiteForm back = bezier_to_hermite(b);
    EXPECT_LE(distance(back.t0, h.t0), 1e-14);
    EXPECT_LE(distance(back.t1, h.t1), 1e-14);
    EXPECT_EQ(back.p0, h.p0);
    EXPECT_EQ(back.p1, h.p1);
}

TEST(Hermite, LowerDegreesElevateAndBadInputIsNamed) {
    // A straight segment: the Hermite tangents are the chord (C' = P1 - P0 for a line on [0, 1]).
    const HermiteForm line = bezier_to_hermite(BezierCurve({{0, 0, 0}, {3, 0, 0}}));
    EXPECT_LE(distance(line.t0, {3, 0, 0}), 1e-14);
    EXPECT_LE(distance(line.t1, {3, 0, 0}), 1e-14);
    EXPECT_ERROR_NAMING(bezier_to_hermite(BezierCurve({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, {1, 2, 1})), "curve");
    EXPECT_ERROR_NAMING(bezier_to_hermite(BezierCurve({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 0}})), "curve");
    EXPECT_ERROR_NAMING(hermite_to_bezier({0, 0, 0}, {test::nan_value, 0, 0}, {1, 0, 0}, {1, 0, 0}), "t0");
}

}  // namespace
}  // namespace ratbez
