// welded: vertices at one place made one, collapsed and cancelling triangles dropped, on meshes known by hand.
#include "ratbez/mesh_welding.hpp"

#include <gtest/gtest.h>

#include "ratbez/error.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

using test::tetrahedron;

TEST(MeshWelding, AClosedMeshWithoutSharedPlacesIsUnchanged) {
    const Mesh m = tetrahedron();
    const Mesh w = welded(m);
    EXPECT_EQ(w.vertices, m.vertices);
    EXPECT_EQ(w.triangles, m.triangles);
}

// Two faces that both took the sliver between an edge and a point beside it (tessellate.cpp): the same corners
// once each way round, on top of a closed mesh. Both go, and the vertex only they named.
TEST(MeshWelding, TrianglesWithTheSameCornersEachWayRoundCancel) {
    Mesh m = tetrahedron();
    m.vertices.push_back({0.5, 1e-9, 0});
    m.triangles.push_back({0, 1, 4});
    m.triangles.push_back({4, 0, 1});  // the same way round as the first: kept with it
    m.triangles.push_back({1, 0, 4});  // the first's reverse
    ASSERT_FALSE(m.is_closed());
    EXPECT_EQ(welded(m).triangles, m.triangles);  // kept unless asked: an STL reader keeps them
    const Mesh w = welded(m, OppositePairs::dropped);
    EXPECT_EQ(w.vertices, m.vertices);  // vertex 4 is still named by the one left
    ASSERT_EQ(w.triangles.size(), 5u);
    EXPECT_EQ(w.triangles.back(), (std::array<std::uint32_t, 3>{4, 0, 1}));
    m.triangles.push_back({4, 1, 0});  // the second's reverse: now both pairs cancel
    const Mesh both = welded(m, OppositePairs::dropped);
    EXPECT_EQ(both.vertices, tetrahedron().vertices);
    EXPECT_EQ(both.triangles, tetrahedron().triangles);
    EXPECT_TRUE(both.is_closed());
}

// An edge split by a vertex at its end's very place (what float32 rounding makes of a vertex 1e-7 away at 100):
// the split triangles that collapse go, the others name the end, and the mesh is the tetrahedron again.
TEST(MeshWelding, VerticesAtOnePlaceBecomeOneAndTrianglesThatCollapseGo) {
    Mesh m = tetrahedron();
    m.vertices.push_back(m.vertices[1]);  // vertex 4 at vertex 1's place, on edge 0-1
    m.triangles = {{0, 2, 4}, {4, 2, 1}, {0, 4, 3}, {4, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const Mesh w = welded(m);
    EXPECT_EQ(w.vertices, tetrahedron().vertices);
    EXPECT_EQ(w.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}));
    EXPECT_TRUE(w.is_closed());
}

TEST(MeshWelding, ATriangleNamingAVertexPastTheTableIsAnError) {
    Mesh m = tetrahedron();
    m.triangles.push_back({0, 1, 9});
    EXPECT_THROW(welded(m), Error);
}

}  // namespace
}  // namespace ratbez
