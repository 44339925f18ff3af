// Cubature (kernel/core/src/analysis/cubature.hpp): Gauss–Legendre rules (math/gauss_legendre.hpp) exact to
// degree 2n - 1, and the adaptive engine over faces (brep/face_integrals.hpp) reaching 1e-14 where the quick
// rule of the orientation check only gets the sign right.

#include "analysis/cubature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "brep/face_integrals.hpp"
#include "math/gauss_legendre.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/primitives.hpp"

namespace ratbez::detail {
namespace {

TEST(GaussLegendre, ExactToDegreeTwoNMinusOne) {
    for (int n = 1; n <= 32; ++n) {
        const GaussRule& g = gauss_legendre(n);
        ASSERT_EQ(g.nodes.size(), static_cast<std::size_t>(n));
        for (int degree : {2 * n - 1, 2 * n}) {
            double sum = 0;
            for (std::size_t i = 0; i < g.nodes.size(); ++i) sum += g.weights[i] * std::pow(g.nodes[i], degree);
            const double exact = 1.0 / (degree + 1);  // the integral of t^k over [0, 1]
            if (degree == 2 * n - 1) {
                EXPECT_NEAR(sum, exact, 1e-14) << n << " nodes";
            } else if (n <= 6) {
                EXPECT_GT(std::abs(sum - exact), 1e-9) << n << " nodes cannot be exact on t^2n";
            }
        }
    }
    EXPECT_THROW(gauss_legendre(0), Error);
    EXPECT_THROW(gauss_legendre(33), Error);
}

TEST(FacesIntegrals, TheEngineReachesItsToleranceWhereTheQuickRuleGetsTheSign) {
    const Solid ball = sphere(2.0);
    const double exact = 4.0 / 3.0 * std::numbers::pi * 8.0;
    EXPECT_NEAR(faces_volume(ball.faces(), "solid"), exact, 1e-14 * exact);
    EXPECT_NEAR(faces_area(ball.faces(), "solid"), 16 * std::numbers::pi, 1e-14 * 16 * std::numbers::pi);
    const double quick = faces_volume(ball.faces(), "faces", /*quick=*/true);
    EXPECT_GT(quick, 0);
    EXPECT_NEAR(quick, exact, 1e-2 * exact);
    // Green's area of a circle of radius 2 about its centre, a rational curve the engine certifies.
    EXPECT_NEAR(green_area(circle(2.0), {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1e-15, "circle"), 4 * std::numbers::pi,
                1e-14 * 4 * std::numbers::pi);
}

}  // namespace
}  // namespace ratbez::detail
