// Affine maps of faces and solids: shared edges and vertices stay shared, mirrors keep every face
// outward (swapped surface parameters, reversed loops), volumes scale by |det L|, and the construction
// record follows the map where the kind survives it.

#include "ratbez/solid_transform.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/tessellate.hpp"
#include "solid_test_support.hpp"

namespace ratbez {
namespace {

const std::vector<double> shear{1.5, 0.4, -0.2, 1.0, 0.1, 0.8, 0.3, -2.0, -0.3, 0.2, 1.2, 0.5};
const std::vector<double> reflect{-1.0, 0.2, 0.0, 0.3, 0.0, 1.1, 0.1, 0.0, 0.2, 0.0, 0.9, -1.0};

TEST(SolidTransform, MirroredPrimitivesStayOutwardAndShared) {
    const Solid solid = cylinder(1.0, 2.0, {1, 0, 0}, {0, 1, 1});
    const AffineMap mirror = AffineMap::mirror({0, 0, 0}, {1, 2, 3});
    const Solid image = transformed(solid, mirror);
    EXPECT_EQ(image.faces().size(), solid.faces().size());
    EXPECT_EQ(image.edges().size(), solid.edges().size());
    EXPECT_EQ(image.vertices().size(), solid.vertices().size());
    EXPECT_EQ(image.euler_characteristic(), solid.euler_characteristic());
    EXPECT_NEAR(enclosed_volume(image), enclosed_volume(solid), 1e-12 * enclosed_volume(solid));
    // Inside the mirror image of the cylinder: the mirrored point is inside the original.
    const auto* record = solid.construction().get<Construction::Cylinder>();
    ASSERT_NE(record, nullptr);
    test::expect_outward(image, [&](const Vec3& p) {
        const Vec3 q = mirror(p) - record->center;  // a mirror is its own inverse
        const double h = dot(q, record->axis);
        return h > 0 && h < record->height && norm(q - record->axis * h) < record->radius;
    }, 1e-6, 50);
    const Mesh mesh = tessellate(image, 0.01);
    EXPECT_TRUE(mesh.is_closed());
    EXPECT_GT(mesh.volume(), 0);
}

TEST(SolidTransform, VolumesScaleByTheDeterminant) {
    const Solid torus_solid = torus(3.0, 1.0, {0, 0, 1}, {1, 0, 1});
    for (const auto* entries : {&shear, &reflect}) {
        const AffineMap map = AffineMap::from_matrix(*entries, 3);
        const Solid image = transformed(torus_solid, map);
        EXPECT_EQ(image.construction().kind(), "none");
        EXPECT_NEAR(enclosed_volume(image), std::abs(map.determinant()) * enclosed_volume(torus_solid),
                    1e-12 * enclosed_volume(image));
    }
}

TEST(SolidTransform, ConstructionFollowsSimilaritiesAndExtrusionsEveryMap) {
    const AffineMap similarity =
        AffineMap::rotation({1, 0, 0}, {1, 2, 0}, 40).after(AffineMap::scaling(2.5, {0, 1, 0}));
    const Solid cone_image = transformed(cone(2.0, 0.5, 3.0, {0, 0, 1}, {0, 0, 1}), similarity);
    const auto* k = cone_image.construction().get<Construction::Cone>();
    ASSERT_NE(k, nullptr);
    EXPECT_NEAR(k->radius1, 5.0, 1e-14);
    EXPECT_NEAR(k->height, 7.5, 1e-14);
    EXPECT_TRUE(test::near(k->center, similarity({0, 0, 1}), 1e-14));
    EXPECT_NEAR(*cone_image.construction().exact_volume(), enclosed_volume(cone_image), 1e-12 * 200);

    const Solid mirrored_revolution =
        transformed(revolve(Profile({line_segment({1, 0, 0}, {2, 0, 1}), line_segment({2, 0, 1}, {1, 0, 1}),
                                     line_segment({1, 0, 1}, {1, 0, 0})}),
                            {0, 0, 0}, {0, 0, 1}, 200),
                    AffineMap::mirror({0, 0, 0}, {1, 0, 0}));
    const auto* r = mirrored_revolution.construction().get<Construction::Revolution>();
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->axis_dir, (Vec3{0, 0, -1}));
    EXPECT_EQ(r->angle_deg, 200);

    const Solid prism = extrude(Profile({circle(1.0)}), {0, 0, 1}, 2.0);
    const AffineMap map = AffineMap::from_matrix(shear, 3);
    const Solid sheared = transformed(prism, map);
    const auto* e = sheared.construction().get<Construction::Extrusion>();
    ASSERT_NE(e, nullptr);
    EXPECT_NEAR(e->distance, 2.0 * norm(map.apply_linear({0, 0, 1})), 1e-14);
    EXPECT_EQ(transformed(sphere(1.0, {}), map).construction().kind(), "none");
}

}  // namespace
}  // namespace ratbez
