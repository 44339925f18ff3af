// Global B-spline interpolation (The NURBS Book §9.2: A9.1 for curves, A9.4 for surfaces); see
// interpolation.hpp (the private solver) and ratbez/interpolation.hpp (the public functions).
#include "ratbez/interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/clamping.hpp"
#include "geometry/interpolation.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/limits.hpp"

namespace ratbez {

namespace detail {

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

namespace {

// The non-zero basis values (or derivatives of `order`) at t: values[j] for N_{first + j, p}.
struct BasisRow {
    std::size_t first = 0;
    std::vector<double> values;
};

BasisRow basis_row(int degree, const std::vector<double>& knots, double t, int order) {
    const int span = find_span(degree, knots, t);
    std::vector<double> ders((to_size(order) + 1) * to_size(degree + 1));
    basis_function_derivatives(span, t, degree, knots, order, ders);
    BasisRow row{to_size(span - degree), {}};
    row.values.assign(ders.begin() + static_cast<std::ptrdiff_t>(to_size(order) * to_size(degree + 1)),
                      ders.begin() + static_cast<std::ptrdiff_t>((to_size(order) + 1) * to_size(degree + 1)));
    return row;
}

// The band of a matrix from its rows' column ranges (row k uses columns first_k .. first_k + p).
BandedMatrix banded_matrix(const std::vector<BasisRow>& rows) {
    std::size_t lower = 0, upper = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const std::size_t last = rows[k].first + rows[k].values.size() - 1;
        if (rows[k].first < k) lower = std::max(lower, k - rows[k].first);
        if (last > k) upper = std::max(upper, last - k);
    }
    BandedMatrix matrix(rows.size(), lower, upper);
    for (std::size_t k = 0; k < rows.size(); ++k)
        for (std::size_t j = 0; j < rows[k].values.size(); ++j) matrix.at(k, rows[k].first + j) += rows[k].values[j];
    return matrix;
}

}  // namespace

Collocation::Collocation(int degree, const std::vector<double>& knots, const std::vector<Condition>& conditions)
    : matrix_(0, 0, 0) {
    std::vector<BasisRow> rows;
    rows.reserve(conditions.size());
    for (const Condition& c : conditions) rows.push_back(basis_row(degree, knots, c.parameter, c.order));
    matrix_ = banded_matrix(rows);
    ok_ = matrix_.factor();
}

std::vector<Vec4> interpolate(int degree, const std::vector<double>& knots, const std::vector<double>& parameters,
                              const std::vector<Vec4>& data, const std::string& argument) {
    std::vector<Condition> conditions;
    for (const double t : parameters) conditions.push_back({t, 0});
    const Collocation system(degree, knots, conditions);
    require(system.ok(), argument, "the interpolation system is singular (parameters too close together)");
    return system.solve(data);
}

std::vector<double> chord_parameters(const std::vector<Vec3>& points, double exponent, bool closed) {
    const std::size_t n = points.size();
    std::vector<double> steps;
    for (std::size_t k = 1; k < n + (closed ? 1 : 0); ++k)
        steps.push_back(std::pow(distance(points[k % n], points[k - 1]), exponent));
    CompensatedSum total;
    for (const double s : steps) total.add(s);
    std::vector<double> t(n, 0.0);
    CompensatedSum running;
    for (std::size_t k = 1; k < n; ++k) {
        running.add(steps[k - 1]);
        t[k] = running.value() / total.value();
    }
    if (!closed) t.back() = 1.0;
    return t;
}

std::vector<double> averaged_parameters(const std::vector<std::vector<Vec3>>& lines, const std::string& argument,
                                        const std::string& what) {
    const std::size_t count = lines.front().size();
    std::vector<double> t(count, 0.0);
    int used = 0;
    for (const std::vector<Vec3>& line : lines) {
        double total = 0;
        for (std::size_t k = 1; k < count; ++k) total += distance(line[k], line[k - 1]);
        if (!(total > 0)) continue;
        // Eq. 9.5 along this line; the averaging below is the book's for surfaces (§9.2.5).
        double running = 0;
        for (std::size_t k = 1; k < count; ++k) {
            running += distance(line[k], line[k - 1]);
            t[k] += running / total;
        }
        ++used;
    }
    require(used > 0, argument, [&] { return "every " + what + " has all its points in one place"; });
    for (std::size_t k = 1; k + 1 < count; ++k) t[k] /= used;
    t.back() = 1.0;
    for (std::size_t k = 1; k < count; ++k)
        require(t[k] > t[k - 1], argument, [&] {
            return what + "s " + std::to_string(k - 1) + " and " + std::to_string(k) +
                   " coincide (every one of their points is the same), so no parameter separates them";
        });
    return t;
}

}  // namespace detail

namespace {

using detail::Collocation;
using detail::Condition;
using detail::to_size;

double exponent_of(Parameterization parameterization) {
    switch (parameterization) {
        case Parameterization::chord: return 1.0;
        case Parameterization::centripetal: return 0.5;
        case Parameterization::uniform: return 0.0;
    }
    return 1.0;
}

double point_size(const std::vector<Vec3>& points) {
    Box box;
    for (const Vec3& p : points) box.add(p);
    return box.diagonal();
}

// Validated points: finite, at least two, none equal to the one before; a closed list loses a last point
// equal to the first.
std::vector<Vec3> checked_points(std::vector<Vec3> points, bool closed) {
    require(points.size() >= 2, "points", [&] { return "needs at least 2 points, got " + std::to_string(points.size()); });
    limits::require_curve_points(points.size(), "points");
    for (std::size_t k = 0; k < points.size(); ++k)
        require(is_finite(points[k]), "points", [&] { return "point " + std::to_string(k) + " is not finite"; });
    const double size = point_size(points);
    require(size > 0, "points", "all points are the same");
    if (closed && points.size() > 2 && distance(points.back(), points.front()) <= 1e-12 * size) points.pop_back();
    for (std::size_t k = 1; k < points.size(); ++k)
        require(distance(points[k], points[k - 1]) > 1e-12 * size, "points", [&] {
            return "points " + std::to_string(k - 1) + " and " + std::to_string(k) +
                   " coincide; an interpolating curve cannot pass through one point twice in a row";
        });
    if (closed)
        require(points.size() >= 3, "points", "a closed curve needs at least 3 distinct points");
    return points;
}

void require_interpolation_degree(int degree) {
    require(degree >= 1, "degree", [&] { return "must be >= 1, got " + std::to_string(degree); });
    limits::require_degree(degree, "degree");
}

void require_enough(std::size_t conditions, int degree, const char* what) {
    require(conditions >= to_size(degree) + 1, "points", [&] {
        return "a degree-" + std::to_string(degree) + " curve through them needs at least " +
               std::to_string(degree + 1) + " " + what + ", got " + std::to_string(conditions) +
               " (lower the degree for fewer points)";
    });
}

Vec3 checked_tangent(const Vec3& tangent, const char* end) {
    require(is_finite(tangent), "tangents", [&] { return std::string("the ") + end + " tangent is not finite"; });
    const double length = norm(tangent);
    require(length > 0, "tangents", [&] { return std::string("the ") + end + " tangent is the zero vector"; });
    return tangent / length;
}

// A9.1 with optional end derivatives (§9.2.2).
NurbsCurve open_interpolant(const std::vector<Vec3>& points, int degree, const std::vector<double>& t,
                            const EndTangents& tangents) {
    const std::size_t n = points.size();
    double chord = 0;
    for (std::size_t k = 1; k < n; ++k) chord += distance(points[k], points[k - 1]);
    std::vector<Condition> conditions;
    std::vector<Vec3> data;
    std::vector<double> listed;  // the parameters, an end's twice when it has a tangent (Eq. 9.22)
    for (std::size_t k = 0; k < n; ++k) {
        const bool start = k == 0 && tangents.start, end = k + 1 == n && tangents.end;
        if (end) {
            conditions.push_back({t[k], 1});
            data.push_back(chord * checked_tangent(*tangents.end, "end"));
            listed.push_back(t[k]);
        }
        conditions.push_back({t[k], 0});
        data.push_back(points[k]);
        listed.push_back(t[k]);
        if (start) {
            conditions.push_back({t[k], 1});
            data.push_back(chord * checked_tangent(*tangents.start, "start"));
            listed.push_back(t[k]);
        }
    }
    require_enough(conditions.size(), degree, tangents.start || tangents.end ? "points and tangents" : "points");
    std::vector<double> knots = detail::averaged_knots(listed, degree);
    const Collocation system(degree, knots, conditions);
    require(system.ok(), "points", "the interpolation system is singular (parameters too close together)");
    std::vector<Vec3> control = system.solve(std::move(data));
    // The ends are the data themselves (clamped knots), not their rounded solution.
    control.front() = points.front();
    control.back() = points.back();
    return NurbsCurve(degree, std::move(knots), std::move(control));
}

// The periodic interpolant through Q_0..Q_{N-1} and back to Q_0, returned clamped at Q_0.
NurbsCurve closed_interpolant(const std::vector<Vec3>& points, int degree, const std::vector<double>& t) {
    const int p = degree;
    const int count = static_cast<int>(points.size());
    // The parameters continued periodically: T(k + N) = T(k) + 1; the knots kappa_i = mean of
    // T(i - p) .. T(i - 1), so that N_i's support (kappa_i, kappa_{i+p+1}) has T(i) inside it (it lies
    // between the mean of the p parameters before it and of the p after it): the cyclic analogue of
    // Eq. 9.8, and the cyclic Schoenberg–Whitney condition that keeps the system non-singular.
    auto T = [&](int k) {
        const int wraps = k >= 0 ? k / count : -((-k + count - 1) / count);
        return t[to_size(k - wraps * count)] + wraps;
    };
    const int first = -2 * p - 2, last = count + 2 * p + 2;  // the knot indices kept: kappa_first .. kappa_last
    std::vector<double> kappa;
    for (int i = first; i <= last; ++i) {
        double sum = 0;
        for (int k = i - p; k <= i - 1; ++k) sum += T(k);
        // A knot a rounding error away from a whole period (0, 1, ...) is that period exactly: the cut at Q_0
        // below would otherwise leave a span of width 1e-17 there.
        const double knot = sum / p, whole = std::round(knot);
        kappa.push_back(std::abs(knot - whole) <= 1e-12 ? whole : knot);
    }
    auto knot_index = [&](int i) { return to_size(i - first); };
    auto control_index = [&](int i) { return to_size(((i % count) + count) % count); };

    // Rows and columns interleaved from both ends (0, N-1, 1, N-2, ...): the cyclic band (entries in the
    // corners) becomes an ordinary band about twice as wide, which the banded solver takes as it is.
    std::vector<std::size_t> position(to_size(count));
    for (int k = 0; k < count; ++k) position[to_size(k)] = k < (count + 1) / 2 ? to_size(2 * k) : to_size(2 * (count - 1 - k) + 1);
    struct Entry {
        std::size_t row, column;
        double value;
    };
    std::vector<Entry> entries;
    std::vector<double> basis(to_size(p + 1));
    for (int k = 0; k < count; ++k) {
        const double tk = t[to_size(k)];
        const int span = static_cast<int>(std::upper_bound(kappa.begin(), kappa.end(), tk) - kappa.begin()) - 1;
        basis_functions(span, tk, p, kappa, basis);
        for (int j = 0; j <= p; ++j) {
            const int i = span - p + j + first;  // the basis function's own index
            entries.push_back({position[to_size(k)], position[control_index(i)], basis[to_size(j)]});
        }
    }
    std::size_t lower = 0, upper = 0;
    for (const Entry& e : entries) {
        if (e.column < e.row) lower = std::max(lower, e.row - e.column);
        if (e.column > e.row) upper = std::max(upper, e.column - e.row);
    }
    detail::BandedMatrix matrix(to_size(count), lower, upper);
    for (const Entry& e : entries) matrix.at(e.row, e.column) += e.value;
    require(matrix.factor(), "points", "the closed interpolation system is singular (parameters too close together)");
    std::vector<Vec3> solved(to_size(count));
    for (int k = 0; k < count; ++k) solved[position[to_size(k)]] = points[to_size(k)];
    matrix.solve(solved);
    std::vector<Vec3> control(to_size(count));
    for (int k = 0; k < count; ++k) control[to_size(k)] = solved[position[to_size(k)]];

    // One unclamped piece of the periodic curve whose domain [kappa_a, kappa_b] covers [0, 1], then the
    // part over [0, 1] (knot insertion).
    int a = 0;
    while (kappa[knot_index(a + 1)] <= 0.0) ++a;
    while (kappa[knot_index(a)] > 0.0) --a;
    int b = a + 1;
    while (kappa[knot_index(b)] < 1.0) ++b;
    std::vector<double> knots(kappa.begin() + static_cast<std::ptrdiff_t>(knot_index(a - p)),
                              kappa.begin() + static_cast<std::ptrdiff_t>(knot_index(b + p)) + 1);
    std::vector<Vec3> poles;
    for (int i = a - p; i <= b - 1; ++i) poles.push_back(control[control_index(i)]);
    NurbsCurve clamped = detail::restricted(NurbsCurve(p, std::move(knots), std::move(poles)), 0.0, 1.0);
    // Both ends are Q_0 itself, so the curve closes exactly.
    std::vector<Vec3> ends = clamped.points();
    ends.front() = ends.back() = points.front();
    return NurbsCurve(p, clamped.knots(), std::move(ends));
}

}  // namespace

Parameterization parse_parameterization(std::string_view name, std::string_view argument) {
    if (name == "chord") return Parameterization::chord;
    if (name == "centripetal") return Parameterization::centripetal;
    if (name == "uniform") return Parameterization::uniform;
    fail(argument, "must be \"chord\", \"centripetal\" or \"uniform\", got \"" + std::string(name) + "\"");
}

std::vector<double> interpolation_parameters(const std::vector<Vec3>& points, Parameterization parameterization,
                                             bool closed) {
    return detail::chord_parameters(checked_points(points, closed), exponent_of(parameterization), closed);
}

NurbsCurve interpolate(const std::vector<Vec3>& input, int degree, Parameterization parameterization,
                       const EndTangents& tangents, bool closed) {
    require_interpolation_degree(degree);
    const std::vector<Vec3> points = checked_points(input, closed);
    const std::vector<double> t = detail::chord_parameters(points, exponent_of(parameterization), closed);
    if (tangents.start || tangents.end) {
        require(!closed, "tangents", "a closed curve has no ends to give tangents at");
        require(degree >= 2, "tangents", "a degree-1 curve (a polyline) cannot take end tangents; use degree >= 2");
    }
    if (!closed) return open_interpolant(points, degree, t, tangents);
    require_enough(points.size(), degree, "distinct points");
    return closed_interpolant(points, degree, t);
}

NurbsSurface interpolate_surface(const std::vector<std::vector<Vec3>>& grid, int degree_u, int degree_v) {
    for (const auto& [degree, name] : {std::pair{degree_u, "degree_u"}, std::pair{degree_v, "degree_v"}}) {
        // (captured by copy: clang 14 cannot capture a structured binding, and the fuzzers build with it)
        require(degree >= 1, name, [d = degree] { return "must be >= 1, got " + std::to_string(d); });
        limits::require_degree(degree, name);
    }
    const std::size_t rows = grid.size();
    require(rows > to_size(degree_u), "grid", [&] {
        return "a degree-" + std::to_string(degree_u) + " surface in u needs at least " + std::to_string(degree_u + 1) +
               " rows, got " + std::to_string(rows);
    });
    const std::size_t columns = grid.front().size();
    for (std::size_t i = 0; i < rows; ++i) {
        require(grid[i].size() == columns, "grid", [&] {
            return "row " + std::to_string(i) + " has " + std::to_string(grid[i].size()) + " points, row 0 has " +
                   std::to_string(columns) + " (the grid must be rectangular)";
        });
        for (std::size_t j = 0; j < columns; ++j)
            require(is_finite(grid[i][j]), "grid", [&] {
                return "point [" + std::to_string(i) + "][" + std::to_string(j) + "] is not finite";
            });
    }
    require(columns > to_size(degree_v), "grid", [&] {
        return "a degree-" + std::to_string(degree_v) + " surface in v needs at least " + std::to_string(degree_v + 1) +
               " points per row, got " + std::to_string(columns);
    });
    limits::require_surface_points(rows, columns, "grid");

    // The u parameters from the columns (lines along u), the v parameters from the rows (§9.2.5).
    std::vector<std::vector<Vec3>> along_u(columns, std::vector<Vec3>(rows));
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < columns; ++j) along_u[j][i] = grid[i][j];
    const std::vector<double> u = detail::averaged_parameters(along_u, "grid", "row");
    const std::vector<double> v = detail::averaged_parameters(grid, "grid", "column");
    std::vector<double> knots_u = detail::averaged_knots(u, degree_u);
    std::vector<double> knots_v = detail::averaged_knots(v, degree_v);
    std::vector<Condition> at_u, at_v;
    for (const double x : u) at_u.push_back({x, 0});
    for (const double x : v) at_v.push_back({x, 0});
    const Collocation system_u(degree_u, knots_u, at_u), system_v(degree_v, knots_v, at_v);
    require(system_u.ok() && system_v.ok(), "grid", "the interpolation system is singular (parameters too close together)");

    // A9.4: curves through each column in u give R_{i,j}; curves through each row of R in v give P_{i,j}.
    for (std::vector<Vec3>& line : along_u) line = system_u.solve(std::move(line));
    std::vector<std::vector<Vec3>> net(rows, std::vector<Vec3>(columns));
    std::vector<Vec3> row(columns);
    for (std::size_t i = 0; i < rows; ++i) {
        for (std::size_t j = 0; j < columns; ++j) row[j] = along_u[j][i];
        net[i] = system_v.solve(row);
    }
    // The corners are the data themselves (clamped in both directions).
    net.front().front() = grid.front().front();
    net.front().back() = grid.front().back();
    net.back().front() = grid.back().front();
    net.back().back() = grid.back().back();
    return NurbsSurface(degree_u, degree_v, std::move(knots_u), std::move(knots_v), std::move(net));
}

}  // namespace ratbez
