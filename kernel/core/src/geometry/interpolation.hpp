#pragma once
// Global B-spline interpolation (The NURBS Book §9.2.1, A9.1): the control points of the degree-p curve on
// a knot vector that passes through data points D_k at parameters t_k. Used by skinning (loft.cpp) on
// homogeneous points. Defined in interpolation.cpp. Not installed, not part of the public API.

#include <vector>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// The clamped knot vector by averaging (Eq. 9.8): u_0..u_p = 0, u_{m-p}..u_m = 1 and
// u_{j+p} = (1/p) sum_{i=j}^{j+p-1} t_i for j = 1 .. n - p, for parameters 0 = t_0 < ... < t_n = 1.
// It makes the interpolation system non-singular (Schoenberg–Whitney) and banded.
std::vector<double> averaged_knots(const std::vector<double>& parameters, int degree);

// The control points P_j with sum_j N_{j,p}(t_k) P_j = D_k for every k (A9.1): the linear system solved by
// Gaussian elimination with partial pivoting (its matrix is totally positive, so no pivot is small) in band
// storage, O(n p^2) time and O(n p) memory.
std::vector<Vec4> interpolate(int degree, const std::vector<double>& knots, const std::vector<double>& parameters,
                              const std::vector<Vec4>& data);

}  // namespace ratbez::detail
