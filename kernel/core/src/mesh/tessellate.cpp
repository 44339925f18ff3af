// Adaptive watertight tessellation (tessellate.hpp), the pipeline:
//  1. planning (tessellate_plan.hpp): every surface face gets a tensor grid of parameter lines, chosen
//     from its curvature, and offsets that move its vertices off the surface so that the mesh straddles
//     it; a face closed on itself along u (a sphere, a torus, a revolution) gets staggered rows instead
//     where they need fewer triangles (tessellate_rows.hpp); then checked cell by cell (strip by strip) on
//     the real surface, with the vertices where the mesh will have them, and refined where a cell fails
//     (tessellate_cells.hpp);
//  2. edge sampling (here): edges are sampled once: an edge used by surface faces takes the union of
//     their lines along it (tessellate_sides.hpp), an edge of planar faces only is sampled by its own
//     chordal deviation; a sample, and a B-rep vertex, moves as all the faces using it wish
//     (tessellate_offsets.hpp), a function of the plans alone (proposals_of), so that the checks of both
//     faces and the mesh see the same point; a crease's polyline is split where it strays from its curve;
//  3. assembly (here): the cells of each grid (the strips between rows) become triangles on the shared
//     edge samples; cells along a boundary whose edge carries extra samples (from the neighbouring face)
//     are closed with a zipper strip; degenerate sides collapse to their single vertex, so cells at a pole
//     become fan triangles.
//     Planar faces are triangulated from their boundary loops; trimmed faces by a constrained Delaunay
//     triangulation of their (u, v) region on the edge samples, refined by the chord error
//     (trimmed_domain.hpp). Edges and vertices of trimmed faces stay on their curves (no offset): the
//     p-curves say where they are in the face.

#include "ratbez/tessellate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <tuple>
#include <numbers>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/tessellate_cells.hpp"
#include "mesh/tessellate_offsets.hpp"
#include "mesh/tessellate_plan.hpp"
#include "mesh/tessellate_rows.hpp"
#include "mesh/tessellate_sides.hpp"
#include "mesh/tessellator.hpp"
#include "mesh/triangle_grid.hpp"
#include "mesh/domain_triangulation.hpp"
#include "mesh/weight_limit.hpp"
#include "math/numeric_internal.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/convex_hull.hpp"
#include "ratbez/convexity.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh_topology.hpp"
#include "ratbez/mesh_welding.hpp"
#include "ratbez/solid_transform.hpp"
#include "ratbez/surface_grid.hpp"

namespace ratbez {
namespace {

// Samples of one edge of a trimmed face beyond which its refinement is refused (refine_for_trimmed): a
// boundary that needs more at a tolerance the triangle limits allow does not follow its face.
constexpr std::size_t kMaxTrimmedEdgeSamples = 1'000'000;

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
    template <class MakePoint>
    Id vertex_id(const Vertex* vertex, MakePoint&& make_point) {
        const auto [it, inserted] = vertex_ids_.try_emplace(vertex, 0);
        if (inserted) it->second = add_point(make_point());
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
        : faces_(faces), settings_(settings) {
        for (const auto& [edge, halvings] : settings_.finer_edges) finer_vertices_.insert({edge->start.get(), edge->end.get()});
    }

    // Progress: planning reports up to kPlannedFraction, then each face meshed takes an equal share of
    // the rest (rows of a surface face poll in between).
    Mesh run() {
        detail::plan_surfaces(
            faces_, settings_, [this](const SurfacePlan& p, std::vector<Vec3>& out) { grid_points(p, out); }, plans_);
        sample_edges();
        // Every face whose boundary comes out too coarse is gathered, so that one more attempt samples all their
        // edges finer.
        std::optional<std::string> coarse_first;
        std::vector<const Edge*> coarse_edges;
        const auto gather_coarse = [&](std::size_t i, const Error& e, std::span<const Edge* const> edges) {
            if (!coarse_first) coarse_first = "face " + std::to_string(i) + ": " + e.what();
            coarse_edges.insert(coarse_edges.end(), edges.begin(), edges.end());
        };
        const double step = (1 - detail::kPlannedFraction) / static_cast<double>(faces_.size());
        double done = detail::kPlannedFraction;
        for (const SurfacePlan& plan : plans_) {
            settings_.report(done);
            try {
                mesh_surface(plan);
            } catch (const detail::CoarseBoundary& e) {
                gather_coarse(static_cast<std::size_t>(plan.face - faces_.data()), e, e.edges());
            }
            done += step;
        }
        for (std::size_t i = 0; i < faces_.size(); ++i) {
            const Face& face = faces_[i];
            if (face.kind() == Face::Kind::surface) continue;
            settings_.report(done);
            try {
                if (face.kind() == Face::Kind::planar) mesh_planar(face);
                else mesh_trimmed(face);
            } catch (const TooFine&) {
                throw;
            } catch (const detail::CrossingLoops& e) {
                gather_coarse(i, e, edges_of(face));  // where they cross is a place in (u, v), not an edge
            } catch (const detail::CoarseBoundary& e) {
                gather_coarse(i, e, e.edges());
            } catch (const Error& e) {
                throw Error("solid", "face " + std::to_string(i) + ": " + e.what());
            }
            done += step;
        }
        if (coarse_first) throw detail::CoarseBoundary("solid", *coarse_first, std::move(coarse_edges));
        // The plans were held against the count their mesh cannot fall below; the zippers, split cells and
        // trimmed faces may add more. The mesh's own count decides, so that max_triangles holds exactly.
        Mesh mesh = assembler_.take();
        if (mesh.triangles.size() > settings_.max_triangles)
            throw TooFine(static_cast<double>(mesh.triangles.size()), settings_.max_triangles);
        settings_.report(1.0);
        return mesh;
    }

private:
    // One use of an edge by a face: a side of a surface face (plan index), a loop of a planar face or a
    // coedge of a trimmed face.
    struct EdgeUse {
        const Face* face;
        std::size_t plan = 0;  // surface faces
        Side side = Side::v_min;
        const Coedge* coedge = nullptr;  // trimmed faces
    };
    // Where a B-rep vertex sits on a surface face: a corner (u, v), or a whole collapsed side (a pole).
    struct VertexUse {
        const Face* face;
        std::size_t plan = 0;
        double u = 0, v = 0;
        std::optional<Side> pole;  // the collapsed side, for a pole
    };

    // Who uses each edge and each vertex, from the plans (built once, the first time it is asked for).
    void index_uses() {
        if (!edge_uses_.empty()) return;
        for (std::size_t k = 0; k < plans_.size(); ++k) {
            const SurfacePlan& p = plans_[k];
            const NurbsSurface& s = p.face->surface();
            for (Side side : kSides) {
                const SideMap& m = p.sides[side_slot(side)];
                const Coedge& coedge = p.face->sides()[side_slot(side)];
                edge_uses_[m.edge].push_back({p.face, k, side});
                const double fixed = detail::side_parameter(s, side);
                auto corner = [&](double q) { return runs_along_u(side) ? std::pair{q, fixed} : std::pair{fixed, q}; };
                if (m.degenerate) {
                    const auto [u, v] = corner(0.5 * (m.p0 + m.p1));
                    vertex_uses_[coedge.edge->start.get()].push_back({p.face, k, u, v, side});
                    continue;
                }
                const auto [u0, v0] = corner(m.p0);
                const auto [u1, v1] = corner(m.p1);
                vertex_uses_[(m.flipped ? coedge.edge->end : coedge.edge->start).get()].push_back({p.face, k, u0, v0, std::nullopt});
                vertex_uses_[(m.flipped ? coedge.edge->start : coedge.edge->end).get()].push_back({p.face, k, u1, v1, std::nullopt});
            }
        }
        for (const Face& face : faces_) {
            if (face.kind() == Face::Kind::surface) continue;
            for (const auto& loop : face.loops())
                for (const Coedge& coedge : loop) {
                    edge_uses_[coedge.edge.get()].push_back({&face, 0, Side::v_min, &coedge});
                    for (const Vertex* v : {coedge.edge->start.get(), coedge.edge->end.get()})
                        vertex_uses_[v].push_back({&face, 0, 0, 0, std::nullopt});
                }
        }
    }

    // True when a trimmed face uses the edge (vertex): its samples stay on the curve (the point).
    bool used_by_trimmed(const Edge* edge) {
        const auto& uses = edge_uses_[edge];
        return std::any_of(uses.begin(), uses.end(), [](const EdgeUse& use) { return use.face->kind() == Face::Kind::trimmed; });
    }
    bool used_by_trimmed(const Vertex* vertex) {
        const auto& uses = vertex_uses_[vertex];
        return std::any_of(uses.begin(), uses.end(), [](const VertexUse& use) { return use.face->kind() == Face::Kind::trimmed; });
    }

    // The (u, v) of a trimmed face's use of an edge at the edge's parameter t (its p-curve shares it).
    static std::pair<double, double> pcurve_point(const EdgeUse& use, double t) {
        const NurbsCurve& pcurve = *use.coedge->pcurve;
        const Vec3 p = pcurve.point(std::clamp(t, pcurve.domain().min, pcurve.domain().max));
        return {p.x, p.y};
    }

    // The face's unit normal at (u, v) (the surface's limit normal where its partials are parallel), or none
    // where it has no tangent plane at all (a profile that meets the axis in a cusp): no offset there. The
    // limit normals, costly and asked for at the same poles and corners at every refinement of a grid
    // (grid_points), are kept.
    std::optional<Vec3> face_normal(const SurfacePlan& p, double u, double v) {
        const detail::SurfaceFirstDerivatives d = p.evaluator->first_derivatives(u, v);
        const Vec3 n = cross(d.su, d.sv);
        const double length = norm(n);
        if (length > 1e-10 * (dot(d.su, d.su) + dot(d.sv, d.sv))) return n / length;
        const auto [it, inserted] = limit_normals_.try_emplace({p.face, u, v});
        if (!inserted) return it->second;
        try {
            return it->second = p.face->surface().normal(u, v);
        } catch (const Error&) {
            return std::nullopt;
        }
    }

    // The surface's unit normal at (u, v) (clamped into its domain), or none where it has no tangent plane.
    static std::optional<Vec3> surface_normal(const NurbsSurface& surface, double u, double v) {
        const Interval du = surface.domain_u(), dv = surface.domain_v();
        try {
            return surface.normal(std::clamp(u, du.min, du.max), std::clamp(v, dv.min, dv.max));
        } catch (const Error&) {
            return std::nullopt;
        }
    }

    static detail::OffsetWish planar_wish(const Face& face) {
        return {face.plane().normal, 0.0, 0.0, 0.0, true, 0.0, &face};
    }
    static detail::OffsetWish surface_wish(const SurfacePlan& p, const Vec3& normal, double u, double v) {
        if (!p.straddle) return {normal, 0.0, 0.0, 0.0, true, p.cells(), p.face};
        return {normal, p.offsets.at(u, v), p.offsets.lowest_at(u, v), p.offsets.highest_at(u, v), false, p.cells(),
                p.face};
    }

    // The (u, v) of the surface face of `use` at the edge's parameter t, on the side the edge is.
    std::pair<double, double> side_point(const EdgeUse& use, double t) const {
        const SurfacePlan& p = plans_[use.plan];
        const double q = p.sides[side_slot(use.side)].to_face(t), fixed = detail::side_parameter(p.face->surface(), use.side);
        return runs_along_u(use.side) ? std::pair{q, fixed} : std::pair{fixed, q};
    }

    // The move of the edge sample at parameter t, `gap` and `chord` away from its nearer and farther
    // neighbours on the edge (proposals_of): what its faces wish (a planar face: to stay in its plane), at
    // most the smallest max_offset of its surface faces, a quarter of the edge's radius of curvature there
    // (longer moves towards the centre of curvature would fold the edge's polygon, and a cap with it) and the
    // offset_room its neighbours leave; at a crease leaning towards centring the edge's polyline on its curve.
    Vec3 edge_offset(const Edge* edge, double t, double gap, double chord) {
        if (used_by_trimmed(edge) || settings_.finer_edges.contains(edge)) return {};
        wishes_.clear();
        double cap = std::numeric_limits<double>::infinity();
        for (const EdgeUse& use : edge_uses_[edge]) {
            if (use.face->kind() == Face::Kind::planar) {
                wishes_.push_back(planar_wish(*use.face));
                continue;
            }
            const SurfacePlan& p = plans_[use.plan];
            cap = std::min(cap, p.max_offset());
            const auto [u, v] = side_point(use, t);
            const std::optional<Vec3> n = face_normal(p, u, v);
            if (!n) return {};
            wishes_.push_back(surface_wish(p, *n, u, v));
        }
        if (!std::isfinite(cap)) return {};  // planar faces only: the edge stays put
        const std::vector<Vec3> d = edge->curve.derivatives(t, 2);
        const Vec3 &d1 = d[1], &d2 = d[2];
        const double speed = norm(d1);
        const double curvature = speed > 0 ? norm(cross(d1, d2)) / (speed * speed * speed) : 0.0;
        if (curvature > 0) cap = std::min(cap, 0.25 / curvature);
        cap = detail::offset_room(gap, cap);
        // The edge's own wish (used at a crease): its chords, `chord` long, sag by curvature chord^2 / 8.
        detail::EdgeBend bend{};
        if (curvature > 0 && std::isfinite(chord)) {
            const Vec3 tangent = d1 / speed, towards_centre = d2 - tangent * dot(d2, tangent);
            bend = {towards_centre / -norm(towards_centre), curvature * chord * chord / 16};
        }
        return detail::shared_offset(wishes_, cap, curvature > 0 && std::isfinite(chord) ? &bend : nullptr);
    }

    // True when the faces along the edge meet at an angle (their normals differ at its middle).
    bool is_crease(const Edge* edge) {
        const auto [it, inserted] = crease_.try_emplace(edge, false);
        if (!inserted) return it->second;
        const double t = 0.5 * (edge->curve.domain().min + edge->curve.domain().max);
        std::vector<Vec3> normals;
        for (const EdgeUse& use : edge_uses_[edge]) {
            if (use.face->kind() == Face::Kind::planar) {
                normals.push_back(use.face->plane().normal);
                continue;
            }
            if (use.face->kind() == Face::Kind::trimmed) {
                const auto [u, v] = pcurve_point(use, t);
                if (const std::optional<Vec3> n = surface_normal(use.face->surface(), u, v)) normals.push_back(*n);
                continue;
            }
            const auto [u, v] = side_point(use, t);
            if (const std::optional<Vec3> n = face_normal(plans_[use.plan], u, v)) normals.push_back(*n);
        }
        for (std::size_t a = 0; a < normals.size(); ++a)
            for (std::size_t b = a + 1; b < normals.size(); ++b)
                if (dot(normals[a], normals[b]) < std::cos(1e-3)) it->second = true;
        return it->second;
    }

    // The direction a pole of plan p's surface moves along (its degenerate side `pole`), or none. A pole
    // has one limit normal all around it; an apex (a profile meeting the axis at other than a right angle)
    // has a cone of them, and moves along the cone's axis when they all lie within kApexSpread of it. The
    // plan gives the pole the offsets of the row next to it (offset_field): an apex left on the surface
    // made its fan inscribed where the plan straddled (the revolved cubic of the bench failed its first
    // check at 1.19 and 1.34 times the target, a grid and a half of checks for it), while moved along the
    // axis by d it lies at least kApexSpread d from each tangent plane around it. Wider cones (a sharp tip)
    // stay put. The axis is the normal of the plane through three of the normals: exact where they lie on
    // a circle (a surface of revolution, whatever its parameterisation around the axis), so the tip of a
    // revolved profile stays on its axis.
    std::optional<Vec3> pole_normal(const SurfacePlan& p, Side pole) {
        static constexpr double kApexSpread = 0.9;  // cosine: 26 degrees
        const SideMap& m = p.sides[side_slot(pole)];
        const double fixed = detail::side_parameter(p.face->surface(), pole);
        auto normal_at = [&](double q) { return runs_along_u(pole) ? face_normal(p, q, fixed) : face_normal(p, fixed, q); };
        std::array<Vec3, 7> normals;  // at sixths of the side
        bool one = true;
        for (std::size_t k = 0; k < normals.size(); ++k) {
            const std::optional<Vec3> n = normal_at(m.p0 + static_cast<double>(k) / 6.0 * (m.p1 - m.p0));
            if (!n) return std::nullopt;
            normals[k] = *n;
            one = one && distance(normals[k], normals[0]) <= 1e-6;
        }
        if (one) return normals[0];
        Vec3 axis = cross(normals[2] - normals[0], normals[4] - normals[0]);
        if (norm(axis) < 1e-12) return std::nullopt;
        axis = axis / norm(axis);
        if (dot(axis, normals[0]) < 0) axis = -axis;
        for (const Vec3& n : normals)
            if (dot(n, axis) < kApexSpread) return std::nullopt;
        return axis;
    }

    // The move of a B-rep vertex: as its faces wish (a planar face, an inscribed one: none), nothing at a
    // corner of three or more faces or where a face has no normal, and at a pole along pole_normal (not at a
    // sharp apex).
    Vec3 vertex_offset(const Vertex* vertex) {
        const auto [known, inserted] = vertex_offsets_.try_emplace(vertex);
        if (inserted) known->second = wished_vertex_offset(vertex);
        return known->second;
    }
    Vec3 wished_vertex_offset(const Vertex* vertex) {
        if (used_by_trimmed(vertex) || finer_vertices_.contains(vertex)) return {};
        wishes_.clear();
        double cap = std::numeric_limits<double>::infinity();
        const auto& uses = vertex_uses_[vertex];
        for (const VertexUse& use : uses) {
            if (use.face->kind() == Face::Kind::planar) {
                wishes_.push_back(planar_wish(*use.face));
                continue;
            }
            // A face's corners at its own pole are the pole (whose direction pole_normal gives): at an apex
            // the limit normal at a corner is one generator's, which would tilt the tip off the axis.
            const auto is_pole_of_plan = [&](const VertexUse& other) { return other.pole && other.plan == use.plan; };
            if (!use.pole && std::any_of(uses.begin(), uses.end(), is_pole_of_plan)) continue;
            const SurfacePlan& p = plans_[use.plan];
            cap = std::min(cap, p.max_offset());
            if (use.pole) {
                const std::optional<Vec3> n = pole_normal(p, *use.pole);
                if (!n) return {};
                wishes_.push_back(surface_wish(p, *n, use.u, use.v));
                continue;
            }
            const std::optional<Vec3> n = face_normal(p, use.u, use.v);
            if (!n) return {};
            wishes_.push_back(surface_wish(p, *n, use.u, use.v));
        }
        if (!std::isfinite(cap)) return {};
        return detail::shared_offset(wishes_, cap);
    }

    Id vertex_id(const VertexPtr& vertex) {
        return assembler_.vertex_id(vertex.get(), [&] { return vertex->point + vertex_offset(vertex.get()); });
    }

    // Where the mesh puts the vertices of plan p's grid or rows (detail::GridPoints): inside, the plan's own
    // offsets; on its sides what the shared edge samples, poles and corners get.
    void grid_points(const SurfacePlan& p, std::vector<Vec3>& out) {
        index_uses();
        vertex_offsets_.clear();  // a plan may have changed since the last call
        if (!p.rows.empty()) {
            row_points(p, out);
            return;
        }
        detail::interior_grid_points(p, p.grid, out);
        const std::size_t nu = p.grid.u.size(), nv = p.grid.v.size();
        for (Side side : kSides) {
            const bool along_u = runs_along_u(side);
            const std::size_t fixed = side == Side::v_min || side == Side::u_min ? 0 : (along_u ? nv : nu) - 1;
            side_points(p, side, along_u ? p.grid.u : p.grid.v,
                        [&](std::size_t k) -> Vec3& { return along_u ? out[k * nv + fixed] : out[fixed * nv + k]; });
        }
        // A corner between a degenerate side and another: the pole wins (it is the same vertex).
        for (Side side : kSides) {
            if (!p.sides[side_slot(side)].degenerate) continue;
            const Vec3 pole = pole_point(p, side);
            const bool along_u = runs_along_u(side);
            const std::size_t fixed = side == Side::v_min || side == Side::u_min ? 0 : (along_u ? nv : nu) - 1;
            for (std::size_t k = 0; k < (along_u ? nu : nv); ++k) (along_u ? out[k * nv + fixed] : out[fixed * nv + k]) = pole;
        }
    }

    // grid_points for a plan in rows (tessellate_rows.hpp), row after row: the seam's points at the ends of
    // every row, the first and last rows from their sides (a pole's whole row last: it wins at the corners).
    void row_points(const SurfacePlan& p, std::vector<Vec3>& out) {
        const detail::RowGrid& rows = p.rows;
        const std::vector<std::size_t> starts = detail::row_starts(rows);
        detail::interior_row_points(p, out);
        std::vector<std::size_t> seam_rows;  // the rows with the seam's vertex at their ends (rows.seam_v)
        for (std::size_t j = 0; j < rows.v.size(); ++j)
            if (rows.on_seam[j]) seam_rows.push_back(j);
        side_points(p, Side::u_min, rows.seam_v, [&](std::size_t k) -> Vec3& { return out[starts[seam_rows[k]]]; });
        side_points(p, Side::u_max, rows.seam_v, [&](std::size_t k) -> Vec3& { return out[starts[seam_rows[k] + 1] - 1]; });
        side_points(p, Side::v_min, rows.u.front(), [&](std::size_t k) -> Vec3& { return out[k]; });
        side_points(p, Side::v_max, rows.u.back(), [&](std::size_t k) -> Vec3& { return out[starts[rows.v.size() - 1] + k]; });
    }

    Vec3 pole_point(const SurfacePlan& p, Side side) {
        const Vertex* pole = p.face->sides()[side_slot(side)].edge->start.get();
        return pole->point + vertex_offset(pole);
    }

    // The points of a side of plan p at its `lines` (face parameters; the ends are the side's corners) into
    // at(k): the shared edge samples as they will be placed, or the pole.
    template <class At>
    void side_points(const SurfacePlan& p, Side side, const std::vector<double>& lines, At&& at) {
        const SideMap& m = p.sides[side_slot(side)];
        const Coedge& coedge = p.face->sides()[side_slot(side)];
        if (m.degenerate) {
            const Vec3 pole = pole_point(p, side);
            for (std::size_t k = 0; k < lines.size(); ++k) at(k) = pole;
            return;
        }
        const std::vector<Proposal> proposals = proposals_of(m.edge);
        const Interval d = m.edge->curve.domain();
        for (std::size_t k = 0; k < lines.size(); ++k) {
            if (k == 0 || k + 1 == lines.size()) {
                const Vertex* v = (k == 0) != m.flipped ? coedge.edge->start.get() : coedge.edge->end.get();
                at(k) = v->point + vertex_offset(v);
            } else {
                const double t = m.to_edge(lines[k]);
                const auto [gap, chord] = proposed_at(proposals, t, 1e-12 * (d.max - d.min));
                at(k) = m.edge->curve.point(t) + edge_offset(m.edge, t, gap, chord);
            }
        }
    }

    // Every edge's samples: the union of the lines of the surface faces along it (or its own chordal
    // sampling for an edge of planar faces only), each moved by edge_offset as its proposals say: the very
    // point the faces' checks saw. A face that did not propose it sees it as an extra sample of a boundary
    // cell, as before the offsets.
    void sample_edges() {
        index_uses();  // a solid of trimmed and planar faces only has no plan that asked for it yet
        vertex_offsets_.clear();  // the plans are final from here on
        for (const EdgePtr& edge : distinct_edges(faces_)) {
            EdgeSamples samples;
            if (edge->degenerate) {
                samples.ids = {vertex_id(edge->start)};
                samples.params = {edge->curve.domain().min};
                edge_samples_.emplace(edge.get(), std::move(samples));
                continue;
            }
            const Interval d = edge->curve.domain();
            const std::vector<Proposal> proposals = proposals_of(edge.get());
            if (!proposals.empty()) {
                std::vector<double> ts;
                for (const Proposal& q : proposals) ts.push_back(q.t);
                samples.params = detail::merge_params(std::move(ts), d.min, d.max);
            } else {
                samples.params = detail::merge_params(sample_curve(edge->curve, settings_.tolerance), d.min, d.max);
            }
            const double eps = 1e-12 * (d.max - d.min);  // merge_params' rounding
            std::vector<Vec3> points;
            auto place = [&] {
                const std::size_t n = samples.params.size();
                side_points_.resize(n);
                for (std::size_t k = 0; k < n; ++k) side_points_[k] = edge->curve.point(samples.params[k]);
                points.resize(n);
                for (std::size_t k = 0; k < n; ++k) {
                    if (k == 0 || k + 1 == n) {
                        const Vertex* v = k == 0 ? edge->start.get() : edge->end.get();
                        points[k] = v->point + vertex_offset(v);
                        continue;
                    }
                    // As the faces' checks placed it (grid_points); a sample added below: from its neighbours.
                    const double t = samples.params[k];
                    auto [gap, chord] = proposed_at(proposals, t, eps);
                    if (!std::isfinite(gap)) gap = neighbour_gap(side_points_, k), chord = neighbour_chord(side_points_, k);
                    points[k] = side_points_[k] + edge_offset(edge.get(), t, gap, chord);
                }
            };
            place();
            // Along a crease the edge is the faces' boundary: the polyline must keep within the tolerance of
            // the curve itself, which neither face's check sees. A chord that strays further is split (the
            // faces close the cells along it with a zipper strip, as for another face's extra samples).
            // The bound: the loosest target of the faces along the edge. Between faces inscribed in their
            // surfaces the chords still owe the curve the tolerance: a face's check measures its triangles'
            // distance to its surface, and a chord close to the surface can be farther than that from the curve
            // bulging past it at a crease (the corner runs of a loft through a square).
            double bound = 0;
            bool straddled = false, surface_use = false;
            for (const EdgeUse& use : edge_uses_[edge.get()])
                if (use.face->kind() == Face::Kind::surface) {
                    bound = std::max(bound, plans_[use.plan].target);
                    straddled = straddled || plans_[use.plan].straddle;
                    surface_use = true;
                }
            if (!straddled) bound = settings_.check_tolerance();
            // Chords that stray from the curve by more than `limit` split at their middle, in rounds.
            const auto split_chords_beyond = [&](double limit) {
                for (int round = 0; round < 8; ++round) {
                    std::vector<double> added;
                    for (std::size_t k = 0; k + 1 < samples.params.size(); ++k) {
                        const double a = samples.params[k], b = samples.params[k + 1];
                        double error = 0;
                        for (double f : {0.25, 0.5, 0.75})
                            error = std::max(error, detail::point_segment_distance(edge->curve.point(a + f * (b - a)), points[k],
                                                                           points[k + 1]));
                        if (error > limit) added.push_back(0.5 * (a + b));
                    }
                    if (added.empty()) break;
                    added.insert(added.end(), samples.params.begin(), samples.params.end());
                    samples.params = detail::merge_params(std::move(added), d.min, d.max);
                    place();
                }
            };
            if (surface_use && is_crease(edge.get())) split_chords_beyond(bound);
            // An edge of a loop that came out too coarse on an earlier attempt (CoarseBoundary).
            if (const auto finer = settings_.finer_edges.find(edge.get()); finer != settings_.finer_edges.end())
                split_chords_beyond(std::ldexp(settings_.check_tolerance(), -finer->second));
            const double crease_bound = surface_use && is_crease(edge.get()) ? bound : 0;
            if (used_by_trimmed(edge.get()) && refine_for_trimmed(edge.get(), samples.params, crease_bound, !surface_use)) place();
            const std::size_t n = samples.params.size();
            samples.ids.reserve(n);
            for (std::size_t k = 0; k < n; ++k) {
                if (k == 0) samples.ids.push_back(vertex_id(edge->start));
                else if (k + 1 == n) samples.ids.push_back(vertex_id(edge->end));
                else samples.ids.push_back(assembler_.add_point(points[k]));
            }
            edge_samples_.emplace(edge.get(), std::move(samples));
        }
    }

    // A trimmed face triangulates its (u, v) region on the edge's samples, whose segments in (u, v) then map
    // onto the surface along curves the mesh does not follow: the chord between two samples. An interval
    // [a, b] of the edge is fine when that curve strays from the chord by at most 0.9 of the tolerance
    // (domain_triangulation.cpp's lattice check, at 0.95, then still converges along the boundary: a lattice
    // point sees at most 0.69 of a boundary segment's error), the edge itself by at most the tolerance (and
    // `crease_bound`, the crease refinement's bound, where it is positive), and, with an angle limit, the
    // face's normals turn by at most the limit. Returns by how much the interval must shrink to be fine
    // (<= 1: it is): the square root of an error's ratio to its bound (a chord's error is quadratic in its
    // length), the angle's ratio itself.
    double shrink_needed(const Edge* edge, double a, double b, double crease_bound) {
        const Interval d = edge->curve.domain();
        const double tolerance = settings_.check_tolerance(), inner = 0.9 * tolerance;
        const auto point_at = [&](double t) {
            if (t <= d.min) return edge->start->point;
            if (t >= d.max) return edge->end->point;
            return edge->curve.point(t);
        };
        const Vec3 pa = point_at(a), pb = point_at(b);
        double need = 0;
        const auto error_ratio = [&](double error, double bound) { need = std::max(need, std::sqrt(error / bound)); };
        for (double f : {0.25, 0.5, 0.75}) {
            const Vec3 chord = pa + (pb - pa) * f;
            const double off_curve = distance(edge->curve.point(a + f * (b - a)), chord);
            error_ratio(off_curve, tolerance);
            if (crease_bound > 0) error_ratio(off_curve, crease_bound);
            for (const EdgeUse& use : edge_uses_[edge]) {
                if (use.face->kind() != Face::Kind::trimmed) continue;
                const auto [ua, va] = pcurve_point(use, a);
                const auto [ub, vb] = pcurve_point(use, b);
                const NurbsSurface& s = use.face->surface();
                const Interval su = s.domain_u(), sv = s.domain_v();
                error_ratio(distance(s.point(std::clamp(ua + f * (ub - ua), su.min, su.max),
                                             std::clamp(va + f * (vb - va), sv.min, sv.max)), chord), inner);
                // With an angle limit the face's normals at the two ends may turn by at most the limit
                // (its inner edges are the triangulation's business).
                if (settings_.angle_rad > 0 && f == 0.5) {
                    const std::optional<Vec3> na = surface_normal(s, ua, va), nb = surface_normal(s, ub, vb);
                    if (na && nb) need = std::max(need, std::acos(std::clamp(dot(*na, *nb), -1.0, 1.0)) / settings_.angle_rad);
                }
            }
        }
        return std::isfinite(need) ? need : std::numeric_limits<double>::infinity();
    }

    // Samples an edge of a trimmed face so that every interval is fine (shrink_needed). The faces' proposals
    // stay when they are fine (the surface faces' grids meet them without a zipper); else the fewest equal
    // parameter steps that are (an arc needs one spacing everywhere: bisecting proposals that are 20% too far
    // apart would double them, and a fillet's corner then took 8 chords per quarter circle where 5 do), and
    // failing that, every interval that is not fine is halved until all are. Returns whether it changed any.
    bool refine_for_trimmed(const Edge* edge, std::vector<double>& params, double crease_bound, bool may_respace) {
        const Interval d = edge->curve.domain();
        const auto all_fine = [&](const std::vector<double>& ts) {
            for (std::size_t k = 0; k + 1 < ts.size(); ++k)
                if (shrink_needed(edge, ts[k], ts[k + 1], crease_bound) > 1) return false;
            return true;
        };
        // One pass over the proposals: whether all are fine, and the equal steps that would make every interval
        // fine, from each interval's own need.
        double worst_need = 0, uniform = 0;
        for (std::size_t k = 0; k + 1 < params.size(); ++k) {
            const double need = shrink_needed(edge, params[k], params[k + 1], crease_bound);
            worst_need = std::max(worst_need, need);
            uniform = std::max(uniform, need * (d.max - d.min) / (params[k + 1] - params[k]));
        }
        if (worst_need <= 1) return false;
        const double estimate = std::ceil(uniform);
        const double intervals = static_cast<double>(params.size() - 1);
        if (may_respace && estimate < 2 * intervals) {
            const auto first = static_cast<std::size_t>(std::max(1.0, estimate));
            for (std::size_t n = first; n < first + 3 && static_cast<double>(n) < 2 * intervals; ++n) {
                std::vector<double> uniform(n + 1);
                for (std::size_t k = 0; k <= n; ++k) uniform[k] = d.min + (d.max - d.min) * static_cast<double>(k) / static_cast<double>(n);
                uniform.back() = d.max;
                if (all_fine(uniform)) {
                    params = std::move(uniform);
                    return true;
                }
            }
        }
        for (int round = 0; round < 30; ++round) {
            std::vector<double> added;
            for (std::size_t k = 0; k + 1 < params.size(); ++k)
                if (shrink_needed(edge, params[k], params[k + 1], crease_bound) > 1) added.push_back(0.5 * (params[k] + params[k + 1]));
            if (added.empty()) break;
            // Each round may double the samples: a face whose curve in (u, v) does not follow its edge (a damaged
            // file, found by fuzz_read_step) never converges, and 30 doublings would take minutes and gigabytes.
            const std::size_t cap = std::min<std::size_t>(settings_.max_triangles, kMaxTrimmedEdgeSamples);
            require(params.size() + added.size() <= cap, "solid", [&] {
                std::vector<std::string> faces;  // the trimmed faces that use the edge, numbered as the solid's faces
                for (const EdgeUse& use : edge_uses_[edge])
                    if (use.coedge && (faces.empty() || faces.back() != std::to_string(use.face - faces_.data())))
                        faces.push_back(std::to_string(use.face - faces_.data()));  // a seam's two uses once
                const std::string which = faces.empty()      ? "face"
                                          : faces.size() == 1 ? "face " + faces[0]
                                                              : "faces " + faces[0] + " and " + faces.back();
                return "an edge of trimmed " + which + " needs more than " + std::to_string(cap) +
                       " samples to follow the face within the tolerance: its curve on the face strays from the edge";
            });
            settings_.poll();
            added.insert(added.end(), params.begin(), params.end());
            params = detail::merge_params(std::move(added), d.min, d.max);
        }
        return true;
    }

    // A sample a surface face proposes for an edge: one of its lines along it, with the distances to the
    // nearer (gap) and farther (chord) of its neighbouring lines there, measured on the edge's curve.
    struct Proposal {
        double t, gap, chord;
    };

    // The proposals of every surface face along `edge` from the plans as they are now, sorted by t: what
    // the checks and the mesh both place the edge's samples from (a function of the plans alone).
    std::vector<Proposal> proposals_of(const Edge* edge) {
        std::vector<Proposal> proposals;
        for (const EdgeUse& use : edge_uses_[edge]) {
            if (use.face->kind() != Face::Kind::surface) continue;
            const SurfacePlan& plan = plans_[use.plan];
            const SideMap& m = plan.sides[side_slot(use.side)];
            if (m.degenerate) continue;
            const std::vector<double>& lines = detail::side_lines(plan, use.side);
            side_points_.resize(lines.size());
            for (std::size_t k = 0; k < lines.size(); ++k) side_points_[k] = edge->curve.point(m.to_edge(lines[k]));
            for (std::size_t k = 0; k < lines.size(); ++k)
                proposals.push_back({m.to_edge(lines[k]), neighbour_gap(side_points_, k), neighbour_chord(side_points_, k)});
        }
        std::sort(proposals.begin(), proposals.end(), [](const Proposal& a, const Proposal& b) { return a.t < b.t; });
        return proposals;
    }

    // The smallest gap and chord the proposals at t hold (infinity for none).
    static std::pair<double, double> proposed_at(const std::vector<Proposal>& proposals, double t, double eps) {
        const auto lower = std::lower_bound(proposals.begin(), proposals.end(), t - eps,
                                            [](const Proposal& q, double x) { return q.t < x; });
        double gap = std::numeric_limits<double>::infinity(), chord = gap;
        for (auto q = lower; q != proposals.end() && q->t <= t + eps; ++q) gap = std::min(gap, q->gap), chord = std::min(chord, q->chord);
        return {gap, chord};
    }

    // The distance from points[k] to the farther of its neighbours in the list.
    static double neighbour_chord(const std::vector<Vec3>& points, std::size_t k) {
        double chord = 0;
        if (k > 0) chord = std::max(chord, distance(points[k], points[k - 1]));
        if (k + 1 < points.size()) chord = std::max(chord, distance(points[k], points[k + 1]));
        return chord;
    }

    // The distance from points[k] to the nearer of its neighbours in the list.
    static double neighbour_gap(const std::vector<Vec3>& points, std::size_t k) {
        double gap = std::numeric_limits<double>::infinity();
        if (k > 0) gap = std::min(gap, distance(points[k], points[k - 1]));
        if (k + 1 < points.size()) gap = std::min(gap, distance(points[k], points[k + 1]));
        return gap;
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

        if (!plan.rows.empty()) {
            mesh_rows(plan, side_samples, side_id);
            return;
        }

        // The interior grid points in one batch (surface_grid.hpp), moved by the plan's offsets; boundary
        // points are edge samples.
        detail::interior_grid_points(plan, g, grid_points_);
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
                ids[i * nv + j] = chosen ? chosen->second : assembler_.add_point(grid_points_[i * nv + j]);
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
                    const std::optional<Vec3> n = face_normal(plan, u, v);
                    const Vec3 p = s.point(u, v) + (n ? *n * plan.offsets.at(u, v) : Vec3{});
                    center = CellVertex{u, v, p, assembler_.add_point(p)};
                }
                if (nu == 2 || nv == 2) require_unfolded(plan, triangles, 0.5 * (g.u[i] + g.u[i + 1]), 0.5 * (g.v[j] + g.v[j + 1]));
                for (const auto& t : triangles) assembler_.add_triangle(t[0]->id, t[1]->id, t[2]->id);
            }
        }
    }

    // A face one cell across (a flat ring 0.004 wide at the foot of a wall) has the samples of two edges as the
    // corners of every triangle: where one edge's samples are moved across the face by a neighbour's straddling
    // offsets, or the other's chords dip past them, its triangles fold back over its neighbours' (the mesh
    // intersected itself, and was handed out). Each triangle must face as the surface does at (u, v), within 120
    // degrees (a sliver's normal is rounding); else the face's edges are sampled finer, on their curves.
    void require_unfolded(const SurfacePlan& plan, std::span<const CellTriangle> triangles, double u, double v) {
        const std::optional<Vec3> n = face_normal(plan, u, v);
        if (!n) return;
        for (const CellTriangle& t : triangles) {
            const Vec3 normal = cross(t[1]->point - t[0]->point, t[2]->point - t[0]->point);
            if (dot(normal, *n) < -0.5 * norm(normal))
                throw detail::CoarseBoundary("boundary", "the triangles across it fold back (the face is narrower than its edges' samples are apart)",
                                             edges_of(*plan.face));
        }
    }

    // The strips of a plan in rows (tessellate_rows.hpp), each zipped between its two rows: an inner row's
    // ends are the seam's samples, a first or last row all the samples of its side's edge (a pole's one).
    template <class SideId>
    void mesh_rows(const SurfacePlan& plan, const std::array<std::vector<std::pair<double, Id>>, 4>& side_samples,
                   SideId&& side_id) {
        const detail::RowGrid& rows = plan.rows;
        const std::vector<std::size_t> starts = detail::row_starts(rows);
        detail::interior_row_points(plan, grid_points_);
        const std::size_t count = rows.v.size();
        const Interval du = plan.face->surface().domain_u();
        const double period = du.max - du.min;
        std::vector<Id> ids(starts.back());
        std::vector<detail::RailPoint> rail_points;
        auto rail = [&](std::size_t j, std::vector<CellVertex>& out) {
            out.clear();
            const double v = rows.v[j];
            if (j == 0 || j + 1 == count) {
                const Side side = j == 0 ? Side::v_min : Side::v_max;
                if (plan.sides[side_slot(side)].degenerate) {
                    const Id pole = side_id(side, 0.0).second;
                    for (double u : {rows.u[j].front(), rows.u[j].back()}) out.push_back(CellVertex{u, v, assembler_.point(pole), pole});
                    return;
                }
                for (const auto& [u, id] : side_samples[side_slot(side)]) out.push_back(CellVertex{u, v, assembler_.point(id), id});
                return;
            }
            // The seam's samples at a row's ends, new vertices inside (row_rail: a row off the seam closes
            // across it, its last vertex first again).
            const std::size_t first = starts[j], last = starts[j + 1] - 1;
            for (std::size_t k = first; k <= last; ++k) {
                const bool end = rows.on_seam[j] && (k == first || k == last);
                ids[k] = end ? side_id(k == first ? Side::u_min : Side::u_max, v).second : assembler_.add_point(grid_points_[k]);
            }
            detail::row_rail(rows, starts, j, period, rail_points);
            for (const detail::RailPoint& x : rail_points) out.push_back(CellVertex{x.u, v, assembler_.point(ids[x.vertex]), ids[x.vertex]});
        };
        std::vector<CellVertex> bottom, top, lower, upper;
        std::vector<CellTriangle> triangles;
        rail(0, bottom);
        for (std::size_t j = 0; j + 1 < count; ++j) {
            if (j % 64 == 63) settings_.poll();
            rail(j + 1, top);
            triangles.clear();
            detail::triangulate_strip(bottom, top, lower, upper, triangles);
            if (count == 2)
                for (const CellTriangle& t : triangles) {
                    // At the triangle's middle, its u taken across the seam as its row closes (row_rail).
                    double u = t[0]->u;
                    for (int k : {1, 2}) u += std::remainder(t[k]->u - t[0]->u, period) / 3;
                    if (u > du.max) u -= period;
                    if (u < du.min) u += period;
                    require_unfolded(plan, std::span<const CellTriangle>(&t, 1), u, (t[0]->v + t[1]->v + t[2]->v) / 3);
                }
            for (const auto& t : triangles) assembler_.add_triangle(t[0]->id, t[1]->id, t[2]->id);
            std::swap(bottom, top);
        }
    }

    void mesh_planar(const Face& face) {
        const Plane& plane = face.plane();
        // Counterclockwise in the (x, y) frame is along x × y; flip if the frame is left-handed to the normal.
        const bool flip = dot(cross(plane.x_axis, plane.y_axis), plane.normal) < 0;
        std::vector<std::vector<detail::Point2>> loops;
        std::vector<std::vector<Id>> loop_ids;
        std::size_t outer = 0, outers = 0;  // the counterclockwise loops
        const std::vector<std::vector<Coedge>> face_loops = without_bridges(face.loops());
        const bool bridged = face_loops.size() != face.loops().size();
        for (const auto& loop : face_loops) {
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
            // A loop of two edges (an arc closed by a line, a Fusion 360 servo's flat) whose arc the tolerance lets
            // its chord stand for: two points, no area. Its edges are sampled finer.
            if (cleaned.size() < 3) throw too_coarse(loop, kNoArea);
            std::vector<detail::Point2> points;
            for (Id id : cleaned) {
                const Vec3 d = assembler_.point(id) - plane.origin;
                points.push_back({dot(d, plane.x_axis), dot(d, plane.y_axis)});
            }
            // The outer loop runs counterclockwise seen from the normal, holes clockwise (brep.hpp); samples that
            // run the other way would mesh the outside of the loop.
            if (!encloses_area(points)) throw too_coarse(loop, kNoArea);
            const bool counterclockwise = (detail::twice_signed_area(points) > 0) != flip;
            if (counterclockwise != loops.empty() && !bridged) throw too_coarse(loop, kWrongWayRound);
            if (counterclockwise) outer = loops.size();
            outers += counterclockwise;
            loops.push_back(std::move(points));
            loop_ids.push_back(std::move(cleaned));
        }
        // A bridged loop's parts come in any order: its one outer part goes first.
        if (bridged) {
            if (outers != 1) throw too_coarse(face_loops.front(), kWrongWayRound);
            std::swap(loops.front(), loops[outer]);  // the holes' order does not matter
            std::swap(loop_ids.front(), loop_ids[outer]);
        }
        std::vector<Id> flat_ids;
        for (const std::vector<Id>& ids : loop_ids) flat_ids.insert(flat_ids.end(), ids.begin(), ids.end());
        // Numbered by mesh vertex: loops that share a vertex (a hole meeting the outer boundary at a corner of
        // both, as in Voron's blower duct) touch there.
        for (const auto& t : detail::triangulate_polygon(loops, flat_ids)) {
            if (flip) assembler_.add_triangle(t[0], t[2], t[1]);
            else assembler_.add_triangle(t[0], t[1], t[2]);
        }
    }

    // A loop that runs along an edge and later back along it (a bridge: a Fusion 360 plate's outline joined to
    // the circle inside it by a line the face lies on both sides of) bounds the same region as its two parts
    // without the bridge, an outer loop and a hole; as it is, its polygon overlaps itself along the bridge and
    // was refused. Each such loop is split there, repeatedly; the bridge's edge is then inside the face, like
    // any of its triangles' edges.
    static std::vector<std::vector<Coedge>> without_bridges(const std::vector<std::vector<Coedge>>& loops) {
        std::vector<std::vector<Coedge>> result;
        std::vector<std::vector<Coedge>> pending(loops.rbegin(), loops.rend());
        while (!pending.empty()) {
            std::vector<Coedge> loop = std::move(pending.back());
            pending.pop_back();
            std::optional<std::pair<std::size_t, std::size_t>> bridge;
            for (std::size_t i = 0; i < loop.size() && !bridge; ++i)
                for (std::size_t j = i + 1; j < loop.size() && !bridge; ++j)
                    if (loop[i].edge == loop[j].edge && loop[i].reversed != loop[j].reversed && !loop[i].edge->degenerate)
                        bridge = std::pair{i, j};
            if (!bridge) {
                result.push_back(std::move(loop));
                continue;
            }
            const auto [i, j] = *bridge;
            std::vector<Coedge> inner(loop.begin() + static_cast<std::ptrdiff_t>(i + 1), loop.begin() + static_cast<std::ptrdiff_t>(j));
            std::vector<Coedge> outer(loop.begin() + static_cast<std::ptrdiff_t>(j + 1), loop.end());
            outer.insert(outer.end(), loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(i));
            for (auto* part : {&inner, &outer})
                if (!part->empty()) pending.push_back(std::move(*part));
        }
        return result;
    }

    // The refusal of a loop sampled too coarsely to mesh (its samples enclose no area or run round it the other way),
    // naming its edges to be sampled finer.
    static detail::CoarseBoundary too_coarse(const std::vector<Coedge>& loop, std::string_view reason) {
        std::vector<const Edge*> edges;
        append_edges(loop, edges);
        return detail::CoarseBoundary("loops", reason, std::move(edges));
    }
    static void append_edges(std::span<const Coedge> loop, std::vector<const Edge*>& edges) {
        for (const Coedge& coedge : loop)
            if (!coedge.edge->degenerate) edges.push_back(coedge.edge.get());
    }
    static std::vector<const Edge*> edges_of(const Face& face) {
        std::vector<const Edge*> edges;
        if (face.kind() == Face::Kind::surface) append_edges(face.sides(), edges);
        for (const auto& loop : face.loops()) append_edges(loop, edges);
        return edges;
    }
    static constexpr std::string_view kWrongWayRound = "a loop's samples run round it the wrong way (a sliver beside an arc's chord)";
    static constexpr std::string_view kNoArea = "a loop's samples enclose no area (an arc its chord stands for)";

    // Whether a loop's samples enclose more than 1e-9 of the square of their perimeter. An arc its chord stands
    // for, closed by two line edges that meet on that chord (a Voron idler's segment faces), encloses 1e-14: its
    // one triangle had no shape, which OpenSCAD's CGAL_Nef_polyhedron3() fails on. Its edges are sampled finer.
    static bool encloses_area(const std::vector<detail::Point2>& points) {
        double perimeter = 0;
        for (std::size_t k = 0; k < points.size(); ++k) {
            const detail::Point2 &a = points[k], &b = points[(k + 1) % points.size()];
            perimeter += std::hypot(b.x - a.x, b.y - a.y);
        }
        return std::abs(detail::twice_signed_area(points)) > 2e-9 * perimeter * perimeter;
    }

    // A trimmed face: its loops as boundary samples in (u, v) (each coedge's samples in the direction the face
    // runs it, its last one left to the next coedge; a degenerate coedge contributes the start of its pole
    // segment), then the refined triangulation of the region they bound.
    void mesh_trimmed(const Face& face) {
        index_uses();
        std::vector<std::vector<detail::BoundarySample>> loops;
        for (const auto& loop : face.loops()) {
            auto& samples = loops.emplace_back();
            std::vector<std::size_t> corners;  // where each coedge's samples start: at its first vertex
            for (const Coedge& coedge : loop) {
                corners.push_back(samples.size());
                const EdgeSamples& e = samples_of(coedge.edge.get());
                const NurbsCurve& pcurve = *coedge.pcurve;
                const Interval d = pcurve.domain();
                if (coedge.edge->degenerate) {
                    const Vec3 uv = coedge.reversed ? pcurve.end_point() : pcurve.start_point();
                    samples.push_back({uv.x, uv.y, e.ids[0], assembler_.point(e.ids[0])});
                    continue;
                }
                const std::size_t n = e.params.size();
                for (std::size_t k = 0; k + 1 < n; ++k) {
                    const std::size_t at = coedge.reversed ? n - 1 - k : k;
                    const Vec3 uv = pcurve.point(std::clamp(e.params[at], d.min, d.max));
                    samples.push_back({uv.x, uv.y, e.ids[at], assembler_.point(e.ids[at])});
                }
            }
            detail::unhook_corners(samples, corners);
            // The outer loop counterclockwise in (u, v), holes clockwise (brep.hpp), as in mesh_planar.
            std::vector<detail::Point2> uv;
            for (const detail::BoundarySample& sample : samples) uv.push_back({sample.u, sample.v});
            if (!encloses_area(uv)) throw too_coarse(loop, kNoArea);
            if ((detail::twice_signed_area(uv) > 0) != (loops.size() == 1)) throw too_coarse(loop, kWrongWayRound);
        }
        const detail::SurfaceEvaluator evaluator(face.surface());
        const std::function<Id(const Vec3&)> add = [this](const Vec3& p) { return assembler_.add_point(p); };
        for (const auto& t : detail::triangulate_trimmed_domain(evaluator, loops, settings_, add))
            assembler_.add_triangle(t[0], t[1], t[2]);
    }

    std::span<const Face> faces_;
    detail::TessellationSettings settings_;
    std::vector<SurfacePlan> plans_;
    std::map<const Edge*, EdgeSamples> edge_samples_;
    MeshAssembler assembler_;
    std::vector<Vec3> grid_points_;  // mesh_surface's batch, kept to reuse its storage from face to face
    std::map<const Edge*, std::vector<EdgeUse>> edge_uses_;
    std::map<const Vertex*, std::vector<VertexUse>> vertex_uses_;
    std::vector<detail::OffsetWish> wishes_;
    std::map<const Edge*, bool> crease_;
    std::map<std::tuple<const Face*, double, double>, std::optional<Vec3>> limit_normals_;  // face_normal's
    // vertex_offset's answers while the plans stay as they are (a vertex is asked for at every corner and
    // edge end that meets it): cleared by grid_points and once more by sample_edges.
    std::map<const Vertex*, Vec3> vertex_offsets_;
    std::set<const Vertex*> finer_vertices_;  // the ends of settings_.finer_edges: on their edges' curves, as those
    std::vector<Vec3> side_points_;
};

}  // namespace

namespace {

// The planner's count covers the faces it planned before it stopped, so it is a lower bound for the whole.
// A coarser tessellation of all faces that fits (tolerance x4 each step, at most 20,000 triangles: about a
// second) scaled by the tolerance ratio gives the estimate: a curved face's triangles grow as 1 / tolerance,
// flat ones not at all (so it errs high). The same scaling gives a tolerance that fits the budget (10%
// coarser than the scaling says, and never finer than a coarse tolerance that was seen to fit).
struct Estimate {
    double triangles = 0;
    double fitting_tolerance = 0;  // 0: no coarser tessellation fitted
};

// Tessellates the faces. Where faces' boundaries come out too coarse to mesh (detail::CoarseBoundary: samples
// running round a loop the wrong way, loops crossing or passing each other, triangles folded beside a narrow
// face), only their edges are sampled finer, their chords' bound halved per attempt. Crossing loops took the whole
// solid to half the tolerance per attempt: a band 0.0044 wide between two arcs of a Prusa extruder body to 1/32,
// 20,000 triangles where 5,000 do, and below the file's own edge tolerance, which no mesh follows (refused).
Mesh run_retrying(std::span<const Face> faces, detail::TessellationSettings attempt) {
    constexpr int kMaxHalvings = 12;
    for (;;) {
        try {
            return Tessellator(faces, attempt).run();
        } catch (const detail::CoarseBoundary& e) {
            require(!e.edges().empty(), "solid", e.reason());
            for (const Edge* edge : std::set<const Edge*>(e.edges().begin(), e.edges().end()))
                if (++attempt.finer_edges[edge] > kMaxHalvings)
                    throw Error("solid", std::string(e.reason()) + " (also with its edges at 1/" +
                                             std::to_string(1 << kMaxHalvings) + " of the tolerance)");
        }
    }
}

Estimate estimate_triangles(std::span<const Face> faces, detail::TessellationSettings settings, double lower_bound) {
    const double requested = settings.tolerance;
    const double budget = static_cast<double>(settings.max_triangles);
    settings.max_triangles = std::min<std::size_t>(settings.max_triangles, 20'000);
    // The coarse runs are part of the refusal, not progress of the tessellation asked for: they poll the
    // caller's callback (Ctrl-C) with the fraction reached so far instead of reporting their own.
    const Progress* caller = settings.progress;
    const double reached = settings.reported;
    const Progress poll_only = [caller, reached](double) {
        if (caller != nullptr && *caller) (*caller)(reached);
    };
    settings.progress = &poll_only;
    // Up to 4^64 coarser: a tolerance of 1e-30 still gets the one that fits (24 steps stopped at 3e-16 and named
    // none). A step that does not fit stops at the coarse budget, so the finest ones cost little.
    for (int step = 0; step < 64; ++step) {
        settings.tolerance *= 4;
        try {
            const double count = static_cast<double>(run_retrying(faces, settings).triangles.size());
            const double estimate = std::max(lower_bound, count * settings.tolerance / requested);
            // Scaled from the coarse mesh, and from the estimate at the requested tolerance (which does not fit,
            // so the answer must be coarser than it).
            const double scaled = TooFine::two_digits_up(1.1 * std::max(settings.tolerance * count, requested * estimate) / budget);
            if (count > budget || scaled >= settings.tolerance) return {estimate, scaled};
            // A small budget is near the coarsest meshes, where the count no longer scales with 1 / tolerance
            // (every face keeps its fewest cells): the scaled tolerance is tried (a mesh of at most 20,000
            // triangles), and the coarse one, seen to fit, named instead when it does not.
            if (budget > static_cast<double>(settings.max_triangles)) return {estimate, scaled};
            detail::TessellationSettings check = settings;
            check.tolerance = scaled;
            try {
                (void)run_retrying(faces, check);
                return {estimate, scaled};
            } catch (const TooFine&) {
                return {estimate, settings.tolerance};
            }
        } catch (const TooFine&) {
        }
    }
    return {lower_bound, 0};
}

}  // namespace

namespace {

// The face of `solid` read with the largest tolerance (Face::tolerance: how far the file's edges lie from the
// face's surface, 0 for faces the kernel made), and that tolerance. No mesh follows such a face's boundary
// closer than its edges lie to its surface.
std::pair<std::size_t, double> loosest_face(const Solid& solid) {
    std::pair<std::size_t, double> loosest{0, 0.0};
    for (std::size_t i = 0; i < solid.faces().size(); ++i)
        if (solid.faces()[i].tolerance() > loosest.second) loosest = {i, solid.faces()[i].tolerance()};
    return loosest;
}

// The largest share of the mesh tolerance a face's own tolerance may take for the mesh of a convex solid to be
// hulled: gaps between faces up to twice that can add to the hull's deviation, a fraction of a percent.
constexpr double kHullGap = 1e-3;

}  // namespace

double default_tolerance(const Solid& solid) {
    return std::max(1e-3 * solid.bounding_box().diagonal(), loosest_face(solid).second);
}

namespace {

detail::TessellationSettings settings_of(const TessellationOptions& options) {
    require(std::isfinite(options.tolerance) && options.tolerance > 0, "tolerance",
            "must be a finite number > 0 (got " + detail::number(options.tolerance) + ")");
    detail::TessellationSettings settings;
    settings.tolerance = options.tolerance;
    if (options.angle_deg) {
        require(std::isfinite(*options.angle_deg) && *options.angle_deg > 0 && *options.angle_deg < 180, "angle_deg",
                "must be in (0, 180) degrees (got " + detail::number(*options.angle_deg) + ")");
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
        return run_retrying(faces, settings);
    } catch (const TooFine& e) {
        const Estimate estimate = estimate_triangles(faces, settings, e.estimated_triangles());
        throw TooFine(estimate.triangles, settings.max_triangles, estimate.fitting_tolerance);
    }
}

}  // namespace

namespace {

// Far from unit size the planner's curvature products (E G - F^2 grows as size^4) leave the double range:
// below about 1e-75 and above 1e75 a sphere still meshed within its tolerance, with up to seven times the
// triangles (radius 1e-99: 3000 for the 432 of radius 1). Such a solid is meshed at a power-of-two scale
// near size 1, which is exact (every control point, vertex and tolerance scaled, nothing rounded), and the
// mesh scaled back, exactly too. 0: the solid's own scale will do.
int unit_scale_exponent(const Box& box) {
    const double size = box.diagonal();
    if (!(size > 0) || !std::isfinite(size)) return 0;
    const int exponent = std::ilogb(size);
    return std::abs(exponent) > 64 ? exponent : 0;
}

Mesh scaled_back(Mesh mesh, int exponent) {
    for (Vec3& v : mesh.vertices) v = {std::ldexp(v.x, exponent), std::ldexp(v.y, exponent), std::ldexp(v.z, exponent)};
    return mesh;
}

// mesh_of(shape, options), at the power-of-two scale near size 1 when the shape's size calls for one
// (unit_scale_exponent); a refusal's tolerance that fits is scaled back too.
template <class Shape, class MeshOf>
Mesh at_unit_scale(const Shape& shape, const Box& box, const TessellationOptions& options, MeshOf mesh_of) {
    const int exponent = unit_scale_exponent(box);
    if (exponent == 0) return mesh_of(shape, options);
    (void)settings_of(options);  // the options are checked as given
    TessellationOptions unit = options;
    unit.tolerance = std::ldexp(options.tolerance, -exponent);
    const Shape scaled = transformed(shape, AffineMap::scaling(std::ldexp(1.0, -exponent), {}));
    try {
        return scaled_back(mesh_of(scaled, unit), exponent);
    } catch (const TooFine& e) {
        throw TooFine(e.estimated_triangles(), e.max_triangles(), std::ldexp(e.fitting_tolerance(), exponent));
    }
}

}  // namespace

Mesh tessellate(const Solid& solid, const TessellationOptions& options) {
    detail::require_tessellatable_weights(solid.faces(), "solid");
    const auto whole_mesh = [&](const TessellationOptions& asked) {
        return at_unit_scale(solid, solid.bounding_box(), asked, [&asked](const Solid& s, const TessellationOptions& o) {
            Mesh mesh = run_within_budget(s.faces(), settings_of(o));
            // Mesh::is_closed, from the topology taken once for it and the fans below.
            const auto closed = [](const Mesh& m, const MeshTopology& t) { return !m.triangles.empty() && t.watertight(); };
            MeshTopology topology = mesh_topology(mesh);
            // Two faces that meet where their edges run tangent may both take the same sliver along the edge they
            // share (a Voron LED mount's fillet ends in a cusp between a plane and a cylinder, its edges 2.6e-3
            // apart there, their tolerance): the plane and the fillet each fanned the edge's samples from the cusp,
            // the same triangles once each way round. Welding drops such pairs (mesh_welding.hpp); taken only when
            // it leaves a closed 2-manifold, else the faces' gap is reported below as it is.
            if (!closed(mesh, topology)) {
                Mesh joined = welded(mesh, OppositePairs::dropped);
                const MeshTopology joined_topology = mesh_topology(joined);
                if (closed(joined, joined_topology) && joined_topology.oriented_manifold())
                    mesh = std::move(joined), topology = joined_topology;
            }
            // Closed by construction for a valid solid; the check (O(triangles), a few % of the time) keeps a
            // solid whose faces fold onto each other — a profile that runs back over itself, found by
            // fuzz_geometry; parts of users' files that touch themselves (065_umbilical_mount) — from handing out
            // an open mesh.
            if (!closed(mesh, topology)) {
                // Where: a solid that touches itself (an audio jack's two pins meeting along an edge, a switch body whose
                // two walls share a face) can only be mended by the user, in the model. `asked` may be at another scale.
                std::string where;
                if (const auto edge = topology.defective_edge) {
                    const Vec3 at = 0.5 * (mesh.vertices[(*edge)[0]] + mesh.vertices[(*edge)[1]]) * (asked.tolerance / o.tolerance);
                    where = " near " + detail::format_point(at);
                }
                throw Error("solid", "its faces do not close up into a watertight mesh" + where +
                                         ": they overlap, fold back or touch each other (a profile that runs back over "
                                         "itself, a part read from a file that touches itself)");
            }
            // A void touching the outer skin (or another void) at a vertex joins two sheets at one mesh vertex: no
            // 2-manifold mesh holds that (pythonocc's 11752.stp), and the export's checks refused it only after the
            // rest of their work (4 minutes).
            require(topology.singular_vertices == 0, "solid",
                    "two of its shells, or its faces, touch at a single point (a void meeting the skin at a vertex): no "
                    "2-manifold mesh can hold that");
            // A convex solid gets a convex mesh: the straddling offsets follow each face's own spacing, and a
            // sphere's came out with half its triangles a little out of plane with their neighbours, which
            // sends OpenSCAD's minkowski() from its convex fast path to decomposition (0.96 s -> 570 s).
            // The hull keeps the tolerance where the faces close up (convex_hull.hpp). Faces read with a loose
            // tolerance leave gaps of that size, which the hull bridges: a KiCad box whose middle band sinks 0.02
            // within its file's 0.02 came out as its 8 corners, 0.028 from its faces (0.014 unhulled).
            if (loosest_face(s).second <= kHullGap * o.tolerance && is_convex(s))  // the cheap test first
                return convex_hull(mesh);  // a few flips where the mesh is nearly convex already
            return mesh;
        });
    };
    try {
        return whole_mesh(options);
    } catch (const TooFine&) {
        throw;
    } catch (const Error& e) {
        // A face read from a file whose edges lie further from its surface than the tolerance asked (042_Belt_Clip's
        // up to 0.088, asked 0.036): its boundary cannot be followed, which the errors above blame on the faces.
        // Said so where that face's own tolerance meshes (tried: the advice must hold), else the error stands.
        const auto [face, loose] = loosest_face(solid);
        if (e.argument() != "solid" || !(loose > options.tolerance)) throw;
        const double enough = TooFine::two_digits_up(loose);
        TessellationOptions coarser = options;
        coarser.tolerance = enough;
        try {
            whole_mesh(coarser);
        } catch (const Error&) {
            throw e;
        }
        throw Error("solid", "face " + std::to_string(face) + " was read with tolerance " + detail::number(enough) +
                                 " (its edges lie up to that far from its surface in the file), more than the tolerance asked (" +
                                 detail::number(options.tolerance) + "): no mesh follows it closer; ask for at least " +
                                 detail::number(enough));
    }
}

Mesh tessellate(const Face& face, const TessellationOptions& options) {
    detail::require_tessellatable_weights(std::span<const Face>(&face, 1), "face");
    return at_unit_scale(face, face.surface().control_box(), options, [](const Face& f, const TessellationOptions& o) {
        return run_within_budget(std::span<const Face>(&f, 1), settings_of(o));
    });
}

Mesh tessellate(const NurbsSurface& surface, const TessellationOptions& options) {
    (void)settings_of(options);  // the options first, then the surface
    const Face face = Face::from_surface(surface);
    detail::require_tessellatable_weights(std::span<const Face>(&face, 1), "surface");
    return tessellate(face, options);
}

}  // namespace ratbez
