#pragma once
// B-spline basis functions (001): knot vector validation, span search and Cox–de Boor evaluation with
// the convention 0/0 := 0. Algorithm numbers follow the standard NURBS texts (A2.1–A2.4).
//
// A knot vector U = {u_0 .. u_m} for degree p and n+1 control points has m = n + p + 1, is
// non-decreasing, has end knots of multiplicity at most p + 1 and interior knots (inside the domain) of
// multiplicity at most p (more would break the curve apart), and the valid parameter domain is
// [u_p, u_{m-p}] with u_p < u_{m-p}. Spans are half-open [u_k, u_{k+1}) except the last one of the
// domain, which is closed at u_{m-p}, so N_{n,p}(u_{m-p}) = 1 for a clamped vector (endpoint interpolation).
//
// Degree 0 is allowed: the multiplicity rules leave exactly one span, so a degree-0 B-spline is a single
// constant piece on {a, b} with one control point.

#include <span>
#include <string>
#include <vector>

#include "ratbez/interval.hpp"

namespace ratbez {

// Throws ratbez::Error naming `argument` unless `knots` is a valid knot vector for `degree` and
// `control_point_count` control points (sizes, finiteness, non-decreasing, multiplicities, non-empty domain).
void validate_knot_vector(int degree, std::span<const double> knots, int control_point_count,
                          const std::string& argument = "knots");

// N_{i,p}(u) by the Cox–de Boor recursion with 0/0 := 0 (001; A2.4). Validates its arguments: p >= 0,
// 0 <= i <= knots.size() - p - 2, finite non-decreasing knots (no multiplicity limits, so that the lower
// degrees of 001's triangular table can be evaluated on the same vector), u any finite number (0 outside
// [u_i, u_{i+p+1}]). The span ending at u_{m-p} (or at u_m when p has no domain on `knots`) is closed on
// the right, so inside the domain this agrees with basis_functions (A2.2).
double bspline_basis(int i, int p, std::span<const double> knots, double u);

// The span index k with u_k <= u < u_{k+1} inside the domain, the last non-empty span for u = u_{m-p} (A2.1).
// Requires a validated knot vector and u inside the domain.
int find_span(int degree, std::span<const double> knots, double u);

// The p+1 non-vanishing basis functions N_{span-p,p}(u) .. N_{span,p}(u) (A2.2), written to `out`.
void basis_functions(int span, double u, int degree, std::span<const double> knots, std::span<double> out);

// ders[k][j] = k-th derivative of N_{span-p+j,p} at u, 0 <= k <= order (A2.3); derivatives above p are 0.
std::vector<std::vector<double>> basis_function_derivatives(int span, double u, int degree,
                                                            std::span<const double> knots, int order);
// The same without allocating: out[k * (degree + 1) + j] = ders[k][j]; out.size() >= (order + 1) * (degree + 1).
void basis_function_derivatives(int span, double u, int degree, std::span<const double> knots, int order,
                                std::span<double> out);

// The domain [u_p, u_{m-p}] of a knot vector.
Interval knot_domain(int degree, std::span<const double> knots);

// The distinct knot values of the domain [u_p, u_{m-p}], ascending: the ends of its non-empty spans
// (the break points where the Bezier pieces of a curve or surface meet, 001). Both ends included.
std::vector<double> breakpoints(int degree, std::span<const double> knots);

}  // namespace ratbez
