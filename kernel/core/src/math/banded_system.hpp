#pragma once
// Banded linear systems: the collocation matrices of B-spline interpolation (A9.1, A9.4) and the normal
// equations of least-squares fitting (The NURBS Book §9.4.1) have at most p + 1 non-zero entries per row
// around the diagonal, so Gaussian elimination confined to the band solves them in O(n p^2) instead of
// O(n^3): what makes interpolation through 10^5 points possible. Not installed, not part of the public API.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ratbez::detail {

// An n x n matrix whose non-zero entries lie at most `lower` diagonals below and `upper` above the main
// one, factored by Gaussian elimination with partial pivoting within the band (LAPACK's dgbtrf scheme):
// a row exchanged with one at most `lower` rows below can carry entries up to `lower` columns further
// right, so each row stores the columns [row - lower, row + upper + lower]. The row exchanges and the
// multipliers are kept, so one factorisation solves for any number of right-hand sides.
class BandedMatrix {
public:
    BandedMatrix(std::size_t size, std::size_t lower, std::size_t upper)
        : size_(size), lower_(lower), upper_(upper), width_(2 * lower + upper + 1),
          entries_(size * width_, 0.0), multipliers_(size * (lower + 1), 0.0), pivots_(size, 0) {}

    std::size_t size() const { return size_; }

    // Entry (row, column); the caller keeps column - row within [-lower, upper].
    double& at(std::size_t row, std::size_t column) { return entries_[row * width_ + column + lower_ - row]; }

    // LU with partial pivoting in place. False when a pivot is zero or below `relative_pivot` times the
    // largest entry of the matrix: the system is singular (to rounding), and nothing may be solved.
    bool factor(double relative_pivot = 1e-14) {
        double largest = 0;
        for (const double a : entries_) largest = std::max(largest, std::abs(a));
        if (!(largest > 0)) return false;
        const std::size_t reach = lower_ + upper_;  // how far right a row's entries go after exchanges
        for (std::size_t col = 0; col < size_; ++col) {
            const std::size_t last_row = std::min(size_ - 1, col + lower_);
            const std::size_t last_col = std::min(size_ - 1, col + reach);
            std::size_t pivot = col;
            for (std::size_t row = col + 1; row <= last_row; ++row)
                if (std::abs(get(row, col)) > std::abs(get(pivot, col))) pivot = row;
            if (!(std::abs(get(pivot, col)) > relative_pivot * largest)) return false;
            pivots_[col] = pivot;
            if (pivot != col)
                for (std::size_t j = col; j <= last_col; ++j) std::swap(ref(col, j), ref(pivot, j));
            const double diagonal = get(col, col);
            for (std::size_t row = col + 1; row <= last_row; ++row) {
                const double factor = get(row, col) / diagonal;
                multipliers_[col * (lower_ + 1) + (row - col)] = factor;
                if (factor == 0.0) continue;
                for (std::size_t j = col; j <= last_col; ++j) ref(row, j) -= factor * get(col, j);
            }
        }
        factored_ = true;
        return true;
    }

    // Solves A x = b in place (b becomes x) after factor(); T is a double or a vector type (Vec3, Vec4)
    // with +, - and scaling by a double.
    template <class T>
    void solve(std::vector<T>& b) const {
        const std::size_t reach = lower_ + upper_;
        for (std::size_t col = 0; col < size_; ++col) {
            if (pivots_[col] != col) std::swap(b[col], b[pivots_[col]]);
            const std::size_t last_row = std::min(size_ - 1, col + lower_);
            for (std::size_t row = col + 1; row <= last_row; ++row) {
                const double factor = multipliers_[col * (lower_ + 1) + (row - col)];
                if (factor != 0.0) b[row] = b[row] - factor * b[col];
            }
        }
        for (std::size_t row = size_; row-- > 0;) {
            const std::size_t last_col = std::min(size_ - 1, row + reach);
            for (std::size_t j = row + 1; j <= last_col; ++j) b[row] = b[row] - get(row, j) * b[j];
            b[row] = (1.0 / get(row, row)) * b[row];
        }
    }

    bool factored() const { return factored_; }

private:
    // Inside the stored window of the row (0 outside it, for reads).
    double get(std::size_t row, std::size_t column) const {
        if (column + lower_ < row || column > row + upper_ + lower_) return 0.0;
        return entries_[row * width_ + column + lower_ - row];
    }
    double& ref(std::size_t row, std::size_t column) { return entries_[row * width_ + column + lower_ - row]; }

    std::size_t size_, lower_, upper_, width_;
    std::vector<double> entries_;
    std::vector<double> multipliers_;
    std::vector<std::size_t> pivots_;
    bool factored_ = false;
};

}  // namespace ratbez::detail
