#pragma once
// The distance from a point to a triangle mesh: the triangles bucketed in a uniform grid by their bounding
// boxes, a query searching boxes of doubling size around the point until the nearest triangle found lies
// within the box searched. What max_surface_to_mesh_distance (deviation.hpp) asks for every surface
// sample. Not installed, not part of the public API.

#include <array>
#include <cstdint>
#include <vector>

#include "ratbez/mesh.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The distance from p to the segment (a, b): to its closest point, the projection clamped to the segment.
double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b);

// The distance from p to the triangle (a, b, c): the closest point on a triangle by its Voronoi regions
// (Ericson, Real-Time Collision Detection, 2005, §5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleGrid {
public:
    // `mesh` must outlive the grid; its indices must be valid and it must have a triangle.
    explicit TriangleGrid(const Mesh& mesh);
    double distance(const Vec3& p) const;

private:
    std::array<int, 3> cell_of(const Vec3& p) const;
    std::size_t flat(int x, int y, int z) const {
        return static_cast<std::size_t>((x * dims_[1] + y) * dims_[2] + z);
    }
    const Mesh& mesh_;
    Vec3 lo_, hi_;
    double cell_ = 1;
    std::array<int, 3> dims_{1, 1, 1};
    std::vector<std::uint32_t> start_, order_;
};

}  // namespace ratbez::detail
