// mesh_topology: edge uses, orientation and vertex fans, on small meshes whose counts are known by hand.
#include "ratbez/mesh_topology.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "ratbez/error.hpp"
#include "test_support.hpp"

namespace ratbez {
namespace {

using test::tetrahedron;

TEST(MeshTopology, TetrahedronIsAClosedOrientedManifold) {
    const MeshTopology t = mesh_topology(tetrahedron());
    EXPECT_TRUE(t.closed());
    EXPECT_TRUE(t.oriented_manifold());
    EXPECT_EQ(t.border_edges + t.non_manifold_edges + t.repeated_edges + t.singular_vertices, 0u);
    EXPECT_FALSE(t.defective_edge.has_value());
}

TEST(MeshTopology, AFlippedTriangleRepeatsItsThreeEdges) {
    Mesh m = tetrahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    const MeshTopology t = mesh_topology(m);
    EXPECT_TRUE(t.closed());
    EXPECT_EQ(t.repeated_edges, 3u);
    EXPECT_FALSE(t.oriented_manifold());
    // The place an error names: the first of them by its smaller vertex, an edge of the flipped triangle.
    ASSERT_TRUE(t.defective_edge.has_value());
    const auto [a, b] = *t.defective_edge;
    EXPECT_LT(a, b);
    int on_flipped = 0;
    for (const std::uint32_t v : m.triangles[3]) on_flipped += v == a || v == b;
    EXPECT_EQ(on_flipped, 2);
}

TEST(MeshTopology, AMissingTriangleLeavesThreeBorderEdges) {
    Mesh m = tetrahedron();
    m.triangles.pop_back();
    const MeshTopology t = mesh_topology(m);
    EXPECT_EQ(t.border_edges, 3u);
    EXPECT_FALSE(t.closed());
    EXPECT_TRUE(t.oriented_manifold());  // a disc: a manifold with boundary
    // The first border edge by its smaller vertex: the missing triangle's edges are the border.
    const std::array<std::uint32_t, 3> gone = tetrahedron().triangles.back();
    ASSERT_TRUE(t.defective_edge.has_value());
    int on_gone = 0;
    for (const std::uint32_t v : gone) on_gone += v == (*t.defective_edge)[0] || v == (*t.defective_edge)[1];
    EXPECT_EQ(on_gone, 2);
}

TEST(MeshTopology, TetrahedraTouchingAtAVertexMakeItSingular) {
    // A second tetrahedron whose vertex 0 is the first one's vertex 3 (0, 0, 1).
    Mesh m = tetrahedron();
    for (const Vec3& p : {Vec3{1, 0, 1}, Vec3{0, 1, 1}, Vec3{0, 0, 2}}) m.vertices.push_back(p);
    for (auto triangle : tetrahedron().triangles) {
        for (auto& v : triangle) v = v == 0 ? 3 : v + 3;
        m.triangles.push_back(triangle);
    }
    const MeshTopology t = mesh_topology(m);
    EXPECT_TRUE(t.closed());
    EXPECT_EQ(t.repeated_edges, 0u);
    EXPECT_EQ(t.singular_vertices, 1u);
    EXPECT_FALSE(t.oriented_manifold());
}

TEST(MeshTopology, ThreeTrianglesOnOneEdgeAreNonManifold) {
    Mesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const MeshTopology t = mesh_topology(m);
    EXPECT_EQ(t.non_manifold_edges, 1u);
    EXPECT_EQ(t.repeated_edges, 1u);  // 0 -> 1 twice
    EXPECT_EQ(t.border_edges, 6u);
}

TEST(MeshTopology, DegenerateTrianglesAreCountedAndLeftOut) {
    Mesh m = tetrahedron();
    m.triangles.push_back({0, 0, 1});
    const MeshTopology t = mesh_topology(m);
    EXPECT_EQ(t.degenerate_triangles, 1u);
    EXPECT_TRUE(t.closed());
    EXPECT_FALSE(t.oriented_manifold());
}

TEST(MeshTopology, AnIndexPastTheTableIsAnErrorNamingTheMesh) {
    Mesh m = tetrahedron();
    m.triangles.push_back({0, 1, 9});
    try {
        mesh_topology(m);
        FAIL() << "expected Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.argument(), "mesh");
        EXPECT_NE(e.reason().find("vertex 9"), std::string::npos);
    }
}

// An open n x n grid of vertices, two triangles per cell.
Mesh grid(std::uint32_t n) {
    Mesh m;
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = 0; j < n; ++j) m.vertices.push_back({double(i), double(j), 0});
    for (std::uint32_t i = 0; i + 1 < n; ++i)
        for (std::uint32_t j = 0; j + 1 < n; ++j) {
            const std::uint32_t a = i * n + j, b = a + n;
            m.triangles.push_back({a, b, b + 1});
            m.triangles.push_back({a, b + 1, a + 1});
        }
    return m;
}

TEST(MeshTopology, AGridHasItsPerimeterAsBorder) {
    const MeshTopology t = mesh_topology(grid(30));
    EXPECT_EQ(t.border_edges, 4u * 29u);
    EXPECT_TRUE(t.oriented_manifold());
}

TEST(MeshTopology, ProgressIsPolledAndMayCancel) {
    const Mesh m = grid(300);  // 90,000 vertices: polls at 0 and 65,536, then the end
    std::vector<double> fractions;
    mesh_topology(m, [&](double f) { fractions.push_back(f); });
    ASSERT_EQ(fractions.size(), 3u);
    EXPECT_EQ(fractions.front(), 0.0);
    EXPECT_EQ(fractions.back(), 1.0);
    EXPECT_THROW(mesh_topology(m, [](double f) {
                     if (f > 0) throw Cancelled();
                 }),
                 Cancelled);
}

}  // namespace
}  // namespace ratbez
