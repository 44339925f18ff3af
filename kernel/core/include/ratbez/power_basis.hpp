#pragma once
// Power basis form C(u) = sum a_i u^i (000 §1.2), Horner evaluation (A1.1) and its tensor-product form
// for power basis surfaces (A1.6), and the exact change of basis to and from Bézier form
// (Exercise 1.14: [B_{0,n} .. B_{n,n}] = [1 u .. u^n] M).

#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez {

// Horner's rule, A1.1: a[0] + u (a[1] + u (a[2] + ...)).
double horner(const std::vector<double>& coefficients, double u);
Vec3 horner(const std::vector<Vec3>& coefficients, double u);

// A1.6 (Horner2): the point of the power basis surface S(u, v) = sum_i sum_j a[i][j] u^i v^j (Eq. 1.21):
// A1.1 in v on every row i gives b_i = sum_j a[i][j] v^j (Eq. 1.22), then A1.1 in u on the b_i. The rows
// must all have the same, non-zero length; any finite u and v.
Vec3 horner(const std::vector<std::vector<Vec3>>& coefficients, double u, double v);

// The (n+1) x (n+1) matrix M with B_{j,n}(u) = sum_i u^i M[i][j]; M[i][j] = (-1)^{i-j} C(n,i) C(i,j).
std::vector<std::vector<double>> bezier_to_power_matrix(int n);

// a = M P (Bézier control points -> power coefficients) and P = M^{-1} a (the inverse, exactly:
// M^{-1}[i][j] = C(i,j) / C(n,j) for j <= i).
std::vector<Vec3> bezier_to_power(const std::vector<Vec3>& control_points);
std::vector<Vec3> power_to_bezier(const std::vector<Vec3>& coefficients);

}  // namespace ratbez
