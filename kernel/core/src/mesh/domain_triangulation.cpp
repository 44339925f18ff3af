// Constrained Delaunay triangulations of plane regions (domain_triangulation.hpp).
//
// 1. The loops' points go into a constrained Delaunay triangulation (exact predicates); a trimmed face's in
//    scaled coordinates (u, v per chord the tolerance allows along them, averaged over the region), so that
//    Delaunay's empty circles are roughly round in units of the error and a cylinder's triangles run along
//    its rulings (choose_scale).
// 2. The region is the set of triangles nested an odd number of constrained boundaries deep, found by a flood
//    fill from the infinite face across boundary segments (CGAL's own example does the same): holes and the
//    outside are even.
// 3. A doubly curved region is first seeded with rows of points about as far apart as the tolerance allows
//    (seed_interior), so that the refinement starts from triangles near their largest.
// 4. The region is refined in rounds: every triangle not yet known good is checked at the 25 non-corner
//    points of the barycentric lattice of step 1/6 (the triangle's point against the surface near the lattice
//    point's (u, v), one Gauss-Newton step toward its foot where the point at (u, v) itself is too far); a
//    failing triangle gets one new vertex at its worst point (or, for a triangle on a pole, the middle of the
//    pole segment it spans, which fans the pole out). Points of a boundary segment are not checked and never
//    added: the segment is the edge's chord, within the tolerance of the edge by the edge sampling
//    (tessellate.cpp samples the edges of trimmed faces so that the chord in (u, v) also maps within 0.9 of
//    the tolerance of it). A triangle created in the current round waits for the next, so one round adds at
//    most one point per failing region.

#include "mesh/domain_triangulation.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <string>

#include "math/numeric_internal.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::detail {
namespace {

struct VertexInfo {
    double u = 0, v = 0;
    MeshVertexId id = 0;
    Vec3 point;
    bool known = false;  // false: a vertex CGAL made where two boundary segments cross
};

struct FaceInfo {
    int nesting = -1;      // constrained boundaries crossed from the outside
    bool checked = false;  // known to be within the tolerance
    bool fresh = false;    // made in this round (by the insertion of a new vertex)
    bool inside() const { return nesting % 2 == 1; }
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>,
                                                       CGAL::Exact_predicates_tag>;
using Point = Cdt::Point;
using FaceHandle = Cdt::Face_handle;
using VertexHandle = Cdt::Vertex_handle;

// The lattice points of step 1/kLattice in a triangle, corners excluded: barycentric (i, j, k) / kLattice.
// The 25 points of step 1/6 and a check at 0.95 of the tolerance leave room for the largest error falling
// between them (the error of a small triangle is about quadratic in its barycentric coordinates).
constexpr int kLattice = 6;
constexpr double kLatticeShare = 0.95;
// Rounds of refinement before giving up on a triangle that cannot be improved (its error comes from a
// boundary segment it touches): far more than a smooth surface needs (each round halves the failing sizes).
constexpr int kMaxRounds = 200;

// The triangulation of the loops' points and the region they bound.
class Region {
public:
    // One loop: the points and their ids; consecutive points are joined by a constrained segment.
    void add_loop(const std::vector<Point>& points, const std::vector<VertexInfo>& info) {
        std::vector<VertexHandle> handles;
        handles.reserve(points.size());
        for (std::size_t k = 0; k < points.size(); ++k) {
            const VertexHandle h = cdt_.insert(points[k]);
            if (h->info().known && h->info().id != info[k].id)
                fail("loops", "two points of the boundary fall on one place (" + number(info[k].u) + ", " + number(info[k].v) +
                                  "): the loops touch themselves or each other");
            h->info() = info[k];
            handles.push_back(h);
        }
        for (std::size_t k = 0; k < handles.size(); ++k) {
            const VertexHandle a = handles[k], b = handles[(k + 1) % handles.size()];
            if (a != b) cdt_.insert_constraint(a, b);
        }
        loops_.push_back(std::move(handles));
    }
    // Once every loop is in: a vertex CGAL made itself sits where two boundary segments cross.
    void require_simple_loops() const {
        for (auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
            if (!v->info().known)
                throw CrossingLoops("loops", "the boundary crosses itself (near (" + number(v->point().x()) + ", " + number(v->point().y()) +
                                  ") in the triangulated plane): its loops overlap");
    }

    // Once the domains are marked: the first loop has the outside beyond it, and every further loop is a hole in
    // the region it bounds. Loops sampled too coarsely can pass each other without crossing: a band's inner
    // circle, its samples straddling out from its wall, all beyond the samples of its outer circle (a band 0.004
    // wide between a trimmed shoulder and a cylinder). The loops then nest the wrong way round, and the band
    // meshed facing backwards, folded into its neighbours.
    void require_nested_loops() const {
        for (std::size_t l = 0; l < loops_.size(); ++l) {
            const int beyond = l == 0 ? 0 : 1;  // the nesting on the side of the loop away from the region
            const std::vector<VertexHandle>& loop = loops_[l];
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const VertexHandle a = loop[k], b = loop[(k + 1) % loop.size()];
                FaceHandle f;
                int i = 0;
                if (a == b || !cdt_.is_edge(a, b, f, i)) continue;  // a segment split where loops cross or touch
                const int one = f->info().nesting, other = f->neighbor(i)->info().nesting;
                if (std::min(one, other) != beyond || std::max(one, other) != beyond + 1)
                    throw CrossingLoops("loops", "the loops pass each other (near (" + number(a->point().x()) + ", " +
                                                     number(a->point().y()) + ") in the triangulated plane): a hole lies outside its outer loop");
            }
        }
    }

    // Nesting levels by flood fill from the infinite face; crossing a constrained segment adds one.
    void mark_domains() {
        for (auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f) f->info().nesting = -1;
        std::deque<Cdt::Edge> border;
        flood(cdt_.infinite_face(), 0, border);
        while (!border.empty()) {
            const Cdt::Edge e = border.front();
            border.pop_front();
            const FaceHandle n = e.first->neighbor(e.second);
            if (n->info().nesting == -1) flood(n, e.first->info().nesting + 1, border);
        }
    }

    // The ids of the region's triangles, counterclockwise; those with a repeated id (collapsed at a pole) left out.
    std::vector<std::array<MeshVertexId, 3>> triangles() const {
        std::vector<std::array<MeshVertexId, 3>> out;
        for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
            if (!f->info().inside()) continue;
            const MeshVertexId a = f->vertex(0)->info().id, b = f->vertex(1)->info().id, c = f->vertex(2)->info().id;
            if (a == b || b == c || c == a) continue;
            out.push_back({a, b, c});
        }
        return out;
    }

protected:
    void flood(FaceHandle start, int level, std::deque<Cdt::Edge>& border) {
        if (start->info().nesting != -1) return;
        std::deque<FaceHandle> queue{start};
        while (!queue.empty()) {
            const FaceHandle f = queue.front();
            queue.pop_front();
            if (f->info().nesting != -1) continue;
            f->info().nesting = level;
            for (int i = 0; i < 3; ++i) {
                const FaceHandle n = f->neighbor(i);
                if (n->info().nesting != -1) continue;
                if (cdt_.is_constrained(Cdt::Edge(f, i))) border.emplace_back(f, i);
                else queue.push_back(n);
            }
        }
    }

    Cdt cdt_;
    std::vector<std::vector<VertexHandle>> loops_;  // as added: the outer loop first
};

// A trimmed face's region, refined on its surface.
class DomainMesher : public Region {
public:
    DomainMesher(const SurfaceEvaluator& surface, const TessellationSettings& settings,
                 const std::function<MeshVertexId(const Vec3&)>& add_point)
        : surface_(surface), settings_(settings), add_point_(add_point) {}

    std::vector<std::array<MeshVertexId, 3>> run(std::span<const std::vector<BoundarySample>> loops) {
        choose_scale(loops);
        for (const auto& loop : loops) {
            require(loop.size() >= 2, "solid", "a trimmed face has a boundary loop of fewer than two samples");
            std::vector<Point> points;
            std::vector<VertexInfo> info;
            for (const BoundarySample& sample : loop) {
                points.push_back(to_point(sample.u, sample.v));
                info.push_back(VertexInfo{sample.u, sample.v, sample.id, sample.point, true});
            }
            add_loop(points, info);
        }
        require_simple_loops();
        mark_domains();
        require_nested_loops();
        if (seed_interior()) mark_domains();
        for (int round = 0; round < kMaxRounds; ++round) {
            settings_.poll();
            if (!refine_once()) break;
            mark_domains();
        }
        if (unimprovable_)
            fail("solid", "its boundary keeps further from its surface than the tolerance near (" + number(unimprovable_->x) + ", " +
                              number(unimprovable_->y) + ", " + number(unimprovable_->z) +
                              ") (a vertex or an edge of the file off the face): no mesh follows it closer");
        remove_slivers();
        return triangles();
    }

private:
    // The metric the Delaunay triangulation runs in: (u, v) scaled per direction by the density of points the
    // chord error asks for, averaged over a 9 x 9 grid of the loops' (u, v) box. Along a direction of normal
    // curvature k a chord of length h sags k h^2 / 8, so the tolerance t allows h = sqrt(8 t / k) in space and
    // h / |S_u| in u; a straight direction (a cylinder's rulings) is capped at the box's diagonal. Triangles
    // equilateral in this metric are long along the rulings and short across them, as the error allows (in
    // |S_u|, |S_v| alone, a trimmed cylinder wall took 7x BRepMesh's triangles); the refinement's error
    // check stays what decides, the metric only shapes the triangles.
    void choose_scale(std::span<const std::vector<BoundarySample>> loops) {
        double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
        Vec3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
        for (const auto& loop : loops)
            for (const BoundarySample& s : loop) {
                u0 = std::min(u0, s.u), u1 = std::max(u1, s.u), v0 = std::min(v0, s.v), v1 = std::max(v1, s.v);
                low = {std::min(low.x, s.point.x), std::min(low.y, s.point.y), std::min(low.z, s.point.z)};
                high = {std::max(high.x, s.point.x), std::max(high.y, s.point.y), std::max(high.z, s.point.z)};
            }
        longest_ = norm(high - low);
        double su = 0, sv = 0;
        int n = 0;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const Interval du = surface_.domain_u(), dv = surface_.domain_v();
                const SurfaceJet jet = surface_.jet(std::clamp(u0 + (u1 - u0) * i / 8.0, du.min, du.max),
                                                    std::clamp(v0 + (v1 - v0) * j / 8.0, dv.min, dv.max));
                const std::optional<Density> d = density(jet);
                if (!d) continue;
                su += d->u, sv += d->v, ++n;
            }
        scale_u_ = n > 0 && su > 0 && std::isfinite(su) ? su / n : 1.0;
        scale_v_ = n > 0 && sv > 0 && std::isfinite(sv) ? sv / n : 1.0;
        origin_u_ = u0, origin_v_ = v0;
        box_ = {u0, u1, v0, v1};
    }

    // The chords per unit of u and of v the tolerance t allows at a point (none where there is no tangent
    // plane): along a direction of normal curvature k a chord of length h sags k h^2 / 8, so h = sqrt(8 t / k)
    // in space and h / |S_u| in u; a straight direction is capped at the loops' diagonal.
    struct Density {
        double u, v;
    };
    std::optional<Density> density(const SurfaceJet& jet) const {
        const Vec3 normal = cross(jet.su, jet.sv);
        const double area = norm(normal);
        if (!(area > 1e-10 * (dot(jet.su, jet.su) + dot(jet.sv, jet.sv))) || !std::isfinite(area)) return std::nullopt;
        const double tolerance = settings_.check_tolerance();
        const auto along = [&](const Vec3& d, const Vec3& dd) {
            const double speed = norm(d);
            const double curvature = std::abs(dot(dd, normal / area)) / (speed * speed);
            return speed * std::max(std::sqrt(curvature / (8 * tolerance)), 1 / longest_);
        };
        const Density d{along(jet.su, jet.suu), along(jet.sv, jet.svv)};
        if (!std::isfinite(d.u) || !std::isfinite(d.v)) return std::nullopt;
        return d;
    }

    // Seeds the region's inside with points spaced as the tolerance allows before the refinement runs:
    // rows along u, each point a step of kSeedSpacing chords (Density) from the last, every other row shifted
    // by half a step, so that the triangles come out near equilateral on the surface and near their largest
    // (an equilateral triangle of side h sags k h^2 / 6 at its centre: 0.87 chords reach the tolerance).
    // Refining a coarse triangulation alone splits a triangle that fails by 1% into three, and the mesh
    // settled at half the tolerance with twice the triangles; the seeds leave the refinement the few
    // triangles the local steps misjudge. A seed within half a step of a vertex already there (the
    // boundary, the pole) is left out. Returns whether any was added.
    bool seed_interior() {
        constexpr double kSeedSpacing = 0.75;
        const Interval du = surface_.domain_u(), dv = surface_.domain_v();
        const double u0 = box_[0], u1 = box_[1], v0 = box_[2], v1 = box_[3];
        if (!(u1 > u0) || !(v1 > v0)) return false;
        // Where one direction is straight across the region (a cylinder's, a cone's rulings: under two chords)
        // the refinement's long triangles along it are already the fewest; seeds would cut them in rows.
        if (scale_u_ * (u1 - u0) < 2 || scale_v_ * (v1 - v0) < 2) return false;
        // The parameter steps of kSeedSpacing chords at (u, v) and the smaller of them in space; a tenth of
        // the box where the surface has no tangent plane.
        struct Steps {
            double u, v, space;
        };
        const auto steps_at = [&](double u, double v) {
            const SurfaceJet jet = surface_.jet(std::clamp(u, du.min, du.max), std::clamp(v, dv.min, dv.max));
            const std::optional<Density> d = density(jet);
            if (!d || !(d->u > 0) || !(d->v > 0)) return Steps{0.1 * (u1 - u0), 0.1 * (v1 - v0), 0};
            const Steps steps{std::clamp(kSeedSpacing / d->u, 1e-3 * (u1 - u0), u1 - u0),
                              std::clamp(kSeedSpacing / d->v, 1e-3 * (v1 - v0), v1 - v0), 0};
            return Steps{steps.u, steps.v, std::min(steps.u * norm(jet.su), steps.v * norm(jet.sv))};
        };
        // Rows of equilateral triangles are sqrt(3) / 2 of their sides apart; each step is taken from the
        // density at its middle (a rational span's speed changes along it).
        const double middle_u = 0.5 * (u0 + u1), row = std::sqrt(3.0) / 2;
        // The seeds the average densities ask for: past the triangle budget the refinement refuses the face
        // (TooFine) sooner than the seeding would, and a face far denser in places than on average (a damaged
        // file's, found by fuzz_read_step: 23 s under the sanitizers) stops seeding at four times as many
        // candidates.
        const double expected = (scale_u_ * (u1 - u0) / kSeedSpacing + 1) * (scale_v_ * (v1 - v0) / (row * kSeedSpacing) + 1);
        if (!(expected <= 0.5 * static_cast<double>(settings_.max_triangles))) return false;
        const double max_candidates = 4 * expected + 1000;
        double candidates = 0;
        const auto row_step = [&](double v) { return row * steps_at(middle_u, v + 0.5 * row * steps_at(middle_u, v).v).v; };
        std::size_t seeds = 0;
        FaceHandle hint;
        bool shifted = false;
        for (double v = v0 + row_step(v0); v < v1; v += row_step(v)) {
            shifted = !shifted;
            for (double u = u0 + (shifted ? 0.5 * steps_at(u0, v).u : 0); u < u1;) {
                if (++candidates > max_candidates) return seeds > 0;
                const Steps steps = steps_at(u, v);
                if (steps.space > 0 && seed(u, v, 0.5 * steps.space, hint) && ++seeds > settings_.max_triangles / 2)
                    throw TooFine(static_cast<double>(seeds) * 2, settings_.max_triangles);
                u += steps_at(u + 0.5 * steps.u, v).u;
            }
            settings_.poll();
        }
        return seeds > 0;
    }

    // Inserts a seed at (u, v) if it is inside the region and no vertex of the triangle it falls in is
    // nearer than `keep` in space. Returns whether it did.
    bool seed(double u, double v, double keep, FaceHandle& hint) {
        const Point p = to_point(u, v);
        Cdt::Locate_type type;
        int index = 0;
        const FaceHandle f = cdt_.locate(p, type, index, hint);
        if (type != Cdt::FACE || cdt_.is_infinite(f) || !f->info().inside()) return false;
        const Vec3 point = surface_point(u, v);
        for (int m = 0; m < 3; ++m)
            if (distance(f->vertex(m)->info().point, point) < keep) return false;
        const int nesting = f->info().nesting;  // the insertion's flips stay within its constrained region
        const VertexHandle h = cdt_.insert(p, type, f, index);
        h->info() = VertexInfo{u, v, add_point_(point), point, true};
        for (Cdt::Face_circulator c = cdt_.incident_faces(h), end = c;;) {
            c->info().nesting = nesting;
            if (++c == end) break;
        }
        hint = h->face();
        fan_pole_towards(h);
        return true;
    }

    // A seed next to a pole gets a point of the pole at its own u, as refine_once's pole fan would add:
    // a triangle from the seeds to a pole corner at another u interpolates (u, v) across the whole pole and
    // fails the lattice check however small it is in space.
    void fan_pole_towards(VertexHandle seed) {
        const VertexInfo info = seed->info();
        for (Cdt::Face_circulator c = cdt_.incident_faces(seed), end = c;;) {
            for (int i = 0; i < 3; ++i) {
                if (cdt_.is_infinite(c) || !is_pole(c, i)) continue;
                const VertexInfo a = c->vertex(Cdt::ccw(i))->info(), b = c->vertex(Cdt::cw(i))->info();
                const bool along_u = std::abs(a.v - b.v) <= std::abs(a.u - b.u);
                const double t = along_u ? (info.u - a.u) / (b.u - a.u) : (info.v - a.v) / (b.v - a.v);
                if (!(t > 0.01 && t < 0.99)) continue;
                const double u = along_u ? info.u : a.u, v = along_u ? a.v : info.v;
                const VertexHandle h = cdt_.insert(to_point(u, v), Cdt::EDGE, c, i);
                h->info() = VertexInfo{u, v, a.id, a.point, true};
                mark_domains();  // the pole's split reaches the outside too
                return;
            }
            if (++c == end) break;
        }
    }

    Point to_point(double u, double v) const { return Point((u - origin_u_) * scale_u_, (v - origin_v_) * scale_v_); }

    SurfaceFirstDerivatives evaluate(double u, double v) const {
        const Interval du = surface_.domain_u(), dv = surface_.domain_v();
        return surface_.first_derivatives(std::clamp(u, du.min, du.max), std::clamp(v, dv.min, dv.max));
    }
    Vec3 surface_point(double u, double v) const {
        const Interval du = surface_.domain_u(), dv = surface_.domain_v();
        return surface_.point(std::clamp(u, du.min, du.max), std::clamp(v, dv.min, dv.max));
    }

    // The distance from a point p of a triangle to the surface, from `at`, the surface point at the same
    // (u, v), moved by one Gauss-Newton step on |S(u, v) - p|^2 toward the foot point (the step solves the
    // normal equations of the tangent plane): an upper bound, as any surface point's distance is, and a tight
    // one. The point at (u, v) alone also counts the parameterisation's drift along the surface, which is no
    // error of the mesh: a pole-degenerate sphere patch measured so took 2.5x the triangles its curvature
    // asks for.
    double foot_distance(const Vec3& p, double u, double v, double direct) const {
        const SurfaceFirstDerivatives d = evaluate(u, v);
        const Vec3 r = p - d.s;
        const double a = dot(d.su, d.su), b = dot(d.su, d.sv), c = dot(d.sv, d.sv);
        const double det = a * c - b * b;
        if (!(det > 1e-12 * a * c)) return direct;  // no tangent plane (a pole): the point itself
        const double ru = dot(r, d.su), rv = dot(r, d.sv);
        const double du = (c * ru - b * rv) / det, dv = (a * rv - b * ru) / det;
        return std::min(direct, distance(surface_point(u + du, v + dv), p));
    }

    // A constrained segment of the boundary proper (not a pole, whose ends are one mesh vertex).
    bool is_boundary(FaceHandle f, int i) const {
        return cdt_.is_constrained(Cdt::Edge(f, i)) && f->vertex(Cdt::ccw(i))->info().id != f->vertex(Cdt::cw(i))->info().id;
    }
    bool is_pole(FaceHandle f, int i) const {
        return cdt_.is_constrained(Cdt::Edge(f, i)) && f->vertex(Cdt::ccw(i))->info().id == f->vertex(Cdt::cw(i))->info().id;
    }

    // Where a failing triangle wants its new vertex: a lattice point of the triangle with these corners
    // (vertices are never removed, so the corners outlive the triangle, which a flip may have replaced).
    struct Candidate {
        std::array<VertexHandle, 3> corners;
        double error = 0;
        std::array<int, 3> lattice{};  // barycentric numerators of the point, per corner
    };

    // The triangle's largest distance from the surface over its lattice points (boundary segments' points
    // excluded), and that point; with an angle limit, a corner normal turning too far fails it at its centre.
    Candidate assess(FaceHandle f) const {
        Candidate worst{{f->vertex(0), f->vertex(1), f->vertex(2)}, 0, {2, 2, 2}};
        const double accept = kLatticeShare * settings_.check_tolerance();
        bool failing = false;
        double worst_direct = 0;
        const VertexInfo* corner[3] = {&f->vertex(0)->info(), &f->vertex(1)->info(), &f->vertex(2)->info()};
        for (int i = 0; i <= kLattice; ++i)
            for (int j = 0; i + j <= kLattice; ++j) {
                const int k = kLattice - i - j;
                if (i == kLattice || j == kLattice || k == kLattice) continue;
                const std::array<int, 3> b{i, j, k};
                bool on_boundary = false;
                for (int m = 0; m < 3; ++m)
                    if (b[static_cast<std::size_t>(m)] == 0 && is_boundary(f, m)) on_boundary = true;
                if (on_boundary) continue;
                double u = 0, v = 0;
                Vec3 linear{};
                for (int m = 0; m < 3; ++m) {
                    const double w = b[static_cast<std::size_t>(m)] / static_cast<double>(kLattice);
                    u += w * corner[m]->u, v += w * corner[m]->v;
                    linear = linear + corner[m]->point * w;
                }
                // The point at (u, v) first; the foot step only where that is over the tolerance. Once one
                // point fails, the triangle does: the rest are ranked by that first distance alone (where to
                // insert), which kept damaged files' faces from tripling the refinement's cost.
                const double direct = distance(surface_point(u, v), linear);
                if (failing) {
                    if (direct > worst_direct) worst_direct = direct, worst.lattice = b;
                    continue;
                }
                const double error = direct <= std::max(worst.error, accept) ? direct : foot_distance(linear, u, v, direct);
                if (error > worst.error) worst.error = error, worst.lattice = b, worst_direct = direct;
                failing = worst.error > accept;
            }
        if (worst.error <= kLatticeShare * settings_.check_tolerance() && settings_.angle_rad > 0) {
            // The normals at the ends of every inner edge may turn by at most the angle limit; a boundary
            // segment's are the edge sampling's business (tessellate.cpp refines the edges of trimmed faces for it).
            std::array<std::optional<Vec3>, 3> normals;
            for (int m = 0; m < 3; ++m) {
                const SurfaceFirstDerivatives d = evaluate(corner[m]->u, corner[m]->v);
                const Vec3 n = cross(d.su, d.sv);
                const double length = norm(n);
                if (length > 1e-10 * (dot(d.su, d.su) + dot(d.sv, d.sv))) normals[static_cast<std::size_t>(m)] = n / length;
            }
            for (int m = 0; m < 3; ++m) {  // the edge opposite corner m
                if (cdt_.is_constrained(Cdt::Edge(f, m))) continue;
                const auto& a = normals[static_cast<std::size_t>(Cdt::ccw(m))];
                const auto& b = normals[static_cast<std::size_t>(Cdt::cw(m))];
                if (a && b && std::acos(std::clamp(dot(*a, *b), -1.0, 1.0)) > settings_.angle_rad) {
                    worst.error = 2 * settings_.check_tolerance();
                    worst.lattice = {kLattice / 2, kLattice / 2, kLattice / 2};
                    worst.lattice[static_cast<std::size_t>(m)] = 0;  // the middle of that edge
                    break;
                }
            }
        }
        return worst;
    }

    // One round: checks the triangles not yet known good, adds a vertex in each failing one that this
    // round has not replaced yet. Returns whether anything was added.
    bool refine_once() {
        std::vector<Candidate> failing;
        std::size_t inside = 0;
        for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
            f->info().fresh = false;
            if (!f->info().inside()) continue;
            ++inside;
            if (f->info().checked) continue;
            Candidate c = assess(f);
            if (c.error <= kLatticeShare * settings_.check_tolerance()) f->info().checked = true;
            else failing.push_back(c);
        }
        if (inside > settings_.max_triangles) throw TooFine(static_cast<double>(inside) * 2, settings_.max_triangles);
        if (failing.empty()) return false;
        std::sort(failing.begin(), failing.end(), [](const Candidate& a, const Candidate& b) { return a.error > b.error; });
        bool added = false;
        for (const Candidate& c : failing) {
            FaceHandle f;
            if (!cdt_.is_face(c.corners[0], c.corners[1], c.corners[2], f) || f->info().fresh) continue;
            added = insert(c, f) || added;
        }
        return added;
    }

    // A triangle whose corners are distinct mesh vertices but collinear in space (near an apex: two points of
    // one generator of a cone and the apex) has no area: its inner edge is flipped, when the flip keeps the
    // triangulation valid in (u, v), to the one across the neighbour. The region stays covered; only the
    // diagonal of a quadrilateral changes (the lattice check passed both triangles, which are on the surface).
    void remove_slivers() {
        const auto sliver = [](FaceHandle f) {
            const VertexInfo &a = f->vertex(0)->info(), &b = f->vertex(1)->info(), &c = f->vertex(2)->info();
            if (a.id == b.id || b.id == c.id || c.id == a.id) return false;  // a pole's collapsed triangle, left out
            return is_flat_triangle(a.point, b.point, c.point);
        };
        for (int pass = 0; pass < 3; ++pass) {
            std::vector<std::array<VertexHandle, 3>> found;
            for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
                if (f->info().inside() && sliver(f)) found.push_back({f->vertex(0), f->vertex(1), f->vertex(2)});
            bool flipped = false;
            for (const auto& corners : found) {
                FaceHandle f;
                if (!cdt_.is_face(corners[0], corners[1], corners[2], f) || !sliver(f)) continue;
                for (int m = 0; m < 3; ++m) {
                    const FaceHandle n = f->neighbor(m);
                    if (cdt_.is_constrained(Cdt::Edge(f, m)) || cdt_.is_infinite(n) || !n->info().inside()) continue;
                    // The flip is valid where the quadrilateral is strictly convex in the triangulation's plane.
                    const Point& apex = f->vertex(m)->point();
                    const Point& mirror = n->vertex(cdt_.mirror_index(f, m))->point();
                    if (CGAL::orientation(apex, mirror, f->vertex(Cdt::ccw(m))->point()) *
                            CGAL::orientation(apex, mirror, f->vertex(Cdt::cw(m))->point()) >= 0)
                        continue;
                    const int nesting = f->info().nesting;
                    cdt_.flip(f, m);
                    f->info().nesting = nesting, n->info().nesting = nesting;
                    flipped = true;
                    break;
                }
            }
            if (!flipped) return;
        }
    }

    // Adds the candidate's vertex in its triangle f: the middle of a pole segment of f if it has one (a fan
    // at the pole), else its lattice point (on an interior edge: that edge is split, the neighbour too).
    bool insert(const Candidate& c, FaceHandle f) {
        for (int m = 0; m < 3; ++m) {
            if (!is_pole(f, m)) continue;
            const VertexInfo a = f->vertex(Cdt::ccw(m))->info();
            const VertexInfo b = f->vertex(Cdt::cw(m))->info();
            const double u = 0.5 * (a.u + b.u), v = 0.5 * (a.v + b.v);
            const VertexHandle h = cdt_.insert(to_point(u, v), Cdt::EDGE, f, m);
            h->info() = VertexInfo{u, v, a.id, a.point, true};
            touched(h);
            return true;
        }
        double u = 0, v = 0;
        int edge = -1;  // the index in f of the edge the point lies on, if any
        for (std::size_t m = 0; m < 3; ++m) {
            const double w = c.lattice[m] / static_cast<double>(kLattice);
            u += w * c.corners[m]->info().u, v += w * c.corners[m]->info().v;
            if (c.lattice[m] == 0) edge = f->index(c.corners[m]);
        }
        if (edge >= 0 && cdt_.is_constrained(Cdt::Edge(f, edge))) return false;  // never on the boundary
        // A triangle whose new vertex would fall a thousandth of the tolerance from a corner cannot be improved:
        // its error is the boundary's own gap from the surface (a vertex of an Inventor extruder body 0.1 off a
        // face it bounds), and halving toward it round after round left 182 mesh vertices in one place. The
        // region is refused instead (run), naming where.
        const Vec3 point = surface_point(u, v);
        for (const VertexHandle& corner : c.corners)
            if (distance(corner->info().point, point) < 1e-3 * settings_.check_tolerance()) {
                f->info().checked = true;
                if (!unimprovable_) unimprovable_ = corner->info().point;
                return false;
            }
        const Point p = to_point(u, v);
        const VertexHandle h = edge >= 0 ? cdt_.insert(p, Cdt::EDGE, f, edge) : cdt_.insert(p, Cdt::FACE, f, 0);
        if (h->info().known) return false;  // fell on an existing vertex (rounding)
        h->info() = VertexInfo{u, v, add_point_(point), point, true};
        touched(h);
        return true;
    }

    // The triangles around a new vertex are new (or reused by a flip): not checked, not to be refined again
    // in this round.
    void touched(VertexHandle h) {
        Cdt::Face_circulator f = cdt_.incident_faces(h), end = f;
        do {
            f->info().checked = false;
            f->info().fresh = true;
        } while (++f != end);
    }

    const SurfaceEvaluator& surface_;
    const TessellationSettings& settings_;
    const std::function<MeshVertexId(const Vec3&)>& add_point_;
    std::optional<Vec3> unimprovable_;  // a corner a failing triangle could not be refined toward (insert)
    double scale_u_ = 1, scale_v_ = 1, origin_u_ = 0, origin_v_ = 0, longest_ = 1;
    std::array<double, 4> box_{};  // the loops' (u, v) box: u0, u1, v0, v1
};

}  // namespace

std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<std::vector<Point2>>& loops,
                                                            std::span<const MeshVertexId> ids) {
    require(!loops.empty(), "loops", "a polygon needs an outer loop");
    std::size_t count = 0;
    for (const auto& loop : loops) count += loop.size();
    require(ids.empty() || ids.size() == count, "ids", "must number every point of the loops");
    Region region;
    std::size_t index = 0;
    for (const auto& loop : loops) {
        require(loop.size() >= 3, "loops", "a loop needs at least three points");
        std::vector<Point> points;
        std::vector<VertexInfo> info;
        for (const Point2& p : loop) {
            require(std::isfinite(p.x) && std::isfinite(p.y), "loops", "points must be finite");
            points.emplace_back(p.x, p.y);
            const MeshVertexId id = ids.empty() ? index : ids[index];
            ++index;
            info.push_back(VertexInfo{p.x, p.y, id, Vec3{p.x, p.y, 0}, true});
        }
        region.add_loop(points, info);
    }
    region.require_simple_loops();
    region.mark_domains();
    region.require_nested_loops();
    std::vector<std::array<std::size_t, 3>> out;
    for (const auto& t : region.triangles()) out.push_back({t[0], t[1], t[2]});
    return out;
}

double twice_signed_area(const std::vector<Point2>& polygon) {
    if (polygon.empty()) return 0;
    // About the first point: far from the origin the products of raw coordinates cancel, and a sliver's sign
    // (the loops tessellate.cpp holds to their orientation) would be rounding.
    const Point2 o = polygon.front();
    double sum = 0;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Point2& a = polygon[k];
        const Point2& b = polygon[(k + 1) % polygon.size()];
        sum += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
    }
    return sum;
}

// How short a hook is beside the chord before it: the touch screen's, 4.7e-7 after 1.3e-3, is 3.6e-4 of it.
constexpr double kHookShare = 0.01;

void unhook_corners(std::vector<BoundarySample>& loop, std::span<const std::size_t> corners) {
    const std::size_t n = loop.size();
    if (n < 3) return;
    // Sample `at` between `from` and `corner` on the loop.
    const auto place = [&](std::size_t at, std::size_t from, std::size_t corner) {
        BoundarySample &s = loop[at], &a = loop[from], &c = loop[corner];
        // A hook: a step back to the corner, short beside the chord before it. A sharp turn of the edge in (u, v)
        // (a cable's rounded end, chords of 0.41 on either side) is the edge's own and stays.
        const double back_u = c.u - s.u, back_v = c.v - s.v, chord_u = s.u - a.u, chord_v = s.v - a.v;
        if (back_u * chord_u + back_v * chord_v >= 0) return;  // no turn back at s
        if (std::hypot(back_u, back_v) > kHookShare * std::hypot(chord_u, chord_v)) return;
        const double along = distance(a.point, s.point), rest = distance(s.point, c.point);
        const double f = along + rest > 0 ? along / (along + rest) : 0.5;
        s.u = a.u + f * (c.u - a.u);
        s.v = a.v + f * (c.v - a.v);
    };
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const std::size_t corner = corners[k];
        // The samples of the coedges ending and starting at the corner, the corner counted with the later one.
        const std::size_t before = k == 0 ? n - corners.back() : corner - corners[k - 1];
        const std::size_t after = (k + 1 < corners.size() ? corners[k + 1] : n) - corner;
        if (before >= 2) place((corner + n - 1) % n, (corner + n - 2) % n, corner);
        if (after >= 2) place((corner + 1) % n, (corner + 2) % n, corner);
    }
}

std::vector<std::array<MeshVertexId, 3>> triangulate_trimmed_domain(
    const SurfaceEvaluator& surface, std::span<const std::vector<BoundarySample>> loops,
    const TessellationSettings& settings, const std::function<MeshVertexId(const Vec3&)>& add_point) {
    return DomainMesher(surface, settings, add_point).run(loops);
}

}  // namespace ratbez::detail
