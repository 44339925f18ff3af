// Global B-spline interpolation (A9.1); see interpolation.hpp.
#include "geometry/interpolation.hpp"

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
    // The collocation matrix A[k][j] = N_{j,p}(t_k): p + 1 non-zero entries per row (A2.1, A2.2).
    std::vector<std::vector<double>> a(size, std::vector<double>(size, 0.0));
    std::vector<double> basis(to_size(degree + 1));
    for (std::size_t k = 0; k < size; ++k) {
        const int span = find_span(degree, knots, parameters[k]);
        basis_functions(span, parameters[k], degree, knots, basis);
        for (int j = 0; j <= degree; ++j) a[k][to_size(span - degree + j)] = basis[to_size(j)];
    }
    std::vector<Vec4> x = data;
    for (std::size_t col = 0; col < size; ++col) {
        std::size_t pivot = col;
        for (std::size_t row = col + 1; row < size; ++row)
            if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
        std::swap(a[col], a[pivot]);
        std::swap(x[col], x[pivot]);
        for (std::size_t row = col + 1; row < size; ++row) {
            const double factor = a[row][col] / a[col][col];
            if (factor == 0.0) continue;
            for (std::size_t j = col; j < size; ++j) a[row][j] -= factor * a[col][j];
            x[row] -= factor * x[col];
        }
    }
    for (std::size_t col = size; col-- > 0;) {
        for (std::size_t j = col + 1; j < size; ++j) x[col] -= a[col][j] * x[j];
        x[col] *= 1.0 / a[col][col];
    }
    return x;
}

}  // namespace ratbez::detail
