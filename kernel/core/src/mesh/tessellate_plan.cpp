// Grid planning for the surface faces of a solid (tessellate_plan.hpp).

#include "mesh/tessellate_plan.hpp"

#include <algorithm>
#include <set>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include "mesh/tessellate_rows.hpp"
#include "mesh/triangle_grid.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/surface_grid.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::detail {
namespace {

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

std::vector<double> bisect_marked(const std::vector<double>& lines, const std::vector<char>& marked) {
    std::vector<double> out{lines.front()};
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
        if (marked[k]) out.push_back(0.5 * (lines[k] + lines[k + 1]));
        out.push_back(lines[k + 1]);
    }
    return out;
}

// The largest number of cells a grid may have before its triangles are counted (triangles_at_least): one
// triangle per cell, since a cell along a collapsed side (a pole) is one triangle, not two. The budget
// itself is held against triangles_at_least, a count the mesh never falls below, so that a mesh within
// max_triangles is never refused for an estimate above it.
double max_cells(const TessellationSettings& settings) { return static_cast<double>(settings.max_triangles); }

// ---- matching lines across crease edges

// One face's side on an edge.
struct EdgeUse {
    SurfacePlan* plan;
    Side side;
};

// Per interval of the lines along `side`: 1 where the row's cell is thin, i.e. its far rail's chord
// sags by more than kThinRow times the row's width there (a well-shaped cell's chord sags a few
// percent of its size; seed 20261342's sagged 1.5 times, and 0.25 still let seed 20263292 through).
std::vector<char> thin_intervals(const SurfacePlan& plan, Side side) {
    constexpr double kThinRow = 0.1;
    const SurfaceEvaluator& s = *plan.evaluator;
    const ParameterGrid& g = plan.grid;
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
bool is_crease(const Edge& edge, const EdgeUse& a, const EdgeUse& b) {
    auto normal_at = [&](const EdgeUse& use, double t) {
        const SideMap& m = use.plan->sides[side_slot(use.side)];
        const NurbsSurface& s = use.plan->face->surface();
        const double p = m.to_face(t);
        const double fixed = side_parameter(s, use.side);
        return runs_along_u(use.side) ? s.normal(p, fixed) : s.normal(fixed, p);
    };
    const Interval d = edge.curve.domain();
    for (double f : {0.25, 0.5, 0.75}) {
        const double t = d.min + f * (d.max - d.min);
        if (dot(normal_at(a, t), normal_at(b, t)) < std::cos(1e-3)) return true;
    }
    return false;
}

}  // namespace

IntervalPosition locate_in(const std::vector<double>& t, double x) {
    const auto k = static_cast<std::size_t>(std::upper_bound(t.begin() + 1, t.end() - 1, x) - t.begin()) - 1;
    const double h = t[k + 1] - t[k];
    return {k, h > 0 ? std::clamp((x - t[k]) / h, 0.0, 1.0) : 0.0};
}

double spacing_at(const std::vector<double>& lines, double t) {
    const std::size_t k = locate_in(lines, t).k;  // lines[k] <= t <= lines[k + 1]
    double h = lines[k + 1] - lines[k];
    if (k > 0 && lines[k] == t) h = std::max(h, lines[k] - lines[k - 1]);
    return h;
}

double curvature_sample_count(const NurbsSurface& s, std::size_t per_span) {
    return static_cast<double>(sample_params(breakpoints(s.degree_u(), s.knots_u()), per_span).size()) *
           static_cast<double>(sample_params(breakpoints(s.degree_v(), s.knots_v()), per_span).size());
}

CurvatureSamples sample_curvature(const NurbsSurface& s, std::size_t per_span) {
    CurvatureSamples c;
    c.us = sample_params(breakpoints(s.degree_u(), s.knots_u()), per_span);
    c.vs = sample_params(breakpoints(s.degree_v(), s.knots_v()), per_span);
    c.L.resize(c.us.size() * c.vs.size());
    c.N.resize(c.L.size());
    c.M.resize(c.L.size());
    c.k_max.assign(c.L.size(), 0.0);
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
            c.M[k] = dot(g.duv[k], n);
            c.normals[k] = n;
            // The principal curvatures from the fundamental forms: kappa = H +- sqrt(H^2 - K), with
            // K = (LN - M^2) / (EG - F^2) and H = (EN - 2FM + GL) / (2 (EG - F^2)).
            const double E = dot(su, su), F = dot(su, sv), G = dot(sv, sv), M = c.M[k];
            const double area2 = E * G - F * F;
            if (area2 > 1e-20 * (E * G + 1e-300)) {
                const double K = (c.L[k] * c.N[k] - M * M) / area2;
                const double H = (E * c.N[k] - 2 * F * M + G * c.L[k]) / (2 * area2);
                c.k_max[k] = std::abs(H) + std::sqrt(std::max(H * H - K, 0.0));
            }
        }
    return c;
}

// Everything that does not depend on the share is computed once per call: the first direction's
// curvature term is max |k| over each sample line divided by the share's budget, and the angle terms
// depend on the samples only. What remains per share is one pass over the samples for the second
// direction's budget (which depends on the first direction's actual spacing), comparing |k| / budget
// and taking one square root per sample interval.
ParameterGrid choose_grid(const CurvatureSamples& c, double target, double angle_rad, std::array<int, 2> min_segments,
                          const std::array<std::vector<double>, 2>& creases, double max_cells, bool straddle) {
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

    ParameterGrid best;
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
        // The second direction needs at least the lines it would with the whole span to itself (what the first
        // leaves is never more): the first may have at most max_cells / that many, which refuses a hopeless
        // tolerance before millions of lines are placed.
        const std::vector<double>& max_k_second = u_first ? max_N : max_L;
        const double span = straddle ? 2 * kOffsetShare * target : target;
        double second_least = 0;
        for (std::size_t b = 0; b + 1 < second_samples.size(); ++b) {
            const double h = second_samples[b + 1] - second_samples[b];
            second_least += h * interval_density(floor_second, std::max(max_k_second[b], max_k_second[b + 1]) / (8 * span),
                                                 turn_second[b], h, angle_rad);
        }
        const double max_first = max_cells / std::max(1.0, second_least);
        for (double share : {0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8}) {
            // |k| h^2 is 8 times a direction's part of the span, which may be twice the largest offset in
            // all for a straddling mesh, the target for an inscribed one.
            const double budget8 = 8 * share * span;
            const auto first = lines_from_density(
                first_samples,
                [&](std::size_t a) {
                    return interval_density(floor_first, std::max(max_k_first[a], max_k_first[a + 1]) / budget8,
                                            turn_first[a], first_samples[a + 1] - first_samples[a], angle_rad);
                },
                creases_first, max_first, rho);
            if (first.empty()) continue;
            // What the first direction's actual chords leave of the span at each place (whatever the signs:
            // the mesh straddles the surface, see tessellate_plan.hpp), for the second direction's chords and
            // the twist: 8 x span = |k1| h1^2 + |k2| h2^2 + 2 |M| h1 h2 <= 16 target, solved for 1 / h2^2.
            h_first.resize(first_samples.size());
            for (std::size_t a = 0; a < h_first.size(); ++a) h_first[a] = spacing_at(first, first_samples[a]);
            // An inscribed mesh: the larger of the two directions' errors where the curvatures differ in sign
            // (they take both signs already), their sum where they agree; the twist is left to the check.
            const double full = 8 * span, least = 0.05 * 8 * span;
            ratio.assign(second_samples.size(), 0.0);
            for (std::size_t i = 0; i < nu; ++i)
                for (std::size_t j = 0; j < nv; ++j) {
                    const std::size_t k = c.at(i, j), a = u_first ? i : j, b = u_first ? j : i;
                    if (!straddle) {
                        const double k1 = k_first[k], k2 = k_second[k];
                        const double used = k1 * k2 > 0 ? std::abs(k1) * h_first[a] * h_first[a] : 0.0;
                        ratio[b] = std::max(ratio[b], std::abs(k2) / std::max(full - used, least));
                        continue;
                    }
                    const double used = std::abs(k_first[k]) * h_first[a] * h_first[a];
                    const double rest = std::max(full - used, least), twist = std::abs(c.M[k]) * h_first[a];
                    if (twist == 0) {  // most samples of most faces: the root below squared, without the roots
                        ratio[b] = std::max(ratio[b], std::abs(k_second[k]) / rest);
                        continue;
                    }
                    const double inverse_h2 = (twist + std::sqrt(twist * twist + std::abs(k_second[k]) * rest)) / rest;
                    ratio[b] = std::max(ratio[b], inverse_h2 * inverse_h2);
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

double OffsetField::interpolate(const std::vector<double>& field, double u, double v) const {
    if (field.empty()) return 0;
    const auto [i, fu] = locate_in(us, u);
    const auto [j, fv] = locate_in(vs, v);
    const std::size_t n = vs.size();
    return (1 - fu) * ((1 - fv) * field[i * n + j] + fv * field[i * n + j + 1]) +
           fu * ((1 - fv) * field[(i + 1) * n + j] + fv * field[(i + 1) * n + j + 1]);
}

OffsetField offset_field(const CurvatureSamples& c, const ParameterGrid& g, const std::array<bool, 4>& collapsed_sides,
                         double max_offset, double target, bool straddle) {
    const auto span_at = [&](std::size_t i, std::size_t j) {
        const std::size_t k = c.at(i, j);
        const double hu = spacing_at(g.u, c.us[i]), hv = spacing_at(g.v, c.vs[j]);
        // Each chord term on the side its curvature puts it, the twist's on the other (see tessellate_plan.hpp).
        ErrorSpan span;
        for (double term : {c.L[k] * hu * hu / 8, c.N[k] * hv * hv / 8, -c.M[k] * hu * hv / 4})
            (term < 0 ? span.below : span.above) += term;
        return span;
    };
    return offset_field(c, span_at, collapsed_sides, max_offset, target, straddle);
}

OffsetField offset_field(const CurvatureSamples& c, const std::function<ErrorSpan(std::size_t, std::size_t)>& span_at,
                         const std::array<bool, 4>& collapsed_sides, double max_offset, double target, bool straddle) {
    OffsetField field;
    field.us = c.us;
    field.vs = c.vs;
    const std::size_t nu = c.us.size(), nv = c.vs.size();
    field.values.assign(nu * nv, 0.0);
    field.lowest.assign(nu * nv, 0.0);
    field.highest.assign(nu * nv, 0.0);
    for (std::size_t i = 0; i < nu; ++i) {
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t k = c.at(i, j);
            const double reach = c.k_max[k] > 0 ? std::min(max_offset, 0.25 / c.k_max[k]) : max_offset;
            const auto [below, above] = span_at(i, j);
            const double centre = std::clamp(-(below + above) / 2, -reach, reach);
            field.values[k] = straddle ? centre : 0.0;
            field.lowest[k] = std::max(-target - below, -reach);
            field.highest[k] = std::min(target - above, reach);
            if (field.lowest[k] > field.highest[k]) field.lowest[k] = field.highest[k] = field.values[k];
        }
    }
    // A collapsed side's row takes the next row's values.
    for (std::vector<double>* values : {&field.values, &field.lowest, &field.highest}) {
        std::vector<double>& f = *values;
        for (std::size_t i = 0; i < nu && nv > 1; ++i) {
            if (collapsed_sides[side_slot(Side::v_min)]) f[c.at(i, 0)] = f[c.at(i, 1)];
            if (collapsed_sides[side_slot(Side::v_max)]) f[c.at(i, nv - 1)] = f[c.at(i, nv - 2)];
        }
        for (std::size_t j = 0; j < nv && nu > 1; ++j) {
            if (collapsed_sides[side_slot(Side::u_min)]) f[c.at(0, j)] = f[c.at(1, j)];
            if (collapsed_sides[side_slot(Side::u_max)]) f[c.at(nu - 1, j)] = f[c.at(nu - 2, j)];
        }
    }
    return field;
}

void interior_grid_points(const SurfacePlan& plan, const ParameterGrid& grid, std::vector<Vec3>& out) {
    thread_local SurfaceGrid batch;
    const std::size_t nu = grid.u.size(), nv = grid.v.size();
    out.resize(nu * nv);
    const NurbsSurface& surface = plan.face->surface();
    evaluate_grid(surface, grid.u, grid.v, plan.straddle ? GridOutput::partials : GridOutput::points, batch);
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = batch.points[k];
    if (!plan.straddle) return;
    // The unit normals from the batch's partials. Where they are nearly parallel the surface's own limit
    // normal (NurbsSurface::normal, as evaluate_grid's normals would take it), except on a collapsed side:
    // a pole's points are the pole vertex's (GridPoints), and its limit normals, dear and asked again at
    // every refinement, would be thrown away.
    auto on_collapsed_side = [&](std::size_t i, std::size_t j) {
        return (j == 0 && plan.sides[side_slot(Side::v_min)].degenerate) ||
               (i + 1 == nu && plan.sides[side_slot(Side::u_max)].degenerate) ||
               (j + 1 == nv && plan.sides[side_slot(Side::v_max)].degenerate) ||
               (i == 0 && plan.sides[side_slot(Side::u_min)].degenerate);
    };
    thread_local std::vector<Vec3> normals;
    normals.resize(out.size());
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t k = i * nv + j;
            const Vec3 su = batch.du[k], sv = batch.dv[k], n = cross(su, sv);
            const double scale2 = dot(su, su) + dot(sv, sv);
            if (dot(n, n) > 1e-12 * scale2 * scale2) normals[k] = n / norm(n);
            else if (on_collapsed_side(i, j)) normals[k] = Vec3{};
            else {
                try {
                    normals[k] = surface.normal(grid.u[i], grid.v[j]);
                } catch (const Error&) {
                    return;  // a grid point without a tangent plane (nor a limit normal): none is moved
                }
            }
        }
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t k = i * nv + j;
            const Vec3 p = batch.points[k];
            // The room the grid's neighbours leave (offset_room); a collapsed neighbour (a pole row) counts
            // as far as any.
            double gap = std::numeric_limits<double>::infinity();
            auto near = [&](std::size_t a, std::size_t b) {
                const double d = distance(p, batch.points[a * nv + b]);
                if (d > 0) gap = std::min(gap, d);
            };
            if (i > 0) near(i - 1, j);
            if (i + 1 < nu) near(i + 1, j);
            if (j > 0) near(i, j - 1);
            if (j + 1 < nv) near(i, j + 1);
            const double reach = offset_room(gap, plan.max_offset());
            out[k] = p + normals[k] * std::clamp(plan.offsets.at(grid.u[i], grid.v[j]), -reach, reach);
        }
}

double offset_room(double gap, double max_offset) {
    if (!std::isfinite(gap)) return max_offset;
    return std::min(max_offset, 0.25 * gap * std::min(1.0, gap / (4 * max_offset)));
}

// Detected by normals just either side of the knot, from the evaluator's partials (NurbsSurface::normal,
// far dearer, only where they are nearly parallel).
std::vector<double> crease_lines(const NurbsSurface& s, const SurfaceEvaluator& e, bool along_u) {
    auto normal = [&](double u, double v) {
        const SurfaceFirstDerivatives p = e.first_derivatives(u, v);
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
        // A knot within delta of an end is that end, already a line of the grid: a file's B-spline may keep one
        // within rounding of its end (a servo's strip: a span of 1.6e-10 at the start of a u range of 0.96,
        // its poles there coincident, so no normal at the end).
        if (breaks[k] - delta <= d.min || breaks[k] + delta >= d.max) continue;
        const double t0 = breaks[k] - delta, t1 = breaks[k] + delta;
        bool crease = false;
        for (int q = 1; q <= 5 && !crease; ++q) {
            const double w = other.min + (other.max - other.min) * q / 6.0;
            const Vec3 before = along_u ? normal(t0, w) : normal(w, t0);
            const Vec3 after = along_u ? normal(t1, w) : normal(w, t1);
            crease = distance(before, after) > 1e-4;
        }
        if (crease) result.push_back(breaks[k]);
    }
    result.push_back(d.max);
    return result;
}

std::array<int, 2> minimum_segments(const std::array<SideMap, 4>& sides) {
    // A direction closed on itself (both sides the same edge) needs three intervals to enclose anything;
    // one bounded by two degenerate sides needs two (one interval would join pole to pole).
    auto minimum = [&](Side a, Side b) {
        const SideMap &sa = sides[side_slot(a)], &sb = sides[side_slot(b)];
        if (sa.edge == sb.edge && !sa.degenerate) return 3;
        if (sa.degenerate && sb.degenerate) return 2;
        return 1;
    };
    return {minimum(Side::u_min, Side::u_max), minimum(Side::v_min, Side::v_max)};
}

namespace {

// The triangles a face's grid would need when choose_grid found none within the budget, for the error
// message: the grid for a tolerance f times coarser (and an angle sqrt(f) times wider) that fits, scaled
// back by f, since the line spacing in each direction goes as sqrt(tolerance / curvature) (the chord
// sagitta) and as the angle, so the cells go as 1 / f. At least the budget + 1. The coarse grids are held to
// kEstimateCells, not to the budget: a hopeless request (tolerance 1e-15 under the default 20 million) is
// refused in milliseconds instead of after placing millions of lines for each f (26 s, measured).
constexpr double kEstimateCells = 1e5;

double over_budget_triangles(const SurfacePlan& plan, const CurvatureSamples& curvature,
                             const TessellationSettings& settings) {
    const double at_least = static_cast<double>(settings.max_triangles) + 1;
    const double cells = std::min(max_cells(settings), kEstimateCells);
    for (double f = 4; settings.tolerance * f < std::numeric_limits<double>::max() / 4; f *= 4) {
        const ParameterGrid coarse = choose_grid(curvature, settings.tolerance * f, settings.angle_rad * std::sqrt(f),
                                                 plan.min_segments, plan.creases, cells);
        if (!coarse.u.empty()) return std::max(at_least, 2 * coarse.cells() * f);
    }
    return at_least;
}

}  // namespace

double triangles_at_least(const SurfacePlan& plan, std::size_t lines_u, std::size_t lines_v) {
    const double along_u = static_cast<double>(lines_u - 1), along_v = static_cast<double>(lines_v - 1);
    double count = 2 * along_u * along_v;
    // A cell along a collapsed side loses one of its two triangles (a fan at the pole), one along two
    // collapsed sides both.
    for (Side side : kSides)
        if (plan.sides[side_slot(side)].degenerate) count -= runs_along_u(side) ? along_u : along_v;
    return std::max(count, 0.0);
}

double triangles_at_least(const SurfacePlan& plan) {
    if (!plan.rows.empty()) return kRowsAtLeast * row_triangles(plan, plan.rows);
    return triangles_at_least(plan, plan.grid.u.size(), plan.grid.v.size());
}

std::array<bool, 4> collapsed_sides(const SurfacePlan& plan) {
    std::array<bool, 4> collapsed{};
    for (Side side : kSides) collapsed[side_slot(side)] = plan.sides[side_slot(side)].degenerate;
    return collapsed;
}

double SurfacePlan::cells() const { return rows.empty() ? grid.cells() : row_triangles(*this, rows) / 2; }

bool may_straddle(std::span<const Face> faces) {
    for (const Face& face : faces) {
        if (face.kind() != Face::Kind::surface) continue;
        double lightest = std::numeric_limits<double>::infinity(), heaviest = 0;
        for (const auto& row : face.surface().weights())
            for (double w : row) lightest = std::min(lightest, w), heaviest = std::max(heaviest, w);
        if (!(heaviest <= kStraddleWeightRatio * lightest)) return false;
    }
    return true;
}

namespace {

// True when no sample of the face is a saddle or twisted (L N >= 0 and M = 0, up to rounding: spheres,
// cylinders, cones, tori's outer halves, revolutions in their natural parameters): there the straddling
// model's span is 2 kOffsetShare check_tolerance() against the inscribed one's tolerance, its first
// direction's share of it as large, and what remains for the second direction larger too, so it never
// needs more cells than the inscribed grid, which need not be chosen to be compared.
bool straddling_is_cheaper(const CurvatureSamples& c) {
    for (std::size_t k = 0; k < c.L.size(); ++k) {
        const double L = c.L[k], N = c.N[k], scale = std::abs(L) + std::abs(N);
        if (L * N < 0 && std::min(std::abs(L), std::abs(N)) > 1e-9 * scale) return false;
        if (std::abs(c.M[k]) > 1e-9 * scale) return false;
    }
    return true;
}

}  // namespace

SurfacePlan plan_face(const Face& face, const TessellationSettings& settings, CurvatureSamples& curvature,
                      bool straddle) {
    // The curvature samples cost memory and time like triangles do (about 200 bytes each): a face
    // with more knot spans than the budget can sample (10^5 spans revolved into 4 x 10^5 patches) is
    // refused up front. A small budget still allows the 2^18 samples any ordinary face needs.
    const double samples = curvature_sample_count(face.surface(), kCoarseSamplesPerSpan);
    const double sample_budget = std::max(4.0 * static_cast<double>(settings.max_triangles), 262'144.0);
    if (samples > sample_budget)
        fail("max_triangles", "a face with " + std::to_string(face.surface().knots_u().size()) + " x " +
                                  std::to_string(face.surface().knots_v().size()) + " knots needs " +
                                  std::to_string(static_cast<long long>(samples)) + " curvature samples, more than " +
                                  std::to_string(static_cast<long long>(sample_budget)) + " that a budget of " +
                                  std::to_string(settings.max_triangles) + " triangles allows");
    SurfacePlan plan;
    plan.face = &face;
    plan.evaluator = std::make_shared<const SurfaceEvaluator>(face.surface());
    for (Side side : kSides) plan.sides[side_slot(side)] = map_side(face, side);
    plan.min_segments = minimum_segments(plan.sides);
    plan.creases = {crease_lines(face.surface(), *plan.evaluator, true),
                    crease_lines(face.surface(), *plan.evaluator, false)};
    // Every piece between two creases gets a line interval of its own, so a face with more creased
    // pieces than the budget allows (a profile with many sharp corners) is refused here already.
    const double crease_cells = static_cast<double>(std::max<std::size_t>(plan.creases[0].size(), 2) - 1) *
                                static_cast<double>(std::max<std::size_t>(plan.creases[1].size(), 2) - 1);
    if (crease_cells > max_cells(settings)) throw TooFine(crease_cells, settings.max_triangles);
    // The coarse samples first. Their line densities are a little more conservative (each is the
    // largest over a longer sample interval): that costs a few cells on a small grid, while the fine
    // sampling would cost more than checking the whole grid. Resampled finely once the grid has
    // more than a quarter as many cells as the fine samples (or the coarse estimate is over budget).
    // Straddling the surface or inscribed in it, whichever the model finds cheaper: a twisted or saddle
    // shaped face errs both ways already when inscribed (see tessellate_plan.hpp), and gains little or
    // nothing from offsets. The inscribed grid is checked against the tolerance itself, as before there
    // were offsets; the straddling one a little below it (check_tolerance).
    // A face that rows may mesh gets its grid within a wider cap: rows need up to a third fewer triangles, and
    // a mesh within max_triangles must not be refused for its grid's count (the count decides once planned).
    const SideMap &u_low = plan.sides[side_slot(Side::u_min)], &u_high = plan.sides[side_slot(Side::u_max)];
    const bool rows_possible = straddle && settings.angle_rad == 0 && !u_low.degenerate && u_low.edge == u_high.edge;
    const double grid_cap = (rows_possible ? 1.5 : 1.0) * max_cells(settings);
    auto choose = [&] {
        const ParameterGrid straddling = choose_grid(curvature, settings.check_tolerance(), settings.angle_rad,
                                                     plan.min_segments, plan.creases, grid_cap, true);
        ParameterGrid inscribed;
        if (!straddle || straddling.u.empty() || !straddling_is_cheaper(curvature))
            inscribed = choose_grid(curvature, settings.tolerance, settings.angle_rad, plan.min_segments, plan.creases,
                                    grid_cap, false);
        plan.straddle = straddle && !straddling.u.empty() && (inscribed.u.empty() || straddling.cells() < inscribed.cells());
        plan.target = plan.straddle ? settings.check_tolerance() : settings.tolerance;
        plan.grid = plan.straddle ? straddling : std::move(inscribed);
    };
    curvature = sample_curvature(face.surface(), kCoarseSamplesPerSpan);
    choose();
    if (plan.grid.u.empty() || 4 * plan.grid.cells() > curvature_sample_count(face.surface(), kFineSamplesPerSpan)) {
        curvature = sample_curvature(face.surface(), kFineSamplesPerSpan);
        choose();
    }
    if (plan.grid.u.empty()) throw TooFine(over_budget_triangles(plan, curvature, settings), settings.max_triangles);
    // Staggered rows where the face allows them and the model finds them cheaper (tessellate_rows.hpp); the
    // grid stays as the fallback should their check not converge.
    if (rows_apply(plan, settings) && triangles_at_least(plan) >= kRowsFrom) {
        RowGrid rows = plan_rows(plan, curvature, plan.target, max_cells(settings) / kRowsAtLeast);
        if (!rows.empty() && row_triangles(plan, rows) < kRowsGain * triangles_at_least(plan)) plan.rows = std::move(rows);
    }
    if (triangles_at_least(plan) > max_cells(settings))
        throw TooFine(over_budget_triangles(plan, curvature, settings), settings.max_triangles);
    set_offsets(plan, curvature);
    return plan;
}

namespace {


// The polylines along the face's sides against its boundary curves: a side's points are off the surface
// (by its offsets, or as the faces beyond it wish), and at a crease the curve is the mesh's edge, which no
// cell's check sees: a chord whose curve strays more than the target from it fails like a cell (marking
// its interval), so that the surface's points keep within the tolerance of the mesh along the boundary too.
void check_sides(const SurfacePlan& plan, const std::vector<Vec3>& corners, GridCheck& check) {
    const ParameterGrid& g = plan.grid;
    const std::size_t nu = g.u.size(), nv = g.v.size();
    for (Side side : kSides) {
        if (plan.sides[side_slot(side)].degenerate) continue;
        const bool along_u = runs_along_u(side);
        const std::vector<double>& lines = along_u ? g.u : g.v;
        const std::size_t fixed = side == Side::v_min || side == Side::u_min ? 0 : (along_u ? nv : nu) - 1;
        const double across = along_u ? g.v[fixed] : g.u[fixed];
        std::vector<char>& marks = along_u ? check.refine_u : check.refine_v;
        for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
            const Vec3& a = along_u ? corners[k * nv + fixed] : corners[fixed * nv + k];
            const Vec3& b = along_u ? corners[(k + 1) * nv + fixed] : corners[fixed * nv + k + 1];
            double error = 0;
            for (double f : {0.25, 0.5, 0.75}) {
                const double t = lines[k] + f * (lines[k + 1] - lines[k]);
                const Vec3 p = along_u ? plan.evaluator->point(t, across) : plan.evaluator->point(across, t);
                error = std::max(error, point_segment_distance(p, a, b));
            }
            const double ratio = error / plan.target;
            check.worst_ratio = std::max(check.worst_ratio, ratio);
            if (ratio > 1) marks[k] = 1;
        }
    }
}

}  // namespace

void set_offsets(SurfacePlan& plan, const CurvatureSamples& curvature) {
    if (!plan.rows.empty()) {
        plan.offsets = row_offset_field(plan, curvature);
        return;
    }
    plan.offsets = offset_field(curvature, plan.grid, collapsed_sides(plan), plan.max_offset(), plan.target, plan.straddle);
}

bool refine_grid(SurfacePlan& plan, const CurvatureSamples& curvature, const TessellationSettings& settings,
                 const GridPoints& points, const RefineStart& start) {
    if (!plan.rows.empty()) {
        const RowRefinement outcome = refine_rows(plan, curvature, settings, points, start.rescale);
        if (outcome != RowRefinement::given_up) return outcome == RowRefinement::changed;
        // The tensor grid the rows were chosen over, fresh: planned, checked and refined as any.
        plan.rows = {};
        set_offsets(plan, curvature);
        refine_grid(plan, curvature, settings, points);
        return true;
    }
    double target = plan.target;
    std::vector<Vec3> corners;
    const std::array<bool, 4> collapsed = collapsed_sides(plan);
    // The intervals whose cells are to be checked: all of them for a fresh grid, and after every change of
    // the grid, whose offsets follow its spacing.
    std::vector<char> new_u = start.check_u, new_v = start.check_v;
    if (new_u.empty()) new_u.assign(plan.grid.u.size() - 1, 1);
    if (new_v.empty()) new_v.assign(plan.grid.v.size() - 1, 1);
    bool changed = false, bisected = false;
    for (int iteration = 0; iteration < 40; ++iteration) {
        settings.poll();
        if (const double at_least = triangles_at_least(plan); at_least > static_cast<double>(settings.max_triangles))
            throw TooFine(at_least, settings.max_triangles);
        points(plan, corners);
        GridCheck check = check_grid(*plan.evaluator, plan.face->surface(), plan.grid, collapsed, plan.target,
                                     settings.angle_rad, new_u, new_v, corners, [&] { settings.poll(); });
        if (plan.straddle) check_sides(plan, corners, check);  // an inscribed face's sides lie on its surface
        if (check.worst_ratio <= 1) return changed;
        const bool some_marked = std::count(check.refine_u.begin(), check.refine_u.end(), 1) +
                                     std::count(check.refine_v.begin(), check.refine_v.end(), 1) > 0;
        if (start.rescale && iteration == 0 && plan.straddle && check.worst_ratio > kStraddleGiveUp) {
            // The model is far off on this face (curvature that jumps between its samples, a strong twist):
            // the offsets it centres the errors with are no better, and the grid inscribed in the surface is
            // planned and refined as it was before there were offsets.
            plan.straddle = false;
            plan.target = target = settings.tolerance;
            ParameterGrid g = choose_grid(curvature, target, settings.angle_rad, plan.min_segments, plan.creases,
                                          max_cells(settings), false);
            if (g.u.empty()) throw TooFine(max_cells(settings) + 1, settings.max_triangles);
            plan.grid = std::move(g);
        } else if (start.rescale && !bisected && iteration < 3 && check.worst_ratio < 1.5) {
            target *= 0.99 / check.worst_ratio;
            ParameterGrid g = choose_grid(curvature, target, settings.angle_rad, plan.min_segments, plan.creases,
                                          max_cells(settings), plan.straddle);
            if (g.u.empty()) throw TooFine(max_cells(settings) + 1, settings.max_triangles);
            plan.grid = std::move(g);
        } else if (some_marked) {
            plan.grid.u = bisect_marked(plan.grid.u, check.refine_u);
            plan.grid.v = bisect_marked(plan.grid.v, check.refine_v);
            bisected = true;
        } else {
            return changed;
        }
        changed = true;
        set_offsets(plan, curvature);
        new_u.assign(plan.grid.u.size() - 1, 1);
        new_v.assign(plan.grid.v.size() - 1, 1);
    }
    return changed;
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
// whole creases cost 60%, bisecting the thin cells instead several times that). Lines only subdivide
// cells that passed their check. Repeated until no face gains a line, since lines can pass on along a
// ring of thin rows.
void match_lines_at_creases(std::vector<SurfacePlan>& plans, const TessellationSettings& settings) {
    // The uses of each edge, edges in order of first use (not of their addresses: the result must
    // not depend on where the allocator put them).
    std::vector<std::pair<const Edge*, std::vector<EdgeUse>>> uses;
    std::map<const Edge*, std::size_t> slot;
    for (SurfacePlan& plan : plans)
        for (Side side : kSides) {
            const SideMap& m = plan.sides[side_slot(side)];
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
            if (!list[0].plan->rows.empty() || !list[1].plan->rows.empty()) continue;  // rows take no lines
            for (int k = 0; k < 2; ++k) {
                const EdgeUse& to = list[static_cast<std::size_t>(k)];
                const EdgeUse& from = list[static_cast<std::size_t>(1 - k)];
                const SideMap& to_map = to.plan->sides[side_slot(to.side)];
                const SideMap& from_map = from.plan->sides[side_slot(from.side)];
                std::vector<double>& lines = lines_of(*to.plan, to.side);
                const std::vector<char> thin = thin_intervals(*to.plan, to.side);
                std::vector<double> merged = lines;
                for (double p : lines_of(*from.plan, from.side)) {
                    const double q = to_map.to_face(from_map.to_edge(p));
                    const auto k_interval = std::upper_bound(lines.begin(), lines.end(), q) - lines.begin() - 1;
                    if (k_interval >= 0 && static_cast<std::size_t>(k_interval) < thin.size() &&
                        thin[static_cast<std::size_t>(k_interval)])
                        merged.push_back(q);
                }
                merged = merge_params(std::move(merged), lines.front(), lines.back());
                if (merged.size() > lines.size()) {
                    const std::size_t across = runs_along_u(to.side) ? to.plan->grid.v.size() : to.plan->grid.u.size();
                    const double at_least = runs_along_u(to.side)
                                                ? triangles_at_least(*to.plan, merged.size(), across)
                                                : triangles_at_least(*to.plan, across, merged.size());
                    if (at_least > static_cast<double>(settings.max_triangles))
                        throw TooFine(at_least, settings.max_triangles);
                    lines = std::move(merged);
                    changed = true;
                }
            }
        }
        if (!changed) break;
    }
}

const std::vector<double>& side_lines(const SurfacePlan& plan, Side side) {
    if (plan.rows.empty()) return runs_along_u(side) ? plan.grid.u : plan.grid.v;
    if (!runs_along_u(side)) return plan.rows.seam_v;
    return side == Side::v_min ? plan.rows.u.front() : plan.rows.u.back();
}

void take_lines_into_rows(std::vector<SurfacePlan>& plans) {
    for (SurfacePlan& plan : plans) {
        if (plan.rows.empty()) continue;
        for (Side side : {Side::v_min, Side::v_max}) {
            const SideMap& m = plan.sides[side_slot(side)];
            if (m.degenerate) continue;
            std::vector<double>& row = side == Side::v_min ? plan.rows.u.front() : plan.rows.u.back();
            std::vector<double> merged = row;
            for (const SurfacePlan& other : plans)
                for (Side beyond : kSides) {
                    const SideMap& o = other.sides[side_slot(beyond)];
                    if (o.degenerate || o.edge != m.edge || (&other == &plan && beyond == side)) continue;
                    for (double p : side_lines(other, beyond)) merged.push_back(m.to_face(o.to_edge(p)));
                }
            row = merge_params(std::move(merged), row.front(), row.back());
        }
    }
}

void plan_surfaces(std::span<const Face> faces, const TessellationSettings& settings, const GridPoints& points,
                   std::vector<SurfacePlan>& plans) {
    plans.clear();
    std::vector<CurvatureSamples> curvatures;
    const bool straddle = may_straddle(faces);
    // A face beside a trimmed face is inscribed: the trimmed face's boundary samples stay on their curves
    // (its p-curves say where they are in its (u, v)), and a straddling grid whose side is held on the curve
    // covers its own surface near that side by less than the tolerance (a torus beside trimmed faces: 1.005x).
    std::set<const Edge*> trimmed_edges;
    for (const Face& face : faces)
        if (face.kind() == Face::Kind::trimmed) for_each_coedge(face, [&](const Coedge& c) { trimmed_edges.insert(c.edge.get()); });
    for (const Face& face : faces) {
        if (face.kind() != Face::Kind::surface) continue;
        bool beside_trimmed = false;
        for (const Coedge& c : face.sides()) beside_trimmed = beside_trimmed || trimmed_edges.count(c.edge.get()) > 0;
        curvatures.emplace_back();
        plans.push_back(plan_face(face, settings, curvatures.back(), straddle && !beside_trimmed));
    }
    // The count for the whole solid before any cell is checked or any mesh built: what the plans' grids
    // give at least (triangles_at_least), and at least one triangle per planar face. Only a count the mesh
    // cannot fall below may refuse it (a mesh within max_triangles must pass); the refinement below grows
    // the grids, and is held against the same count of all faces after every face.
    const auto planned_total = [&] {
        double total = 0;
        for (const Face& face : faces) total += face.kind() == Face::Kind::planar ? 1.0 : 0.0;
        for (const SurfacePlan& plan : plans) total += triangles_at_least(plan);
        return total;
    };
    if (const double total = planned_total(); total > static_cast<double>(settings.max_triangles))
        throw TooFine(total, settings.max_triangles);
    // stale[k]: the points along face k's sides may have moved since its cells were last checked (a face
    // refined after it changed its grid and offsets).
    std::vector<char> stale(plans.size(), 0);
    auto others_moved = [&](std::size_t k) {
        for (std::size_t j = 0; j < plans.size(); ++j)
            if (j != k) stale[j] = 1;
    };
    for (std::size_t k = 0; k < plans.size(); ++k) {
        settings.report(kPlannedFraction * static_cast<double>(k) / static_cast<double>(plans.size()));
        stale[k] = 0;
        if (refine_grid(plans[k], curvatures[k], settings, points)) others_moved(k);
        if (const double total = planned_total(); total > static_cast<double>(settings.max_triangles))
            throw TooFine(total, settings.max_triangles);
    }
    std::vector<std::size_t> cells_before;
    for (const SurfacePlan& plan : plans) cells_before.push_back(static_cast<std::size_t>(plan.cells()));
    match_lines_at_creases(plans, settings);
    take_lines_into_rows(plans);
    // The points along a face's sides move as the faces on both sides wish (and a face that took lines
    // across a crease has new offsets): the faces refined before a neighbour were checked with points that
    // have moved since. Checked again with the final points, all cells of a face whose grid changed, the
    // cells along the sides of the others whose points may have moved, until no face changes (bounded: a
    // change is rare after the first round). A solid with one surface face (a sphere, a cylinder) was
    // checked with its final points already.
    std::vector<char> changed(plans.size());
    for (std::size_t k = 0; k < plans.size(); ++k) {
        changed[k] = static_cast<std::size_t>(plans[k].cells()) != cells_before[k];
        if (changed[k]) {
            set_offsets(plans[k], curvatures[k]);
            others_moved(k);
        }
    }
    for (int round = 0; round < 4; ++round) {
        bool any = false;
        for (std::size_t k = 0; k < plans.size(); ++k) {
            if (!changed[k] && !stale[k]) continue;
            RefineStart start;
            start.rescale = false;
            if (!changed[k]) {
                auto ring = [](std::size_t intervals) {
                    std::vector<char> r(intervals, 0);
                    r.front() = r.back() = 1;
                    return r;
                };
                start.check_u = ring(plans[k].grid.u.size() - 1);
                start.check_v = ring(plans[k].grid.v.size() - 1);
            }
            stale[k] = 0;
            changed[k] = refine_grid(plans[k], curvatures[k], settings, points, start) ? 1 : 0;
            if (changed[k]) others_moved(k);
            any = any || changed[k];
        }
        if (!any) break;
    }
}

}  // namespace ratbez::detail
