// The integration engine (cubature.hpp): globally adaptive Gauss–Legendre cubature on the rational
// Bézier pieces of surfaces and plane curves, for the measures of faces (brep/face_integrals.cpp) and
// the area checks of profiles and planar loops (green_area).
//
// Every surface is cut into its rational Bézier patches (A5.7, NurbsSurface::bezier_patches) and every
// curve into its Bézier segments; each piece is a "cell" with a homogeneous control net of its own over
// [0, 1]^2 (a curve is a net of one column). A fixed rule is not enough: extreme weights crowd the
// geometry into a tiny parameter interval (a quadratic with weights 1, w, 1 runs from P0 to P1 for
// t of order 1/w), where no Gauss node falls, so a rule and its refinement agree on a wrong value.
// Two phases therefore:
//  1. Weight certificate. A cell is halved by deCasteljau (A1.5 on the homogeneous points, Eq. 1.19)
//     until, along each direction, its weights' Bernstein coefficients differ by at most a factor
//     kMaxWeightSpread. The weight function then stays within that factor over the cell (convex hull
//     property) and |w_s / w| <= degree · spread, so no pole of the rational integrand comes near the
//     cell and Gauss–Legendre converges geometrically on it. Circle arcs (weights 1, cos θ) pass at once;
//     a weight ratio R costs about log2(R) halvings per end, each a cell.
//  2. Global adaptivity (QUADPACK's QAG strategy in 2D). On each cell the n x n rule on the whole cell
//     is compared with the rule on its two halves in u and, separately, in v; the differences estimate
//     the error of the whole-cell rule in each direction. The cell with the largest estimate is halved
//     in the direction that disagrees most, until the estimates add up to at most the tolerance
//     (kRelativeTolerance of size^3 for volume, size^2 for area, size = control box diagonal).
// Rounding sets a floor under every cell's estimate: the quotient rule and the subdivision leave
// errors of about ε · size in S_s and S_t, so a cell's integral carries noise of about
// ε · size^(k-1) · (its rounding lengths in s and t: control polygon lengths plus the quotient rule's
// cancellation, see rounding_length), k = 2 for area, 3 for volume; a curve's cell made by halving also
// measures its noise (the rule on its own net against its parent's on the same points, see assess). Refining a
// cell whose estimate is at that floor cannot improve it (with weights 1e300 thousands of cells sit
// where the surface all but stops), so such a cell counts as converged.
// Both phases count cells against kMaxCells, so hostile input costs bounded work; when the budget runs
// out before the tolerance is met, Error says so instead of returning an unverified number.
// Two shortcuts keep large faces (10^5 spans) cheap without changing what is computed:
//  - A non-rational face or edge has a polynomial integrand for the volume and for Green's area, and
//    n Gauss nodes integrate a polynomial of degree 2n - 1 exactly: its cells need no error estimate.
//  - The quick rule of the orientation check takes a face or edge whose control weights already vary by
//    at most kMaxWeightSpread straight on its knot spans (span_rule.hpp): every patch would pass the
//    certificate at once, so extracting the patches would only cost allocations.
#include "analysis/cubature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include "analysis/span_rule.hpp"
#include "geometry/subdivision.hpp"
#include "geometry/surface_evaluator.hpp"
#include "math/gauss_legendre.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/box.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"

namespace ratbez::detail {

namespace {

// ------------------------------------------------------------------------------------ the engine

constexpr double kRelativeTolerance = 1e-14;
constexpr int kRulePoints = 12;
constexpr int kQuickRulePoints = 6;
constexpr std::size_t kMaxCells = 40'000;
// The rounding floor of a cell, in units of ε · size^(k-1) · (polygon lengths): generous for degree 25.
constexpr double kNoiseFactor = 16 * std::numeric_limits<double>::epsilon();
// A curve's cell's measured noise (assess) counts this many times in its floor: the error estimate compares three
// rules, each as noisy.
constexpr double kMeasuredNoiseFactor = 4;

using Integrand = Cubature::Integrand;

// One integrand over Bézier pieces of one pair of degrees: a surface face, or one edge of a planar
// face's loop (degree_v = 0: the piece is a curve in s and S_t = 0).
// `polynomial_factor` k > 0 says that the integrand is a polynomial of degree k·p - 1 along a direction
// of degree p (a non-rational source: k = 3 for the volume, 2 for Green's area); 0 that it is not.
struct Source {
    int degree_u = 0, degree_v = 0;
    Integrand integrand;
    int polynomial_factor = 0;
    // The integrand's own rounding relative to its size where the control polygon does not tell it: the inner
    // integral of a trimmed region (Gauss on the surface's spans, summed) under the boundary curve's cells.
    double relative_noise = 0;
};

// A piece of a source as a rational Bézier patch over [0, 1]^2 of its own; the integrand is taken in
// these local parameters (S_s x S_t carries the Jacobian of the halving, so no scaling is needed).
struct Cell {
    const Source* source = nullptr;
    std::vector<Vec4> net;  // (degree_u + 1) x (degree_v + 1), row-major
    double whole = std::numeric_limits<double>::quiet_NaN();  // the rule on the whole cell, once known
    // Set by assess(): the rule on the halves in u and in v, the estimate and its error bound.
    std::array<double, 2> halves_u{}, halves_v{};
    // `error` is the error bound, or 0 once the bound is down at the rounding floor.
    double estimate = 0, error = 0;
    bool split_along_u = true;
};

}  // namespace

// The pieces and integrands of a problem; sources live in a deque so cells can point at them.
// The integrals add up to within `tolerance`; `noise_scale` = kNoiseFactor · size^(k-1).
// A `quick` problem (the orientation check) keeps a net whose weights pass the certificate as a whole
// in `nets`, for the quick rule on its spans, instead of cutting it into cells.
// Everything is held in `frame` (cubature.hpp): the cells' nets and the quick nets' points (kept in
// `local_points`, which the nets' spans view); `power` scales the sum back to world units.
struct Cubature::Problem {
    std::deque<Source> sources;
    std::vector<Cell> cells;
    double tolerance = 0, noise_scale = 0;
    bool quick = false;
    std::vector<std::pair<const Source*, SpanNet>> nets;
    LocalFrame frame;
    int power = 0;
    std::deque<std::vector<Vec4>> local_points;

    std::vector<Vec4> local(std::span<const Vec4> points) const {
        std::vector<Vec4> moved(points.size());
        for (std::size_t k = 0; k < points.size(); ++k) moved[k] = frame.to_local(points[k]);
        return moved;
    }
};

namespace {

using Problem = Cubature::Problem;

// Cells created so far against kMaxCells. `quick` (the orientation check of a new Solid) stops refining
// when the budget is spent; the measuring functions say that they cannot reach the accuracy.
// Every kCellsPerPoll new cells the caller's progress callback is polled (progress.hpp), which is how
// Ctrl-C reaches a measurement of a face that extreme weights cut into very many cells.
// The budget grows with the pieces the problem starts from (kCellsPerPiece each, besides kMaxCells), so
// that the work stays proportional to the input: a loft of 200 sections, whose 2,600 Bézier patches each
// need a few halvings, ran out of a fixed 40,000 and was refused as if extreme weights crowded it (issue 29).
constexpr std::size_t kCellsPerPiece = 16;

struct Budget {
    static constexpr std::size_t kCellsPerPoll = 256;
    std::string_view argument;
    bool quick = false;
    const Progress* progress = nullptr;
    std::size_t cells = 0;
    std::size_t pieces = 0;  // the cells the problem started from

    std::size_t limit() const { return kMaxCells + kCellsPerPiece * pieces; }
    // Counts n new cells; false (quick) or Error (measuring) once the budget is spent.
    bool spend(std::size_t n) {
        if (progress != nullptr && *progress && cells / kCellsPerPoll != (cells + n) / kCellsPerPoll) (*progress)(0.0);
        cells += n;
        if (cells <= limit()) return true;
        if (quick) return false;
        fail(argument, "the quadrature of its area or volume cannot reach a relative accuracy of 1e-14 within " +
                           std::to_string(limit()) + " cells for its " + std::to_string(pieces) +
                           " Bézier pieces (its rational weights crowd the surface into too small a parameter range)");
    }
};

// ------------------------------------------------------------------------------------ cell geometry

// The net of a cell as lines along one direction: `count` lines of `degree + 1` entries each.
struct Lines {
    const Source& source;
    bool along_u;
    int count() const { return (along_u ? source.degree_v : source.degree_u) + 1; }
    int degree() const { return along_u ? source.degree_u : source.degree_v; }
    // The index in the row-major net (i along u, j along v) of entry k of line `line`.
    std::size_t at(int line, int k) const {
        const int i = along_u ? k : line, j = along_u ? line : k;
        return static_cast<std::size_t>(i * (source.degree_v + 1) + j);
    }
};

// max / min of the weights along one direction, the worst over the lines of the net.
double weight_spread(const Cell& cell, bool along_u) {
    const Lines lines{*cell.source, along_u};
    double worst = 1;
    for (int line = 0; line < lines.count(); ++line) {
        double lo = std::numeric_limits<double>::infinity(), hi = 0;
        for (int k = 0; k <= lines.degree(); ++k) {
            const double w = cell.net[lines.at(line, k)].w;
            lo = std::min(lo, w);
            hi = std::max(hi, w);
        }
        worst = std::max(worst, hi / lo);
    }
    return worst;
}

// The scale of the rounding errors of S_s or S_t on a cell, along one direction, the worst over the
// lines of the net: the control polygon's length (the size of the isocurves, which the subdivision's
// errors are proportional to) plus |P|max · n · max|Δw| / min w, the quotient rule's share: S_s =
// (A_s - S w_s) / w loses about ε |S| |w_s / w| to cancellation, and |S| is the distance from the
// coordinate origin, not from the cell. The second term matters where extreme weights make a curve all
// but stop (a conic with weights 1, 1e300, 1 near its middle): the polygon is tiny there, but S_s is
// still the difference of two large numbers.
double rounding_length(const Cell& cell, bool along_u) {
    const Lines lines{*cell.source, along_u};
    double longest = 0;
    for (int line = 0; line < lines.count(); ++line) {
        double polygon = 0, magnitude = 0, min_weight = std::numeric_limits<double>::infinity(), max_step = 0;
        for (int k = 0; k <= lines.degree(); ++k) {
            const Vec4& p = cell.net[lines.at(line, k)];
            magnitude = std::max(magnitude, norm(project(p)));
            min_weight = std::min(min_weight, p.w);
            if (k == 0) continue;
            const Vec4& q = cell.net[lines.at(line, k - 1)];
            polygon += distance(project(q), project(p));
            max_step = std::max(max_step, std::abs(p.w - q.w));
        }
        longest = std::max(longest, polygon + magnitude * lines.degree() * max_step / min_weight);
    }
    return longest;
}

// The two halves of a cell at the parameter 1/2 along one direction: deCasteljau (A1.5) on every line
// of homogeneous points; the left edge of the triangle is the first half's net, the right edge the
// second's (the same subdivision as BezierCurve::split, Eq. 1.19).
std::pair<Cell, Cell> halve(const Cell& cell, bool along_u) {
    const Lines lines{*cell.source, along_u};
    const int n = lines.degree();
    std::pair<Cell, Cell> halves{Cell{cell.source, cell.net}, Cell{cell.source, cell.net}};
    std::vector<Vec4> row(static_cast<std::size_t>(n + 1));
    for (int line = 0; line < lines.count(); ++line) {
        for (int k = 0; k <= n; ++k) row[static_cast<std::size_t>(k)] = cell.net[lines.at(line, k)];
        const auto [left, right] = halve_bezier(row);
        for (int k = 0; k <= n; ++k) {
            halves.first.net[lines.at(line, k)] = left[static_cast<std::size_t>(k)];
            halves.second.net[lines.at(line, k)] = right[static_cast<std::size_t>(k)];
        }
    }
    return halves;
}

// ------------------------------------------------------------------------------------- quadrature

// The tensor Gauss–Legendre rule on [s0, s1] x [t0, t1] of a cell with `points_s` x `points_t` nodes
// (one node in t for a curve, whose integrand does not depend on t).
double rule(const Cell& cell, double s0, double s1, double t0, double t1, int points_s, int points_t) {
    const Source& source = *cell.source;
    const GaussRule& rs = gauss_legendre(points_s);
    const GaussRule& rt = gauss_legendre(source.degree_v == 0 ? 1 : points_t);
    double sum = 0;
    for (std::size_t i = 0; i < rs.nodes.size(); ++i) {
        const double s = s0 + (s1 - s0) * rs.nodes[i];
        double row = 0;
        for (std::size_t j = 0; j < rt.nodes.size(); ++j) {
            const double t = t0 + (t1 - t0) * rt.nodes[j];
            row += rt.weights[j] *
                   source.integrand(bezier_patch_first_derivatives(cell.net.data(), source.degree_u, source.degree_v, s, t));
        }
        sum += rs.weights[i] * row;
    }
    return sum * (s1 - s0) * (t1 - t0);
}
double rule(const Cell& cell, double s0, double s1, double t0, double t1, int points) {
    return rule(cell, s0, s1, t0, t1, points, points);
}

// Gauss nodes that integrate a polynomial source's integrand exactly along a direction of degree p
// (n nodes are exact to degree 2n - 1, the integrand has degree k·p - 1), or 0 for another source.
int exact_points(const Source& source, int degree) {
    if (source.polynomial_factor == 0) return 0;
    return std::max(1, (source.polynomial_factor * degree + 1) / 2);
}

// The whole-cell rule against the rules on the halves in u and in v. Their differences estimate the
// whole rule's error in each direction (E_u, E_v); halves_u + halves_v - whole removes both to first
// order and is the cell's estimate, E_u + E_v its (pessimistic) error bound — or 0 when that is no more
// than the cell's rounding floor. A polynomial integrand is integrated exactly at once: error 0, so the
// cell is never halved.
void assess(Cell& cell, double noise_scale) {
    const int exact_u = exact_points(*cell.source, cell.source->degree_u), exact_v = exact_points(*cell.source, cell.source->degree_v);
    if (exact_u > 0 && exact_u <= kRulePoints && exact_v <= kRulePoints) {
        cell.whole = cell.estimate = rule(cell, 0, 1, 0, 1, exact_u, exact_v);
        cell.error = 0;
        return;
    }
    // A curve's cell (degree_v = 0: Green's edges and trimming curves) made by halving has its whole rule from its
    // parent, at the same points of the curve: the rule again on its own net differs from it only by rounding,
    // which measures the cell's noise. Its control points are rounded to ε · |C| however short the cell is (and a
    // trimming curve's inner integral loses as much in u - start), so that noise does not shrink with the cell:
    // far out in its parameters a hole's boundary was halved into tens of thousands of cells, their noise adding
    // up beyond the tolerance, until the budget ran out (a screw thread's face from a SolidWorks STEP file).
    double measured_noise = 0;
    if (std::isnan(cell.whole)) {
        cell.whole = rule(cell, 0, 1, 0, 1, kRulePoints);
    } else if (cell.source->degree_v == 0) {
        measured_noise = std::abs(rule(cell, 0, 1, 0, 1, kRulePoints) - cell.whole);
    }
    cell.halves_u = {rule(cell, 0, 0.5, 0, 1, kRulePoints), rule(cell, 0.5, 1, 0, 1, kRulePoints)};
    if (cell.source->degree_v == 0)
        cell.halves_v = {cell.whole, 0.0};  // a curve: nothing varies along t
    else
        cell.halves_v = {rule(cell, 0, 1, 0, 0.5, kRulePoints), rule(cell, 0, 1, 0.5, 1, kRulePoints)};
    const double along_u = cell.halves_u[0] + cell.halves_u[1], along_v = cell.halves_v[0] + cell.halves_v[1];
    const double error_u = std::abs(along_u - cell.whole), error_v = std::abs(along_v - cell.whole);
    cell.estimate = along_u + along_v - cell.whole;
    const double floor = noise_scale * (rounding_length(cell, true) + rounding_length(cell, false)) +
                         cell.source->relative_noise * (std::abs(cell.halves_u[0]) + std::abs(cell.halves_u[1])) +
                         kMeasuredNoiseFactor * measured_noise;
    cell.error = error_u + error_v > floor ? error_u + error_v : 0.0;
    cell.split_along_u = error_u >= error_v;
}

// Phase 1: halve every cell until its weights vary by at most kMaxWeightSpread in each direction.
std::vector<Cell> certified(std::vector<Cell> pending, Budget& budget) {
    std::vector<Cell> done;
    while (!pending.empty()) {
        Cell cell = std::move(pending.back());
        pending.pop_back();
        const double spread_u = weight_spread(cell, true), spread_v = weight_spread(cell, false);
        if (std::max(spread_u, spread_v) <= kMaxWeightSpread || !budget.spend(2)) {
            done.push_back(std::move(cell));
            continue;
        }
        auto [first, second] = halve(cell, spread_u >= spread_v);
        pending.push_back(std::move(first));
        pending.push_back(std::move(second));
    }
    return done;
}

// Phase 2: refine the cell with the largest error estimate until the estimates add up to `tolerance`.
double adaptive_sum(std::vector<Cell> cells, double tolerance, double noise_scale, Budget& budget) {
    auto by_error = [](const Cell& a, const Cell& b) { return a.error < b.error; };
    for (Cell& cell : cells) assess(cell, noise_scale);
    std::make_heap(cells.begin(), cells.end(), by_error);
    auto total_error = [&] {
        double e = 0;
        for (const Cell& cell : cells) e += cell.error;
        return e;
    };
    double error = total_error();
    for (;;) {
        // The running total drifts by rounding as errors are removed and added: confirm with a fresh sum.
        if (error <= tolerance && (error = total_error()) <= tolerance) break;
        if (!std::isfinite(error)) break;  // a non-finite integrand: the caller reports the non-finite result
        budget.spend(2);
        std::pop_heap(cells.begin(), cells.end(), by_error);
        Cell worst = std::move(cells.back());
        cells.pop_back();
        auto [first, second] = halve(worst, worst.split_along_u);
        const auto& halves = worst.split_along_u ? worst.halves_u : worst.halves_v;
        first.whole = halves[0];
        second.whole = halves[1];
        error -= worst.error;
        for (Cell* child : {&first, &second}) {
            assess(*child, noise_scale);
            error += child->error;
            cells.push_back(std::move(*child));
            std::push_heap(cells.begin(), cells.end(), by_error);
        }
    }
    CompensatedSum sum;  // 10^5 cells: naive summation would cost more than the tolerance
    for (const Cell& cell : cells) sum.add(cell.estimate);
    return sum.value();
}

// Nodes per direction for the quick rule: the volume integrand (S - c) · (S_u x S_v) of a polynomial
// cell of degree p has degree 3p - 1 there, which ceil(3p / 2) Gauss nodes integrate exactly (exact to
// degree 2n - 1); one more for the certified rational cells, at most kQuickRulePoints. A polygonal
// profile (p = 1) of 10^5 segments costs 3 nodes across each instead of 6.
int quick_points(int degree) { return std::min(kQuickRulePoints, (3 * degree + 1) / 2 + 1); }

// The quick estimate for the orientation check: the low-order rule on the certified cells and on the
// spans of the nets that needed no certificate (the same rule: a span is a patch), no refinement.
double quick_sum(const std::vector<Cell>& cells, const std::vector<std::pair<const Source*, SpanNet>>& nets) {
    double sum = 0;
    for (const Cell& cell : cells)
        sum += rule(cell, 0, 1, 0, 1, quick_points(cell.source->degree_u), quick_points(cell.source->degree_v));
    for (const auto& [source, net] : nets)
        sum += span_rule(net, quick_points(net.degree_u), quick_points(net.degree_v), source->integrand);
    return sum;
}

double integrate(Problem problem, Budget& budget) {
    for (const Source& source : problem.sources)
        require(source.degree_u <= kMaxEvaluatorDegree && source.degree_v <= kMaxEvaluatorDegree,
                budget.argument, "a face or edge of degree above 25 cannot be measured (OpenCASCADE's limit too)");
    budget.pieces = problem.cells.size();
    std::vector<Cell> cells = certified(std::move(problem.cells), budget);
    return problem.quick ? quick_sum(cells, problem.nets) : adaptive_sum(std::move(cells), problem.tolerance, problem.noise_scale, budget);
}

// ------------------------------------------------------------------------------------------- faces

// The source of a curve's or surface's integrand (`polynomial_factor` as in Source, if its weights are
// all equal). Returns the source for the caller to add its Bézier pieces as cells, or nullptr when a
// quick problem takes the net whole (its weights pass the certificate already).
// `in_parameters`: the net is a curve in a surface's (u, v) (a trimming curve), which the local frame does not
// move; `relative_noise` as in Source.
const Source* add_source(SpanNet net, Integrand integrand, int polynomial_factor, Problem& problem,
                         double relative_noise = 0, bool in_parameters = false) {
    const double weight_ratio = control_weight_ratio(net.points);
    const Source& source = problem.sources.emplace_back(
        Source{net.degree_u, net.degree_v, std::move(integrand), weight_ratio == 1 ? polynomial_factor : 0, relative_noise});
    if (!problem.quick || !(weight_ratio <= kMaxWeightSpread)) return &source;
    net.points = problem.local_points.emplace_back(in_parameters ? std::vector<Vec4>(net.points.begin(), net.points.end())
                                                                 : problem.local(net.points));
    problem.nets.emplace_back(&source, net);
    return nullptr;
}

// The cells of a surface face's Bézier patches (A5.7), all with one integrand of (S, S_u, S_v).
void add_surface(const NurbsSurface& surface, Integrand integrand, int polynomial_factor, Problem& problem) {
    const Source* source = add_source(span_net(surface), std::move(integrand), polynomial_factor, problem);
    if (source == nullptr) return;
    for (const auto& row : surface.bezier_patches())
        for (const BezierSurface& patch : row) problem.cells.push_back(Cell{source, problem.local(patch.homogeneous_points())});
}

// The cells of one curve's Bézier segments for `factor` times Green's area integral (1/2)(x y' - y x'),
// x = (C - origin)·x_axis, y = (C - origin)·y_axis, in the curve's own direction; `origin` in world
// coordinates, `factor` in the problem's local units. The frame is copied into the integrand, so the
// caller's vectors need not outlive the problem.
void add_green(const NurbsCurve& curve, const Vec3& world_origin, const Vec3& x_axis, const Vec3& y_axis, double factor,
               Problem& problem) {
    const Vec3 origin = problem.frame.to_local(world_origin);
    // x y' - y x' has degree 2p - 1 on a polynomial curve of degree p.
    const Source* source = add_source(
        span_net(curve),
        [factor, origin, x_axis, y_axis](const SurfaceFirstDerivatives& d) {
            const Vec3 r = d.s - origin;
            const double x = dot(r, x_axis), y = dot(r, y_axis);
            return factor * 0.5 * (x * dot(d.su, y_axis) - y * dot(d.su, x_axis));
        },
        2, problem);
    if (source == nullptr) return;
    for (const BezierCurve& segment : curve.bezier_segments())
        problem.cells.push_back(Cell{source, problem.local(segment.homogeneous_points())});
}

// The inner integral of a trimmed region (Cubature::add_trimmed_surface): G(u, v) = ∫ g(S(s, v)) ds from the
// domain's start to u along one parameter direction (`along_u`; with the roles of u and v swapped
// otherwise), Gauss–Legendre on each knot span it crosses. A span's rational integrand stays smooth when its
// weights do, so a span whose weights vary by more than kMaxWeightSpread along the direction is cut into
// 2^k equal pieces for a spread of up to kMaxWeightSpread^k (the same measure as the engine's certificate).
class InnerIntegral {
public:
    // The integral runs from `start` (inside the domain: the region's lowest parameter keeps G small, so the
    // boundary pieces' contributions cancel less).
    InnerIntegral(const NurbsSurface& surface, Integrand integrand, bool along_u, double start)
        : evaluator_(surface), integrand_(std::move(integrand)), along_u_(along_u) {
        const int degree = along_u ? surface.degree_u() : surface.degree_v();
        const std::vector<double> breaks = breakpoints(degree, along_u ? surface.knots_u() : surface.knots_v());
        // The pieces: each knot span from `start` on, cut where its weights spread widely.
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            if (breaks[k + 1] <= start) continue;
            const double a = std::max(breaks[k], start), b = breaks[k + 1];
            const double spread = span_weight_spread(surface, breaks[k], breaks[k + 1], along_u);
            int pieces = 1;
            for (double s = spread; s > kMaxWeightSpread && pieces < 64; s /= kMaxWeightSpread) pieces *= 2;
            for (int j = 0; j < pieces; ++j) starts_.push_back(a + (b - a) * j / pieces);
        }
        if (starts_.empty()) starts_.push_back(breaks.back());
        starts_.push_back(breaks.back());
        points_ = std::min(32, std::max(kRulePoints, (3 * degree + 1) / 2 + 1));
    }

    // G at (u, v), or H at (u, v) for the direction v: the integral from the domain's start to the
    // running parameter (u, or v) with the other one fixed.
    double operator()(double u, double v) const {
        const double end = along_u_ ? u : v, fixed = along_u_ ? v : u;
        const GaussRule& rule = gauss_legendre(points_);
        CompensatedSum sum;
        for (std::size_t k = 0; k + 1 < starts_.size() && starts_[k] < end; ++k) {
            const double a = starts_[k], b = std::min(starts_[k + 1], end);
            double piece = 0;
            for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
                const double s = a + (b - a) * rule.nodes[i];
                piece += rule.weights[i] * integrand_(along_u_ ? evaluator_.first_derivatives(s, fixed)
                                                               : evaluator_.first_derivatives(fixed, s));
            }
            sum.add(piece * (b - a));
        }
        return sum.value();
    }

private:
    // max w / min w of the weights of the control points that act on [a, b] along the direction, over
    // every line across it: bounds the spread of the weight function there (convex hull property).
    static double span_weight_spread(const NurbsSurface& surface, double a, double b, bool along_u) {
        const int degree = along_u ? surface.degree_u() : surface.degree_v();
        const std::vector<double>& knots = along_u ? surface.knots_u() : surface.knots_v();
        const int span = find_span(degree, knots, 0.5 * (a + b));
        double worst = 1;
        const int lines = along_u ? surface.columns() : surface.rows();
        for (int line = 0; line < lines; ++line) {
            double lo = std::numeric_limits<double>::infinity(), hi = 0;
            for (int k = span - degree; k <= span; ++k) {
                const double w = (along_u ? surface.homogeneous_point(k, line) : surface.homogeneous_point(line, k)).w;
                lo = std::min(lo, w);
                hi = std::max(hi, w);
            }
            worst = std::max(worst, hi / lo);
        }
        return worst;
    }

    SurfaceEvaluator evaluator_;
    Integrand integrand_;
    bool along_u_;
    std::vector<double> starts_;  // the pieces' starts, then the domain's end
    int points_ = kRulePoints;
};

// The boundary curve with its Bézier segments ending wherever its coordinate `axis` (0: u, 1: v) crosses one
// of `lines`: the outer integrand jumps there (across a C0 knot of the surface in that direction, as the double
// knots of a rational circle, the speed |S_u| jumps, and G or H with it), and a cell with a jump inside converges
// only linearly under halving. Crossings are found per segment from 32 samples and bisection; a curve that only
// touches a line gains nothing from a cut.
NurbsCurve cut_at_crossings(const NurbsCurve& curve, int axis, const std::vector<double>& lines) {
    if (lines.empty()) return curve;
    const auto coordinate = [&](double t) {
        const Vec3 p = curve.point(t);
        return axis == 0 ? p.x : p.y;
    };
    std::vector<double> cuts;
    const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
    const std::vector<BezierCurve> segments = curve.bezier_segments();
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const Vec4& pw : segments[k].homogeneous_points()) {
            const Vec3 p = project(pw);
            lo = std::min(lo, axis == 0 ? p.x : p.y), hi = std::max(hi, axis == 0 ? p.x : p.y);
        }
        for (double line : lines) {
            if (line <= lo || line >= hi) continue;  // convex hull: the segment stays on one side
            constexpr int kSamples = 32;
            double a = breaks[k], fa = coordinate(a) - line;
            for (int j = 1; j <= kSamples; ++j) {
                const double b = j == kSamples ? breaks[k + 1] : breaks[k] + (breaks[k + 1] - breaks[k]) * j / kSamples;
                const double fb = coordinate(b) - line;
                if ((fa < 0) != (fb < 0)) {
                    double x0 = a, x1 = b, f0 = fa;
                    for (int step = 0; step < 60 && x1 - x0 > 1e-15 * (std::abs(x0) + std::abs(x1)); ++step) {
                        const double m = 0.5 * (x0 + x1), fm = coordinate(m) - line;
                        if ((fm < 0) == (f0 < 0)) x0 = m, f0 = fm;
                        else x1 = m;
                    }
                    cuts.push_back(0.5 * (x0 + x1));
                }
                a = b, fa = fb;
            }
        }
    }
    NurbsCurve out = curve;
    const Interval d = curve.domain();
    std::sort(cuts.begin(), cuts.end());
    for (double t : cuts) {
        if (t <= d.min || t >= d.max) continue;
        const int multiplicity = static_cast<int>(std::count(out.knots().begin(), out.knots().end(), t));
        if (multiplicity < out.degree()) out = out.insert_knot(t, out.degree() - multiplicity);
    }
    return out;
}

// The distinct interior breakpoints of a surface in one direction.
std::vector<double> interior_breaks(const NurbsSurface& surface, bool along_u) {
    std::vector<double> breaks = breakpoints(along_u ? surface.degree_u() : surface.degree_v(),
                                             along_u ? surface.knots_u() : surface.knots_v());
    if (breaks.size() <= 2) return {};
    return std::vector<double>(breaks.begin() + 1, breaks.end() - 1);
}

// The cells of a trimmed region's boundary curves: on each Bézier segment of a curve (x(t), y(t)) = (u, v),
// sign · G(u, v) · v'(t) (sign · -H(u, v) · u'(t) along v), which sums to the double integral of g over the
// region by Green's theorem (∮ G dv = ∬ ∂G/∂u du dv = ∬ g du dv; likewise ∮ -H du = ∬ ∂H/∂v).
void add_trimmed_surface(const NurbsSurface& surface, const std::vector<Cubature::TrimmingCurve>& boundary,
                         Integrand integrand, Problem& problem) {
    const auto spans = [](int degree, const std::vector<double>& knots) { return breakpoints(degree, knots).size(); };
    const bool along_u = spans(surface.degree_u(), surface.knots_u()) <= spans(surface.degree_v(), surface.knots_v());
    // G from the region's lowest parameter in that direction (the curves' control boxes bound it from below).
    const Interval domain = along_u ? surface.domain_u() : surface.domain_v();
    double start = domain.max;
    for (const Cubature::TrimmingCurve& curve : boundary) {
        const Box box = curve.pcurve->control_box();
        start = std::min(start, along_u ? box.min.x : box.min.y);
    }
    start = std::clamp(start, domain.min, domain.max);
    // The integrand sees the surface in the problem's local frame (cubature.hpp), as every other source does;
    // the trimming curves are parameters, which the frame leaves alone.
    const NurbsSurface local = NurbsSurface::from_homogeneous(surface.degree_u(), surface.degree_v(), surface.knots_u(),
                                                              surface.knots_v(), problem.local(surface.homogeneous_points()),
                                                              surface.is_rational());
    const auto inner = std::make_shared<const InnerIntegral>(local, std::move(integrand), along_u, start);
    for (const Cubature::TrimmingCurve& curve : boundary) {
        const double sign = along_u ? curve.sign : -curve.sign;
        // G is a sum of 12-point rules over the spans, each rounding at a few ulps of its terms, and the line
        // integral of G dv cancels between the region's sides (its terms are as large as the strip under the
        // region, not the region): 1e-13 of a cell's value is its rounding floor (measured: a hole's wall
        // through a cylinder stalled at 8e-15 on cells of 0.1).
        const Source* source = add_source(
            span_net(*curve.pcurve),
            [inner, sign, along_u](const SurfaceFirstDerivatives& d) {
                return sign * (*inner)(d.s.x, d.s.y) * (along_u ? d.su.y : d.su.x);
            },
            0, problem, 1e-13, /*in_parameters=*/true);
        if (source == nullptr) continue;
        // Cut where the curve crosses the surface's knot lines across the inner direction (H jumps there).
        const NurbsCurve cut = cut_at_crossings(*curve.pcurve, along_u ? 1 : 0, interior_breaks(surface, !along_u));
        for (const BezierCurve& segment : cut.bezier_segments()) problem.cells.push_back(Cell{source, segment.homogeneous_points()});
    }
}

}  // namespace

LocalFrame LocalFrame::of(const Box& box) {
    LocalFrame frame;
    if (box.empty()) return frame;
    frame.reference = box.center();
    const double size = box.diagonal();
    // ilogb: exact, and no rounding in 2^-exponent; a size of 0 or beyond the double range stays unscaled.
    if (size > 0 && std::isfinite(size) && is_finite(frame.reference)) frame.exponent = std::ilogb(size);
    else frame.reference = {};
    return frame;
}

Vec3 LocalFrame::to_local(const Vec3& world) const {
    return {std::ldexp(world.x - reference.x, -exponent), std::ldexp(world.y - reference.y, -exponent),
            std::ldexp(world.z - reference.z, -exponent)};
}

Vec4 LocalFrame::to_local(const Vec4& p) const {
    return {std::ldexp(std::fma(-p.w, reference.x, p.x), -exponent), std::ldexp(std::fma(-p.w, reference.y, p.y), -exponent),
            std::ldexp(std::fma(-p.w, reference.z, p.z), -exponent), p.w};
}

Cubature::Cubature(const Box& box, int power, bool quick) : problem_(std::make_unique<Problem>()) {
    problem_->quick = quick;
    problem_->frame = LocalFrame::of(box);
    problem_->power = power;
    const double size = problem_->frame.to_local(box.diagonal());
    // The tolerance and the rounding floor of kNoiseFactor in units of size^power and size^(power - 1), in the
    // local frame (size between 1 and 2).
    if (power == 3) {
        problem_->tolerance = kRelativeTolerance * size * size * size;
        problem_->noise_scale = kNoiseFactor * size * size;
    } else {
        require(power == 2, "power", "an integral here is an area (2) or a volume (3)");
        problem_->tolerance = kRelativeTolerance * size * size;
        problem_->noise_scale = kNoiseFactor * size;
    }
}

Cubature::Cubature(Cubature&&) noexcept = default;
Cubature& Cubature::operator=(Cubature&&) noexcept = default;
Cubature::~Cubature() = default;

void Cubature::add_surface(const NurbsSurface& surface, Integrand integrand, int polynomial_factor) {
    detail::add_surface(surface, std::move(integrand), polynomial_factor, *problem_);
}

void Cubature::add_surface_area(const NurbsSurface& surface) {
    add_surface(surface, [](const SurfaceFirstDerivatives& d) { return norm(cross(d.su, d.sv)); }, 0);
}

void Cubature::add_green(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                         double factor) {
    detail::add_green(curve, origin, x_axis, y_axis, factor, *problem_);
}

void Cubature::add_trimmed_surface(const NurbsSurface& surface, const std::vector<TrimmingCurve>& boundary,
                                   Integrand integrand) {
    detail::add_trimmed_surface(surface, boundary, std::move(integrand), *problem_);
}

const LocalFrame& Cubature::frame() const { return problem_->frame; }

double Cubature::integrate(std::string_view argument, const Progress* progress) {
    Budget budget{argument, problem_->quick, progress};
    const int scale = problem_->power * problem_->frame.exponent;
    return std::ldexp(detail::integrate(std::move(*problem_), budget), scale);
}

double surface_area(const NurbsSurface& surface, std::string_view argument) {
    Cubature area(surface.control_box(), 2);
    area.add_surface_area(surface);
    return area.integrate(argument);
}

double green_area(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                  double absolute_tolerance, std::string_view argument) {
    // The same two phases as the measurements: the weight certificate puts Gauss nodes where extreme
    // weights crowd the curve (a fixed-depth rule misses a piece with weights 1e12 / 1e-12 entirely
    // and calls the profile empty), then refinement to the caller's tolerance.
    // The integrand x y' - y x' carries rounding noise of about ε · reach · |C'| (reach: how far the curve
    // gets from `origin`), so the integral cannot be known better than about ε · reach · (polygon length).
    // A tolerance below that would refine forever; it is raised to a few times that floor instead.
    // In the LocalFrame of the curve's box with `origin` (cubature.hpp): the integral of a small curve far
    // from the coordinate origin is then as accurate as at the origin.
    Box box = curve.control_box();
    Problem problem;
    problem.frame = LocalFrame::of([&] {
        Box with_origin = box;
        with_origin.add(origin);
        return with_origin;
    }());
    const LocalFrame& frame = problem.frame;
    const Vec3 local_origin = frame.to_local(origin);
    const Box local_box{frame.to_local(box.min), frame.to_local(box.max)};
    const double reach = local_box.diagonal() + norm(local_box.min - local_origin);
    double length = 0;
    const std::vector<Vec4> points = problem.local(curve.homogeneous_points());
    for (std::size_t i = 0; i + 1 < points.size(); ++i) length += distance(project(points[i]), project(points[i + 1]));
    problem.noise_scale = kNoiseFactor * reach;
    problem.tolerance = std::max(frame.to_local(frame.to_local(absolute_tolerance)), 4 * problem.noise_scale * length);
    add_green(curve, origin, x_axis, y_axis, 1.0, problem);
    Budget budget{argument};
    return std::ldexp(integrate(std::move(problem), budget), 2 * frame.exponent);
}

}  // namespace ratbez::detail
