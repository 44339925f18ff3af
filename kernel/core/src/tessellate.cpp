// Adaptive watertight tessellation (tessellate.hpp), the pipeline:
//  1. planning (tessellate_plan.hpp): every surface face gets a tensor grid of parameter lines, chosen
//     from its curvature, then checked cell by cell on the real surface and refined where a cell fails
//     (tessellate_cells.hpp);
//  2. edge sampling (here): edges are sampled once: an edge used by surface faces takes the union of
//     their lines along it (tessellate_sides.hpp), an edge of planar faces only is sampled by its own
//     chordal deviation;
//  3. assembly (here): the cells of each grid become triangles on the shared edge samples; cells along
//     a boundary whose edge carries extra samples (from the neighbouring face) are closed with a zipper
//     strip; degenerate sides collapse to their single vertex, so cells at a pole become fan triangles.
//     Planar faces are triangulated from their boundary loops.

#include "ratbez/tessellate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "polygon_triangulation.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/surface_grid.hpp"
#include "tessellate_cells.hpp"
#include "tessellate_plan.hpp"
#include "tessellate_sides.hpp"

namespace ratbez {
namespace {

using detail::CellTriangle;
using detail::CellVertex;
using detail::kSides;
using detail::runs_along_u;
using detail::side_slot;
using detail::SideMap;
using detail::SurfacePlan;
using Id = detail::MeshVertexId;

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

// ---------------------------------------------------------------------------------------------------------
// The driver: plan every surface face, sample every edge once, then mesh the faces on those samples.

class Tessellator {
public:
    Tessellator(std::span<const Face> faces, const detail::TessellationSettings& settings)
        : faces_(faces), settings_(settings) {}

    // Progress: planning reports up to kPlannedFraction, then each face meshed takes an equal share of
    // the rest (rows of a surface face poll in between).
    Mesh run() {
        plans_ = detail::plan_surfaces(faces_, settings_);
        sample_edges();
        const double step = (1 - detail::kPlannedFraction) / static_cast<double>(faces_.size());
        double done = detail::kPlannedFraction;
        for (const SurfacePlan& plan : plans_) {
            settings_.report(done);
            mesh_surface(plan);
            done += step;
        }
        for (const Face& face : faces_)
            if (face.kind() == Face::Kind::planar) {
                settings_.report(done);
                mesh_planar(face);
                done += step;
            }
        settings_.report(1.0);
        return assembler_.take();
    }

private:
    void sample_edges() {
        std::map<const Edge*, std::vector<double>> from_surfaces;
        for (const SurfacePlan& plan : plans_)
            for (Side side : kSides) {
                const SideMap& m = plan.sides[side_slot(side)];
                if (m.degenerate) continue;
                auto& params = from_surfaces[m.edge];
                for (double p : runs_along_u(side) ? plan.grid.u : plan.grid.v) params.push_back(m.to_edge(p));
            }
        for (const EdgePtr& edge : distinct_edges(faces_)) {
            EdgeSamples samples;
            if (edge->degenerate) {
                samples.ids = {assembler_.vertex_id(edge->start)};
                samples.params = {edge->curve.domain().min};
            } else {
                const Interval d = edge->curve.domain();
                const auto it = from_surfaces.find(edge.get());
                samples.params = detail::merge_params(it != from_surfaces.end() ? it->second : sample_curve(edge->curve, settings_.tolerance),
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
        require(it != edge_samples_.end(), "solid", "a face uses an edge the faces do not list");
        return it->second;
    }

    void mesh_surface(const SurfacePlan& plan) {
        const detail::SurfaceEvaluator& s = *plan.evaluator;
        const detail::ParameterGrid& g = plan.grid;
        const std::size_t nu = g.u.size(), nv = g.v.size();

        // Per side: (face parameter, id) of every edge sample, ascending in the face parameter.
        std::array<std::vector<std::pair<double, Id>>, 4> side_samples;
        for (Side side : kSides) {
            const SideMap& m = plan.sides[side_slot(side)];
            const EdgeSamples& e = samples_of(m.edge);
            auto& list = side_samples[side_slot(side)];
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
            const auto& list = side_samples[side_slot(side)];
            auto it = std::lower_bound(list.begin(), list.end(), std::make_pair(p, Id{0}),
                                       [](const auto& a, const auto& b) { return a.first < b.first; });
            if (it == list.end() || (it != list.begin() && std::abs(std::prev(it)->first - p) < std::abs(it->first - p))) --it;
            return static_cast<std::size_t>(it - list.begin());
        };
        auto side_id = [&](Side side, double p) -> std::pair<bool, Id> {
            const SideMap& m = plan.sides[side_slot(side)];
            if (m.degenerate) return {true, samples_of(m.edge).ids[0]};
            return {false, side_samples[side_slot(side)][side_index(side, p)].second};
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
            const SideMap& m = plan.sides[side_slot(side)];
            if (m.degenerate) return;
            const auto& list = side_samples[side_slot(side)];
            const bool along_u = runs_along_u(side);
            for (std::size_t k = side_index(side, p0) + 1, end = side_index(side, p1); k < end; ++k) {
                const auto& [p, id] = list[k];
                chain.push_back(CellVertex{along_u ? p : fixed, along_u ? fixed : p, assembler_.point(id), id});
            }
        };

        std::vector<CellVertex> bottom, right, top, left, lower, upper;
        CellVertex center;
        std::vector<CellTriangle> triangles;
        for (std::size_t i = 0; i + 1 < nu; ++i) {
            if (i % 64 == 63) settings_.poll();
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
                if (detail::triangulate_cell(s, bottom, right, top, left, lower, upper, center, triangles)) {
                    const double u = 0.5 * (g.u[i] + g.u[i + 1]), v = 0.5 * (g.v[j] + g.v[j + 1]);
                    const Vec3 p = s.point(u, v);
                    center = CellVertex{u, v, p, assembler_.add_point(p)};
                }
                for (const auto& t : triangles) assembler_.add_triangle(t[0]->id, t[1]->id, t[2]->id);
            }
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

    std::span<const Face> faces_;
    detail::TessellationSettings settings_;
    std::vector<SurfacePlan> plans_;
    std::map<const Edge*, EdgeSamples> edge_samples_;
    MeshAssembler assembler_;
    SurfaceGrid grid_points_;  // mesh_surface's batch, kept to reuse its storage from face to face
};

}  // namespace

namespace {

// Round to two significant digits: an estimate, not a count.
std::string about(double count) {
    const double rounded = count < 100 ? std::ceil(count)
                                       : [&] {
                                             const double unit = std::pow(10.0, std::floor(std::log10(count)) - 1);
                                             return std::ceil(count / unit) * unit;
                                         }();
    return std::to_string(static_cast<long long>(std::min(rounded, 9e18)));
}

}  // namespace

TooFine::TooFine(double estimated_triangles, std::size_t max_triangles)
    : Error("tolerance", "too fine: the mesh would need about " + about(estimated_triangles) +
                             " triangles, more than max_triangles = " + std::to_string(max_triangles) + " allows"),
      estimated_(estimated_triangles),
      max_triangles_(max_triangles) {}

namespace {

// The planner's estimate covers the face it stopped at, so it is a lower bound for the whole. A coarser
// tessellation of all faces that fits (tolerance x4 each step, at most 20,000 triangles: about a second)
// scaled by the tolerance ratio gives the estimate: a curved face's triangles grow as 1 / tolerance, flat
// ones not at all (so it errs high).
double estimate_triangles(std::span<const Face> faces, detail::TessellationSettings settings, double lower_bound) {
    const double requested = settings.tolerance;
    settings.max_triangles = std::min<std::size_t>(settings.max_triangles, 20'000);
    for (int step = 0; step < 24; ++step) {
        settings.tolerance *= 4;
        try {
            const Mesh coarse = Tessellator(faces, settings).run();
            return std::max(lower_bound, static_cast<double>(coarse.triangles.size()) * settings.tolerance / requested);
        } catch (const TooFine&) {
        }
    }
    return lower_bound;
}

}  // namespace

double default_tolerance(const Solid& solid) { return 1e-3 * solid.bounding_box().diagonal(); }

namespace {

detail::TessellationSettings settings_of(const TessellationOptions& options) {
    require(std::isfinite(options.tolerance) && options.tolerance > 0, "tolerance",
            "must be a finite number > 0 (got " + std::to_string(options.tolerance) + ")");
    detail::TessellationSettings settings;
    settings.tolerance = options.tolerance;
    if (options.angle_deg) {
        require(std::isfinite(*options.angle_deg) && *options.angle_deg > 0 && *options.angle_deg < 180, "angle_deg",
                "must be in (0, 180) degrees (got " + std::to_string(*options.angle_deg) + ")");
        settings.angle_rad = *options.angle_deg * std::numbers::pi / 180.0;
    }
    require(options.max_triangles > 0, "max_triangles", "must be positive");
    settings.max_triangles = options.max_triangles;
    settings.progress = &options.progress;
    return settings;
}

// Tessellates the faces; a request over the budget is reported with the estimate for all of them.
Mesh run_within_budget(std::span<const Face> faces, const detail::TessellationSettings& settings) {
    try {
        return Tessellator(faces, settings).run();
    } catch (const TooFine& e) {
        throw TooFine(estimate_triangles(faces, settings, e.estimated_triangles()), settings.max_triangles);
    }
}

}  // namespace

Mesh tessellate(const Solid& solid, const TessellationOptions& options) {
    Mesh mesh = run_within_budget(solid.faces(), settings_of(options));
    // Closed by construction for a valid solid; the check (O(triangles), a few % of the time) keeps a
    // solid whose faces fold onto each other — a profile that runs back over itself, found by
    // fuzz_geometry — from handing out an open mesh.
    require(mesh.is_closed(), "solid", "its faces do not close up into a watertight mesh (they overlap or fold "
                                       "back on each other, e.g. a profile that runs back over itself)");
    return mesh;
}

Mesh tessellate(const Face& face, const TessellationOptions& options) {
    return run_within_budget(std::span<const Face>(&face, 1), settings_of(options));
}

Mesh tessellate(const NurbsSurface& surface, const TessellationOptions& options) {
    const detail::TessellationSettings settings = settings_of(options);  // the options first, then the surface
    const Face face = Face::from_surface(surface);
    return run_within_budget(std::span<const Face>(&face, 1), settings);
}

}  // namespace ratbez
