#pragma once
// The "zipper": triangulates the strip between two sampled rails that face each other, e.g. a face
// boundary sampled finer than the parameter grid next to it, by walking both sample sequences at once
// and always closing the triangle whose new diagonal costs less (the greedy contour stitching of Fuchs,
// Kedem and Uselton, "Optimal surface reconstruction from planar contours", CACM 1977; the cost here is
// supplied by the caller, e.g. the chordal deviation at the diagonal's midpoint).

#include <array>
#include <cstddef>
#include <vector>

namespace ratbez::detail {

// Rails: `lower` samples 0 .. lower_count-1 and `upper` samples 0 .. upper_count-1, both running left to
// right, the lower rail being the bottom of the strip and the upper its top; triangles then come out
// counterclockwise.
// A rail may be a single point (a pole): the strip is then a fan. Vertex numbering in the result:
// lower k -> k, upper k -> lower_count + k. diagonal_cost(i, j) is the cost of the diagonal from lower i
// to upper j; ties go to the lower rail.
template <class DiagonalCost>
std::vector<std::array<std::size_t, 3>> zip_rails(std::size_t lower_count, std::size_t upper_count,
                                                  DiagonalCost&& diagonal_cost) {
    std::vector<std::array<std::size_t, 3>> triangles;
    if (lower_count == 0 || upper_count == 0 || lower_count + upper_count < 3) return triangles;
    triangles.reserve(lower_count + upper_count - 2);
    std::size_t i = 0, j = 0;
    const std::size_t up = lower_count;  // offset of the upper rail's numbering
    while (i + 1 < lower_count || j + 1 < upper_count) {
        bool advance_lower;
        if (i + 1 >= lower_count) advance_lower = false;
        else if (j + 1 >= upper_count) advance_lower = true;
        else advance_lower = !(diagonal_cost(i, j + 1) < diagonal_cost(i + 1, j));
        if (advance_lower) {
            triangles.push_back({i, i + 1, up + j});
            ++i;
        } else {
            triangles.push_back({i, up + j + 1, up + j});
            ++j;
        }
    }
    return triangles;
}

}  // namespace ratbez::detail
