#pragma once
// Triangulations of plane regions bounded by loops: a constrained Delaunay triangulation with exact
// predicates (CGAL's Constrained_Delaunay_triangulation_2) of the loops' points, the region being the
// triangles nested an odd number of loops deep. Two uses:
//  - the polygon of a planar face (its loops' samples in the plane's frame), as it is: a plane needs no
//    interior points;
//  - the (u, v) region of a trimmed face, refined with interior points until every triangle is within the
//    tolerance of the surface (Delaunay refinement driven by the 3D chord error: where Chew and Ruppert insert
//    circumcentres for shape, this inserts the point where the error is largest).
// The loops' points are the shared edges' samples, used as they are: no point is ever added on a loop
// (except along a pole, whose points are all one mesh vertex), so a face meets its neighbours' meshes
// exactly. Defined in domain_triangulation.cpp, the core's one translation unit with CGAL; not installed,
// not part of the public API.

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "geometry/surface_evaluator.hpp"
#include "mesh/tessellate_cells.hpp"
#include "mesh/tessellator.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

struct Point2 {
    double x = 0, y = 0;
};

// loops[0] is the outer boundary, further loops are holes; any orientation is accepted. Vertices are
// numbered by their position in the concatenation of the loops, or by `ids` (one per point of the
// concatenation) where given: points of one id are one vertex, where loops touch (a hole meeting the outer
// boundary at a corner of both). Every returned triangle is counterclockwise and has positive area; every
// polygon edge appears in exactly one triangle, so the result shares its boundary exactly with whatever
// meshes the neighbouring faces. Throws ratbez::Error naming "loops" for fewer than three vertices in a
// loop, non-finite points, loops that cross, or two points in one place that are not one vertex.
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<std::vector<Point2>>& loops,
                                                            std::span<const MeshVertexId> ids = {});

// Twice the signed area of a closed polygon (positive when counterclockwise).
double twice_signed_area(const std::vector<Point2>& polygon);

// A sample of a trimmed face's boundary: its (u, v) on the face, its mesh vertex and where the mesh has it.
// Consecutive samples of a loop with the same mesh vertex run along a pole (a degenerate edge): the
// segment between them may be split (the new point is that vertex too).
struct BoundarySample {
    double u = 0, v = 0;
    MeshVertexId id = 0;
    Vec3 point;
};

// A p-curve that runs past its vertex and turns back to it within the file's tolerance (a Creo touch screen's
// corner blend: 4.7e-7 past in u, 5e-6 in space against a vertex tolerance of 1.3e-3) puts its last sample
// beyond the corner, and the loop crossed itself there at any sampling. Each sample next to a corner (loop[k]
// for k in `corners`: where a coedge's samples start) whose chord to the corner turns back on the chord before
// it (an angle over 90 degrees in (u, v)) and is under a hundredth of its length is placed on the chord from the
// sample before it to the corner instead, as far along as it lies in space. A longer step back is the edge's own
// sharp turn in (u, v) and stays. Only its (u, v) moves: its mesh vertex is the edge's, which the
// neighbouring face shares.
void unhook_corners(std::vector<BoundarySample>& loop, std::span<const std::size_t> corners);

// The triangles (counterclockwise in (u, v), so along S_u x S_v) covering the region a trimmed face's loops
// bound: loops[0] the outer loop, counterclockwise, further loops holes, clockwise; each closed (its last
// sample is followed by its first). Triangles collapsed at a pole (two corners on one mesh vertex) are left
// out. Interior vertices are made through `add_point`, given the surface point. The refinement checks every
// triangle at the points of a barycentric lattice against 0.95 settings.check_tolerance() (the distance between
// the surface at the (u, v) and the triangle at the same barycentric coordinates bounds the distance both
// ways), and with an angle limit the surface normals at its corners. Throws Error naming "solid" when the
// boundary crosses itself in (u, v) and TooFine past settings.max_triangles.
std::vector<std::array<MeshVertexId, 3>> triangulate_trimmed_domain(
    const SurfaceEvaluator& surface, std::span<const std::vector<BoundarySample>> loops,
    const TessellationSettings& settings, const std::function<MeshVertexId(const Vec3&)>& add_point);

}  // namespace ratbez::detail
