// Cells of a face's parameter grid: triangulation and the error check (tessellate_cells.hpp).

#include "mesh/tessellate_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <span>
#include <utility>

#include "analysis/point_inversion.hpp"
#include "math/vector_angle.hpp"
#include "mesh/strip_zipper.hpp"
#include "ratbez/surface_grid.hpp"

namespace ratbez::detail {
namespace {

// The deviation at the midpoint of a candidate diagonal: how far the chord strays from the surface.
double diagonal_deviation(const SurfaceEvaluator& s, const CellVertex& a, const CellVertex& b) {
    return distance(s.point(0.5 * (a.u + b.u), 0.5 * (a.v + b.v)), 0.5 * (a.point + b.point));
}

// The strip between two rails (bottom and top, or right and left; a collapsed rail is one vertex) by the
// zipper with `cost` for each diagonal.
template <class Cost>
void zip(const std::vector<CellVertex>& lower, const std::vector<CellVertex>& upper, Cost&& cost,
         std::vector<CellTriangle>& out) {
    for (const auto& t : zip_rails(lower.size(), upper.size(), cost)) {
        CellTriangle tri;
        for (int k = 0; k < 3; ++k)
            tri[static_cast<std::size_t>(k)] = t[static_cast<std::size_t>(k)] < lower.size()
                                                   ? &lower[t[static_cast<std::size_t>(k)]]
                                                   : &upper[t[static_cast<std::size_t>(k)] - lower.size()];
        out.push_back(tri);
    }
}

// The strip between two rails of a cell by the chordal deviation of each diagonal: of a cell's two diagonals
// the one that sags less makes the better pair of triangles.
void zip(const SurfaceEvaluator& s, const std::vector<CellVertex>& lower, const std::vector<CellVertex>& upper,
         std::vector<CellTriangle>& out) {
    zip(lower, upper, [&](std::size_t i, std::size_t j) {
        // Prefer the smaller chordal deviation; between equal ones (flat directions), the shorter diagonal.
        return diagonal_deviation(s, lower[i], upper[j]) + 1e-9 * distance(lower[i].point, upper[j].point);
    }, out);
}

// A rail collapsed to its single vertex when the side is degenerate; its u (or v) is the side's middle,
// which keeps the parameter triangle of a pole fan tight for the error bound.
std::vector<CellVertex> collapse(std::vector<CellVertex> rail, CellVertex::Free free) {
    if (rail.size() > 1 && std::all_of(rail.begin(), rail.end(), [&](const CellVertex& c) { return c.id == rail[0].id; })) {
        CellVertex mid = rail.front();
        mid.free = free;
        mid.u = 0.5 * (rail.front().u + rail.back().u);
        mid.v = 0.5 * (rail.front().v + rail.back().v);
        return {mid};
    }
    return rail;
}

// The parameters of the barycentric point b of a cell triangle: the same combination of the vertices'
// (u, v), except that a pole's free parameter is taken from the other two vertices (the collapsed
// bilinear map of Duffy, SIAM J. Numer. Anal. 1982), so that the edge from a pole to a ring vertex maps
// onto that vertex's isoparametric line: the meridian the chord actually spans.
std::pair<double, double> triangle_parameters(const CellTriangle& t, const std::array<double, 3>& b) {
    double u = 0, v = 0;
    for (std::size_t k = 0; k < 3; ++k) u += b[k] * t[k]->u, v += b[k] * t[k]->v;
    for (std::size_t k = 0; k < 3; ++k) {
        if (t[k]->free == CellVertex::Free::none) continue;
        const std::size_t i = (k + 1) % 3, j = (k + 2) % 3;
        const double rest = b[i] + b[j];
        if (rest <= 0) continue;
        if (t[k]->free == CellVertex::Free::u) u = (b[i] * t[i]->u + b[j] * t[j]->u) / rest;
        else v = (b[i] * t[i]->v + b[j] * t[j]->v) / rest;
    }
    return {u, v};
}

// The points of a triangle where its chordal error is sampled: every barycentric point with coordinates
// in sixths except the vertices (25: five on each edge, ten inside). Edge midpoints and the centroid alone
// missed the largest error where a rational parameterisation moves the bulge off-centre (seeds
// 20261182, 20261752 of the round trip test: up to 15% over the tolerance at a third of an edge).
constexpr std::array<std::array<double, 3>, 25> sixths_barycentric() {
    std::array<std::array<double, 3>, 25> out{};
    std::size_t n = 0;
    for (int i = 0; i <= 6; ++i)
        for (int j = 0; i + j <= 6; ++j) {
            const int k = 6 - i - j;
            if (i == 6 || j == 6 || k == 6) continue;
            out[n++] = {i / 6.0, j / 6.0, k / 6.0};
        }
    return out;
}
constexpr auto kBarycentric = sixths_barycentric();

// An upper bound of the chordal error of a triangle at the kBarycentric points: the distance from each
// sample to the surface point at its triangle_parameters, improved by gauss_newton_bound (which stops
// refining towards the true distance once a sample is within `good_enough`).
double triangle_error(const SurfaceEvaluator& s, const ParameterBox& domain, const CellTriangle& t, double good_enough) {
    double worst = 0;
    for (const auto& b : kBarycentric) {
        double u = 0, v = 0;
        std::tie(u, v) = triangle_parameters(t, b);
        const Vec3 p = b[0] * t[0]->point + b[1] * t[1]->point + b[2] * t[2]->point;
        worst = std::max(worst, gauss_newton_bound(s, p, domain, u, v, s.point(u, v),
                                                   [&] { return s.first_derivatives(u, v); }, good_enough));
    }
    return worst;
}

using detail::angle_between;

// How far the unit normals turn across cell (i, j), from the grid's normals (`nv` per row of the grid;
// empty: no angle limit): the largest turn along u, along v, and whether any of those or a diagonal's
// exceeds `angle_rad`.
struct NormalTurn {
    double u = 0, v = 0;
    bool too_far = false;
};
NormalTurn normal_turn(const std::vector<Vec3>& normals, std::size_t nv, std::size_t i, std::size_t j, double angle_rad) {
    NormalTurn turn;
    if (normals.empty()) return turn;
    const Vec3 &n00 = normals[i * nv + j], &n10 = normals[(i + 1) * nv + j];
    const Vec3 &n01 = normals[i * nv + j + 1], &n11 = normals[(i + 1) * nv + j + 1];
    turn.u = std::max(angle_between(n00, n10), angle_between(n01, n11));
    turn.v = std::max(angle_between(n00, n01), angle_between(n10, n11));
    const double diagonal = std::max(angle_between(n00, n11), angle_between(n10, n01));
    turn.too_far = std::max({turn.u, turn.v, diagonal}) > angle_rad;
    return turn;
}

// Records the check of cell (i, j): its error `ratio` (error / tolerance) and its normals' `turn`. A
// failing cell marks the direction whose chords err more for bisection (both when comparable), or,
// when only the angle fails, the direction whose normals turn more. `chords()` gives the chordal
// deviations (u, v) of the cell's sides, asked only for a failing cell.
template <class Chords>
void record_cell(GridCheck& result, std::size_t i, std::size_t j, double ratio, const NormalTurn& turn, Chords&& chords) {
    result.worst_ratio = std::max(result.worst_ratio, ratio);
    if (ratio > 1 || turn.too_far) {
        const auto [chord_u, chord_v] = chords();
        bool split_u = chord_u >= 0.5 * chord_v, split_v = chord_v >= 0.5 * chord_u;
        if (turn.too_far && ratio <= 1) split_u = turn.u >= 0.5 * turn.v, split_v = turn.v >= 0.5 * turn.u;
        if (split_u) result.refine_u[i] = 1;
        if (split_v) result.refine_v[j] = 1;
        if (turn.too_far) result.worst_ratio = std::max(result.worst_ratio, 1.0 + 1e-9);
    }
}

// The samples of triangle_error for the two triangles of a plain cell, in sixths of the cell: the corners
// are (0,0), (6,0), (6,6) and (0,6), and every sample (kBarycentric, in sixths) lands on that 7 x 7
// lattice, so one batched evaluation of the lattice serves the whole check of a cell.
struct LatticeSample {
    std::array<int, 3> corners;  // indices into the cell's corners c00, c10, c11, c01
    std::array<double, 3> weights;
    int a, b;                    // lattice position (u, v) in sixths
};
// 45 distinct samples: the five on the diagonal belong to both triangles and are kept once.
using CellSamples = std::array<LatticeSample, 2 * kBarycentric.size() - 5>;

CellSamples lattice_samples(bool diagonal_00_11) {
    static constexpr std::array<std::array<int, 2>, 4> kCorner{{{0, 0}, {6, 0}, {6, 6}, {0, 6}}};
    // The triangles zip() makes of a plain cell (see check_plain_cell).
    const std::array<std::array<int, 3>, 2> triangles =
        diagonal_00_11 ? std::array<std::array<int, 3>, 2>{{{0, 2, 3}, {0, 1, 2}}}
                       : std::array<std::array<int, 3>, 2>{{{0, 1, 3}, {1, 2, 3}}};
    CellSamples out{};
    std::size_t n = 0;
    for (const auto& t : triangles)
        for (const auto& w : kBarycentric) {
            double a = 0, b = 0;
            for (std::size_t k = 0; k < 3; ++k) {
                a += w[k] * kCorner[static_cast<std::size_t>(t[k])][0];
                b += w[k] * kCorner[static_cast<std::size_t>(t[k])][1];
            }
            const LatticeSample sample{t, w, static_cast<int>(std::lround(a)), static_cast<int>(std::lround(b))};
            const bool seen = std::any_of(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n),
                                          [&](const LatticeSample& o) { return o.a == sample.a && o.b == sample.b; });
            if (!seen) out[n++] = sample;
        }
    return out;
}

// The check of one cell from its 7 x 7 lattice of surface points (`at(a, b)`, parameters `us[a]`,
// `vs[b]`): what the general path of check_grid computes for a cell without collapsed corners, with the
// surface points taken from the batch instead of evaluated one by one, and the first Gauss-Newton step of
// gauss_newton_bound steered by `partials_at(a, b)` (S_u, S_v from lattice differences) instead of a jet.
template <class At, class PartialsAt>
void check_plain_cell(const SurfaceEvaluator& s, const ParameterBox& domain, double tolerance, At&& at,
                      PartialsAt&& partials_at, const double* us, const double* vs, std::size_t i, std::size_t j,
                      const std::array<Vec3, 4>& c, const NormalTurn& turn, GridCheck& result) {
    static const std::array<CellSamples, 2> kSamples{lattice_samples(false), lattice_samples(true)};
    const Vec3 center = at(3, 3);
    // zip_rails on the rails {c00, c10} and {c01, c11}: the diagonal c00-c11 unless it costs no less.
    const double cost_00_11 = distance(center, 0.5 * (c[0] + c[2])) + 1e-9 * distance(c[0], c[2]);
    const double cost_10_01 = distance(center, 0.5 * (c[1] + c[3])) + 1e-9 * distance(c[1], c[3]);
    const CellSamples& samples = kSamples[cost_00_11 < cost_10_01 ? 1 : 0];
    // The cell's error is the largest sample bound. A sample within the tolerance passes as it is (its
    // first value is its bound): only the few above it need Gauss-Newton steps. A step only lowers a
    // bound below its first value, so taking those by decreasing first value, one whose first value is
    // already below the largest bound so far cannot change the maximum: the same maximum as refining
    // every sample, for a fraction of the point-wise evaluations.
    const double good_enough = tolerance;
    constexpr std::size_t kCount = std::tuple_size_v<CellSamples>;
    struct Above {
        double first;
        std::size_t sample;
        Vec3 chord;
    };
    std::array<Above, kCount> above;
    std::size_t above_count = 0;
    double within2 = 0;  // the largest squared first value within the tolerance
    const double good_enough2 = good_enough * good_enough;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const LatticeSample& x = samples[k];
        const Vec3 chord = x.weights[0] * c[static_cast<std::size_t>(x.corners[0])] +
                           x.weights[1] * c[static_cast<std::size_t>(x.corners[1])] +
                           x.weights[2] * c[static_cast<std::size_t>(x.corners[2])];
        const Vec3 d = at(x.a, x.b) - chord;
        const double d2 = dot(d, d);
        if (d2 <= good_enough2) within2 = std::max(within2, d2);
        else above[above_count++] = {std::sqrt(d2), k, chord};
    }
    std::sort(above.begin(), above.begin() + static_cast<std::ptrdiff_t>(above_count),
              [](const Above& x, const Above& y) { return x.first > y.first; });
    double error = std::sqrt(within2);
    for (std::size_t n = 0; n < above_count && above[n].first > error; ++n) {
        const LatticeSample& x = samples[above[n].sample];
        error = std::max(error, gauss_newton_bound(s, above[n].chord, domain, us[x.a], vs[x.b], at(x.a, x.b),
                                                   [&] { return partials_at(x.a, x.b); }, good_enough));
    }
    // Which direction to refine is the surface's own chords' business (the offsets are not).
    record_cell(result, i, j, error / tolerance, turn, [&] {
        const std::array<Vec3, 4> q{at(0, 0), at(6, 0), at(6, 6), at(0, 6)};
        return std::pair{std::max(distance(at(3, 0), 0.5 * (q[0] + q[1])), distance(at(3, 6), 0.5 * (q[3] + q[2]))),
                         std::max(distance(at(0, 3), 0.5 * (q[0] + q[3])), distance(at(6, 3), 0.5 * (q[1] + q[2])))};
    });
}

}  // namespace

bool triangulate_cell(const SurfaceEvaluator& s, const std::vector<CellVertex>& bottom,
                      const std::vector<CellVertex>& right, const std::vector<CellVertex>& top,
                      const std::vector<CellVertex>& left, std::vector<CellVertex>& lower,
                      std::vector<CellVertex>& upper, CellVertex& center, std::vector<CellTriangle>& out) {
    const bool plain_left = left.size() == 2, plain_right = right.size() == 2;
    const bool plain_bottom = bottom.size() == 2, plain_top = top.size() == 2;
    // Rails: bottom and top (left to right) when the left and right sides are plain, else left and right
    // (bottom to top).
    if (plain_left && plain_right) {
        lower = collapse(bottom, CellVertex::Free::u);
        upper = collapse(top, CellVertex::Free::u);
        zip(s, lower, upper, out);
        return false;
    }
    if (plain_bottom && plain_top) {
        lower = collapse(right, CellVertex::Free::v);
        upper = collapse(left, CellVertex::Free::v);
        zip(s, lower, upper, out);
        return false;
    }
    // Extra samples on adjacent sides: a fan from the cell's center never makes a degenerate triangle.
    lower.clear();
    auto append = [&](const std::vector<CellVertex>& chain, bool forward) {
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
            const CellVertex& c = forward ? chain[k] : chain[chain.size() - 1 - k];
            if (lower.empty() || lower.back().id != c.id) lower.push_back(c);
        }
    };
    append(bottom, true);
    append(right, true);
    append(top, false);
    append(left, false);
    while (lower.size() > 1 && lower.back().id == lower.front().id) lower.pop_back();
    for (std::size_t k = 0; k < lower.size(); ++k) out.push_back({&center, &lower[k], &lower[(k + 1) % lower.size()]});
    return true;
}

namespace {

// Sorts a sequence that is nearly in order: insertion sort, linear in the length times the distance things move,
// finished by std::sort should they move far. A strip's samples come triangle after triangle along u, out of
// order only within a triangle or two (and the few of a rail's first triangle, wrapped across the seam), where
// std::sort took a tenth of the rows' check.
template <class T, class Less>
void sort_nearly_sorted(std::vector<T>& items, Less&& less) {
    std::size_t moves = 0;
    for (std::size_t k = 1; k < items.size(); ++k) {
        if (!less(items[k], items[k - 1])) continue;
        T item = std::move(items[k]);
        std::size_t m = k;
        for (; m > 0 && less(item, items[m - 1]); --m) items[m] = std::move(items[m - 1]);
        items[m] = std::move(item);
        moves += k - m;
        if (moves > 16 * items.size()) {
            std::sort(items.begin(), items.end(), less);
            return;
        }
    }
}

}  // namespace

void strip_errors(const SurfaceEvaluator& s, const NurbsSurface& surface, std::span<const CellTriangle> triangles,
                  double v0, double v1, double good_enough, std::vector<double>& errors) {
    const ParameterBox domain{s.domain_u(), s.domain_v()};
    // Every sample of a triangle between the two rows lies on one of the 7 lines v0 + (q / 6) (v1 - v0): its
    // upper vertices' weight in sixths is q.
    struct Sample {
        std::size_t triangle;
        double u;
        Vec3 chord;
    };
    thread_local std::array<std::vector<Sample>, 7> levels;
    for (auto& level : levels) level.clear();
    for (std::size_t n = 0; n < triangles.size(); ++n) {
        const CellTriangle& t = triangles[n];
        for (const auto& b : kBarycentric) {
            auto [u, v] = triangle_parameters(t, b);
            // A rail that closes across a seam starts below u's domain (tessellate_rows.hpp): the same points.
            if (u < domain.u.min) u += domain.u.max - domain.u.min;
            double upper = 0;
            for (std::size_t k = 0; k < 3; ++k)
                if (t[k]->v == v1 && v1 != v0) upper += b[k];
            const auto q = static_cast<std::size_t>(std::lround(6 * upper));
            (void)v;
            levels[q].push_back({n, u, b[0] * t[0]->point + b[1] * t[1]->point + b[2] * t[2]->point});
        }
    }
    errors.assign(triangles.size(), 0.0);
    thread_local std::vector<double> us;
    thread_local SurfaceGrid batch;
    for (std::size_t q = 0; q < levels.size(); ++q) {
        std::vector<Sample>& level = levels[q];
        if (level.empty()) continue;
        sort_nearly_sorted(level, [](const Sample& a, const Sample& b) { return a.u < b.u; });
        us.clear();
        for (const Sample& x : level) us.push_back(x.u);
        const double v = q == 6 ? v1 : v0 + (v1 - v0) * (static_cast<double>(q) / 6.0);
        evaluate_grid(surface, us, std::span<const double>(&v, 1), GridOutput::points, batch);
        for (std::size_t k = 0; k < level.size(); ++k) {
            const Sample& x = level[k];
            double& error = errors[x.triangle];
            const Vec3 on_surface = batch.points[k];
            const double first = distance(on_surface, x.chord);
            // A sample within good_enough is its own bound; only those above it (and above the triangle's largest
            // so far, which a step only lowers towards) take Gauss-Newton steps, as triangle_error's.
            if (first <= good_enough || first <= error) {
                error = std::max(error, first);
                continue;
            }
            error = std::max(error, gauss_newton_bound(s, x.chord, domain, x.u, v, on_surface,
                                                       [&] { return s.first_derivatives(x.u, v); }, good_enough));
        }
    }
}

void triangulate_strip(const std::vector<CellVertex>& bottom, const std::vector<CellVertex>& top,
                       std::vector<CellVertex>& lower, std::vector<CellVertex>& upper, std::vector<CellTriangle>& out) {
    lower = collapse(bottom, CellVertex::Free::u);
    upper = collapse(top, CellVertex::Free::u);
    zip(lower, upper, [&](std::size_t i, std::size_t j) { return distance(lower[i].point, upper[j].point); }, out);
}

// The surface points of the checked cells come from batched lattice evaluations (evaluate_grid), a few
// rows of cells at a time; only the Gauss-Newton steps of gauss_newton_bound and the cells at collapsed
// sides (pole fans, whose samples leave the lattice) evaluate point by point.
GridCheck check_grid(const SurfaceEvaluator& s, const NurbsSurface& surface, const ParameterGrid& g,
                     const std::array<bool, 4>& collapsed_sides, double tolerance, double angle_rad,
                     const std::vector<char>& new_u, const std::vector<char>& new_v, const std::vector<Vec3>& corners,
                     const std::function<void()>& poll) {
    const std::size_t nu = g.u.size(), nv = g.v.size();
    const ParameterBox domain{s.domain_u(), s.domain_v()};
    std::vector<Vec3> normals;
    if (angle_rad > 0) {
        const SurfaceGrid n = evaluate_grid(surface, g.u, g.v, GridOutput::normals);
        normals.resize(nu * nv);
        for (std::size_t k = 0; k < normals.size(); ++k) normals[k] = n.normals[k];
    }
    // The corner vertices of a grid cell (edge samples not yet known): collapsed sides share one pseudo
    // id so that they collapse like in the final mesh.
    const auto pole_base = static_cast<MeshVertexId>(nu * nv);
    auto id_of = [&](std::size_t i, std::size_t j) -> MeshVertexId {
        if (j == 0 && collapsed_sides[0]) return pole_base + 0;
        if (i == nu - 1 && collapsed_sides[1]) return pole_base + 1;
        if (j == nv - 1 && collapsed_sides[2]) return pole_base + 2;
        if (i == 0 && collapsed_sides[3]) return pole_base + 3;
        return static_cast<MeshVertexId>(i * nv + j);
    };
    auto plain = [&](std::size_t i, std::size_t j) {
        return !(j == 0 && collapsed_sides[0]) && !(i + 2 == nu && collapsed_sides[1]) &&
               !(j + 2 == nv && collapsed_sides[2]) && !(i == 0 && collapsed_sides[3]);
    };

    GridCheck result;
    result.refine_u.assign(nu - 1, 0);
    result.refine_v.assign(nv - 1, 0);
    std::vector<CellVertex> lower, upper;
    CellVertex center;
    std::vector<CellTriangle> triangles;
    // The general path: any cell, every surface point evaluated here.
    auto check_general = [&](std::size_t i, std::size_t j) {
        auto vertex = [&](std::size_t a, std::size_t b) { return CellVertex{g.u[a], g.v[b], corners[a * nv + b], id_of(a, b)}; };
        triangles.clear();
        const CellVertex c00 = vertex(i, j), c10 = vertex(i + 1, j), c11 = vertex(i + 1, j + 1), c01 = vertex(i, j + 1);
        if (triangulate_cell(s, {c00, c10}, {c10, c11}, {c01, c11}, {c00, c01}, lower, upper, center, triangles)) {
            // Not reached (a cell's sides carry only its corners here); the fan's center, were it needed.
            const double u = 0.5 * (g.u[i] + g.u[i + 1]), v = 0.5 * (g.v[j] + g.v[j + 1]);
            center = CellVertex{u, v, s.point(u, v), pole_base + 4};
        }
        double error = 0;
        for (const auto& t : triangles) error = std::max(error, triangle_error(s, domain, t, tolerance));
        record_cell(result, i, j, error / tolerance, normal_turn(normals, nv, i, j, angle_rad), [&] {
            return std::pair{std::max(diagonal_deviation(s, c00, c10), diagonal_deviation(s, c01, c11)),
                             std::max(diagonal_deviation(s, c00, c01), diagonal_deviation(s, c10, c11))};
        });
    };

    // The lattice parameters of a list of intervals: 7 per interval (ends repeated), both ends exact.
    auto lattice = [](const std::vector<double>& lines, const std::vector<std::size_t>& intervals) {
        std::vector<double> t;
        t.reserve(7 * intervals.size());
        for (std::size_t k : intervals) {
            const double a = lines[k], b = lines[k + 1];
            t.push_back(a);
            for (int f = 1; f < 6; ++f) t.push_back(std::min(b, a + (b - a) * (f / 6.0)));
            t.push_back(b);
        }
        return t;
    };
    std::vector<std::size_t> all_columns(nv - 1), new_columns, new_rows, old_rows;
    for (std::size_t j = 0; j + 1 < nv; ++j) {
        all_columns[j] = j;
        if (new_v[j]) new_columns.push_back(j);
    }
    for (std::size_t i = 0; i + 1 < nu; ++i) (new_u[i] ? new_rows : old_rows).push_back(i);

    SurfaceGrid batch;
    std::vector<std::size_t> chunk;
    // Rows `rows` against columns `columns`, a chunk of rows per evaluate_grid call.
    auto check_block = [&](const std::vector<std::size_t>& rows, const std::vector<std::size_t>& columns) {
        if (rows.empty() || columns.empty()) return;
        const std::vector<double> vs = lattice(g.v, columns);
        // About 4096 lattice points per call: their coordinates (100 kB) stay in the cache for the checks.
        const std::size_t per_chunk = std::max<std::size_t>(1, 4096 / (49 * columns.size()));
        for (std::size_t r0 = 0; r0 < rows.size(); r0 += per_chunk) {
            // A chance to cancel every 16 chunks (a few ms): a fine grid's check runs for seconds.
            if (poll && (r0 / per_chunk) % 16 == 15) poll();
            chunk.assign(rows.begin() + static_cast<std::ptrdiff_t>(r0),
                         rows.begin() + static_cast<std::ptrdiff_t>(std::min(rows.size(), r0 + per_chunk)));
            const std::vector<double> us = lattice(g.u, chunk);
            evaluate_grid(surface, us, vs, GridOutput::points, batch);
            const std::size_t width = vs.size();
            for (std::size_t il = 0; il < chunk.size(); ++il)
                for (std::size_t jl = 0; jl < columns.size(); ++jl) {
                    const std::size_t i = chunk[il], j = columns[jl];
                    const std::size_t base = 7 * il * width + 7 * jl;
                    auto at = [&](int a, int b) {
                        return batch.points[base + static_cast<std::size_t>(a) * width + static_cast<std::size_t>(b)];
                    };
                    // S_u and S_v for the first Gauss-Newton step, by differences of the lattice points:
                    // central inside the cell, the second-order one-sided formula on its sides. They only
                    // steer the step (the bound is a distance to an evaluated surface point), and
                    // O(h^2 / 36) accurate they steer it as well as exact partials, without evaluating
                    // partials for the whole lattice or a jet per sample.
                    const double* cu = us.data() + 7 * il;
                    const double* cv = vs.data() + 7 * jl;
                    auto difference = [](auto&& p, int k, const double* t) -> Vec3 {
                        if (k == 0) return (-3.0 * p(0) + 4.0 * p(1) - p(2)) / (t[2] - t[0]);
                        if (k == 6) return (3.0 * p(6) - 4.0 * p(5) + p(4)) / (t[6] - t[4]);
                        return (p(k + 1) - p(k - 1)) / (t[k + 1] - t[k - 1]);
                    };
                    auto partials_at = [&](int a, int b) {
                        return SurfaceFirstDerivatives{at(a, b), difference([&](int k) { return at(k, b); }, a, cu),
                                                       difference([&](int k) { return at(a, k); }, b, cv)};
                    };
                    if (plain(i, j)) {
                        const std::array<Vec3, 4> c{corners[i * nv + j], corners[(i + 1) * nv + j],
                                                    corners[(i + 1) * nv + j + 1], corners[i * nv + j + 1]};
                        check_plain_cell(s, domain, tolerance, at, partials_at, cu, cv, i, j, c,
                                         normal_turn(normals, nv, i, j, angle_rad), result);
                    } else {
                        check_general(i, j);
                    }
                }
        }
    };
    check_block(new_rows, all_columns);
    check_block(old_rows, new_columns);
    return result;
}

}  // namespace ratbez::detail
