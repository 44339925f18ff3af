// Faces as indexed tables and back: the same faces exactly (surfaces, edge curves, sharing), and bad
// indices refused naming the face.

#include "ratbez/brep_tables.hpp"

#include <gtest/gtest.h>

#include "ratbez/curves.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/primitives.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/properties.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

TEST(BrepTables, RoundTripKeepsSurfacesCurvesAndSharing) {
    for (const Solid& solid : {torus(3.0, 1.0), cylinder(1.0, 2.0, {1, 2, 3}, {0, 1, 1}),
                               extrude(Profile({circle(2.0)}), {0, 0, 1}, 1.0, {Profile({circle(0.5)})})}) {
        const BrepTables tables = tables_of(solid.faces());
        EXPECT_EQ(tables.edges.size(), solid.edges().size());
        EXPECT_EQ(tables.vertices.size(), solid.vertices().size());
        const Solid copy(faces_of(tables), solid.construction());
        EXPECT_EQ(copy.edges().size(), solid.edges().size());
        EXPECT_EQ(copy.euler_characteristic(), solid.euler_characteristic());
        EXPECT_EQ(enclosed_volume(copy), enclosed_volume(solid));
        for (std::size_t f = 0; f < solid.faces().size(); ++f) {
            const Face &a = solid.faces()[f], &b = copy.faces()[f];
            EXPECT_EQ(a.kind(), b.kind());
            EXPECT_EQ(a.surface().homogeneous_points(), b.surface().homogeneous_points());
            EXPECT_EQ(a.surface().knots_u(), b.surface().knots_u());
        }
    }
}

TEST(BrepTables, BadIndicesNameTheFace) {
    BrepTables tables = tables_of(sphere(1.0).faces());
    tables.faces[0].sides[1].edge = 42;
    EXPECT_ERROR_NAMING(faces_of(tables), "faces[0]");
    tables = tables_of(sphere(1.0).faces());
    tables.edges[0].start = 42;
    EXPECT_ERROR_NAMING(faces_of(tables), "edges[0]");
    tables = tables_of(sphere(1.0).faces());
    tables.faces[0].sides[1].reversed = !tables.faces[0].sides[1].reversed;  // the seam side no longer chains
    EXPECT_ERROR_NAMING(faces_of(tables), "faces[0].sides");
}

}  // namespace
}  // namespace ratbez
