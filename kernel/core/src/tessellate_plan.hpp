#pragma once
// Grid planning, the first stage of tessellation: the tensor grid of parameter lines of every surface
// face, chosen from the second fundamental form and then checked and refined on the real surface.
//
// Linear interpolation of a surface over a cell of size h_u x h_v errs by about (|L| h_u^2 + |N| h_v^2) / 8
// at the midpoint of the diagonal where L = S_uu . n and N = S_vv . n have the same sign (Gauss curvature
// > 0), and by max(|L| h_u^2, |N| h_v^2) / 8 where they differ (the classic bound for piecewise-linear
// interpolation, e.g. Filip, Magedson and Markot, "Surface algorithms using bounds on derivatives", CAGD
// 1986). Lines in the first direction are equidistributed for a share of the tolerance; the second
// direction gets what that leaves at each place (so a sphere's latitude lines spread out towards the
// poles, where the longitude chords are short). Both orders and several shares are tried and the grid
// with fewest cells kept (choose_grid). Each cell is then checked on the real surface (check_grid,
// tessellate_cells.hpp) and the grid refined where a cell fails (refine_grid). Not installed, not part of
// the public API.

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"
#include "surface_evaluator.hpp"
#include "tessellate_cells.hpp"
#include "tessellate_sides.hpp"

namespace ratbez::detail {

// What the caller of tessellate() asked for.
struct TessellationSettings {
    double tolerance = 0;
    double angle_rad = 0;  // 0: no angle limit
    std::size_t max_triangles = 0;
    const Progress* progress = nullptr;  // TessellationOptions::progress, or none

    // Reports `fraction` of the whole tessellation done (the caller's callback may throw to cancel).
    void report(double fraction) const {
        reported = fraction;
        if (progress != nullptr && *progress) (*progress)(fraction);
    }
    // Reports the last fraction again: a chance to cancel inside a long stage.
    void poll() const { report(reported); }
    mutable double reported = 0;
};

// Throws Error naming "tolerance": the mesh would need about `estimate` triangles, more than `budget`.
[[noreturn]] void throw_over_budget(double estimate, std::size_t budget);

// Curvature samples per knot span: coarse first; fine when the grid turns out dense enough that the finer
// (less conservative) line densities pay for the sampling (see plan_face).
inline constexpr std::size_t kCoarseSamplesPerSpan = 8, kFineSamplesPerSpan = 16;

// The curvature data of a surface on a sample grid: `per_span` samples in every knot span, fewer when
// there are many spans (at most about 64 x per_span in all, at least two per span).
struct CurvatureSamples {
    std::vector<double> us, vs;
    std::vector<double> L, N;      // S_uu . n and S_vv . n, index i * vs.size() + j
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
                          const std::array<std::vector<double>, 2>& creases, double max_cells);

// The knot values along u (along_u) or v across which the surface has a crease (C0 in geometry, not only
// in parameter: the rational circle's double knots are G1 and need no line), with the domain's ends.
std::vector<double> crease_lines(const NurbsSurface& s, const SurfaceEvaluator& e, bool along_u);

// The plan of a surface face: its sides, grid and what the grid must respect.
struct SurfacePlan {
    const Face* face = nullptr;
    std::shared_ptr<const SurfaceEvaluator> evaluator;
    std::array<SideMap, 4> sides;  // indexed by side_slot
    ParameterGrid grid;
    std::array<int, 2> min_segments{1, 1};
    std::array<std::vector<double>, 2> creases;
};

// The fewest intervals along u and along v that enclose anything: three for a direction closed on itself
// (its two sides are one edge), two for one bounded by two collapsed sides, else one.
std::array<int, 2> minimum_segments(const std::array<SideMap, 4>& sides);

// The model plan of surface face `face` (sides, creases, and the grid choose_grid makes from the
// curvature samples, not yet checked); `curvature` receives the samples for refine_grid. Throws Error
// when the face alone needs more curvature samples or cells than settings.max_triangles allows.
SurfacePlan plan_face(const Face& face, const TessellationSettings& settings, CurvatureSamples& curvature);

// The check on the real surface (check_grid) until every cell passes: a small global rescale of the
// target when the model was a little optimistic everywhere, local bisection of the failing intervals
// otherwise. Throws Error when the grid outgrows settings.max_triangles.
void refine_grid(SurfacePlan& plan, const CurvatureSamples& curvature, const TessellationSettings& settings);

// Where a face's row along a crease edge shared with another face is thin, it takes the other face's
// lines across the edge (see tessellate_plan.cpp).
void match_lines_at_creases(std::vector<SurfacePlan>& plans, const TessellationSettings& settings);

// The whole planning stage for the faces of a solid (or a single face): plan_face for every surface face,
// the triangle estimate of them all against the budget, refine_grid for each, then match_lines_at_creases.
// Reports progress from 0 to kPlannedFraction, face by face.
inline constexpr double kPlannedFraction = 0.5;
std::vector<SurfacePlan> plan_surfaces(std::span<const Face> faces, const TessellationSettings& settings);

}  // namespace ratbez::detail
