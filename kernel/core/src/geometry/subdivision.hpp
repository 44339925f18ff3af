#pragma once
// Subdivision of Bézier coefficients at 1/2 (deCasteljau, A1.5 / Eq. 1.19) and the weight certificate
// built on it: rational pieces halved until their weights vary by at most kMaxWeightSpread, so that the
// rational parameterisation cannot crowd a piece into a sliver. What the integration engine
// (analysis/cubature.hpp), point inversion, closest points, the profile checks, revolve and the deviation
// seeds share. Not installed, not part of the public API.

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace ratbez::detail {

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

// The weight certificate of the adaptive integration (analysis/cubature.cpp) and of the deviation seeds
// (mesh/deviation.cpp): a rational Bézier piece is halved until along each direction its weights' Bernstein
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

}  // namespace ratbez::detail
