// The global nearest point of a curve or surface (closest_point.hpp): weight-certified pieces with their
// control boxes, seeds, and Newton's method from point_inversion.hpp.

#include "ratbez/closest_point.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "analysis/point_inversion.hpp"
#include "geometry/subdivision.hpp"
#include "geometry/surface_evaluator.hpp"
#include "ratbez/box.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"

namespace ratbez {
namespace {

// Newton's stop: it converges in a few iterations where the piece is weight-certified (deviation.cpp
// allows as many), and it stops at rounding (point_inversion.hpp: a search to the last bit would cost
// some 80 evaluations of the point per start for nothing).
constexpr detail::NewtonStop kNewtonStop{.max_iterations = 50, .good_enough = -1, .at_rounding = true};

// Newton starts per surface cell at most, nearest first: ordinary points have one or two; where the
// distance is nearly the same over a whole cell (a point near a sphere's center) every seed qualifies,
// and any start is as good.
constexpr std::size_t kMaxStartsPerCell = 4;

void require_finite_point(const Vec3& p) {
    require(is_finite(p), "point", [&] {
        return "must have finite coordinates (got " + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
               std::to_string(p.z) + ")";
    });
}

// The pieces in the order of the distance from p to their bounding boxes, with that distance: a lower
// bound of the distance from p to the piece, so a search can stop at the first piece whose bound is no
// nearer than its best point.
template <class Piece>
std::vector<std::pair<double, std::size_t>> nearest_boxes_first(const std::vector<Piece>& pieces, const Vec3& p) {
    std::vector<std::pair<double, std::size_t>> order(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) order[k] = {pieces[k].bound.distance_to(p), k};
    std::sort(order.begin(), order.end());
    return order;
}

// ---- curves: where the distance along a piece can have a minimum

// The pieces a curve query examines at most (each a halving of a certified piece) and how deep it halves:
// beyond either, a piece is settled as if its distance had one critical point (only equidistant or
// degenerate geometry gets there).
constexpr std::size_t kMaxCurvePieces = 512;
constexpr int kMaxCurveHalvings = 60;

// C(k, i) for k <= max_n.
std::vector<std::vector<double>> binomial_table(int max_n) {
    std::vector<std::vector<double>> c(static_cast<std::size_t>(max_n + 1));
    for (std::size_t k = 0; k < c.size(); ++k) {
        c[k].assign(k + 1, 1.0);
        for (std::size_t i = 1; i < k; ++i) c[k][i] = c[k - 1][i - 1] + c[k - 1][i];
    }
    return c;
}

// How the distance from p varies along a rational Bézier piece with homogeneous points q (n + 1 of
// them). With C = A / w and Q(t) = A(t) - p w(t), d/dt |C(t) - p|^2 = 2 h(t) / w^3 with
//   h = w (Q . Q') - w' |Q|^2,
// a polynomial of degree 3n - 1 whose Bernstein coefficients follow from the products B_i^a B_j^b =
// C(a, i) C(b, j) / C(a + b, i + j) B_{i+j}^{a+b}; w > 0, so h has the sign of the distance's slope. By
// the variation diminishing property h has no more sign changes on [0, 1] than its coefficients, and its
// first and last coefficients are its values at the ends. A coefficient within rounding of 0 counts as
// either sign.
struct DistanceSlope {
    int sign_changes = 0;  // an upper bound; -1: every coefficient is within rounding of 0 (constant distance)
    bool may_fall_at_start = true, may_rise_at_end = true;
    // True unless the distance is monotone on the piece or has only a maximum inside: then its minimum
    // over the piece is at an end.
    bool may_have_inner_minimum() const { return sign_changes >= 1 && may_fall_at_start && may_rise_at_end; }
};

DistanceSlope distance_slope(const std::vector<Vec4>& q, const Vec3& p, const std::vector<std::vector<double>>& c) {
    const std::size_t n = q.size() - 1;
    if (n == 0) return {-1, false, false};
    std::vector<Vec3> b(n + 1), db(n);    // Q's coefficients and the differences that make Q' / n
    std::vector<double> w(n + 1), dw(n);  // w's and the differences that make w' / n
    for (std::size_t i = 0; i <= n; ++i) b[i] = weighted_part(q[i]) - p * q[i].w, w[i] = q[i].w;
    for (std::size_t i = 0; i < n; ++i) db[i] = b[i + 1] - b[i], dw[i] = w[i + 1] - w[i];
    const std::size_t m = 3 * n - 1;
    // Each coefficient with the sum of its terms' magnitudes, the scale of its rounding error.
    std::vector<double> qdq(2 * n, 0.0), qdq_abs(2 * n, 0.0), qq(2 * n + 1, 0.0), qq_abs(2 * n + 1, 0.0);
    for (std::size_t i = 0; i <= n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {  // Q . Q' / n, degree 2n - 1
            const double term = c[n][i] * c[n - 1][j] / c[2 * n - 1][i + j] * dot(b[i], db[j]);
            qdq[i + j] += term, qdq_abs[i + j] += std::abs(term);
        }
        for (std::size_t j = 0; j <= n; ++j) {  // |Q|^2, degree 2n
            const double term = c[n][i] * c[n][j] / c[2 * n][i + j] * dot(b[i], b[j]);
            qq[i + j] += term, qq_abs[i + j] += std::abs(term);
        }
    }
    std::vector<double> h(m + 1, 0.0), h_abs(m + 1, 0.0);  // h / n
    for (std::size_t i = 0; i <= n; ++i)
        for (std::size_t l = 0; l < 2 * n; ++l) {
            const double f = c[n][i] * c[2 * n - 1][l] / c[m][i + l];
            h[i + l] += f * w[i] * qdq[l], h_abs[i + l] += f * w[i] * qdq_abs[l];
        }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t l = 0; l <= 2 * n; ++l) {
            const double f = c[n - 1][i] * c[2 * n][l] / c[m][i + l];
            h[i + l] -= f * dw[i] * qq[l], h_abs[i + l] += f * std::abs(dw[i]) * qq_abs[l];
        }
    auto zero = [&](std::size_t k) { return std::abs(h[k]) <= 1e-12 * h_abs[k]; };
    // The most sign changes any choice of signs for the coefficients within rounding of 0 gives.
    constexpr int kNone = -1'000'000;
    int ending_positive = 0, ending_negative = 0;  // most changes so far over sequences ending on + / on -
    bool all_zero = true;
    for (std::size_t k = 0; k <= m; ++k) {
        all_zero = all_zero && zero(k);
        const int positive = k == 0 ? 0 : std::max(ending_positive, ending_negative + 1);
        const int negative = k == 0 ? 0 : std::max(ending_negative, ending_positive + 1);
        ending_positive = zero(k) || h[k] > 0 ? positive : kNone;
        ending_negative = zero(k) || h[k] < 0 ? negative : kNone;
    }
    if (all_zero) return {-1, false, false};
    return {std::max(ending_positive, ending_negative), zero(0) || h[0] < 0, zero(m) || h[m] > 0};
}

// The point of a rational Bézier piece at local parameter s (deCasteljau on the homogeneous points, A1.5).
Vec3 bezier_point(std::vector<Vec4> q, double s) {
    for (std::size_t level = 1; level < q.size(); ++level)
        for (std::size_t k = 0; k + level < q.size(); ++k) q[k] = q[k] * (1 - s) + q[k + 1] * s;
    return project(q.front());
}

// ---- surfaces: the box of a cell

// The dyadic piece [a, b] of [0, 1] of a row of Bézier coefficients, by halving (deCasteljau at 1/2, A1.5)
// along the path for_each_certified_piece took to it: the coefficients it visited, exactly.
std::vector<Vec4> dyadic_piece(std::vector<Vec4> row, const Interval& piece) {
    double lo = 0, hi = 1;
    for (int depth = 0; depth < 64 && !(lo == piece.min && hi == piece.max); ++depth) {
        const double m = 0.5 * (lo + hi);
        auto halves = detail::halve_bezier(std::move(row));
        if (piece.min < m) row = std::move(halves.first), hi = m;
        else row = std::move(halves.second), lo = m;
    }
    return row;
}

// The box of the control points of the sub-patch of a rational Bézier patch (rows x columns homogeneous
// points, row-major) over the dyadic pieces `u` and `v` of its [0, 1]^2: it contains that part of the
// surface (convex hull property; the weights stay positive).
Box sub_patch_box(const std::vector<Vec4>& net, std::size_t rows, std::size_t columns, const Interval& u,
                  const Interval& v) {
    std::vector<std::vector<Vec4>> restricted(columns);  // per column j: its points along u, restricted to u
    for (std::size_t j = 0; j < columns; ++j) {
        std::vector<Vec4> column(rows);
        for (std::size_t i = 0; i < rows; ++i) column[i] = net[i * columns + j];
        restricted[j] = dyadic_piece(std::move(column), u);
    }
    Box box;
    for (std::size_t i = 0; i < rows; ++i) {
        std::vector<Vec4> row(columns);
        for (std::size_t j = 0; j < columns; ++j) row[j] = restricted[j][i];
        for (const Vec4& q : dyadic_piece(std::move(row), v)) box.add(project(q));
    }
    return box;
}

// Per weight-certified piece of one direction: the range of its seeds in detail::SeedParams::params.
std::vector<std::pair<std::size_t, std::size_t>> seed_ranges(const detail::SeedParams& seeds) {
    std::vector<std::pair<std::size_t, std::size_t>> ranges(seeds.pieces.size(), {0, 0});
    for (std::size_t k = seeds.params.size(); k-- > 0;) ranges[seeds.piece[k]].first = k;
    for (std::size_t k = 0; k < seeds.params.size(); ++k) ranges[seeds.piece[k]].second = k + 1;
    return ranges;
}

}  // namespace

// ---- curves

struct detail::CurvePieces {
    struct Piece {
        Interval params;        // kept one rounding short of an interior knot (see detail::seed_params)
        std::vector<Vec4> net;  // its homogeneous control points: the piece as a rational Bézier curve
        Box bound;              // the box of their points: contains the piece
        int halvings = 0;
    };
    NurbsCurve curve;
    std::vector<Piece> pieces;  // the weight-certified pieces of every span, in order
    std::vector<std::vector<double>> binomials;
};

namespace {

// The pieces of a curve.
std::shared_ptr<const detail::CurvePieces> make_pieces(const NurbsCurve& curve) {
    auto data = std::make_shared<detail::CurvePieces>(
        detail::CurvePieces{curve, {}, binomial_table(3 * std::max(curve.degree(), 1))});
    const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
    const std::vector<BezierCurve> segments = curve.bezier_segments();
    const std::size_t spans = breaks.size() - 1;
    for (std::size_t k = 0; k < spans; ++k) {
        const double t0 = breaks[k], t1 = breaks[k + 1];
        const std::vector<std::vector<Vec4>> lines{segments[k].homogeneous_points()};
        detail::for_each_certified_piece(
            lines, [](const Vec4& q) { return q.w; }, detail::kMaxHalvings,
            [&](const std::vector<std::vector<Vec4>>& piece_lines, double a, double b) {
                detail::CurvePieces::Piece piece;
                const double end = k + 1 < spans ? std::nextafter(t1, t0) : t1;
                piece.params = {a == 0 ? t0 : t0 + (t1 - t0) * a, b == 1 ? end : t0 + (t1 - t0) * b};
                piece.net = piece_lines[0];
                for (const Vec4& q : piece.net) piece.bound.add(project(q));
                data->pieces.push_back(std::move(piece));
            });
    }
    return data;
}

// Branch and bound over the pieces, nearest box first: each piece offers its ends; a piece whose distance
// has at most one critical point (distance_slope) is settled by Newton from its nearest sample where that
// point can be a minimum; any other piece is halved (deCasteljau, A1.5) and its halves queued by their
// boxes. The search ends when no queued box is nearer than the best point found.
CurveFoot search(const detail::CurvePieces& data, const Vec3& p) {
    using Piece = detail::CurvePieces::Piece;
    double best_t = data.pieces.front().params.min, best = distance(project(data.pieces.front().net.front()), p);
    auto consider = [&](double t, double d) {
        if (d < best) best = d, best_t = t;
    };
    std::deque<Piece> halves;  // made during this query (a deque: the queue points into it)
    using Entry = std::pair<double, const Piece*>;
    std::vector<Entry> queue;  // a min-heap by box distance
    auto push = [&](const Piece& piece) {
        queue.emplace_back(piece.bound.distance_to(p), &piece);
        std::push_heap(queue.begin(), queue.end(), std::greater<>());
    };
    for (const Piece& piece : data.pieces) push(piece);
    while (!queue.empty()) {
        std::pop_heap(queue.begin(), queue.end(), std::greater<>());
        const auto [lower_bound, piece] = queue.back();
        queue.pop_back();
        if (lower_bound >= best) break;
        const Interval t = piece->params;
        consider(t.min, distance(project(piece->net.front()), p));
        consider(t.max, distance(project(piece->net.back()), p));
        const DistanceSlope slope = distance_slope(piece->net, p, data.binomials);
        if (slope.sign_changes > 1 && piece->halvings < kMaxCurveHalvings && halves.size() + 2 <= kMaxCurvePieces) {
            auto [left, right] = detail::halve_bezier(piece->net);
            const double middle = 0.5 * (t.min + t.max);
            for (auto* net : {&left, &right}) {
                Piece half;
                half.params = net == &left ? Interval{t.min, middle} : Interval{middle, t.max};
                half.net = std::move(*net);
                for (const Vec4& q : half.net) half.bound.add(project(q));
                half.halvings = piece->halvings + 1;
                halves.push_back(std::move(half));
                push(halves.back());
            }
            continue;
        }
        if (!slope.may_have_inner_minimum()) continue;
        // Newton from the nearest of five samples: with one critical point, a minimum, it descends to it.
        double start = t.min, start_distance = std::numeric_limits<double>::infinity();
        for (int k = 0; k <= 4; ++k) {
            const double d = distance(bezier_point(piece->net, k / 4.0), p);
            if (d < start_distance) start_distance = d, start = k == 4 ? t.max : t.min + t.width() * k / 4.0;
        }
        const double foot = detail::newton_foot_on_curve(data.curve, p, t, start, {.max_iterations = 30, .at_rounding = true});
        consider(foot, distance(data.curve.point(foot), p));
    }
    const Vec3 point = data.curve.point(best_t);
    return {best_t, point, distance(point, p)};
}

}  // namespace

// ---- surfaces

struct detail::SurfaceCells {
    struct Cell {
        detail::ParameterBox params;  // kept one rounding short of an interior knot (see detail::seed_params)
        Box bound;                    // the box of the cell's control points: contains the cell
        std::size_t a = 0, b = 0;     // its weight-certified pieces along u and along v
        std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;  // its seeds: rows i0 .. i1 - 1 x columns j0 .. j1 - 1
        // A side of the cell collapsed to a point (a pole or apex), if any: the parameter it holds fixed,
        // and whether that is v (the side runs along u, the angle about the pole) or u.
        bool has_pole = false, pole_at_fixed_v = false;
        double pole = 0;
    };
    explicit SurfaceCells(const NurbsSurface& surface) : evaluator(surface) {}
    std::size_t index(std::size_t i, std::size_t j) const { return i * vs.size() + j; }

    detail::SurfaceEvaluator evaluator;
    std::size_t pieces_v = 0;
    std::vector<Cell> cells;    // piece a along u, b along v at a * pieces_v + b
    std::vector<double> us, vs;  // the seed grid's parameters (detail::seed_params)
    std::vector<Vec3> points;    // its points, us.size() x vs.size(), row-major
    std::vector<char> usable;    // 0 at a seed that coincides with a neighbour (on a pole)
    // The sides of the domain that do not collapse to a point, searched as curves (certified, above).
    struct Side {
        std::shared_ptr<const CurvePieces> curve;
        Box bound;
        bool fixed_u = false;  // the side is u = fixed (a curve in v), else v = fixed (a curve in u)
        double fixed = 0;
    };
    std::vector<Side> sides;
};

namespace {

// The cells of a surface, their boxes and seeds.
std::shared_ptr<const detail::SurfaceCells> make_pieces(const NurbsSurface& surface) {
    auto data = std::make_shared<detail::SurfaceCells>(surface);
    const std::vector<std::vector<BezierSurface>> patches = surface.bezier_patches();
    const detail::SeedParams along_u = detail::seed_params(patches, true, surface.knots_u(), surface.degree_u());
    const detail::SeedParams along_v = detail::seed_params(patches, false, surface.knots_v(), surface.degree_v());
    data->us = along_u.params;
    data->vs = along_v.params;
    data->pieces_v = along_v.pieces.size();
    const std::size_t nu = data->us.size(), nv = data->vs.size();
    data->points.resize(nu * nv);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) data->points[data->index(i, j)] = data->evaluator.point(data->us[i], data->vs[j]);
    // "The same point" up to rounding relative to the surface's size: a pole row evaluated at different u
    // gives points that differ in the last bits.
    const double coincident = 1e-12 * surface.control_box().diagonal();
    auto same = [&](std::size_t i, std::size_t j, std::size_t k, std::size_t l) {
        return distance(data->points[data->index(i, j)], data->points[data->index(k, l)]) <= coincident;
    };
    data->usable.resize(nu * nv);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j)
            data->usable[data->index(i, j)] = (i > 0 && same(i, j, i - 1, j)) || (i + 1 < nu && same(i, j, i + 1, j)) ||
                                                      (j > 0 && same(i, j, i, j - 1)) || (j + 1 < nv && same(i, j, i, j + 1))
                                                  ? 0
                                                  : 1;
    // The sides of the domain collapsed to a point: a seed column (fixed v) or row (fixed u) all one point.
    auto collapsed = [&](bool fixed_v, std::size_t line) {
        for (std::size_t k = 1; k < (fixed_v ? nu : nv); ++k)
            if (fixed_v ? !same(0, line, k, line) : !same(line, 0, line, k)) return false;
        return true;
    };
    const std::array<bool, 2> pole_v{collapsed(true, 0), collapsed(true, nv - 1)};
    const std::array<bool, 2> pole_u{collapsed(false, 0), collapsed(false, nu - 1)};
    for (const bool fixed_u : {false, true})
        for (const bool at_max : {false, true}) {
            if (fixed_u ? pole_u[at_max ? 1 : 0] : pole_v[at_max ? 1 : 0]) continue;
            const Interval d = fixed_u ? surface.domain_u() : surface.domain_v();
            const double fixed = at_max ? d.max : d.min;
            const NurbsCurve side = fixed_u ? surface.isocurve_u(fixed) : surface.isocurve_v(fixed);
            data->sides.push_back({make_pieces(side), side.control_box(), fixed_u, fixed});
        }
    const auto ranges_u = seed_ranges(along_u), ranges_v = seed_ranges(along_v);
    for (std::size_t a = 0; a < along_u.pieces.size(); ++a)
        for (std::size_t b = 0; b < along_v.pieces.size(); ++b) {
            const BezierSurface& patch = patches[along_u.span[a]][along_v.span[b]];
            detail::SurfaceCells::Cell cell;
            cell.params = {along_u.pieces[a], along_v.pieces[b]};
            cell.bound = sub_patch_box(patch.homogeneous_points(), static_cast<std::size_t>(patch.degree_u() + 1),
                                       static_cast<std::size_t>(patch.degree_v() + 1), along_u.fraction[a],
                                       along_v.fraction[b]);
            cell.a = a, cell.b = b;
            std::tie(cell.i0, cell.i1) = ranges_u[a];
            std::tie(cell.j0, cell.j1) = ranges_v[b];
            auto pole_at = [&](bool fixed_v, double parameter) {
                if (cell.has_pole) return;
                cell.has_pole = true, cell.pole_at_fixed_v = fixed_v, cell.pole = parameter;
            };
            if (cell.j0 == 0 && pole_v[0]) pole_at(true, data->vs.front());
            if (cell.j1 == nv && pole_v[1]) pole_at(true, data->vs.back());
            if (cell.i0 == 0 && pole_u[0]) pole_at(false, data->us.front());
            if (cell.i1 == nu && pole_u[1]) pole_at(false, data->us.back());
            data->cells.push_back(cell);
        }
    return data;
}

// The cells nearest box first, until no box is nearer than the best point found. In each, every seed is
// a candidate, and Newton starts (kept in the cell) from its seeds that are no farther from p than their
// neighbours in the whole seed grid, nearest first. Where Newton ends on a side the cell shares with
// another, it goes on in that cell while that brings the point nearer.
SurfaceFoot search(const detail::SurfaceCells& data, const Vec3& p) {
    using Cell = detail::SurfaceCells::Cell;
    const std::size_t nu = data.us.size(), nv = data.vs.size();
    std::vector<double> seed_distance(nu * nv, -1.0);  // computed when first asked for
    auto distance_at = [&](std::size_t i, std::size_t j) {
        double& d = seed_distance[data.index(i, j)];
        if (d < 0) d = distance(data.points[data.index(i, j)], p);
        return d;
    };
    detail::ParameterFoot best{data.us.front(), data.vs.front(), distance_at(0, 0)};
    auto newton = [&](const detail::ParameterBox& box, double u, double v) {
        const detail::ParameterFoot foot = detail::newton_foot_on_surface(
            data.evaluator, p, box, std::clamp(u, box.u.min, box.u.max), std::clamp(v, box.v.min, box.v.max), kNewtonStop);
        if (foot.distance < best.distance) best = foot;
        return foot;
    };
    // From a foot on a side of `cell` shared with a neighbouring cell, on in the neighbour.
    auto walk_on = [&](const Cell* cell, detail::ParameterFoot foot) {
        const std::size_t pieces_u = data.cells.size() / data.pieces_v;
        for (int step = 0; step < 8; ++step) {
            std::size_t a = cell->a, b = cell->b;
            if (foot.u <= cell->params.u.min && a > 0) --a;
            else if (foot.u >= cell->params.u.max && a + 1 < pieces_u) ++a;
            else if (foot.v <= cell->params.v.min && b > 0) --b;
            else if (foot.v >= cell->params.v.max && b + 1 < data.pieces_v) ++b;
            else return;
            const Cell* next = &data.cells[a * data.pieces_v + b];
            const detail::ParameterFoot moved = newton(next->params, foot.u, foot.v);
            if (!(moved.distance < foot.distance)) return;
            cell = next, foot = moved;
        }
    };
    // Next to a pole Newton from a seed can run into the pole before it has turned to the right angle
    // about it, and on the pole the angle no longer moves the point: it would stay there. So the angle is
    // first set on the seed's own ring about the pole (Newton with the other parameter held), then Newton
    // runs free; if it still ends on the pole (the best angle drifts from ring to ring), once more from a
    // ring 64 times closer to it.
    // A foot held on a side of the domain is a minimum along that side; an interior minimum can sit closer
    // to the side than the seeds are to each other, in a basin between them that no seed starts in (a
    // random rational bicubic: the side's minimum 1.63982 at (0.730, 0), the surface's 1.63921 at
    // (0.676, 0.0196), seeds 1/12 apart). So once more from half a seed spacing inside.
    const Interval domain_u{data.us.front(), data.us.back()}, domain_v{data.vs.front(), data.vs.back()};
    auto from_inside = [&](const Cell& cell, const detail::ParameterFoot& foot) {
        const double step_u = 0.5 * cell.params.u.width() / static_cast<double>(std::max<std::size_t>(cell.i1 - cell.i0, 1));
        const double step_v = 0.5 * cell.params.v.width() / static_cast<double>(std::max<std::size_t>(cell.j1 - cell.j0, 1));
        double u = foot.u, v = foot.v;
        if (u == domain_u.min) u += step_u;
        else if (u == domain_u.max) u -= step_u;
        if (v == domain_v.min) v += step_v;
        else if (v == domain_v.max) v -= step_v;
        if (u != foot.u || v != foot.v) walk_on(&cell, newton(cell.params, u, v));
    };
    auto from_seed = [&](const Cell& cell, double u, double v) {
        if (!cell.has_pole) {
            const detail::ParameterFoot foot = newton(cell.params, u, v);
            walk_on(&cell, foot);
            return from_inside(cell, foot);
        }
        const bool fixed_v = cell.pole_at_fixed_v;
        double ring = fixed_v ? v : u, angle = fixed_v ? u : v;
        for (int attempt = 0; attempt < 2; ++attempt) {
            const detail::ParameterFoot set = fixed_v ? newton({cell.params.u, {ring, ring}}, angle, ring)
                                                      : newton({{ring, ring}, cell.params.v}, ring, angle);
            angle = fixed_v ? set.u : set.v;
            const detail::ParameterFoot free = newton(cell.params, set.u, set.v);
            if ((fixed_v ? free.v : free.u) != cell.pole) return walk_on(&cell, free);
            ring = cell.pole + (ring - cell.pole) / 64;
        }
    };
    std::vector<std::pair<double, std::size_t>> starts;
    for (const auto& [lower_bound, index] : nearest_boxes_first(data.cells, p)) {
        if (lower_bound >= best.distance) break;
        const Cell& cell = data.cells[index];
        starts.clear();
        for (std::size_t i = cell.i0; i < cell.i1; ++i)
            for (std::size_t j = cell.j0; j < cell.j1; ++j) {
                const double d = distance_at(i, j);
                if (d < best.distance) best = {data.us[i], data.vs[j], d};
                if (!data.usable[data.index(i, j)]) continue;
                auto nearer = [&](std::size_t k, std::size_t l) { return data.usable[data.index(k, l)] && distance_at(k, l) < d; };
                if ((i > 0 && nearer(i - 1, j)) || (i + 1 < nu && nearer(i + 1, j)) || (j > 0 && nearer(i, j - 1)) ||
                    (j + 1 < nv && nearer(i, j + 1)))
                    continue;
                starts.emplace_back(d, data.index(i, j));
            }
        std::sort(starts.begin(), starts.end());
        if (starts.size() > kMaxStartsPerCell) starts.resize(kMaxStartsPerCell);
        for (const auto& [d, seed] : starts) from_seed(cell, data.us[seed / nv], data.vs[seed % nv]);
    }
    // A foot on a side of the domain: the side's own certified curve search, where its box is nearer.
    for (const detail::SurfaceCells::Side& side : data.sides) {
        if (side.bound.distance_to(p) >= best.distance) continue;
        const CurveFoot foot = search(*side.curve, p);
        if (foot.distance < best.distance)
            best = side.fixed_u ? detail::ParameterFoot{side.fixed, foot.u, foot.distance}
                                : detail::ParameterFoot{foot.u, side.fixed, foot.distance};
    }
    const Vec3 point = data.evaluator.point(best.u, best.v);
    return {best.u, best.v, point, distance(point, p)};
}

}  // namespace

// ---- both

template <class Shape, class Foot, class Pieces>
Projector<Shape, Foot, Pieces>::Projector(const Shape& shape) : pieces_(make_pieces(shape)) {}

template <class Shape, class Foot, class Pieces>
Foot Projector<Shape, Foot, Pieces>::closest_point(const Vec3& p) const {
    require_finite_point(p);
    return search(*pieces_, p);
}

template class Projector<NurbsCurve, CurveFoot, detail::CurvePieces>;
template class Projector<NurbsSurface, SurfaceFoot, detail::SurfaceCells>;

CurveFoot closest_point(const NurbsCurve& curve, const Vec3& p) { return CurveProjector(curve).closest_point(p); }
SurfaceFoot closest_point(const NurbsSurface& surface, const Vec3& p) { return SurfaceProjector(surface).closest_point(p); }

}  // namespace ratbez
