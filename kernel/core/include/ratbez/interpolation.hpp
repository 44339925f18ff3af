#pragma once
// Interpolation through points (The NURBS Book §9.2): a polynomial B-spline that passes through every
// given point exactly (to rounding, ~1e-15 of the size).
//
// Curves, global interpolation (A9.1): the points Q_0..Q_n get parameters 0 = t_0 < ... < t_n = 1 by
// chord length (Eq. 9.5: steps proportional to |Q_k - Q_{k-1}|), centripetal (Eq. 9.6: to its square root,
// which keeps sharp turns from overshooting) or uniform (Eq. 9.3); the knots are averaged from them
// (Eq. 9.8), which keeps the banded system sum_j N_{j,p}(t_k) P_j = Q_k non-singular (Schoenberg–Whitney),
// and the system is solved by banded Gaussian elimination (O(n p^2)).
//  - End tangents (§9.2.2): each given tangent adds the condition C'(0) = d T/|T| (C'(1) at the end), d
//    being the total chord length (the book's choice of magnitude: the tangent's length is ignored, its
//    direction kept), and one control point; the knots are averaged from the parameters with that end's
//    parameter listed twice, which is Eq. 9.22.
//  - Closed curves: the chord from the last point back to the first is one more parameter step, the
//    curve is the periodic B-spline through the points (knots averaged cyclically, kappa_i = mean of
//    t_{i-p} .. t_{i-1}, so that t_i lies inside the support of N_i and the cyclic system is non-singular)
//    and is returned clamped at Q_0: C(0) = C(1) = Q_0, C^{p-1} across that seam like everywhere else.
//    A last point equal to the first (within 1e-12 of the size) is taken as the closing repeat and dropped.
//
// Surfaces, global interpolation (A9.4): grid[i][j] is passed through at (u_i, v_j); the u_i are the chord
// parameters of each column averaged (§9.2.5, columns whose points all coincide left out), the v_j likewise
// from the rows; the knots averaged; then the curves through each column in u and through the resulting
// control points of each row in v.
//
// Errors (ratbez::Error) name "points" / "grid" (too few, not finite, consecutive points that coincide),
// "degree" (< 1 or above the limit), "tangents" (not finite, zero, with a closed curve or degree 1).

#include <optional>
#include <string_view>
#include <vector>

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

enum class Parameterization { chord, centripetal, uniform };

// "chord", "centripetal" or "uniform"; anything else throws Error naming `argument`.
Parameterization parse_parameterization(std::string_view name, std::string_view argument = "parameterization");

struct EndTangents {
    std::optional<Vec3> start, end;
};

// At least degree + 1 conditions (points plus given tangents; closed: at least degree + 1 points). The
// curve's domain is [0, 1] and C(t_k) = Q_k.
NurbsCurve interpolate(const std::vector<Vec3>& points, int degree = 3,
                       Parameterization parameterization = Parameterization::chord, const EndTangents& tangents = {},
                       bool closed = false);

// The parameters t_k at which interpolate() passes through points[k] (for a closed curve without the
// final 1 of the closing chord, and after a repeated closing point is dropped).
std::vector<double> interpolation_parameters(const std::vector<Vec3>& points,
                                             Parameterization parameterization = Parameterization::chord,
                                             bool closed = false);

// grid[i][j]: i along u (at least degree_u + 1 rows), j along v (at least degree_v + 1 per row, every row
// the same length). S(u_i, v_j) = grid[i][j]; the domain is [0, 1] x [0, 1].
NurbsSurface interpolate_surface(const std::vector<std::vector<Vec3>>& grid, int degree_u = 3, int degree_v = 3);

}  // namespace ratbez
