// Global B-spline interpolation (A9.1); see interpolation.hpp.
#include "geometry/interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"

namespace ratbez::detail {

std::vector<double> averaged_knots(const std::vector<double>& parameters, int degree) {
    const int n = static_cast<int>(parameters.size()) - 1;
    std::vector<double> knots(to_size(degree + 1), 0.0);
    for (int j = 1; j <= n - degree; ++j) {
        double sum = 0;
        for (int i = j; i <= j + degree - 1; ++i) sum += parameters[to_size(i)];
        knots.push_back(sum / degree);
    }
    knots.insert(knots.end(), to_size(degree + 1), 1.0);
    return knots;
}

std::vector<Vec4> interpolate(int degree, const std::vector<double>& knots, const std::vector<double>& parameters,
                              const std::vector<Vec4>& data) {
    const std::size_t size = data.size();
    // The collocation matrix A[k][j] = N_{j,p}(t_k) (A2.1, A2.2) has p + 1 non-zero entries per row, at
    // columns span - p .. span with span - p <= k <= span (the diagonal is non-zero: Schoenberg–Whitney), so
    // both its bandwidths are at most p. Gaussian elimination with partial pivoting among the p rows below
    // keeps the multipliers within p of the diagonal and widens U to 2p above it (LAPACK's dgbtrf): in band
    // storage the solve takes O(n p^2) time and O(n p) memory. It was a dense n x n matrix: 20,000 loft
    // sections asked 3.2 GB and quadratic time (issue 29).
    const std::size_t lower = to_size(degree), upper = 2 * to_size(degree);
    const std::size_t width = lower + upper + 1;
    // band[j * width + (i + upper - j)] holds A[i][j] for j - upper <= i <= j + lower.
    std::vector<double> band(size * width, 0.0);
    const auto at = [&](std::size_t i, std::size_t j) -> double& { return band[j * width + (i + upper - j)]; };
    std::vector<double> basis(to_size(degree + 1));
    for (std::size_t k = 0; k < size; ++k) {
        const int span = find_span(degree, knots, parameters[k]);
        basis_functions(span, parameters[k], degree, knots, basis);
        for (int j = 0; j <= degree; ++j) at(k, to_size(span - degree + j)) = basis[to_size(j)];
    }
    std::vector<Vec4> x = data;
    for (std::size_t col = 0; col < size; ++col) {
        const std::size_t last_row = std::min(size - 1, col + lower), last_col = std::min(size - 1, col + upper);
        std::size_t pivot = col;
        for (std::size_t row = col + 1; row <= last_row; ++row)
            if (std::abs(at(row, col)) > std::abs(at(pivot, col))) pivot = row;
        if (pivot != col) {
            for (std::size_t j = col; j <= last_col; ++j) std::swap(at(col, j), at(pivot, j));
            std::swap(x[col], x[pivot]);
        }
        for (std::size_t row = col + 1; row <= last_row; ++row) {
            const double factor = at(row, col) / at(col, col);
            if (factor == 0.0) continue;
            for (std::size_t j = col; j <= last_col; ++j) at(row, j) -= factor * at(col, j);
            x[row] -= factor * x[col];
        }
    }
    for (std::size_t col = size; col-- > 0;) {
        for (std::size_t j = col + 1; j <= std::min(size - 1, col + upper); ++j) x[col] -= at(col, j) * x[j];
        x[col] *= 1.0 / at(col, col);
    }
    return x;
}

}  // namespace ratbez::detail
