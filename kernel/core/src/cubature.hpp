#pragma once
// Cubature: integrals over rational Bézier and NURBS pieces, what a Solid's orientation check and the
// measurements of properties.hpp share.
//  - Gauss–Legendre rules on [0, 1] (span_rule.hpp applies them straight on the knot spans of a net).
//  - The weight certificate: rational pieces halved (deCasteljau, A1.5) until their weights vary by at
//    most kMaxWeightSpread, so that no pole of a rational integrand comes near a Gauss node.
//  - The adaptive engine (QUADPACK's QAG strategy in 2D) over the faces of a closed shell: enclosed
//    volume by the divergence theorem and area, and Green's area of a curve in a plane.
// Not installed, not part of the public API.

#include <algorithm>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/progress.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// ---- rules

// Gauss–Legendre nodes and weights on [0, 1] (nodes by Newton's method on P_n to machine precision).
struct GaussRule {
    std::vector<double> nodes, weights;
};
const GaussRule& gauss_legendre(int points);

// ---- the weight certificate

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

// The weight certificate of the adaptive integration (below) and of the deviation seeds (deviation.cpp): a rational Bézier piece is halved until along each direction its weights' Bernstein
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

// ---- integrals over faces and curves

// Signed volume enclosed by closed faces (divergence theorem), to about 1e-14 of their size cubed;
// `quick` takes a fixed low-order rule instead, enough for the sign (Solid's orientation check).
// Throws Error naming `argument` when the accuracy cannot be reached within the cell budget. `progress`
// is polled (with 0) every few thousand cells, so that it can cancel (progress.hpp).
double faces_volume(const std::vector<Face>& faces, std::string_view argument, bool quick = false,
                    const Progress& progress = {});
// The area of faces, to about 1e-14 of their size squared; errors and progress as above.
double faces_area(const std::vector<Face>& faces, std::string_view argument, const Progress& progress = {});
// The area of an untrimmed surface, to about 1e-14 of its control box's diagonal squared; errors as above.
double surface_area(const NurbsSurface& surface, std::string_view argument);

// (1/2) ∮ (x dy - y dx) of a curve in a plane frame (x = (C - origin)·x_axis, y = (C - origin)·y_axis):
// the signed area contribution of one loop piece (Green's theorem), to within `absolute_tolerance`.
// By the adaptive engine (weight certificate, then refinement), so extreme rational weights cannot hide
// part of the curve from the rule. Throws Error naming `argument` if a hostile curve exhausts the cell budget.
double green_area(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                  double absolute_tolerance, std::string_view argument);

}  // namespace ratbez::detail
