#pragma once
// Triangulation of a simple polygon with holes by ear clipping (Eberly, "Triangulation by Ear
// Clipping", 2002): holes are joined to the outer loop by bridges (two coincident edges), then ears are
// cut one at a time. Among the valid ears the best-shaped one is cut first, which avoids the slivers a
// plain first-ear sweep produces on a finely sampled circle. Used for the planar faces of a Solid.

#include <array>
#include <cstddef>
#include <vector>

namespace ratbez::detail {

struct Point2 {
    double x = 0, y = 0;
};

// loops[0] is the outer boundary, further loops are holes; any orientation is accepted (the outer loop
// is treated as counterclockwise, holes as clockwise). Vertices are numbered by their position in the
// concatenation of the loops. Every returned triangle is counterclockwise and has positive area unless
// the input itself has no non-degenerate triangulation; every polygon edge appears in exactly one
// triangle, so the result shares its boundary exactly with whatever meshes the neighbouring faces.
// Throws ratbez::Error naming "loops" for fewer than three vertices in a loop or non-finite points.
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<std::vector<Point2>>& loops);

// Twice the signed area of a closed polygon (positive when counterclockwise).
double twice_signed_area(const std::vector<Point2>& polygon);

}  // namespace ratbez::detail
