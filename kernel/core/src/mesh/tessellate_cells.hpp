#pragma once
// The cells of a surface face's parameter grid: how one cell becomes triangles (its sides may carry extra
// boundary samples and may be collapsed to a pole), and the check of a whole grid on the real surface,
// which bounds every cell's chordal error from above and says which grid intervals to bisect where a
// cell fails. Not installed, not part of the public API.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "analysis/point_inversion.hpp"
#include "geometry/surface_evaluator.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// An index into Mesh::vertices.
using MeshVertexId = std::uint32_t;

// A tensor grid of parameter lines over a face's domain, both ends of each direction included.
struct ParameterGrid {
    std::vector<double> u, v;
    double cells() const { return static_cast<double>(u.size() - 1) * static_cast<double>(v.size() - 1); }
};

// Rows of a face whose u direction is closed on itself (a seam), meshed as strips between consecutive
// rows (tessellate_rows.hpp): every row has samples of its own along u, so that rows can be staggered and
// their counts follow the surface. Empty for a face meshed on its tensor grid.
struct RowGrid {
    std::vector<double> v;               // the rows, ascending, both ends of the domain included
    std::vector<std::vector<double>> u;  // each row's samples along u, ascending, both ends included
    std::vector<char> staggered;         // per strip: its rows are staggered (or one is a pole), the model's
                                         // triangle; else they may drift against each other
    std::vector<char> on_seam;           // per row: it has the seam's vertex at both ends; else its samples lie
                                         // strictly inside u and it closes across the seam
    std::vector<double> seam_v;          // the rows on the seam: the lines the seam's edge is sampled at
    bool empty() const { return v.empty(); }
};

// A vertex of a cell: its parameters, its point and its mesh vertex.
struct CellVertex {
    double u = 0, v = 0;
    Vec3 point;
    MeshVertexId id = 0;
    // A pole: a degenerate side collapsed to this vertex, free in u (bottom/top) or in v (left/right).
    enum class Free : unsigned char { none, u, v } free = Free::none;
};

// A triangle of a cell, counterclockwise in (u, v).
using CellTriangle = std::array<const CellVertex*, 3>;

// Triangulates one cell given its four side chains (each including both of its corners, in
// counterclockwise-compatible direction: bottom and top left to right, left and right bottom to top);
// consecutive vertices with one id (a collapsed side) count once. The triangles point into `lower`,
// `upper` and `center`, which the caller keeps alive while it reads them. Returns true when the cell
// has extra samples on two adjacent sides and became a fan around `center`: the caller then sets
// `center` (the cell's middle point), which the triangles already point to.
bool triangulate_cell(const SurfaceEvaluator& s, const std::vector<CellVertex>& bottom,
                      const std::vector<CellVertex>& right, const std::vector<CellVertex>& top,
                      const std::vector<CellVertex>& left, std::vector<CellVertex>& lower,
                      std::vector<CellVertex>& upper, CellVertex& center, std::vector<CellTriangle>& out);

// Triangulates the strip between two rows of samples (each left to right; a row whose vertices share one id,
// a pole, makes a fan) by the zipper, the shorter diagonal first: many samples on both rails leave the zipper
// more than a cell's two diagonals to choose from, and on a saddle the one that sags least runs along an
// asymptotic direction, into slivers. The triangles point into `lower` and `upper`.
void triangulate_strip(const std::vector<CellVertex>& bottom, const std::vector<CellVertex>& top,
                       std::vector<CellVertex>& lower, std::vector<CellVertex>& upper, std::vector<CellTriangle>& out);

// triangle_error for every triangle of a strip between the rows v = v0 and v = v1 (each vertex on one of them),
// into errors[k] for triangles[k]: the samples lie on seven lines of constant v, each evaluated in one batch
// (surface_grid.hpp) instead of point by point.
void strip_errors(const SurfaceEvaluator& s, const NurbsSurface& surface, std::span<const CellTriangle> triangles,
                  double v0, double v1, double good_enough, std::vector<double>& errors);

// The outcome of check_grid.
struct GridCheck {
    double worst_ratio = 0;                // the largest cell error over the tolerance (just above 1 for an angle failure)
    std::vector<char> refine_u, refine_v;  // per grid interval: 1 where a failing cell asks for a bisection
};

// The check of a face's grid on the real surface: every cell is triangulated as the mesh will be (its
// corners only, where the mesh puts them: corners[i * grid.v.size() + j], off the surface by their offsets;
// `collapsed_sides`, indexed like Face::sides(), make pole fans) and its distance to the surface bounded
// from above at 25 barycentric points of each triangle; with `angle_rad` > 0 the unit normals at
// its corners must also turn by at most that. Only the cells in a new row (new_u[i]) or a new column
// (new_v[j]) are checked: every other cell is the same as in the previous check, which it passed (a
// failing cell is always bisected in some direction).
GridCheck check_grid(const SurfaceEvaluator& s, const NurbsSurface& surface, const ParameterGrid& grid,
                     const std::array<bool, 4>& collapsed_sides, double tolerance, double angle_rad,
                     const std::vector<char>& new_u, const std::vector<char>& new_v, const std::vector<Vec3>& corners,
                     const std::function<void()>& poll = {});

}  // namespace ratbez::detail
