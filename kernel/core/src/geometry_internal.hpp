#pragma once
// Private helpers shared by the primitive, revolution, extrusion, B-rep and property sources.
// Not installed, not part of the public API.

#include <algorithm>
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// cos and sin of an angle in degrees, exact (0, ±1) at multiples of 90 degrees: the quadrant is
// removed exactly before the radian conversion, so a quarter circle ends exactly on its axis.
double cos_deg(double degrees);
double sin_deg(double degrees);

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

// The halves at 1/2 of a row of Bézier coefficients (deCasteljau, A1.5 / Eq. 1.19 at u = 1/2): the
// left edge of the triangle for [0, 1/2], the right edge for [1/2, 1]. T is a double (a weight, w s) or
// a homogeneous point. `row` must not be empty.
template <class T>
std::pair<std::vector<T>, std::vector<T>> halve_bezier(std::vector<T> row) {
    const std::size_t n = row.size() - 1;
    std::pair<std::vector<T>, std::vector<T>> halves{row, row};  // entry 0 of the left, n of the right
    for (std::size_t level = 1; level <= n; ++level) {
        for (std::size_t k = 0; k + level <= n; ++k) row[k] = (row[k] + row[k + 1]) * 0.5;
        halves.first[level] = row[0];
        halves.second[n - level] = row[n - level];
    }
    return halves;
}

// The weight certificate of the adaptive integration (properties.cpp) and of the deviation seeds
// (deviation.cpp): a rational Bézier piece is halved until along each direction its weights' Bernstein
// coefficients differ by at most this factor; the weight function then stays within it over the piece
// (convex hull property), so the rational parameterisation cannot crowd the piece into a sliver.
inline constexpr double kMaxWeightSpread = 4;

// The certificate's pieces of a Bézier span: halve it (deCasteljau, A1.5) until on every piece each line
// of coefficients (one per row or column of a patch along the direction; one for a curve) has weights
// within a factor kMaxWeightSpread of each other, or `halvings_left` deep. The weight then varies by at
// most that factor over a piece (convex hull property), so the speed of the parameterisation does too,
// up to the polynomial part, and uniform parameters within a piece spread over its geometry.
// `visit(lines, a, b)` gets each piece in order: its lines and its interval [a, b] of the span's [0, 1].
// T is a weight (double) or a homogeneous point; `weight(T)` reads its weight. The pieces' own lines are
// exact halvings at any depth; their intervals a, b stop resolving beyond about 2^-52 near t = 1.
template <class T, class Weight, class Visit>
void for_each_certified_piece(const std::vector<std::vector<T>>& lines, const Weight& weight, int halvings_left,
                              const Visit& visit, double a = 0.0, double b = 1.0) {
    bool certified = true;
    for (const auto& line : lines) {
        const auto [lo, hi] = std::minmax_element(line.begin(), line.end(),
                                                  [&](const T& x, const T& y) { return weight(x) < weight(y); });
        if (weight(*hi) > kMaxWeightSpread * weight(*lo)) certified = false;
    }
    if (certified || halvings_left <= 0) return visit(lines, a, b);
    std::vector<std::vector<T>> left, right;
    for (const auto& line : lines) {
        auto halves = halve_bezier(line);
        left.push_back(std::move(halves.first));
        right.push_back(std::move(halves.second));
    }
    const double m = 0.5 * (a + b);
    for_each_certified_piece(left, weight, halvings_left - 1, visit, a, m);
    for_each_certified_piece(right, weight, halvings_left - 1, visit, m, b);
}

// The cuts in [0, 1] between the certified pieces of weight lines, both ends included.
std::vector<double> weight_cuts(const std::vector<std::vector<double>>& lines, int max_halvings);

// Gauss–Legendre nodes and weights on [0, 1] (nodes by Newton's method on P_n to machine precision).
struct GaussRule {
    std::vector<double> nodes, weights;
};
const GaussRule& gauss_legendre(int points);

// The distinct knot values inside the domain [u_p, u_{m-p}]: the break points of the non-empty spans.
std::vector<double> breakpoints(int degree, const std::vector<double>& knots);

// Axis-aligned box of Euclidean control points.
struct Box {
    Vec3 min{1e300, 1e300, 1e300}, max{-1e300, -1e300, -1e300};
    void add(const Vec3& p);
    void add(const Box& b);
    bool empty() const { return min.x > max.x; }
    double diagonal() const { return empty() ? 0.0 : norm(max - min); }
};
Box control_box(const NurbsCurve& curve);
Box control_box(const NurbsSurface& surface);

// True when the first and the last p + 1 knots coincide (the curve interpolates its end control points).
bool is_clamped(const NurbsCurve& curve);
// The same curve on a clamped knot vector (break points of multiplicity p, ends p + 1); unchanged if clamped.
NurbsCurve clamped(const NurbsCurve& curve);
// A clamped curve with its first (at_end = false) or last control point moved to `point`, keeping its weight.
NurbsCurve with_end_point(const NurbsCurve& curve, bool at_end, const Vec3& point);

// (1/2) ∮ (x dy - y dx) of a curve in a plane frame (x = (C - origin)·x_axis, y = (C - origin)·y_axis):
// the signed area contribution of one loop piece (Green's theorem), to within `absolute_tolerance`.
// Defined in properties.cpp with the adaptive cubature of the measurements (weight certificate, then
// refinement), so extreme rational weights cannot hide part of the curve from the rule. Throws Error
// naming `argument` if a hostile curve exhausts the cell budget.
double green_area(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                  double absolute_tolerance, std::string_view argument);

// Signed enclosed volume of closed faces; `quick` uses a fixed low-order rule (enough for the sign).
double signed_volume(const std::vector<Face>& faces, bool quick);

// The result of revolving profile pieces (joined end to end, already snapped) about an axis:
// one face per piece, the joint edges (circles or arcs; degenerate on the axis), and the profile edges
// at angle 0 and at the end angle (the same edges for a full turn). joint vertices index 0..m.
struct RevolutionShell {
    std::vector<Face> faces;
    std::vector<EdgePtr> joint_edges;          // m + 1 entries (closed profile: the last is the first)
    std::vector<EdgePtr> start_profile_edges;  // m entries
    std::vector<EdgePtr> end_profile_edges;    // m entries
    std::vector<VertexPtr> start_vertices;     // m + 1 entries
    std::vector<VertexPtr> end_vertices;       // m + 1 entries
};
RevolutionShell build_revolution(const std::vector<NurbsCurve>& pieces, bool closed, const Vec3& axis_point,
                                 const Vec3& unit_axis, double angle_deg);

// Vertex of the control points' convex combination: a shared vertex object.
inline VertexPtr make_vertex(const Vec3& p) { return std::make_shared<const Vertex>(Vertex{p}); }
inline EdgePtr make_edge(NurbsCurve curve, VertexPtr start, VertexPtr end, bool degenerate = false) {
    return std::make_shared<const Edge>(Edge{std::move(curve), std::move(start), std::move(end), degenerate});
}

std::string format_point(const Vec3& p);

}  // namespace ratbez::detail
