#include "ratbez/mesh.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace ratbez {
namespace {

using test::tetrahedron;

TEST(Mesh, TetrahedronIsClosedWithExactVolumeAndArea) {
    const Mesh m = tetrahedron();
    EXPECT_TRUE(m.is_closed());
    EXPECT_DOUBLE_EQ(m.volume(), 1.0 / 6.0);
    EXPECT_NEAR(m.area(), 1.5 + std::sqrt(3.0) / 2.0, 1e-15);
}

TEST(Mesh, FlippedTriangleBreaksClosure) {
    Mesh m = tetrahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    EXPECT_FALSE(m.is_closed());
}

TEST(Mesh, MissingTriangleBreaksClosure) {
    Mesh m = tetrahedron();
    m.triangles.pop_back();
    EXPECT_FALSE(m.is_closed());
}

TEST(Mesh, ReversedMeshHasNegativeVolume) {
    Mesh m = tetrahedron();
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    EXPECT_TRUE(m.is_closed());
    EXPECT_DOUBLE_EQ(m.volume(), -1.0 / 6.0);
}

}  // namespace
}  // namespace ratbez
