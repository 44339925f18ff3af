#pragma once
// The Tessellator behind tessellate.hpp, and the settings every stage of it reads. Which file does what:
//
//   stage                          file                       main entry points
//   the driver, edge sampling,     tessellate.cpp             Tessellator::run, sample_edges, mesh_surface,
//   mesh assembly                                             mesh_planar; TooFine's estimate
//   grid planning and refinement   tessellate_plan.hpp/.cpp   plan_surfaces, plan_face, choose_grid,
//                                                             refine_grid, match_lines_at_creases
//   staggered rows (closed faces)  tessellate_rows.hpp/.cpp   plan_rows, refine_rows, row_offset_field, row_rail
//   the cells: triangles, checks   tessellate_cells.hpp/.cpp  triangulate_cell, check_grid, triangulate_strip,
//                                                             strip_errors
//   a face's sides on its edges    tessellate_sides.hpp/.cpp  map_side, merge_params
//   vertex and sample offsets      tessellate_offsets.hpp/.cpp shared_offset (OffsetWish, EdgeBend)
//   triangle distances             triangle_grid.hpp/.cpp     point_segment_distance, point_triangle_distance
//   strips between two rails       strip_zipper.hpp           zip_rails
//   planar and trimmed faces       domain_triangulation.hpp   triangulate_polygon, triangulate_trimmed_domain
//                                                             (CGAL's constrained Delaunay triangulation)
//   a convex solid's mesh          convex_hull.cpp            convex_hull (ratbez/convex_hull.hpp)
//   the mesh measured afterwards   deviation.cpp              max_deviation (deviation.hpp)
//   its boundary polyline searches segment_search.hpp/.cpp     EvenOddBands, NearestSegment
//
// Not installed, not part of the public API.

#include <cstddef>
#include <map>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "ratbez/error.hpp"
#include "ratbez/progress.hpp"

namespace ratbez {
struct Edge;  // brep.hpp
}  // namespace ratbez

namespace ratbez::detail {

// A face's boundary samples whose polygon crosses itself in the face's plane or (u, v): two edges closer than
// the tolerance, each sampled only as finely as the tolerance asks (a thin ring, the band 0.0044 wide between
// two arcs of an extruder body at a tolerance of 0.11), or a neighbour's straddling offsets pushing one across
// the other. Thrown by the triangulation, which knows no edges; the tessellator names the face's edges
// (CoarseBoundary).
class CrossingLoops : public Error {
public:
    using Error::Error;
};

// Faces whose boundary is sampled too coarsely to mesh: samples running round a loop the other way (the polygon
// encloses the outside of the face: a sliver between an arc and a vertex just beside the arc's chord, as Voron's
// BMGobius idler has 12 of, where the chord the tolerance allows for the arc passes on the far side of the
// vertex), loops that cross or pass each other (CrossingLoops), or a surface face's triangles folded back beside
// its boundary (a ring narrower than the chords and straddling offsets of the wall beside it). The driver samples
// only these edges finer and on their curves (TessellationSettings::finer_edges) and tessellates again; the rest
// of the solid is meshed as before.
class CoarseBoundary : public Error {
public:
    CoarseBoundary(std::string_view argument, std::string_view reason, std::vector<const Edge*> edges)
        : Error(argument, reason), edges_(std::make_shared<const std::vector<const Edge*>>(std::move(edges))) {}
    const std::vector<const Edge*>& edges() const noexcept { return *edges_; }

private:
    std::shared_ptr<const std::vector<const Edge*>> edges_;  // shared: copying an Error cannot throw
};

// What the caller of tessellate() asked for.
struct TessellationSettings {
    double tolerance = 0;  // the distance allowed between mesh and surface, either way
    double angle_rad = 0;  // 0: no angle limit
    std::size_t max_triangles = 0;
    const Progress* progress = nullptr;  // TessellationOptions::progress, or none
    // Edges of loops that came out too coarse on an earlier attempt (CoarseBoundary): their chords keep within
    // tolerance / 2^n of the curve (n the value), and their samples lie on it (no straddling offset, which a
    // neighbour's coarse grid would make as large as its own cells ask). Every other edge is sampled to the
    // tolerance.
    std::map<const Edge*, int> finer_edges = {};

    // Reports `fraction` of the whole tessellation done (the caller's callback may throw to cancel).
    void report(double fraction) const {
        reported = fraction;
        if (progress != nullptr && *progress) (*progress)(fraction);
    }
    // Reports the last fraction again: a chance to cancel inside a long stage.
    void poll() const { report(reported); }
    mutable double reported = 0;

    // The bound every cell is checked against: a little below the tolerance, which leaves room for the error
    // between the checked samples and for writing the coordinates with few digits.
    double check_tolerance() const { return 0.98 * tolerance; }
};

}  // namespace ratbez::detail
