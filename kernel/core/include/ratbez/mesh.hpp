#pragma once
// A triangle mesh as vertex and face tables (004 §1.3): what tessellation hands out and every exporter
// writes. Triangles are outward by the right-hand rule.

#include <array>
#include <cstdint>
#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez {

struct Mesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;

    // Every undirected edge is used by exactly two triangles, in opposite directions.
    bool is_closed() const;
    // Signed volume by the divergence theorem (positive for an outward mesh), and the surface area.
    double volume() const;  // both throw Error when a triangle names a vertex past the table
    double area() const;
};

// Whether the triangle (a, b, c) has no shape: its height below 1e-9 of its longest side, its corners on one line
// to rounding. The tessellator flips such triangles away where it can, and the export's rounding has nothing of
// theirs to keep.
bool is_flat_triangle(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace ratbez
