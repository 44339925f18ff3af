// Compatible knot vectors (compatible_curves.hpp): the curve never changes, the
// representation does exactly as promised (degree, multiplicities, common knots).

#include "ratbez/compatible_curves.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "nurbs_test_support.hpp"
#include "ratbez/curves.hpp"

namespace ratbez {
namespace {

using test::Rng;

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
            test::expect_same_curve(curves[k], compatible[k], 1e-11);
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
