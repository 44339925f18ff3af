#pragma once
// Staggered rows: the second layout of a surface face's mesh beside the tensor grid (tessellate_plan.hpp),
// for a face closed on itself along u (its two u sides are one seam: spheres, tori, cylinders, cones, full
// revolutions). The face is cut by rows of constant v, each with samples of its own along u, and every
// strip between two consecutive rows is zipped into triangles (strip_zipper.hpp).
//
// Why: a tensor grid gives every row the same u lines, so where a row's circle shrinks (towards a pole, over
// the top of a torus) it keeps its samples and pays with its row spacing; and its cells are two right
// triangles. Rows of one count staggered by half a sample make near-equilateral triangles instead (in the
// metric of the second fundamental form), which for the same error cover 1.3 times the area of half a square
// cell. Where two consecutive rows differ in count their samples drift against each other, and somewhere in
// the strip a triangle is a right triangle again: so a count is kept over a zone of rows while it samples the
// row at most kZoneSpread times as finely as the row needs, and the strip where it changes (a transition) is
// planned as a tensor cell. The march starts at the row that needs the most samples and goes both ways (a
// zone that shrinks starts at its need); along a closed v it starts at the seam and meets where rows need the
// fewest. A staggered row lies off the seam and closes across it (row_rail): a vertex of every row on the
// seam would make a column of right triangles there, whose chord along v errs more than any staggered edge.
// Measured at 0.01 (TessellateEconomy): the sphere r = 10 in 3,156 triangles (grid: 4,284; equilateral
// triangles at the model's limit: 2,600), the torus 10 / 3 in 4,388 (5,226), the vase in 2,796 (3,508).
//
// The error model. With z = d^T H d / 2 the surface over its tangent plane in parameters (H = [L M; M N], L =
// S_uu . n, M = S_uv . n, N = S_vv . n), linear interpolation at a triangle's vertices p_i errs at its
// barycentric point lambda by sum_{i<j} lambda_i lambda_j (p_i - p_j)^T H (p_i - p_j) / 2. For the staggered
// triangle (0, 0), (h, 0), (h / 2, k) with L and N of one sign (magnitudes here) and no twist its peak is
// (N k^2 + L h^2 / 4)^2 / (8 N k^2) while L h^2 <= 4 N k^2 (inside), else L h^2 / 8 (the base's midpoint):
// h'^2 / 6 for an equilateral triangle of side h' in H's metric, against h'^2 / 4 for a square cell. The
// twist adds at most |M| h k / 8 either way. On a saddle (L and N of opposite signs, no twist) the extremes
// lie on the edges: L h^2 / 8 at the base's midpoint, (L h^2 / 4 + N k^2) / 8 at the slanted ones'. Where
// the rails drift, or a saddle is twisted, the tensor cell's bound: (|L| h^2 + |N| k^2) / 8 + |M| h k / 4.
// The offsets centre the errors of each row's two strips, computed on the rows themselves (row_offset_field); a
// check that finds the model a little optimistic somewhere (curvature that changes between its samples) plans
// the rows again with the span lowered there.
//
// Not installed, not part of the public API.

#include <cstddef>
#include <span>
#include <vector>

#include "mesh/tessellate_plan.hpp"

namespace ratbez::detail {

// A zone of rows keeps its count while that samples the row at most this many times as finely as it needs: a
// transition strip costs about a strip and a half, so zones may oversample a little (measured on the sphere,
// torus and vase at 0.01: 1.15 to 1.4 within 4% of each other, 1.4 the fewest).
inline constexpr double kZoneSpread = 1.4;

// Rows are planned for a face whose grid has at least kRowsFrom triangles (fewer rows leave the zones no room,
// and the planning costs more than it saves), and taken when they need at most kRowsGain times the grid's
// triangles: their check costs about three times the grid's, which a few triangles do not repay.
inline constexpr double kRowsFrom = 200, kRowsGain = 0.95;

// The share of a plan's rows' triangles its mesh never falls below: the budget (max_triangles) refuses only a
// count the mesh cannot fall below (tessellate_plan.hpp), and planned again after a failing check, the rows may
// come out a little leaner than before (a zone that starts elsewhere; the leanest seen: 1% below).
inline constexpr double kRowsAtLeast = 0.9;

// Whether `plan`'s face may be meshed in rows: it straddles its surface, there is no angle limit (the rows'
// check does not follow normals), and u is closed on itself without a crease.
bool rows_apply(const SurfacePlan& plan, const TessellationSettings& settings);

// A stretch of v where a check found the model optimistic: its strips are planned for `factor` times the span.
struct Tightening {
    double v0, v1, factor;
};

// The rows for error target `target` from the curvature samples: zones of staggered rows marched both ways
// from the row that needs the most samples, every crease of v a row. Empty when they cannot be planned (a
// strip height that vanishes) or need more than `max_triangles` triangles.
RowGrid plan_rows(const SurfacePlan& plan, const CurvatureSamples& c, double target, double max_triangles,
                  std::span<const Tightening> tight = {});

// The triangles of the rows' strips, each strip zipped on its two rows' own samples (a pole row is one vertex).
double row_triangles(const SurfacePlan& plan, const RowGrid& rows);

// Where row j's vertices start in the rows' vertices listed row after row (a pole row lists its two ends).
std::vector<std::size_t> row_starts(const RowGrid& rows);

// A vertex of a row's rail as the strips zip it: its u and its index in row_starts' order.
struct RailPoint {
    double u;
    std::size_t vertex;
};
// The rail of row j, left to right: a row on the seam from one end of u to the other (its first and last vertices
// are the seam's, one mesh vertex); a row off the seam closes across it, so its last vertex comes first too, at
// its u less the period. Strips between rows off the seam have no chord along the seam: a column of right
// triangles there would err more than the staggered ones beside it (its chord along v sags N k^2 / 8).
void row_rail(const RowGrid& rows, const std::vector<std::size_t>& starts, std::size_t j, double period,
              std::vector<RailPoint>& out);

// Rebuilds rows.seam_v from rows.on_seam.
void index_seam(RowGrid& rows);

// The plan's offsets for its rows: offset_field on the rows' own v (the curvature interpolated there), each row at
// the centre of the errors of its two strips.
OffsetField row_offset_field(const SurfacePlan& plan, const CurvatureSamples& c);

// The surface points of every row vertex (row_starts' order), moved along the normal by the plan's offsets
// within the offset_room their neighbours leave; the sides' (the first and last rows, the first and last
// vertex of every row) are GridPoints' business, which replaces them.
void interior_row_points(const SurfacePlan& plan, std::vector<Vec3>& out);

// refine_grid for a plan in rows: checked on the real surface with its vertices where `points` puts them
// (every strip triangulated as the mesh will be, and the polylines of its sides against their curves), then
// planned again for a slightly lower target while the model was only a little optimistic (`rescale`, a fresh
// plan), else the failing row intervals and strips bisected, until every triangle passes. given_up when it
// does not converge or the model is far off: the caller meshes the face on its tensor grid instead.
enum class RowRefinement { unchanged, changed, given_up };
RowRefinement refine_rows(SurfacePlan& plan, const CurvatureSamples& c, const TessellationSettings& settings,
                          const GridPoints& points, bool rescale);

}  // namespace ratbez::detail
