// Adaptive watertight tessellation (tessellate.hpp).
//
// Surface faces get a tensor grid of parameter lines chosen per direction from the second fundamental
// form: linear interpolation of a surface over a cell of size h_u x h_v errs by about
// (|L| h_u^2 + |N| h_v^2) / 8 at the midpoint of the diagonal where L = S_uu . n and N = S_vv . n have the
// same sign (Gauss curvature > 0), and by max(|L| h_u^2, |N| h_v^2) / 8 where they differ (the classic
// bound for piecewise-linear interpolation, e.g. Filip, Magedson and Markot, "Surface algorithms using
// bounds on derivatives", CAGD 1986). Lines in the first direction are equidistributed for a share of the
// tolerance; the second direction gets what that leaves at each place (so a sphere's latitude lines
// spread out towards the poles, where the longitude chords are short). Both orders and several shares
// are tried and the grid with fewest cells kept. Each cell is then checked on the real surface (the
// distance from sample points of its triangles to the surface point with the same barycentric (u, v) is
// an upper bound of the distance to the surface), and the grid refined where a cell fails.
//
// Edges are sampled once: an edge used by surface faces takes the union of their lines along it, an
// edge of planar faces only is sampled by its own chordal deviation. Cells along a boundary whose edge
// carries extra samples (from the neighbouring face) are closed with a zipper strip; degenerate sides
// collapse to their single vertex, so cells at a pole become fan triangles.

#include "ratbez/tessellate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "polygon_triangulation.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/surface_grid.hpp"
#include "ratbez/error.hpp"
#include "strip_zipper.hpp"
#include "surface_evaluator.hpp"

namespace ratbez {
namespace {

using Id = std::uint32_t;

struct Settings {
    double tolerance = 0;
    double angle_rad = 0;  // 0: no angle limit
    std::size_t max_triangles = 0;
};

[[noreturn]] void throw_over_budget(double estimate, std::size_t budget) {
    throw Error("tolerance: too fine for max_triangles: the mesh would need about " +
                std::to_string(static_cast<long long>(std::min(estimate, 9e18))) + " triangles, more than " +
                std::to_string(budget));
}

// ---------------------------------------------------------------------------------------------------------
// Mesh assembly: one mesh vertex per B-rep vertex and per edge sample, so nothing needs welding.

class MeshAssembler {
public:
    Id add_point(const Vec3& p) {
        mesh_.vertices.push_back(p);
        return static_cast<Id>(mesh_.vertices.size() - 1);
    }
    Id vertex_id(const VertexPtr& vertex) {
        const auto [it, inserted] = vertex_ids_.try_emplace(vertex.get(), 0);
        if (inserted) it->second = add_point(vertex->point);
        return it->second;
    }
    void add_triangle(Id a, Id b, Id c) {
        if (a == b || b == c || c == a) return;  // a collapsed side: no zero-area triangle
        mesh_.triangles.push_back({a, b, c});
    }
    const Vec3& point(Id id) const { return mesh_.vertices[id]; }
    Mesh take() { return std::move(mesh_); }

private:
    Mesh mesh_;
    std::map<const Vertex*, Id> vertex_ids_;
};

// ---------------------------------------------------------------------------------------------------------
// The four sides of a surface face and how the face's parameter maps to the edge's.

constexpr std::array<Side, 4> kSides{Side::v_min, Side::u_max, Side::v_max, Side::u_min};
int index(Side s) { return static_cast<int>(s); }
bool runs_along_u(Side s) { return s == Side::v_min || s == Side::v_max; }

struct SideMap {
    const Edge* edge = nullptr;
    bool degenerate = false;
    bool flipped = false;  // the edge runs against the face parameter (tolerated, brep.hpp says it does not)
    double p0 = 0, p1 = 1;  // the face's parameter range along the side
    double t0 = 0, t1 = 1;  // the edge's domain

    double to_edge(double p) const {
        if (p == p0) return flipped ? t1 : t0;
        if (p == p1) return flipped ? t0 : t1;
        const double s = (p - p0) / (p1 - p0);
        return flipped ? t1 - s * (t1 - t0) : t0 + s * (t1 - t0);
    }
    double to_face(double t) const {
        if (t == t0) return flipped ? p1 : p0;
        if (t == t1) return flipped ? p0 : p1;
        const double s = (t - t0) / (t1 - t0);
        return flipped ? p1 - s * (p1 - p0) : p0 + s * (p1 - p0);
    }
};

SideMap map_side(const Face& face, Side side) {
    const Coedge& coedge = face.sides()[static_cast<std::size_t>(index(side))];
    require(coedge.edge != nullptr, "solid", "a surface face has a side without an edge");
    const NurbsSurface& s = face.surface();
    const Interval du = s.domain_u(), dv = s.domain_v();
    SideMap m;
    m.edge = coedge.edge.get();
    m.degenerate = coedge.edge->degenerate;
    const bool along_u = runs_along_u(side);
    m.p0 = along_u ? du.min : dv.min;
    m.p1 = along_u ? du.max : dv.max;
    const Interval dt = coedge.edge->curve.domain();
    m.t0 = dt.min, m.t1 = dt.max;
    if (!m.degenerate) {
        // The edge is the isocurve with the same parameter; compare an interior point of each run
        // direction so that closed edges (start == end) are decided too.
        const double fixed = side == Side::v_min ? dv.min : side == Side::v_max ? dv.max : side == Side::u_min ? du.min : du.max;
        auto surface_at = [&](double p) { return along_u ? s.point(p, fixed) : s.point(fixed, p); };
        const Vec3 edge_quarter = coedge.edge->curve.point(m.t0 + 0.25 * (m.t1 - m.t0));
        const double same = distance(edge_quarter, surface_at(m.p0 + 0.25 * (m.p1 - m.p0)));
        const double opposite = distance(edge_quarter, surface_at(m.p0 + 0.75 * (m.p1 - m.p0)));
        m.flipped = opposite < same;
    }
    return m;
}

// ---------------------------------------------------------------------------------------------------------
// Curvature data of a surface face on a sample grid (coarse, then fine where it pays), and the parameter
// lines derived from it.

// Curvature samples per knot span: coarse first; fine when the grid turns out dense enough that the finer
// (less conservative) line densities pay for the sampling (see Tessellator::plan_surfaces).
constexpr std::size_t kCoarseSamplesPerSpan = 8, kFineSamplesPerSpan = 16;

// `per_span` samples in every knot span, fewer when there are many spans (at most about 64 x per_span
// in all, at least two per span).
std::vector<double> sample_params(const std::vector<double>& breaks, std::size_t per_span_limit) {
    const std::size_t spans = breaks.size() - 1;
    const std::size_t per_span = std::max<std::size_t>(2, std::min(per_span_limit, 64 * per_span_limit / spans));
    std::vector<double> s;
    for (std::size_t k = 0; k < spans; ++k)
        for (std::size_t i = 0; i < per_span; ++i)
            s.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * static_cast<double>(i) / static_cast<double>(per_span));
    s.push_back(breaks.back());
    return s;
}

// How many samples sample_curvature takes with `per_span`.
double sample_count(const NurbsSurface& s, std::size_t per_span) {
    return static_cast<double>(sample_params(breakpoints(s.degree_u(), s.knots_u()), per_span).size()) *
           static_cast<double>(sample_params(breakpoints(s.degree_v(), s.knots_v()), per_span).size());
}
double fine_sample_count(const NurbsSurface& s) { return sample_count(s, kFineSamplesPerSpan); }
double coarse_sample_count(const NurbsSurface& s) { return sample_count(s, kCoarseSamplesPerSpan); }

struct CurvatureSamples {
    std::vector<double> us, vs;
    std::vector<double> L, N;      // S_uu . n and S_vv . n, index i * vs.size() + j
    std::vector<Vec3> normals;
    std::size_t at(std::size_t i, std::size_t j) const { return i * vs.size() + j; }
};

// The unit normal where S_u x S_v vanishes on a collapsed side of the domain (a pole or apex row), by
// l'Hôpital: on a side u = u0 collapsed to a point S_v = 0 all along it, so near it S_v ~ (u - u0) S_uv and
// N -> sign(u - u0) S_u x S_uv / |S_u x S_uv| from inside the domain, from any direction that leaves the
// side (the limit NurbsSurface::normal takes); likewise S_u ~ (v - v0) S_uv on a side v = v0. nullopt
// where that is not decisive (both partials vanish, or S_uv is parallel too): the caller asks normal().
std::optional<Vec3> collapsed_side_normal(const Vec3& su, const Vec3& sv, const Vec3& suv, double u, double v,
                                          const Interval& du, const Interval& dv) {
    const double lu = norm(su), lv = norm(sv), luv = norm(suv);
    Vec3 n;
    if (lv <= 1e-9 * lu && (u == du.min || u == du.max)) n = (u == du.min ? 1.0 : -1.0) * cross(su, suv);
    else if (lu <= 1e-9 * lv && (v == dv.min || v == dv.max)) n = (v == dv.min ? 1.0 : -1.0) * cross(suv, sv);
    else return std::nullopt;
    const double length = norm(n);
    if (!(length > 1e-6 * std::max(lu, lv) * luv)) return std::nullopt;
    return n / length;
}

CurvatureSamples sample_curvature(const NurbsSurface& s, std::size_t per_span) {
    CurvatureSamples c;
    c.us = sample_params(breakpoints(s.degree_u(), s.knots_u()), per_span);
    c.vs = sample_params(breakpoints(s.degree_v(), s.knots_v()), per_span);
    c.L.resize(c.us.size() * c.vs.size());
    c.N.resize(c.L.size());
    c.normals.resize(c.L.size());
    // One batched evaluation of every partial up to order two (surface_grid.hpp), not a jet per sample.
    const SurfaceGrid g = evaluate_grid(s, c.us, c.vs, GridOutput::second_partials);
    const Interval du = s.domain_u(), dv = s.domain_v();
    for (std::size_t i = 0; i < c.us.size(); ++i)
        for (std::size_t j = 0; j < c.vs.size(); ++j) {
            const std::size_t k = c.at(i, j);
            const Vec3 su = g.du[k], sv = g.dv[k];
            const Vec3 cross_product = cross(su, sv);
            const double length = norm(cross_product);
            Vec3 n;
            if (length > 1e-10 * (dot(su, su) + dot(sv, sv))) {
                n = cross_product / length;
            } else {
                // Where a partial vanishes (poles, apexes) the surface's own limit normal: in closed form
                // on a collapsed side, else by the general (and much dearer) NurbsSurface::normal.
                const auto limit = collapsed_side_normal(su, sv, g.duv[k], c.us[i], c.vs[j], du, dv);
                n = limit ? *limit : s.normal(c.us[i], c.vs[j]);
            }
            c.L[k] = dot(g.duu[k], n);
            c.N[k] = dot(g.dvv[k], n);
            c.normals[k] = n;
        }
    return c;
}

// Lines over the samples' range with density rho (per sample interval, lines per unit parameter),
// equidistributed: each line interval carries the same integral of rho. Every piece between two
// consecutive `breaks` gets its own whole number of intervals, at least one.
std::vector<double> place_lines(const std::vector<double>& samples, const std::vector<double>& rho,
                                const std::vector<double>& breaks) {
    std::vector<double> lines{samples.front()};
    std::size_t a = 0;
    for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
        const std::size_t first = a;
        double total = 0;
        while (a + 1 < samples.size() && samples[a] < breaks[piece + 1]) {
            total += rho[a] * (samples[a + 1] - samples[a]);
            ++a;
        }
        const std::size_t last = a;  // sample index of the piece's end
        const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil(total * (1 - 1e-12))));
        const double step = total / static_cast<double>(count);
        double acc = 0;
        std::size_t k = first;
        for (std::size_t line = 1; line < count; ++line) {
            const double target = step * static_cast<double>(line);
            while (k + 1 < last && acc + rho[k] * (samples[k + 1] - samples[k]) < target) {
                acc += rho[k] * (samples[k + 1] - samples[k]);
                ++k;
            }
            const double within = rho[k] > 0 ? (target - acc) / rho[k] : 0;
            lines.push_back(std::min(samples[k] + within, samples[k + 1]));
        }
        lines.push_back(samples[last]);
    }
    return lines;
}

// The line density (lines per unit parameter) of one sample interval of length h: the floor, the
// curvature term sqrt(|k| / budget8) (given as the interval's largest ratio |k| / budget8, budget8 = 8 x the
// allowed error), and the angle limit from `turn`, the largest change of the unit normal across the
// interval (sqrt(2) for the cell diagonal).
double interval_density(double floor, double k_over_budget8, double turn, double h, double angle_rad) {
    double r = std::max(floor, std::sqrt(k_over_budget8));
    if (angle_rad > 0) r = std::max(r, turn / h * std::numbers::sqrt2 / angle_rad);
    return r;
}

// The parameter lines of one direction from the density `density(a)` of each sample interval a; empty
// when they would be more than `max_lines`.
template <class Density>
std::vector<double> lines_from_density(const std::vector<double>& samples, Density&& density,
                                       const std::vector<double>& breaks, double max_lines, std::vector<double>& rho) {
    rho.resize(samples.size() - 1);
    double total = 0;
    for (std::size_t a = 0; a + 1 < samples.size(); ++a) {
        rho[a] = density(a);
        total += rho[a] * (samples[a + 1] - samples[a]);
    }
    if (total > max_lines) return {};
    return place_lines(samples, rho, breaks);
}

// The spacing of the line interval containing parameter t (the larger of the two at a line).
double spacing_at(const std::vector<double>& lines, double t) {
    const auto it = std::upper_bound(lines.begin() + 1, lines.end() - 1, t);
    const auto k = static_cast<std::size_t>(it - lines.begin()) - 1;  // lines[k] <= t <= lines[k + 1]
    double h = lines[k + 1] - lines[k];
    if (k > 0 && lines[k] == t) h = std::max(h, lines[k] - lines[k - 1]);
    return h;
}

struct Grid {
    std::vector<double> u, v;
    double cells() const { return static_cast<double>(u.size() - 1) * static_cast<double>(v.size() - 1); }
};

// The economical grid for an error target: both direction orders and several shares of the tolerance
// for the first direction; the grid with the fewest cells wins. Empty grid: over `max_cells`.
//
// Everything that does not depend on the share is computed once per call: the first direction's
// curvature term is max |k| over each sample line divided by the share's budget, and the angle terms
// depend on the samples only. What remains per share is one pass over the samples for the second
// direction's budget (which depends on the first direction's actual spacing), comparing |k| / budget
// and taking one square root per sample interval.
Grid choose_grid(const CurvatureSamples& c, double target, double angle_rad, std::array<int, 2> min_segments,
                 const std::array<std::vector<double>, 2>& creases, double max_cells) {
    const std::size_t nu = c.us.size(), nv = c.vs.size();
    std::vector<double> max_L(nu, 0.0), max_N(nv, 0.0), turn_u(nu - 1, 0.0), turn_v(nv - 1, 0.0);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t k = c.at(i, j);
            max_L[i] = std::max(max_L[i], std::abs(c.L[k]));
            max_N[j] = std::max(max_N[j], std::abs(c.N[k]));
            if (angle_rad > 0) {
                if (i + 1 < nu) turn_u[i] = std::max(turn_u[i], distance(c.normals[c.at(i + 1, j)], c.normals[k]));
                if (j + 1 < nv) turn_v[j] = std::max(turn_v[j], distance(c.normals[k + 1], c.normals[k]));
            }
        }

    Grid best;
    double best_cells = std::numeric_limits<double>::infinity();
    std::vector<double> rho, h_first, ratio;
    for (bool u_first : {true, false}) {
        const std::vector<double>& first_samples = u_first ? c.us : c.vs;
        const std::vector<double>& second_samples = u_first ? c.vs : c.us;
        const std::vector<double>& max_k_first = u_first ? max_L : max_N;
        const std::vector<double>& turn_first = u_first ? turn_u : turn_v;
        const std::vector<double>& turn_second = u_first ? turn_v : turn_u;
        const std::vector<double>& k_first = u_first ? c.L : c.N;
        const std::vector<double>& k_second = u_first ? c.N : c.L;
        const int min_first = min_segments[u_first ? 0 : 1], min_second = min_segments[u_first ? 1 : 0];
        const auto& creases_first = creases[u_first ? 0 : 1];
        const auto& creases_second = creases[u_first ? 1 : 0];
        const double floor_first = min_first / (first_samples.back() - first_samples.front());
        const double floor_second = min_second / (second_samples.back() - second_samples.front());
        for (double share : {0.3, 0.4, 0.5, 0.6, 0.7, 0.8}) {
            const double budget8 = 8 * share * target;
            const auto first = lines_from_density(
                first_samples,
                [&](std::size_t a) {
                    return interval_density(floor_first, std::max(max_k_first[a], max_k_first[a + 1]) / budget8,
                                            turn_first[a], first_samples[a + 1] - first_samples[a], angle_rad);
                },
                creases_first, max_cells, rho);
            if (first.empty()) continue;
            // What the first direction's actual chords leave of the budget where the curvatures add up.
            h_first.resize(first_samples.size());
            for (std::size_t a = 0; a < h_first.size(); ++a) h_first[a] = spacing_at(first, first_samples[a]);
            const double full = 8 * target, least = 0.05 * 8 * target;
            ratio.assign(second_samples.size(), 0.0);
            for (std::size_t i = 0; i < nu; ++i)
                for (std::size_t j = 0; j < nv; ++j) {
                    const std::size_t k = c.at(i, j), a = u_first ? i : j, b = u_first ? j : i;
                    const double k1 = k_first[k], k2 = k_second[k];
                    const double used = k1 * k2 > 0 ? std::abs(k1) * h_first[a] * h_first[a] : 0.0;
                    ratio[b] = std::max(ratio[b], std::abs(k2) / std::max(full - used, least));
                }
            const auto second = lines_from_density(
                second_samples,
                [&](std::size_t b) {
                    return interval_density(floor_second, std::max(ratio[b], ratio[b + 1]), turn_second[b],
                                            second_samples[b + 1] - second_samples[b], angle_rad);
                },
                creases_second, max_cells / static_cast<double>(first.size() - 1), rho);
            if (second.empty()) continue;
            const double cells = static_cast<double>(first.size() - 1) * static_cast<double>(second.size() - 1);
            if (cells < best_cells) {
                best_cells = cells;
                best.u = u_first ? first : second;
                best.v = u_first ? second : first;
            }
        }
    }
    return best;
}

// Knot lines across which the surface has a crease (C0 in geometry, not only in parameter: the rational
// circle's double knots are G1 and need no line). Detected by normals just either side of the knot, from
// the evaluator's partials (NurbsSurface::normal, far dearer, only where they are nearly parallel).
std::vector<double> crease_lines(const NurbsSurface& s, const detail::SurfaceEvaluator& e, bool along_u) {
    auto normal = [&](double u, double v) {
        const detail::SurfaceFirstDerivatives p = e.first_derivatives(u, v);
        const Vec3 n = cross(p.su, p.sv);
        const double length = norm(n);
        return length > 1e-10 * (dot(p.su, p.su) + dot(p.sv, p.sv)) ? n / length : s.normal(u, v);
    };
    const Interval d = along_u ? s.domain_u() : s.domain_v();
    const Interval other = along_u ? s.domain_v() : s.domain_u();
    const auto breaks = along_u ? breakpoints(s.degree_u(), s.knots_u()) : breakpoints(s.degree_v(), s.knots_v());
    std::vector<double> result{d.min};
    const double delta = 1e-7 * (d.max - d.min);
    for (std::size_t k = 1; k + 1 < breaks.size(); ++k) {
        bool crease = false;
        for (int q = 1; q <= 5 && !crease; ++q) {
            const double w = other.min + (other.max - other.min) * q / 6.0;
            const Vec3 before = along_u ? normal(breaks[k] - delta, w) : normal(w, breaks[k] - delta);
            const Vec3 after = along_u ? normal(breaks[k] + delta, w) : normal(w, breaks[k] + delta);
            crease = distance(before, after) > 1e-4;
        }
        if (crease) result.push_back(breaks[k]);
    }
    result.push_back(d.max);
    return result;
}

// ---------------------------------------------------------------------------------------------------------
// Cells: a grid rectangle whose sides may carry extra boundary samples and may be collapsed (degenerate).

struct CellVertex {
    double u = 0, v = 0;
    Vec3 point;
    Id id = 0;
    // A pole: a degenerate side collapsed to this vertex, free in u (bottom/top) or in v (left/right).
    enum class Free : unsigned char { none, u, v } free = Free::none;
};

// The deviation at the midpoint of a candidate diagonal: how far the chord strays from the surface.
double diagonal_deviation(const detail::SurfaceEvaluator& s, const CellVertex& a, const CellVertex& b) {
    return distance(s.point(0.5 * (a.u + b.u), 0.5 * (a.v + b.v)), 0.5 * (a.point + b.point));
}

// Rails of a cell: bottom and top (left to right) when its left and right sides are plain, else left and
// right (bottom to top). A collapsed rail is one vertex. Returns triangles of CellVertex pointers,
// counterclockwise in (u, v).
using CellTriangle = std::array<const CellVertex*, 3>;

void zip(const detail::SurfaceEvaluator& s, const std::vector<CellVertex>& lower, const std::vector<CellVertex>& upper,
         std::vector<CellTriangle>& out) {
    auto cost = [&](std::size_t i, std::size_t j) {
        // Prefer the smaller chordal deviation; between equal ones (flat directions), the shorter diagonal.
        return diagonal_deviation(s, lower[i], upper[j]) + 1e-9 * distance(lower[i].point, upper[j].point);
    };
    for (const auto& t : detail::zip_rails(lower.size(), upper.size(), cost)) {
        CellTriangle tri;
        for (int k = 0; k < 3; ++k)
            tri[static_cast<std::size_t>(k)] = t[static_cast<std::size_t>(k)] < lower.size()
                                                   ? &lower[t[static_cast<std::size_t>(k)]]
                                                   : &upper[t[static_cast<std::size_t>(k)] - lower.size()];
        out.push_back(tri);
    }
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

// Triangulates one cell given its four side chains (each including both of its corners, in
// counterclockwise-compatible direction: bottom and top left to right, left and right bottom to top).
// `center` (when the cell has extra samples on two adjacent sides) is filled by the callback.
template <class MakeCenter>
void triangulate_cell(const detail::SurfaceEvaluator& s, const std::vector<CellVertex>& bottom, const std::vector<CellVertex>& right,
                      const std::vector<CellVertex>& top, const std::vector<CellVertex>& left,
                      std::vector<CellVertex>& storage_lower, std::vector<CellVertex>& storage_upper,
                      CellVertex& center_storage, MakeCenter&& make_center, std::vector<CellTriangle>& out) {
    const bool plain_left = left.size() == 2, plain_right = right.size() == 2;
    const bool plain_bottom = bottom.size() == 2, plain_top = top.size() == 2;
    if (plain_left && plain_right) {
        storage_lower = collapse(bottom, CellVertex::Free::u);
        storage_upper = collapse(top, CellVertex::Free::u);
        zip(s, storage_lower, storage_upper, out);
    } else if (plain_bottom && plain_top) {
        storage_lower = collapse(right, CellVertex::Free::v);
        storage_upper = collapse(left, CellVertex::Free::v);
        zip(s, storage_lower, storage_upper, out);
    } else {
        // Extra samples on adjacent sides: a fan from the cell's center never makes a degenerate triangle.
        storage_lower.clear();
        auto append = [&](const std::vector<CellVertex>& chain, bool forward) {
            for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
                const CellVertex& c = forward ? chain[k] : chain[chain.size() - 1 - k];
                if (storage_lower.empty() || storage_lower.back().id != c.id) storage_lower.push_back(c);
            }
        };
        append(bottom, true);
        append(right, true);
        append(top, false);
        append(left, false);
        while (storage_lower.size() > 1 && storage_lower.back().id == storage_lower.front().id) storage_lower.pop_back();
        center_storage = make_center();
        for (std::size_t k = 0; k < storage_lower.size(); ++k)
            out.push_back({&center_storage, &storage_lower[k], &storage_lower[(k + 1) % storage_lower.size()]});
    }
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

// The distance from p to the surface point at (u, v), improved (when above `good_enough`) by up to two
// Gauss–Newton steps towards the foot of p: every value is the distance to a point of the surface, so
// an upper bound of the distance to the surface. The steps matter where the parameterisation shears
// (near poles the barycentric (u, v) lands beside the chord's point, not across it). `start()` gives S,
// S_u and S_v at (u, v) for the first step: the caller may have them from a batch; they only steer the
// step, the bound is always a distance to an evaluated surface point.
template <class Start>
double distance_bound(const detail::SurfaceEvaluator& s, const Vec3& p, double u, double v, const Vec3& surface_point,
                      Start&& start, double good_enough) {
    double best = distance(surface_point, p);
    const Interval du = s.domain_u(), dv = s.domain_v();
    for (int step = 0; step < 2 && best > good_enough; ++step) {
        const detail::SurfaceFirstDerivatives d = step == 0 ? start() : s.first_derivatives(u, v);
        const Vec3 r = p - d.s;
        const double a = dot(d.su, d.su), b = dot(d.su, d.sv), c = dot(d.sv, d.sv);
        const double det = a * c - b * b;
        if (!(det > 1e-30 * (a * c + 1e-300))) break;
        const double f = dot(r, d.su), g = dot(r, d.sv);
        u = std::clamp(u + (c * f - b * g) / det, du.min, du.max);
        v = std::clamp(v + (a * g - b * f) / det, dv.min, dv.max);
        best = std::min(best, distance(s.point(u, v), p));
    }
    return best;
}
double distance_bound(const detail::SurfaceEvaluator& s, const Vec3& p, double u, double v, double good_enough) {
    return distance_bound(s, p, u, v, s.point(u, v), [&] { return s.first_derivatives(u, v); }, good_enough);
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

// Upper bound of the chordal error of a triangle at the kBarycentric points (each by distance_bound
// from triangle_parameters); refinement towards the true distance stops once a sample is within
// `good_enough`.
double triangle_error(const detail::SurfaceEvaluator& s, const CellTriangle& t, double good_enough) {
    double worst = 0;
    for (const auto& b : kBarycentric) {
        const auto [u, v] = triangle_parameters(t, b);
        const Vec3 p = b[0] * t[0]->point + b[1] * t[1]->point + b[2] * t[2]->point;
        worst = std::max(worst, distance_bound(s, p, u, v, good_enough));
    }
    return worst;
}

double angle_between(const Vec3& a, const Vec3& b) {
    return std::atan2(norm(cross(a, b)), dot(a, b));
}

// ---------------------------------------------------------------------------------------------------------
// The plan of a surface face: its sides and grid.

struct SurfacePlan {
    const Face* face = nullptr;
    std::shared_ptr<const detail::SurfaceEvaluator> evaluator;
    std::array<SideMap, 4> sides;
    Grid grid;
    std::array<int, 2> min_segments{1, 1};
    std::array<std::vector<double>, 2> creases;
};

std::array<int, 2> minimum_segments(const std::array<SideMap, 4>& sides) {
    // A direction closed on itself (both sides the same edge) needs three intervals to enclose anything;
    // one bounded by two degenerate sides needs two (one interval would join pole to pole).
    auto minimum = [&](Side a, Side b) {
        const SideMap &sa = sides[static_cast<std::size_t>(index(a))], &sb = sides[static_cast<std::size_t>(index(b))];
        if (sa.edge == sb.edge && !sa.degenerate) return 3;
        if (sa.degenerate && sb.degenerate) return 2;
        return 1;
    };
    return {minimum(Side::u_min, Side::u_max), minimum(Side::v_min, Side::v_max)};
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
    // The triangles zip() makes of a plain cell (see check_cell).
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

struct CheckResult {
    double worst_ratio = 0;
    std::vector<char> refine_u, refine_v;  // per grid interval
};

// The check of one cell from its 7 x 7 lattice of surface points (`at(a, b)`, parameters `us[a]`,
// `vs[b]`): what the general path below computes for a cell without collapsed corners, with the surface
// points taken from the batch instead of evaluated one by one, and the first Gauss-Newton step of
// distance_bound steered by `partials_at(a, b)` (S_u, S_v from lattice differences) instead of a jet.
template <class At, class PartialsAt>
void check_plain_cell(const detail::SurfaceEvaluator& s, const Settings& settings, At&& at, PartialsAt&& partials_at, const double* us,
                      const double* vs, std::size_t i, std::size_t j, const Vec3* normals, std::size_t nv,
                      CheckResult& result) {
    static const std::array<CellSamples, 2> kSamples{lattice_samples(false), lattice_samples(true)};
    const std::array<Vec3, 4> c{at(0, 0), at(6, 0), at(6, 6), at(0, 6)};
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
    const double good_enough = settings.tolerance;
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
        error = std::max(error, distance_bound(s, above[n].chord, us[x.a], vs[x.b], at(x.a, x.b),
                                               [&] { return partials_at(x.a, x.b); }, good_enough));
    }
    const double ratio = error / settings.tolerance;
    bool angle_failed = false;
    double angle_u = 0, angle_v = 0;
    if (normals != nullptr) {
        const Vec3 &n00 = normals[i * nv + j], &n10 = normals[(i + 1) * nv + j];
        const Vec3 &n01 = normals[i * nv + j + 1], &n11 = normals[(i + 1) * nv + j + 1];
        angle_u = std::max(angle_between(n00, n10), angle_between(n01, n11));
        angle_v = std::max(angle_between(n00, n01), angle_between(n10, n11));
        const double diagonal = std::max(angle_between(n00, n11), angle_between(n10, n01));
        angle_failed = std::max({angle_u, angle_v, diagonal}) > settings.angle_rad;
    }
    result.worst_ratio = std::max(result.worst_ratio, ratio);
    if (ratio > 1 || angle_failed) {
        const double chord_u = std::max(distance(at(3, 0), 0.5 * (c[0] + c[1])), distance(at(3, 6), 0.5 * (c[3] + c[2])));
        const double chord_v = std::max(distance(at(0, 3), 0.5 * (c[0] + c[3])), distance(at(6, 3), 0.5 * (c[1] + c[2])));
        bool split_u = chord_u >= 0.5 * chord_v, split_v = chord_v >= 0.5 * chord_u;
        if (angle_failed && ratio <= 1) split_u = angle_u >= 0.5 * angle_v, split_v = angle_v >= 0.5 * angle_u;
        if (split_u) result.refine_u[i] = 1;
        if (split_v) result.refine_v[j] = 1;
        if (angle_failed) result.worst_ratio = std::max(result.worst_ratio, 1.0 + 1e-9);
    }
}

// The corner vertices of a grid cell for the error check (edge samples not yet known): degenerate
// sides share one pseudo id so that they collapse like in the final mesh.
//
// Only the cells in a new row (new_u[i]) or a new column (new_v[j]) are checked: every other cell is
// the same as in the previous check, which it passed (a failing cell is always bisected in some direction).
// The surface points of the checked cells come from batched lattice evaluations (evaluate_grid), a few
// rows of cells at a time; only the Gauss-Newton steps of distance_bound and the cells at collapsed
// sides (pole fans, whose samples leave the lattice) evaluate point by point.
CheckResult check_grid(const SurfacePlan& plan, const Settings& settings, const std::vector<char>& new_u,
                       const std::vector<char>& new_v) {
    const detail::SurfaceEvaluator& s = *plan.evaluator;
    const NurbsSurface& surface = plan.face->surface();
    const Grid& g = plan.grid;
    const std::size_t nu = g.u.size(), nv = g.v.size();
    std::vector<Vec3> normals;
    if (settings.angle_rad > 0) {
        const SurfaceGrid n = evaluate_grid(surface, g.u, g.v, GridOutput::normals);
        normals.resize(nu * nv);
        for (std::size_t k = 0; k < normals.size(); ++k) normals[k] = n.normals[k];
    }
    const Id pole_base = static_cast<Id>(nu * nv);
    auto id_of = [&](std::size_t i, std::size_t j) -> Id {
        if (j == 0 && plan.sides[0].degenerate) return pole_base + 0;
        if (i == nu - 1 && plan.sides[1].degenerate) return pole_base + 1;
        if (j == nv - 1 && plan.sides[2].degenerate) return pole_base + 2;
        if (i == 0 && plan.sides[3].degenerate) return pole_base + 3;
        return static_cast<Id>(i * nv + j);
    };
    auto plain = [&](std::size_t i, std::size_t j) {
        return !(j == 0 && plan.sides[0].degenerate) && !(i + 2 == nu && plan.sides[1].degenerate) &&
               !(j + 2 == nv && plan.sides[2].degenerate) && !(i == 0 && plan.sides[3].degenerate);
    };

    CheckResult result;
    result.refine_u.assign(nu - 1, 0);
    result.refine_v.assign(nv - 1, 0);
    std::vector<CellVertex> lower, upper;
    CellVertex center;
    std::vector<CellTriangle> triangles;
    // The general path: any cell, every surface point evaluated here (corners from `corner`).
    auto check_general = [&](std::size_t i, std::size_t j, auto&& corner) {
        auto vertex = [&](std::size_t a, std::size_t b) {
            return CellVertex{g.u[a], g.v[b], corner(a - i, b - j), id_of(a, b)};
        };
        triangles.clear();
        const CellVertex c00 = vertex(i, j), c10 = vertex(i + 1, j), c11 = vertex(i + 1, j + 1), c01 = vertex(i, j + 1);
        triangulate_cell(s, {c00, c10}, {c10, c11}, {c01, c11}, {c00, c01}, lower, upper, center,
                         [] { return CellVertex{}; }, triangles);
        double error = 0;
        for (const auto& t : triangles) error = std::max(error, triangle_error(s, t, settings.tolerance));
        const double ratio = error / settings.tolerance;
        bool angle_failed = false;
        double angle_u = 0, angle_v = 0;
        if (settings.angle_rad > 0) {
            const Vec3 &n00 = normals[i * nv + j], &n10 = normals[(i + 1) * nv + j];
            const Vec3 &n01 = normals[i * nv + j + 1], &n11 = normals[(i + 1) * nv + j + 1];
            angle_u = std::max(angle_between(n00, n10), angle_between(n01, n11));
            angle_v = std::max(angle_between(n00, n01), angle_between(n10, n11));
            const double diagonal = std::max(angle_between(n00, n11), angle_between(n10, n01));
            angle_failed = std::max({angle_u, angle_v, diagonal}) > settings.angle_rad;
        }
        result.worst_ratio = std::max(result.worst_ratio, ratio);
        if (ratio > 1 || angle_failed) {
            // Split the direction whose chords err more (both when comparable).
            const double chord_u = std::max(diagonal_deviation(s, c00, c10), diagonal_deviation(s, c01, c11));
            const double chord_v = std::max(diagonal_deviation(s, c00, c01), diagonal_deviation(s, c10, c11));
            bool split_u = chord_u >= 0.5 * chord_v, split_v = chord_v >= 0.5 * chord_u;
            if (angle_failed && ratio <= 1) split_u = angle_u >= 0.5 * angle_v, split_v = angle_v >= 0.5 * angle_u;
            if (split_u) result.refine_u[i] = 1;
            if (split_v) result.refine_v[j] = 1;
            if (angle_failed) result.worst_ratio = std::max(result.worst_ratio, 1.0 + 1e-9);
        }
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
                        return detail::SurfaceFirstDerivatives{
                            at(a, b), difference([&](int k) { return at(k, b); }, a, cu),
                            difference([&](int k) { return at(a, k); }, b, cv)};
                    };
                    if (plain(i, j)) {
                        check_plain_cell(s, settings, at, partials_at, us.data() + 7 * il, vs.data() + 7 * jl, i, j,
                                         normals.empty() ? nullptr : normals.data(), nv, result);
                    } else {
                        check_general(i, j, [&](std::size_t di, std::size_t dj) { return at(6 * static_cast<int>(di), 6 * static_cast<int>(dj)); });
                    }
                }
        }
    };
    check_block(new_rows, all_columns);
    check_block(old_rows, new_columns);
    return result;
}

std::vector<double> bisect_marked(const std::vector<double>& lines, const std::vector<char>& marked) {
    std::vector<double> out{lines.front()};
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
        if (marked[k]) out.push_back(0.5 * (lines[k] + lines[k + 1]));
        out.push_back(lines[k + 1]);
    }
    return out;
}

// Model grid, then the check on the real surface: a small global rescale when the model was a little
// optimistic everywhere, local bisection of the failing intervals otherwise.
void refine_grid(SurfacePlan& plan, const CurvatureSamples& curvature, const Settings& settings, double max_cells) {
    double target = settings.tolerance;
    // The intervals whose cells are new since the last check (all of them for a fresh grid).
    std::vector<char> new_u(plan.grid.u.size() - 1, 1), new_v(plan.grid.v.size() - 1, 1);
    auto bisect = [](std::vector<double>& lines, const std::vector<char>& marked, std::vector<char>& fresh) {
        fresh.clear();
        for (char m : marked) fresh.insert(fresh.end(), m ? 2 : 1, m);
        lines = bisect_marked(lines, marked);
    };
    for (int iteration = 0; iteration < 40; ++iteration) {
        if (plan.grid.cells() * 2 > static_cast<double>(settings.max_triangles))
            throw_over_budget(plan.grid.cells() * 2, settings.max_triangles);
        const CheckResult check = check_grid(plan, settings, new_u, new_v);
        if (check.worst_ratio <= 1) return;
        const bool some_marked = std::count(check.refine_u.begin(), check.refine_u.end(), 1) +
                                     std::count(check.refine_v.begin(), check.refine_v.end(), 1) > 0;
        if (iteration < 3 && check.worst_ratio < 1.5) {
            target *= 0.99 / check.worst_ratio;
            Grid g = choose_grid(curvature, target, settings.angle_rad, plan.min_segments, plan.creases, max_cells);
            if (g.u.empty()) throw_over_budget(max_cells * 2, settings.max_triangles);
            plan.grid = std::move(g);
            new_u.assign(plan.grid.u.size() - 1, 1);
            new_v.assign(plan.grid.v.size() - 1, 1);
        } else if (some_marked) {
            bisect(plan.grid.u, check.refine_u, new_u);
            bisect(plan.grid.v, check.refine_v, new_v);
        } else {
            return;
        }
    }
}

// ---------------------------------------------------------------------------------------------------------
// Edge samples: parameters on the edge's own curve and the mesh vertex of each.

struct EdgeSamples {
    std::vector<double> params;
    std::vector<Id> ids;
};

// Chordal sampling of a curve on its own (edges of planar faces only): recursive bisection of each knot
// span until the chord is within tolerance of the curve at five interior points.
void sample_curve(const NurbsCurve& curve, double a, double b, const Vec3& pa, const Vec3& pb, double tolerance,
                  int depth, std::vector<double>& out) {
    double worst = 0;
    const Vec3 chord = pb - pa;
    const double chord_length2 = dot(chord, chord);
    for (int k = 1; k <= 5; ++k) {
        const Vec3 p = curve.point(a + (b - a) * k / 6.0);
        double s = chord_length2 > 0 ? dot(p - pa, chord) / chord_length2 : 0;
        s = std::clamp(s, 0.0, 1.0);
        worst = std::max(worst, distance(p, pa + chord * s));
    }
    if (worst > tolerance && depth < 40) {
        const double m = 0.5 * (a + b);
        const Vec3 pm = curve.point(m);
        sample_curve(curve, a, m, pa, pm, tolerance, depth + 1, out);
        sample_curve(curve, m, b, pm, pb, tolerance, depth + 1, out);
    } else {
        out.push_back(b);
    }
}

std::vector<double> sample_curve(const NurbsCurve& curve, double tolerance) {
    const auto breaks = breakpoints(curve.degree(), curve.knots());
    std::vector<double> params{breaks.front()};
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
        sample_curve(curve, breaks[k], breaks[k + 1], curve.point(breaks[k]), curve.point(breaks[k + 1]), tolerance, 0,
                     params);
    return params;
}

// Sorted, with values closer than a relative 1e-12 of the domain merged (the ends kept exact).
std::vector<double> merge_params(std::vector<double> params, double t0, double t1) {
    params.push_back(t0);
    params.push_back(t1);
    std::sort(params.begin(), params.end());
    const double eps = 1e-12 * (t1 - t0);
    std::vector<double> out;
    for (double t : params) {
        if (t < t0 || t > t1) continue;
        if (!out.empty() && t - out.back() <= eps) continue;
        out.push_back(t);
    }
    if (out.back() != t1) {
        if (t1 - out.back() <= eps && out.size() > 1) out.back() = t1;
        else out.push_back(t1);
    }
    return out;
}

// ---------------------------------------------------------------------------------------------------------

class Tessellator {
public:
    Tessellator(const Solid& solid, const Settings& settings) : solid_(solid), settings_(settings) {}

    Mesh run() {
        plan_surfaces();
        sample_edges();
        for (const SurfacePlan& plan : plans_) mesh_surface(plan);
        for (const Face& face : solid_.faces())
            if (face.kind() == Face::Kind::planar) mesh_planar(face);
        return assembler_.take();
    }

private:
    void plan_surfaces() {
        std::vector<CurvatureSamples> curvatures;
        const double max_cells = static_cast<double>(settings_.max_triangles) / 2;
        for (const Face& face : solid_.faces()) {
            if (face.kind() != Face::Kind::surface) continue;
            // The curvature samples cost memory and time like triangles do (about 200 bytes each): a face
            // with more knot spans than the budget can sample (10^5 spans revolved into 4 x 10^5 patches) is
            // refused up front. A small budget still allows the 2^18 samples any ordinary face needs.
            const double samples = coarse_sample_count(face.surface());
            const double sample_budget = std::max(4.0 * static_cast<double>(settings_.max_triangles), 262'144.0);
            if (samples > sample_budget)
                throw Error("max_triangles: a face with " + std::to_string(face.surface().knots_u().size()) + " x " +
                            std::to_string(face.surface().knots_v().size()) + " knots needs " +
                            std::to_string(static_cast<long long>(samples)) + " curvature samples, more than " +
                            std::to_string(static_cast<long long>(sample_budget)) + " that a budget of " +
                            std::to_string(settings_.max_triangles) + " triangles allows");
            SurfacePlan plan;
            plan.face = &face;
            plan.evaluator = std::make_shared<const detail::SurfaceEvaluator>(face.surface());
            for (Side side : kSides) plan.sides[static_cast<std::size_t>(index(side))] = map_side(face, side);
            plan.min_segments = minimum_segments(plan.sides);
            plan.creases = {crease_lines(face.surface(), *plan.evaluator, true),
                            crease_lines(face.surface(), *plan.evaluator, false)};
            // Every piece between two creases gets a line interval of its own, so a face with more creased
            // pieces than the budget allows (a profile with many sharp corners) is refused here already.
            const double crease_cells = static_cast<double>(std::max<std::size_t>(plan.creases[0].size(), 2) - 1) *
                                        static_cast<double>(std::max<std::size_t>(plan.creases[1].size(), 2) - 1);
            if (crease_cells > max_cells) throw_over_budget(2 * crease_cells, settings_.max_triangles);
            // The coarse samples first. Their line densities are a little more conservative (each is the
            // largest over a longer sample interval): that costs a few cells on a small grid, while the fine
            // sampling would cost more than checking the whole grid. Resampled finely once the grid has
            // more than a quarter as many cells as the fine samples (or the coarse estimate is over budget).
            curvatures.push_back(sample_curvature(face.surface(), kCoarseSamplesPerSpan));
            plan.grid = choose_grid(curvatures.back(), settings_.tolerance, settings_.angle_rad, plan.min_segments,
                                    plan.creases, max_cells);
            if (plan.grid.u.empty() || 4 * plan.grid.cells() > fine_sample_count(face.surface())) {
                curvatures.back() = sample_curvature(face.surface(), kFineSamplesPerSpan);
                plan.grid = choose_grid(curvatures.back(), settings_.tolerance, settings_.angle_rad, plan.min_segments,
                                        plan.creases, max_cells);
            }
            if (plan.grid.u.empty()) throw_over_budget(max_cells * 2 + 1, settings_.max_triangles);
            plans_.push_back(std::move(plan));
        }
        // The estimate for the whole solid before any mesh is built: two triangles per cell, plus the
        // planar faces (about one triangle per boundary sample, bounded by the cells along their edges).
        double estimate = 0;
        for (const SurfacePlan& plan : plans_) estimate += 2 * plan.grid.cells() + 2.0 * static_cast<double>(plan.grid.u.size() + plan.grid.v.size());
        if (estimate > static_cast<double>(settings_.max_triangles)) throw_over_budget(estimate, settings_.max_triangles);
        for (std::size_t k = 0; k < plans_.size(); ++k) refine_grid(plans_[k], curvatures[k], settings_, max_cells);
        match_lines_at_creases();
    }

    // Where a face's row along a crease (a profile corner) is thin, it takes the other face's lines
    // across the shared edge. Otherwise it closes that row with a zipper to the other face's samples,
    // and its far rail's chords, spanning several of the other face's intervals, sag by more than the
    // row is wide (weights crowd the face towards the edge): they pass through the other face's first
    // row, and the mesh intersects itself although every triangle is within the tolerance (seeds
    // 20261322, 20261342 and 9 more of the round trip test's first 1000 cases at weights 10^+-3).
    // With the same lines the two rows' cells pair up, each pair the profile's corner swept between
    // the same two lines, which meet only along the edge. Only the lines inside thin cells are taken
    // (about 50% more triangles over the round trip cases at weights 10^+-3, 3% at 10^+-0.3; matching
    // whole creases cost 60%, bisecting the thin cells instead several times that). Lines only subdivide cells that passed their check. Repeated
    // until no face gains a line, since lines can pass on along a ring of thin rows.
    // One face's side on an edge.
    struct EdgeUse {
        SurfacePlan* plan;
        Side side;
    };

    void match_lines_at_creases() {
        // The uses of each edge, edges in order of first use (not of their addresses: the result must
        // not depend on where the allocator put them).
        std::vector<std::pair<const Edge*, std::vector<EdgeUse>>> uses;
        std::map<const Edge*, std::size_t> slot;
        for (SurfacePlan& plan : plans_)
            for (Side side : kSides) {
                const SideMap& m = plan.sides[static_cast<std::size_t>(index(side))];
                if (m.degenerate) continue;
                const auto [it, inserted] = slot.try_emplace(m.edge, uses.size());
                if (inserted) uses.push_back({m.edge, {}});
                uses[it->second].second.push_back({&plan, side});
            }
        // The lines of a plan that cross a side, i.e. run along the side's direction.
        auto lines_of = [](SurfacePlan& plan, Side side) -> std::vector<double>& {
            return runs_along_u(side) ? plan.grid.u : plan.grid.v;
        };
        for (int round = 0; round < 16; ++round) {
            bool changed = false;
            for (auto& [edge, list] : uses) {
                if (list.size() != 2 || list[0].plan == list[1].plan || !is_crease(*edge, list[0], list[1])) continue;
                for (int k = 0; k < 2; ++k) {
                    const EdgeUse& to = list[static_cast<std::size_t>(k)];
                    const EdgeUse& from = list[static_cast<std::size_t>(1 - k)];
                    const SideMap& to_map = to.plan->sides[static_cast<std::size_t>(index(to.side))];
                    const SideMap& from_map = from.plan->sides[static_cast<std::size_t>(index(from.side))];
                    std::vector<double>& lines = lines_of(*to.plan, to.side);
                    const std::vector<char> thin = thin_intervals(*to.plan, to.side);
                    std::vector<double> merged = lines;
                    for (double p : lines_of(*from.plan, from.side)) {
                        const double q = to_map.to_face(from_map.to_edge(p));
                        const auto k_interval = std::upper_bound(lines.begin(), lines.end(), q) - lines.begin() - 1;
                        if (k_interval >= 0 && static_cast<std::size_t>(k_interval) < thin.size() && thin[static_cast<std::size_t>(k_interval)])
                            merged.push_back(q);
                    }
                    merged = merge_params(std::move(merged), lines.front(), lines.back());
                    if (merged.size() > lines.size()) {
                        const std::size_t across = runs_along_u(to.side) ? to.plan->grid.v.size() : to.plan->grid.u.size();
                        const double cells = static_cast<double>(merged.size() - 1) * static_cast<double>(across - 1);
                        if (2 * cells > static_cast<double>(settings_.max_triangles)) throw_over_budget(2 * cells, settings_.max_triangles);
                        lines = std::move(merged);
                        changed = true;
                    }
                }
            }
            if (!changed) break;
        }
    }

    // Per interval of the lines along `side`: 1 where the row's cell is thin, i.e. its far rail's chord
    // sags by more than kThinRow times the row's width there (a well-shaped cell's chord sags a few
    // percent of its size; seed 20261342's sagged 1.5 times, and 0.25 still let seed 20263292 through).
    static std::vector<char> thin_intervals(const SurfacePlan& plan, Side side) {
        constexpr double kThinRow = 0.1;
        const detail::SurfaceEvaluator& s = *plan.evaluator;
        const Grid& g = plan.grid;
        const bool along_u = runs_along_u(side);
        const std::vector<double>& lines = along_u ? g.u : g.v;
        const std::vector<double>& across = along_u ? g.v : g.u;
        const bool at_min = side == Side::v_min || side == Side::u_min;
        const double edge = at_min ? across.front() : across.back();
        const double far = at_min ? across[1] : across[across.size() - 2];
        auto at = [&](double p, double q) { return along_u ? s.point(p, q) : s.point(q, p); };
        std::vector<char> thin(lines.size() - 1, 0);
        for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
            const Vec3 a = at(lines[k], far), b = at(lines[k + 1], far);
            const double width = std::min(distance(at(lines[k], edge), a), distance(at(lines[k + 1], edge), b));
            const double sag = distance(at(0.5 * (lines[k] + lines[k + 1]), far), 0.5 * (a + b));
            thin[k] = sag > kThinRow * width ? 1 : 0;
        }
        return thin;
    }

    // True when the faces' normals differ at an interior point of the shared edge: a crease, not a
    // smooth (G1) joint, where both faces are one sheet and their rows cannot fold into each other.
    static bool is_crease(const Edge& edge, const EdgeUse& a, const EdgeUse& b) {
        auto normal_at = [&](const EdgeUse& use, double t) {
            const SideMap& m = use.plan->sides[static_cast<std::size_t>(index(use.side))];
            const NurbsSurface& s = use.plan->face->surface();
            const double p = m.to_face(t);
            const double fixed = use.side == Side::v_min   ? s.domain_v().min
                                 : use.side == Side::v_max ? s.domain_v().max
                                 : use.side == Side::u_min ? s.domain_u().min
                                                           : s.domain_u().max;
            return runs_along_u(use.side) ? s.normal(p, fixed) : s.normal(fixed, p);
        };
        const Interval d = edge.curve.domain();
        for (double f : {0.25, 0.5, 0.75}) {
            const double t = d.min + f * (d.max - d.min);
            if (dot(normal_at(a, t), normal_at(b, t)) < std::cos(1e-3)) return true;
        }
        return false;
    }

    void sample_edges() {
        std::map<const Edge*, std::vector<double>> from_surfaces;
        for (const SurfacePlan& plan : plans_)
            for (Side side : kSides) {
                const SideMap& m = plan.sides[static_cast<std::size_t>(index(side))];
                if (m.degenerate) continue;
                auto& params = from_surfaces[m.edge];
                for (double p : runs_along_u(side) ? plan.grid.u : plan.grid.v) params.push_back(m.to_edge(p));
            }
        for (const EdgePtr& edge : solid_.edges()) {
            EdgeSamples samples;
            if (edge->degenerate) {
                samples.ids = {assembler_.vertex_id(edge->start)};
                samples.params = {edge->curve.domain().min};
            } else {
                const Interval d = edge->curve.domain();
                const auto it = from_surfaces.find(edge.get());
                samples.params = merge_params(it != from_surfaces.end() ? it->second : sample_curve(edge->curve, settings_.tolerance),
                                              d.min, d.max);
                samples.ids.reserve(samples.params.size());
                for (std::size_t k = 0; k < samples.params.size(); ++k) {
                    if (k == 0) samples.ids.push_back(assembler_.vertex_id(edge->start));
                    else if (k + 1 == samples.params.size()) samples.ids.push_back(assembler_.vertex_id(edge->end));
                    else samples.ids.push_back(assembler_.add_point(edge->curve.point(samples.params[k])));
                }
            }
            edge_samples_.emplace(edge.get(), std::move(samples));
        }
    }

    const EdgeSamples& samples_of(const Edge* edge) const {
        const auto it = edge_samples_.find(edge);
        require(it != edge_samples_.end(), "solid", "a face uses an edge the solid does not list");
        return it->second;
    }

    void mesh_surface(const SurfacePlan& plan) {
        const detail::SurfaceEvaluator& s = *plan.evaluator;
        const Grid& g = plan.grid;
        const std::size_t nu = g.u.size(), nv = g.v.size();

        // Per side: (face parameter, id) of every edge sample, ascending in the face parameter.
        std::array<std::vector<std::pair<double, Id>>, 4> side_samples;
        for (Side side : kSides) {
            const SideMap& m = plan.sides[static_cast<std::size_t>(index(side))];
            const EdgeSamples& e = samples_of(m.edge);
            auto& list = side_samples[static_cast<std::size_t>(index(side))];
            if (m.degenerate) continue;
            for (std::size_t k = 0; k < e.params.size(); ++k) list.emplace_back(m.to_face(e.params[k]), e.ids[k]);
            std::sort(list.begin(), list.end());
        }
        // The sample a grid line lands on: the nearest one (the samples are the union of the grid lines of
        // both faces, up to the rounding of the parameter maps). Cells take their corners AND their extra
        // samples by this index, so every sample of the edge is used exactly once along the side, however
        // close two samples are (two faces' lines a rounding apart give two distinct samples; matching
        // extras by a parameter epsilon instead dropped the one not chosen as the corner: a hole).
        auto side_index = [&](Side side, double p) -> std::size_t {
            const auto& list = side_samples[static_cast<std::size_t>(index(side))];
            auto it = std::lower_bound(list.begin(), list.end(), std::make_pair(p, Id{0}),
                                       [](const auto& a, const auto& b) { return a.first < b.first; });
            if (it == list.end() || (it != list.begin() && std::abs(std::prev(it)->first - p) < std::abs(it->first - p))) --it;
            return static_cast<std::size_t>(it - list.begin());
        };
        auto side_id = [&](Side side, double p) -> std::pair<bool, Id> {
            const SideMap& m = plan.sides[static_cast<std::size_t>(index(side))];
            if (m.degenerate) return {true, samples_of(m.edge).ids[0]};
            return {false, side_samples[static_cast<std::size_t>(index(side))][side_index(side, p)].second};
        };

        // The interior grid points in one batch (surface_grid.hpp); boundary points are edge samples.
        evaluate_grid(plan.face->surface(), g.u, g.v, GridOutput::points, grid_points_);
        std::vector<Id> ids(nu * nv);
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                // (degenerate, id) from the sides through the point: the least, a non-degenerate side first.
                std::optional<std::pair<bool, Id>> chosen;
                auto consider = [&](std::pair<bool, Id> candidate) {
                    if (!chosen || candidate < *chosen) chosen = candidate;
                };
                if (j == 0) consider(side_id(Side::v_min, g.u[i]));
                if (i == nu - 1) consider(side_id(Side::u_max, g.v[j]));
                if (j == nv - 1) consider(side_id(Side::v_max, g.u[i]));
                if (i == 0) consider(side_id(Side::u_min, g.v[j]));
                ids[i * nv + j] = chosen ? chosen->second : assembler_.add_point(grid_points_.point(i, j));
            }

        auto vertex = [&](std::size_t i, std::size_t j) {
            const Id id = ids[i * nv + j];
            return CellVertex{g.u[i], g.v[j], assembler_.point(id), id};
        };
        // Extra samples on a side strictly between the samples of the grid lines p0 < p1, ascending.
        auto extras = [&](Side side, double p0, double p1, double fixed, std::vector<CellVertex>& chain) {
            const SideMap& m = plan.sides[static_cast<std::size_t>(index(side))];
            if (m.degenerate) return;
            const auto& list = side_samples[static_cast<std::size_t>(index(side))];
            const bool along_u = runs_along_u(side);
            for (std::size_t k = side_index(side, p0) + 1, end = side_index(side, p1); k < end; ++k) {
                const auto& [p, id] = list[k];
                chain.push_back(CellVertex{along_u ? p : fixed, along_u ? fixed : p, assembler_.point(id), id});
            }
        };

        std::vector<CellVertex> bottom, right, top, left, lower, upper;
        CellVertex center;
        std::vector<CellTriangle> triangles;
        for (std::size_t i = 0; i + 1 < nu; ++i)
            for (std::size_t j = 0; j + 1 < nv; ++j) {
                const CellVertex c00 = vertex(i, j), c10 = vertex(i + 1, j), c11 = vertex(i + 1, j + 1), c01 = vertex(i, j + 1);
                bottom = {c00};
                if (j == 0) extras(Side::v_min, g.u[i], g.u[i + 1], g.v[0], bottom);
                bottom.push_back(c10);
                right = {c10};
                if (i + 2 == nu) extras(Side::u_max, g.v[j], g.v[j + 1], g.u[nu - 1], right);
                right.push_back(c11);
                top = {c01};
                if (j + 2 == nv) extras(Side::v_max, g.u[i], g.u[i + 1], g.v[nv - 1], top);
                top.push_back(c11);
                left = {c00};
                if (i == 0) extras(Side::u_min, g.v[j], g.v[j + 1], g.u[0], left);
                left.push_back(c01);
                triangles.clear();
                triangulate_cell(
                    s, bottom, right, top, left, lower, upper, center,
                    [&] {
                        const double u = 0.5 * (g.u[i] + g.u[i + 1]), v = 0.5 * (g.v[j] + g.v[j + 1]);
                        const Vec3 p = s.point(u, v);
                        return CellVertex{u, v, p, assembler_.add_point(p)};
                    },
                    triangles);
                for (const auto& t : triangles) assembler_.add_triangle(t[0]->id, t[1]->id, t[2]->id);
            }
    }

    void mesh_planar(const Face& face) {
        const Plane& plane = face.plane();
        std::vector<std::vector<detail::Point2>> loops;
        std::vector<Id> flat_ids;
        for (const auto& loop : face.loops()) {
            std::vector<Id> ids;
            for (const Coedge& coedge : loop) {
                const EdgeSamples& e = samples_of(coedge.edge.get());
                if (coedge.edge->degenerate) continue;
                const std::size_t n = e.ids.size();
                for (std::size_t k = 0; k + 1 < n; ++k) ids.push_back(coedge.reversed ? e.ids[n - 1 - k] : e.ids[k]);
            }
            std::vector<Id> cleaned;
            for (Id id : ids)
                if (cleaned.empty() || cleaned.back() != id) cleaned.push_back(id);
            while (cleaned.size() > 1 && cleaned.back() == cleaned.front()) cleaned.pop_back();
            require(cleaned.size() >= 3, "solid", "a planar face has a loop with fewer than three distinct points");
            std::vector<detail::Point2> points;
            for (Id id : cleaned) {
                const Vec3 d = assembler_.point(id) - plane.origin;
                points.push_back({dot(d, plane.x_axis), dot(d, plane.y_axis)});
            }
            loops.push_back(std::move(points));
            flat_ids.insert(flat_ids.end(), cleaned.begin(), cleaned.end());
        }
        // Counterclockwise in the (x, y) frame is along x × y; flip if the frame is left-handed to the normal.
        const bool flip = dot(cross(plane.x_axis, plane.y_axis), plane.normal) < 0;
        for (const auto& t : detail::triangulate_polygon(loops)) {
            if (flip) assembler_.add_triangle(flat_ids[t[0]], flat_ids[t[2]], flat_ids[t[1]]);
            else assembler_.add_triangle(flat_ids[t[0]], flat_ids[t[1]], flat_ids[t[2]]);
        }
    }

    const Solid& solid_;
    Settings settings_;
    std::vector<SurfacePlan> plans_;
    std::map<const Edge*, EdgeSamples> edge_samples_;
    MeshAssembler assembler_;
    SurfaceGrid grid_points_;  // mesh_surface's batch, kept to reuse its storage from face to face
};

}  // namespace

double default_tolerance(const Solid& solid) { return 1e-3 * solid.bounding_box().diagonal(); }

Mesh tessellate(const Solid& solid, const TessellationOptions& options) {
    require(std::isfinite(options.tolerance) && options.tolerance > 0, "tolerance",
            "must be a finite number > 0 (got " + std::to_string(options.tolerance) + ")");
    Settings settings;
    settings.tolerance = options.tolerance;
    if (options.angle_deg) {
        require(std::isfinite(*options.angle_deg) && *options.angle_deg > 0 && *options.angle_deg < 180, "angle_deg",
                "must be in (0, 180) degrees (got " + std::to_string(*options.angle_deg) + ")");
        settings.angle_rad = *options.angle_deg * std::numbers::pi / 180.0;
    }
    require(options.max_triangles > 0, "max_triangles", "must be positive");
    settings.max_triangles = options.max_triangles;
    Mesh mesh = Tessellator(solid, settings).run();
    // Closed by construction for a valid solid; the check (O(triangles), a few % of the time) keeps a
    // solid whose faces fold onto each other — a profile that runs back over itself, found by
    // fuzz_geometry — from handing out an open mesh.
    require(mesh.is_closed(), "solid", "its faces do not close up into a watertight mesh (they overlap or fold "
                                       "back on each other, e.g. a profile that runs back over itself)");
    return mesh;
}

}  // namespace ratbez
