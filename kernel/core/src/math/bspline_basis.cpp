// B-spline basis functions (001: Cox–de Boor with 0/0 := 0) and the standard evaluation algorithms
// A2.1 FindSpan, A2.2 BasisFuns, A2.3 DersBasisFuns and A2.4 OneBasisFun.
//
// Division by zero cannot happen in A2.2 / A2.3: every denominator there is a knot difference
// u_{span+r+1} - u_{span+1-j+r} over an interval that contains the non-empty span [u_span, u_{span+1}),
// which the functions require. A2.4 divides only by the length of the support of a basis function that
// is non-zero at u, which is therefore positive; that is the 0/0 := 0 rule of 001 made operational.
//
// Where N / (u_{k+1} - u_k) overflows (a domain as short as [0, 5e-324]: inf * 0 gave NaN where every basis
// value is an ordinary number in [0, 1]) the values are formed from RATIOS of knot differences instead
// (ratio_step). Knot vectors whose spread u_m - u_0 overflows are refused, so no difference the algorithms
// take can overflow either.

#include "ratbez/bspline_basis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {
namespace {

using detail::number;
using detail::to_size;

// Work space on the stack for every practical degree: (p+1)^2 + 2(p+1) <= 384 for p <= 17.
using Scratch = detail::Scratch<double, 384>;

void require_degree(int degree) { limits::require_degree(degree, "degree"); }

// value * part / length, one step of the triangular schemes (A2.2, A2.3, A2.4): the textbook's order
// (value / length) * part, whose rounding the grid evaluator (surface_grid.cpp) shares, unless value / length
// overflows (a span as short as 5e-324: inf * 0 gave NaN); then value * (part / length), where the ratio of
// knot differences lies in [0, 1].
inline double ratio_step(double value, double part, double length) {
    const double temp = value / length;
    return std::isfinite(temp) ? part * temp : value * (part / length);
}

// Every knot difference of a vector whose spread u_m - u_0 is finite is finite too (see the top).
void require_finite_spread(std::span<const double> knots, const std::string& argument) {
    require(std::isfinite(knots.back() - knots.front()), argument, [&] {
        return "the knots spread from " + number(knots.front()) + " to " + number(knots.back()) +
               ", a length beyond double range";
    });
}

// The checks shared by A2.2 and A2.3: a span index inside the domain whose span is not empty, so that
// every knot difference the algorithms divide by is positive and every index they touch exists.
void require_evaluable_span(int span, double u, int degree, std::span<const double> knots) {
    require_degree(degree);
    require(knots.size() >= 2 * to_size(degree) + 2, "knots", [&] {
        return "a degree-" + std::to_string(degree) + " basis needs at least " + std::to_string(2 * to_size(degree) + 2) +
               " knots, got " + std::to_string(knots.size());
    });
    const int last_span = static_cast<int>(knots.size()) - degree - 2;
    require(span >= degree && span <= last_span, "span", [&] {
        return "must lie in [" + std::to_string(degree) + ", " + std::to_string(last_span) + "], got " +
               std::to_string(span);
    });
    require(knots[to_size(span)] < knots[to_size(span) + 1], "span",
            [&] { return "knot span " + std::to_string(span) + " is empty"; });
    require_finite(u, "u");
}

// The point at which the last span is closed on the right (see the header): the domain end u_{m-p}
// when p has a non-empty domain on this vector, else the last knot u_m (A2.4's clamped convention).
double right_closure(int degree, std::span<const double> knots) {
    const std::size_t m = knots.size() - 1;
    const std::size_t p = to_size(degree);
    if (m >= 2 * p + 1 && knots[p] < knots[m - p]) return knots[m - p];
    return knots[m];
}

}  // namespace

void validate_knot_vector(int degree, std::span<const double> knots, int control_point_count,
                          const std::string& argument) {
    require_degree(degree);
    require(static_cast<long long>(control_point_count) >= static_cast<long long>(degree) + 1, argument, [&] {
        return "a degree-" + std::to_string(degree) + " B-spline needs at least " +
               std::to_string(to_size(degree) + 1) + " control points, got " + std::to_string(control_point_count);
    });
    const std::size_t expected = to_size(control_point_count) + to_size(degree) + 1;
    require(knots.size() == expected, argument, [&] {
        return "expected " + std::to_string(expected) +
               " knots (control points + degree + 1 = " + std::to_string(control_point_count) + " + " +
               std::to_string(degree) + " + 1), got " + std::to_string(knots.size());
    });
    require_finite(knots, argument);
    for (std::size_t i = 1; i < knots.size(); ++i)
        require(knots[i - 1] <= knots[i], argument, [&] {
            return "must be non-decreasing, but knot " + std::to_string(i) + " (" + number(knots[i]) +
                   ") is less than knot " + std::to_string(i - 1) + " (" + number(knots[i - 1]) + ")";
        });
    require_finite_spread(knots, argument);

    const std::size_t p = to_size(degree);
    const std::size_t m = knots.size() - 1;
    const double domain_min = knots[p], domain_max = knots[m - p];
    require(domain_min < domain_max, argument, [&] {
        return "the domain [u_p, u_{m-p}] = [" + number(domain_min) + ", " + number(domain_max) + "] is empty";
    });

    // Multiplicities: p + 1 anywhere at most (a basis function of zero support would follow), and at most
    // p strictly inside the domain (p + 1 there would make the curve discontinuous: two curves, not one).
    for (std::size_t run_start = 0; run_start < knots.size();) {
        std::size_t run_end = run_start;
        while (run_end < knots.size() && knots[run_end] == knots[run_start]) ++run_end;
        const std::size_t multiplicity = run_end - run_start;
        const double value = knots[run_start];
        require(multiplicity <= p + 1, argument, [&] {
            return "knot " + number(value) + " has multiplicity " + std::to_string(multiplicity) +
                   ", more than degree + 1 = " + std::to_string(p + 1);
        });
        const bool interior = value > domain_min && value < domain_max;
        require(!interior || multiplicity <= p, argument, [&] {
            return "interior knot " + number(value) + " has multiplicity " + std::to_string(multiplicity) +
                   ", more than the degree " + std::to_string(p);
        });
        run_start = run_end;
    }
}

Interval knot_domain(int degree, std::span<const double> knots) {
    require_degree(degree);
    require(knots.size() >= 2 * to_size(degree) + 2, "knots", [&] {
        return "a degree-" + std::to_string(degree) + " knot vector needs at least " + std::to_string(2 * to_size(degree) + 2) +
               " knots, got " + std::to_string(knots.size());
    });
    return {knots[to_size(degree)], knots[knots.size() - 1 - to_size(degree)]};
}

std::vector<double> breakpoints(int degree, std::span<const double> knots) {
    knot_domain(degree, knots);  // validates the degree and the count
    std::vector<double> values;
    for (std::size_t i = to_size(degree); i < knots.size() - to_size(degree); ++i)
        if (values.empty() || knots[i] > values.back()) values.push_back(knots[i]);
    return values;
}

double bspline_basis(int i, int p, std::span<const double> knots, double u) {
    limits::require_degree(p, "p");  // first: the messages below compute with p
    require(knots.size() >= to_size(p) + 2, "knots", [&] {
        return "a degree-" + std::to_string(p) + " basis function needs at least " + std::to_string(to_size(p) + 2) +
               " knots, got " + std::to_string(knots.size());
    });
    const int last_index = static_cast<int>(knots.size()) - p - 2;
    require(i >= 0 && i <= last_index, "i",
            [&] { return "must lie in [0, " + std::to_string(last_index) + "], got " + std::to_string(i); });
    require_finite(knots, "knots");
    for (std::size_t k = 1; k < knots.size(); ++k)
        require(knots[k - 1] <= knots[k], "knots", [&] {
            return "must be non-decreasing, but knot " + std::to_string(k) + " (" + number(knots[k]) +
                   ") is less than knot " + std::to_string(k - 1) + " (" + number(knots[k - 1]) + ")";
        });
    require_finite_spread(knots, "knots");
    require_finite(u, "u");

    // A2.4 (OneBasisFun): the triangle of 001 restricted to the p + 1 step functions N_{i..i+p,0}.
    const std::size_t first = to_size(i);
    const std::size_t order = to_size(p) + 1;
    if (u < knots[first] || u > knots[first + order]) return 0.0;  // local support

    // Step functions N_{j,0}: 1 on the half-open span [u_j, u_{j+1}); at the closure point b the span
    // ending there is used instead, so the function is defined (and continuous) up to the domain's end.
    const double closure = right_closure(p, knots);
    auto step = [&](std::size_t j) {
        if (u == closure) return knots[j] < u && u == knots[j + 1] ? 1.0 : 0.0;
        return knots[j] <= u && u < knots[j + 1] ? 1.0 : 0.0;
    };
    std::vector<double> n(order);  // not the hot path: tessellation evaluates through A2.2
    for (std::size_t j = 0; j < order; ++j) n[j] = step(first + j);

    for (std::size_t k = 1; k < order; ++k) {
        // A zero N_{j,k-1} contributes nothing (0/0 := 0); a non-zero one has a support of positive length
        // that contains u, so the ratios below lie in [0, 1].
        double saved = 0.0;
        if (n[0] != 0.0) {
            const double length = knots[first + k] - knots[first];
            const double product = (u - knots[first]) * n[0] / length;
            saved = std::isfinite(product) ? product : n[0] * ((u - knots[first]) / length);
        }
        for (std::size_t j = 0; j < order - k; ++j) {
            const double knot_left = knots[first + j + 1];
            const double knot_right = knots[first + j + k + 1];
            if (n[j + 1] == 0.0) {
                n[j] = saved;
                saved = 0.0;
            } else {
                const double support = knot_right - knot_left;
                n[j] = saved + ratio_step(n[j + 1], knot_right - u, support);
                saved = ratio_step(n[j + 1], u - knot_left, support);
            }
        }
    }
    return n[0];
}

int find_span(int degree, std::span<const double> knots, double u) {
    const Interval domain = knot_domain(degree, knots);
    require(domain.min < domain.max, "knots",
            [&] { return "the domain [" + number(domain.min) + ", " + number(domain.max) + "] is empty"; });
    require_in_domain(u, domain.min, domain.max, "u");
    // A2.1 by binary search over the knots of the domain: the span k with u_k <= u < u_{k+1}; at the right
    // end the last non-empty span [u_k, u_{m-p}] (closed), which lower_bound finds past repeated knots.
    const auto begin = knots.begin() + degree;
    const auto end = knots.end() - 1 - degree;  // points at u_{m-p}
    if (u >= domain.max) return static_cast<int>(std::lower_bound(begin, end, domain.max) - knots.begin()) - 1;
    return static_cast<int>(std::upper_bound(begin, end, u) - knots.begin()) - 1;
}

void basis_functions(int span, double u, int degree, std::span<const double> knots, std::span<double> out) {
    require_evaluable_span(span, u, degree, knots);
    require(out.size() >= to_size(degree) + 1, "out",
            [&] { return "needs room for " + std::to_string(to_size(degree) + 1) + " values, has " + std::to_string(out.size()); });
    // A2.2 with left[j] = u - u_{span+1-j} and right[j] = u_{span+j} - u read straight from the knots
    // (no work arrays); the triangle of 001 is computed in place in `out`.
    const std::size_t s = to_size(span);
    out[0] = 1.0;
    for (std::size_t j = 1; j <= to_size(degree); ++j) {
        double saved = 0.0;
        for (std::size_t r = 0; r < j; ++r) {
            const double right = knots[s + r + 1] - u;
            const double left = u - knots[s + 1 + r - j];
            const double length = right + left;  // a knot difference > 0
            const double value = out[r];
            out[r] = saved + ratio_step(value, right, length);
            saved = ratio_step(value, left, length);
        }
        out[j] = saved;
    }
}

void basis_function_derivatives(int span, double u, int degree, std::span<const double> knots, int order,
                                std::span<double> out) {
    require_evaluable_span(span, u, degree, knots);
    require(order >= 0, "order", [&] { return "the derivative order must be >= 0, got " + std::to_string(order); });
    const std::size_t p = to_size(degree);
    const std::size_t width = p + 1;
    const std::size_t rows = to_size(order) + 1;
    require(out.size() >= rows * width, "out",
            [&] { return "needs room for " + std::to_string(rows * width) + " values, has " + std::to_string(out.size()); });

    // A2.3 (DersBasisFuns). ndu holds the basis functions of every degree (upper triangle) and the knot
    // differences (lower triangle); a holds two rows of the coefficients a_{k,j}.
    Scratch work(width * width + 2 * width);
    auto ndu = [&](std::size_t row, std::size_t column) -> double& { return work[row * width + column]; };
    auto a = [&](std::size_t row, std::size_t column) -> double& { return work[width * width + row * width + column]; };
    const std::size_t s = to_size(span);

    ndu(0, 0) = 1.0;
    for (std::size_t j = 1; j <= p; ++j) {
        double saved = 0.0;
        for (std::size_t r = 0; r < j; ++r) {
            const double right = knots[s + r + 1] - u;
            const double left = u - knots[s + 1 + r - j];
            ndu(j, r) = right + left;  // u_{s+r+1} - u_{s+1+r-j} > 0
            const double value = ndu(r, j - 1);  // as in A2.2
            ndu(r, j) = saved + ratio_step(value, right, ndu(j, r));
            saved = ratio_step(value, left, ndu(j, r));
        }
        ndu(j, j) = saved;
    }

    std::fill(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(rows * width), 0.0);
    for (std::size_t j = 0; j <= p; ++j) out[j] = ndu(j, p);

    const int highest = std::min(order, degree);  // derivatives above the degree vanish
    for (int r = 0; r <= degree; ++r) {
        std::size_t s1 = 0, s2 = 1;
        a(0, 0) = 1.0;
        for (int k = 1; k <= highest; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = degree - k;
            if (r >= k) {
                a(s2, 0) = a(s1, 0) / ndu(to_size(pk + 1), to_size(rk));
                d = a(s2, 0) * ndu(to_size(rk), to_size(pk));
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = r - 1 <= pk ? k - 1 : degree - r;
            for (int j = j1; j <= j2; ++j) {
                a(s2, to_size(j)) = (a(s1, to_size(j)) - a(s1, to_size(j - 1))) / ndu(to_size(pk + 1), to_size(rk + j));
                d += a(s2, to_size(j)) * ndu(to_size(rk + j), to_size(pk));
            }
            if (r <= pk) {
                a(s2, to_size(k)) = -a(s1, to_size(k - 1)) / ndu(to_size(pk + 1), to_size(r));
                d += a(s2, to_size(k)) * ndu(to_size(r), to_size(pk));
            }
            out[to_size(k) * width + to_size(r)] = d;
            std::swap(s1, s2);
        }
    }
    // Multiply by p! / (p - k)!.
    double factor = static_cast<double>(degree);
    for (int k = 1; k <= highest; ++k) {
        for (std::size_t j = 0; j <= p; ++j) out[to_size(k) * width + j] *= factor;
        factor *= static_cast<double>(degree - k);
    }
}

std::vector<std::vector<double>> basis_function_derivatives(int span, double u, int degree,
                                                            std::span<const double> knots, int order) {
    limits::require_derivative_order(order, "order");
    require_degree(degree);
    const std::size_t width = to_size(degree) + 1;
    std::vector<double> flat((to_size(order) + 1) * width);
    basis_function_derivatives(span, u, degree, knots, order, flat);
    std::vector<std::vector<double>> ders(to_size(order) + 1);
    for (std::size_t k = 0; k < ders.size(); ++k)
        ders[k].assign(flat.begin() + static_cast<std::ptrdiff_t>(k * width),
                       flat.begin() + static_cast<std::ptrdiff_t>((k + 1) * width));
    return ders;
}

}  // namespace ratbez
