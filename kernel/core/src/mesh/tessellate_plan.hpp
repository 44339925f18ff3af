#pragma once
// Grid planning, the first stage of tessellation: the tensor grid of parameter lines of every surface
// face, chosen from the second fundamental form, and the offsets that move its vertices off the surface
// so that the mesh straddles it; then checked and refined on the real surface.
//
// Linear interpolation of a surface over a cell of size h_u x h_v errs at the cell's point (s, t) by
// e = (L s(1-s) h_u^2 + N t(1-t) h_v^2) / 2 along the normal, L = S_uu . n and N = S_vv . n (signed: negative
// where the surface bends away from the outward normal); so e spans at most (|L| h_u^2 + |N| h_v^2) / 8,
// whatever the signs (the classic bound for piecewise-linear interpolation, e.g. Filip, Magedson and
// Markot, "Surface algorithms using bounds on derivatives", CAGD 1986). Vertices moved along the normal by
// delta = -(c_u + c_v) / 2, c = k h^2 / 8, put the middle of that span on the surface: the mesh errs by at
// most half the span on either side, so the span may be twice the tolerance. The twist M = S_uv . n adds
// M s t h_u h_v, which a cell's two triangles interpolate with an error of one sign whatever the diagonal,
// up to c_twist = |M| h_u h_v / 4: it widens the span and shifts the centre by c_twist / 2. A mesh with its
// vertices on the surface (inscribed) may span only one tolerance where the curvatures agree in sign (a
// sphere: it needs twice the cells, and the bound for any inscribed mesh is 4 pi r^2 / ((3 sqrt 3 / 4) 2 r
// tol) triangles), and gains little on a saddle or a twisted face, whose inscribed errors take both signs
// already: plan_face takes whichever model needs fewer cells, and falls back to the inscribed grid when
// the check finds the straddling model far off (refine_grid).
//
// Lines in the first direction are equidistributed for a share of the span; the second direction gets what
// that leaves at each place (so a sphere's latitude lines spread out towards the poles, where the longitude
// chords are short). Both orders and several shares are tried and the grid with fewest cells kept
// (choose_grid). Each cell is then checked on the real surface with its vertices where the mesh will have
// them (check_grid, tessellate_cells.hpp) and the grid refined where a cell fails (refine_grid). Not
// installed, not part of the public API.

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "geometry/surface_evaluator.hpp"
#include "mesh/tessellate_cells.hpp"
#include "mesh/tessellate_sides.hpp"
#include "mesh/tessellator.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::detail {

// The largest offset of a vertex as a share of the target its face is checked against: below it, so that
// refining a failing cell always ends. A straddling grid's errors may span twice that.
inline constexpr double kOffsetShare = 0.95;

// Curvature samples per knot span: coarse first; fine when the grid turns out dense enough that the finer
// (less conservative) line densities pay for the sampling (see plan_face).
inline constexpr std::size_t kCoarseSamplesPerSpan = 8, kFineSamplesPerSpan = 16;

// The curvature data of a surface on a sample grid: `per_span` samples in every knot span, fewer when
// there are many spans (at most about 64 x per_span in all, at least two per span).
struct CurvatureSamples {
    std::vector<double> us, vs;
    std::vector<double> L, N, M;   // S_uu . n, S_vv . n and S_uv . n, index i * vs.size() + j
    std::vector<double> k_max;     // the larger principal curvature, |.|; 0 where the partials are parallel
    std::vector<Vec3> normals;
    std::size_t at(std::size_t i, std::size_t j) const { return i * vs.size() + j; }
};
CurvatureSamples sample_curvature(const NurbsSurface& s, std::size_t per_span);
// How many samples sample_curvature takes with `per_span`.
double curvature_sample_count(const NurbsSurface& s, std::size_t per_span);

// The economical grid for an error target `target` (and the angle limit `angle_rad`, 0 for none): at
// least min_segments[0] intervals along u and min_segments[1] along v, every piece between consecutive
// creases (creases[0] along u, creases[1] along v, both ends included) with a whole number of
// intervals. Both direction orders and several shares of the target for the first direction; the grid
// with the fewest cells wins. An empty grid when every candidate has more than `max_cells` cells.
ParameterGrid choose_grid(const CurvatureSamples& c, double target, double angle_rad, std::array<int, 2> min_segments,
                          const std::array<std::vector<double>, 2>& creases, double max_cells, bool straddle = true);

// The knot values along u (along_u) or v across which the surface has a crease (C0 in geometry, not only
// in parameter: the rational circle's double knots are G1 and need no line), with the domain's ends.
std::vector<double> crease_lines(const NurbsSurface& s, const SurfaceEvaluator& e, bool along_u);

// The spacing of the line interval containing parameter t (the larger of the two at a line).
double spacing_at(const std::vector<double>& lines, double t);

// Where x lies among the sorted values t (at least two): the interval [t[k], t[k + 1]] holding it (clamped to the
// first and the last) and x's fraction of the way through it (clamped to [0, 1]; 0 in an interval of no width).
struct IntervalPosition {
    std::size_t k;
    double f;
};
IntervalPosition locate_in(const std::vector<double>& t, double x);

// The offsets of a face's vertices along its outward normal, and the range of offsets its cells accept
// there: values on the curvature samples, bilinear in between.
struct OffsetField {
    std::vector<double> us, vs;
    std::vector<double> values;            // index i * vs.size() + j
    std::vector<double> lowest, highest;   // the range, same index
    double at(double u, double v) const { return interpolate(values, u, v); }
    double lowest_at(double u, double v) const { return interpolate(lowest, u, v); }
    double highest_at(double u, double v) const { return interpolate(highest, u, v); }

private:
    double interpolate(const std::vector<double>& field, double u, double v) const;
};

// At every curvature sample, with c = k h^2 / 8 on the grid's spacing h there: the offset -(c_u + c_v) / 2 +
// c_twist / 2 that centres the errors (0 for an inscribed face, `straddle` false), within [-max_offset,
// max_offset] and within a quarter of the radius of curvature (an offset towards the centre of curvature
// longer than the radius would fold the mesh; where the surface is that small, a profile that crawls
// through a tiny loop, other parts of it lie as close); and the range of offsets that keep the errors
// within `target` (what a vertex shared with other faces may take, tessellate_offsets.hpp). A collapsed
// side (a pole) takes the next row's values: the surface's own second derivatives vanish there with the
// collapsed parameter, its curvature does not.
OffsetField offset_field(const CurvatureSamples& c, const ParameterGrid& g, const std::array<bool, 4>& collapsed_sides,
                         double max_offset, double target, bool straddle = true);

// The errors (mesh minus surface, along the normal) of the cells at a curvature sample with the vertices
// on the surface: the lowest (<= 0) and the highest (>= 0).
struct ErrorSpan {
    double below = 0, above = 0;
};
// offset_field for any layout of cells: `span_at(i, j)` gives the errors at curvature sample (i, j).
OffsetField offset_field(const CurvatureSamples& c, const std::function<ErrorSpan(std::size_t, std::size_t)>& span_at,
                         const std::array<bool, 4>& collapsed_sides, double max_offset, double target, bool straddle);

// The plan of a surface face: its sides, grid, offsets and what the grid must respect.
struct SurfacePlan {
    const Face* face = nullptr;
    std::shared_ptr<const SurfaceEvaluator> evaluator;
    std::array<SideMap, 4> sides;  // indexed by side_slot
    ParameterGrid grid;
    RowGrid rows;  // not empty: the face is meshed in rows (tessellate_rows.hpp), `grid` is its fallback
    std::array<int, 2> min_segments{1, 1};
    std::array<std::vector<double>, 2> creases;
    bool straddle = true;  // vertices moved off the surface by `offsets`; else on it (no offsets)
    OffsetField offsets;
    double target = 0;  // the bound the cells are checked against (lowered by a global rescale)

    // The largest offset of a vertex of this face: the vertex itself errs by that much, below the target so
    // that refining a failing cell always ends.
    double max_offset() const { return kOffsetShare * target; }
    // The cells of its grid, or half the triangles of its rows: how much the face weighs against another
    // (tessellate_offsets.hpp) and whether its plan changed.
    double cells() const;
};

// Where the mesh puts the vertices of a plan's grid (index i * grid.v.size() + j): inside the face its
// surface point moved along the normal by the plan's offsets (interior_grid_points); on its sides and
// corners what the edges and vertices it shares with other faces get (the tessellator decides).
using GridPoints = std::function<void(const SurfacePlan& plan, std::vector<Vec3>& out)>;

// The surface points of `grid` moved along the normal by the plan's offset field, within the offset_room its
// nearest neighbour in the grid leaves (every grid point, the sides' too; GridPoints replaces those).
void interior_grid_points(const SurfacePlan& plan, const ParameterGrid& grid, std::vector<Vec3>& out);

// The largest move off the surface of a vertex whose nearest neighbour is `gap` away, for a face whose
// vertices may move up to `max_offset`: a quarter of the gap (which cannot turn a segment around), and
// falling off with the square of the gap below four times max_offset: where the surface crowds its points
// that close together it is smaller than the tolerance there (a profile that crawls through a tiny loop,
// weights that crowd a span into a sliver), other parts of it lie as close as the neighbours, and moving
// the vertices off it would let rows that are no neighbours cross (round trip seeds 20261372, 20264282).
double offset_room(double gap, double max_offset);

// The fewest intervals along u and along v that enclose anything: three for a direction closed on itself
// (its two sides are one edge), two for one bounded by two collapsed sides, else one.
std::array<int, 2> minimum_segments(const std::array<SideMap, 4>& sides);

// The model plan of surface face `face` (sides, creases, and the grid choose_grid makes from the
// curvature samples, not yet checked; straddling the surface where that is cheaper and `straddle` allows
// it); `curvature` receives the samples for refine_grid. Throws Error when the face alone needs more
// curvature samples or cells than settings.max_triangles allows.
SurfacePlan plan_face(const Face& face, const TessellationSettings& settings, CurvatureSamples& curvature,
                      bool straddle = true);

// The fewest triangles the mesh of a plan's grid (or of a grid of lines_u x lines_v lines on its face) can
// have: two per cell, one less for each collapsed side (a pole) a cell lies along. The zippers that close a
// row to its neighbour's extra samples, and the centres of cells split in four, only add triangles.
double triangles_at_least(const SurfacePlan& plan);
double triangles_at_least(const SurfacePlan& plan, std::size_t lines_u, std::size_t lines_v);

// False when any surface face's weights differ by more than kStraddleWeightRatio: weights far apart crowd
// a surface's geometry into slivers of its parameter domain (the round trip test's weights within
// 10^+-3), which the offsets, bilinear between curvature samples, follow poorly; their faces and the faces
// they share edges with would be moved by offsets none of the checks can trust (round trip seeds 20261512,
// 20262302: a deviation over the tolerance, a mesh that intersects itself). Such solids are inscribed in
// their surfaces, as before there were offsets.
inline constexpr double kStraddleWeightRatio = 16;
bool may_straddle(std::span<const Face> faces);

// Which of the plan's sides (indexed like Face::sides()) collapse to a point (a pole).
std::array<bool, 4> collapsed_sides(const SurfacePlan& plan);

// The plan's offsets for its current grid (offset_field).
void set_offsets(SurfacePlan& plan, const CurvatureSamples& curvature);

// The worst check of a fresh straddling plan beyond which its model is taken to be far off: the grid is
// meshed inscribed instead, rows fall back to the grid.
inline constexpr double kStraddleGiveUp = 1.5;

// Where refine_grid starts: the cells to check first (rows check_u[i], columns check_v[j]; empty: all) and
// whether it may rescale the whole grid (a fresh plan) or only bisect (a plan other faces' points rely on).
struct RefineStart {
    std::vector<char> check_u, check_v;
    bool rescale = true;
};

// The check on the real surface (check_grid, with the grid's vertices where `points` puts them) until every
// cell passes: a small global rescale of the target when the model was a little optimistic everywhere,
// local bisection of the failing intervals otherwise; the offsets follow every change of the grid (and
// every cell is checked again). True when the grid changed. Throws Error when the grid outgrows
// settings.max_triangles.
bool refine_grid(SurfacePlan& plan, const CurvatureSamples& curvature, const TessellationSettings& settings,
                 const GridPoints& points, const RefineStart& start = {});

// Where a face's row along a crease edge shared with another face is thin, it takes the other face's
// lines across the edge (see tessellate_plan.cpp).
void match_lines_at_creases(std::vector<SurfacePlan>& plans, const TessellationSettings& settings);

// The lines of a plan that meet `side` (its samples along it): the grid's lines along it, or for a plan in
// rows the first or last row's samples along u, the rows along v.
const std::vector<double>& side_lines(const SurfacePlan& plan, Side side);

// A face in rows takes into its first and last rows the lines the other faces along those edges propose there
// (an edge is sampled at the union of its faces' lines): its check then sees the rails its mesh will zip.
void take_lines_into_rows(std::vector<SurfacePlan>& plans);

// The whole planning stage for the faces of a solid (or a single face): plan_face for every surface face
// (into `plans`, which `points` may read: the offsets of a shared edge depend on the faces on both sides),
// the triangle estimate of them all against the budget, refine_grid for each, match_lines_at_creases, then
// every face checked again with the points of the final plans until none changes (the points along a
// face's sides move with its neighbours' plans). Straddling only where may_straddle allows it. Reports
// progress from 0 to kPlannedFraction, face by face.
inline constexpr double kPlannedFraction = 0.5;
void plan_surfaces(std::span<const Face> faces, const TessellationSettings& settings, const GridPoints& points,
                   std::vector<SurfacePlan>& plans);

}  // namespace ratbez::detail
