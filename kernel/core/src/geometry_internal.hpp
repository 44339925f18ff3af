#pragma once
// Private helpers of the sources that build solids (curves, primitives, profiles, revolve, extrude,
// B-rep): the circular-arc layout, knot-vector clamping, shared vertices and edges (and, from degrees.hpp,
// exact degree trigonometry). Defined in geometry_internal.cpp. Not installed, not part of the public API.

#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "degrees.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {


// The control structure of a circular arc of `sweep_deg` in (0, 360] starting at angle `start_deg`,
// on the unit circle of a frame (the NURBS-book construction A7.1, generalising the rational quarter
// circle of 000 §1.4 / Ex1.13): ceil(sweep / 90) segments of equal sweep 2θ, each a rational quadratic
// whose middle control point is the tangents' intersection, (P_0 + P_2) / (1 + cos 2θ), with weight
// cos θ; knots {0,0,0, 1/n,1/n, ..., 1,1,1}.
struct ArcLayout {
    std::vector<double> knots;
    std::vector<double> cos_coefficient;  // control point i = cos_coefficient[i] x + sin_coefficient[i] y
    std::vector<double> sin_coefficient;
    std::vector<double> weights;
};
ArcLayout arc_layout(double start_deg, double sweep_deg);

// The arc with centre frame.origin and the given radius (or the ellipse with semi-axes `radius_x`,
// `radius_y`: the affine image of the circular arc, P1.14) in the plane of frame.x_axis, frame.y_axis.
NurbsCurve arc_in_frame(const Frame& frame, double radius_x, double radius_y, double start_deg, double sweep_deg);

// True when the first and the last p + 1 knots coincide (the curve interpolates its end control points).
bool is_clamped(const NurbsCurve& curve);
// The same curve on a clamped knot vector (break points of multiplicity p, ends p + 1); unchanged if clamped.
NurbsCurve clamped(const NurbsCurve& curve);
// The same curve with only its ends clamped (knot insertion A5.1 at the domain ends up to multiplicity p,
// the knots and control points outside the domain dropped): interior knots keep their multiplicities, so
// the representation keeps the curve's continuity (clamped() makes every break point C0).
NurbsCurve clamped_ends(const NurbsCurve& curve);
// A clamped curve with its first (at_end = false) or last control point moved to `point`, keeping its weight.
NurbsCurve with_end_point(const NurbsCurve& curve, bool at_end, const Vec3& point);

// Vertex of the control points' convex combination: a shared vertex object.
inline VertexPtr make_vertex(const Vec3& p) { return std::make_shared<const Vertex>(Vertex{p}); }
inline EdgePtr make_edge(NurbsCurve curve, VertexPtr start, VertexPtr end, bool degenerate = false) {
    return std::make_shared<const Edge>(Edge{std::move(curve), std::move(start), std::move(end), degenerate});
}

std::string format_point(const Vec3& p);

// The scale rule of limits.hpp for a solid of size `size` (its box diagonal, or the length that sets it:
// a radius) whose coordinates reach `reach` in magnitude: Error naming `size_argument` for a size outside
// [min_solid_size, max_solid_coordinate] or below min_relative_solid_size * reach, `position_argument` for a
// reach beyond max_solid_coordinate. Checked before anything is built, so the message names the cause
// instead of whatever check the degenerate geometry would trip first ("collapses to a point", "inward").
void require_solid_scale(double size, double reach, std::string_view size_argument, std::string_view position_argument);
// The largest coordinate magnitude of a box.
double reach_of(const Box& box);

}  // namespace ratbez::detail
