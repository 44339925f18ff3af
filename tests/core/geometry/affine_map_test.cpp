// Affine maps of curves and surfaces: exact affine invariance (P1.14 / Exercise 1.4: the image of every
// point is the map of the point, weights and knots unchanged), the named maps, and the validation of
// matrices (projective rows, singular maps).

#include "ratbez/affine_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ratbez/curves.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

using test::near;

// A shear with translation (det 1.5 * 0.8 * 1.2 - ... > 0).
const std::vector<double> shear{1.5, 0.4, -0.2, 1.0, 0.1, 0.8, 0.3, -2.0, -0.3, 0.2, 1.2, 0.5};

TEST(AffineMap, RationalCurvesAndSurfacesMapPointForPoint) {
    const AffineMap map = AffineMap::from_matrix(shear, 3);
    const NurbsCurve c = circle(2.0, {1, 2, 3}, {1, 1, 1});
    const NurbsCurve image = transformed(c, map);
    EXPECT_EQ(image.knots(), c.knots());
    EXPECT_EQ(image.weights(), c.weights());
    for (int k = 0; k <= 32; ++k) {
        const double u = k / 32.0;
        EXPECT_TRUE(near(image.point(u), map(c.point(u)), 1e-14 * 10));
        // Tangents map by the linear part (the derivative of an affine image).
        EXPECT_TRUE(near(image.derivative(u), map.apply_linear(c.derivative(u)), 1e-13 * 10));
    }
    const BezierSurface patch({{{0, 0, 0}, {1, 0, 1}}, {{0, 1, 0}, {1, 1, 2}}, {{0, 2, 1}, {2, 2, 0}}},
                              {{1, 2}, {0.5, 1}, {3, 1}});
    const BezierSurface patch_image = transformed(patch, map);
    EXPECT_EQ(patch_image.weights(), patch.weights());
    for (double u : {0.0, 0.3, 1.0})
        for (double v : {0.0, 0.7, 1.0}) EXPECT_TRUE(near(patch_image.point(u, v), map(patch.point(u, v)), 1e-14 * 10));
}

TEST(AffineMap, NamedMaps) {
    const Vec3 p{1, 2, 3};
    // A quarter turn about z through (1, 0, 0) is exact.
    const AffineMap quarter = AffineMap::rotation({1, 0, 0}, {0, 0, 5}, 90);
    EXPECT_EQ(quarter(p), (Vec3{-1, 0, 3}));
    EXPECT_TRUE(near(AffineMap::rotation({0, 0, 0}, {1, 1, 1}, 120)(p), Vec3{3, 1, 2}, 1e-15 * 4));
    EXPECT_EQ(AffineMap::translation({1, 1, 1})(p), (Vec3{2, 3, 4}));
    EXPECT_EQ(AffineMap::scaling(2, {1, 1, 1})(p), (Vec3{1, 3, 5}));
    EXPECT_EQ(AffineMap::mirror({0, 0, 1}, {0, 0, -2})(p), (Vec3{1, 2, -1}));
    EXPECT_TRUE(AffineMap::mirror({0, 0, 1}, {0, 0, -2}).reflects());
    EXPECT_TRUE(AffineMap::scaling(-1, {}).reflects());
    EXPECT_FALSE(quarter.reflects());
    EXPECT_DOUBLE_EQ(*AffineMap::scaling(-3, {}).similarity_scale(), 3);
    EXPECT_NEAR(*AffineMap::rotation({0, 0, 0}, {1, 2, 3}, 33).after(AffineMap::scaling(2, {})).similarity_scale(), 2,
                1e-15);
    EXPECT_FALSE(AffineMap::from_matrix(shear, 3).similarity_scale());
    // The image of a plane's normal is normal to the image of the plane.
    const AffineMap map = AffineMap::from_matrix(shear, 3);
    const Vec3 n{1, -2, 0.5}, in_plane{2, 1, 0};
    EXPECT_NEAR(dot(map.normal_image(n), map.apply_linear(in_plane)), 0, 1e-14);
    EXPECT_TRUE(near(map.after(AffineMap::translation({1, 0, 0}))(p), map(p + Vec3{1, 0, 0}), 1e-14));
}

TEST(AffineMap, RefusesBadMatrices) {
    std::vector<double> m4(shear);
    m4.insert(m4.end(), {0, 0, 0, 1});
    EXPECT_TRUE(near(AffineMap::from_matrix(m4, 4)({1, 1, 1}), AffineMap::from_matrix(shear, 3)({1, 1, 1}), 0));
    m4[14] = 0.1;  // projective
    EXPECT_ERROR_NAMING(AffineMap::from_matrix(m4, 4), "matrix");
    std::vector<double> singular{1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0};
    EXPECT_ERROR_NAMING(AffineMap::from_matrix(singular, 3), "matrix");
    std::vector<double> infinite(shear);
    infinite[5] = test::inf_value;
    EXPECT_ERROR_NAMING(AffineMap::from_matrix(infinite, 3), "matrix");
    EXPECT_ERROR_NAMING(AffineMap::from_matrix(shear, 4), "matrix");
    EXPECT_ERROR_NAMING(AffineMap::rotation({}, {0, 0, 0}, 10), "axis_dir");
    EXPECT_ERROR_NAMING(AffineMap::rotation({}, {0, 0, 1}, test::nan_value), "angle_deg");
    EXPECT_ERROR_NAMING(AffineMap::scaling(0, {}), "factor");
    EXPECT_ERROR_NAMING(AffineMap::mirror({}, {0, 0, 0}), "plane_normal");
    EXPECT_ERROR_NAMING(AffineMap::translation({test::nan_value, 0, 0}), "v");
}

}  // namespace
}  // namespace ratbez
