// Face and Solid construction with the validation promised by brep.hpp.
#include "ratbez/brep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

#include "analysis/cubature.hpp"
#include "brep/consistency.hpp"
#include "brep/face_integrals.hpp"
#include "math/numeric_internal.hpp"
#include "math/solid_scale.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/properties.hpp"

namespace ratbez {

namespace {

constexpr int kSideSamples = 9;
// The share of its box's diagonal cubed below which a shell's enclosed volume from the quick rule is measured
// again by the adaptive one before its sign orients the shell: a plate 1000 x 1000 x 0.1 encloses 3.5e-5 of it,
// a wire 1000 long of radius 0.1 3e-8 (measured again, at the cost of a volume).
constexpr double kQuickVolumeShare = 1e-6;

const char* side_name(int side) {
    static const char* names[] = {"v_min", "u_max", "v_max", "u_min"};
    return names[side];
}

VertexPtr traversal_start(const Coedge& c) { return c.reversed ? c.edge->end : c.edge->start; }
VertexPtr traversal_end(const Coedge& c) { return c.reversed ? c.edge->start : c.edge->end; }

}  // namespace

Face Face::from_surface(NurbsSurface surface, std::array<Coedge, 4> sides) {
    const double size = surface.control_box().diagonal();
    require(size > 0 && std::isfinite(size), "surface", "must not collapse to a single point");
    const double tolerance = detail::consistency_tolerance(surface.control_box());
    const Interval du = surface.domain_u(), dv = surface.domain_v();

    for (int s = 0; s < 4; ++s) {
        const Coedge& coedge = sides[static_cast<std::size_t>(s)];
        const std::string where = std::string("side ") + side_name(s);
        require(coedge.edge != nullptr, "sides", where + " has no edge");
        require(coedge.edge->start != nullptr && coedge.edge->end != nullptr, "sides", where + "'s edge has no vertices");
        const bool along_u = (s == 0 || s == 2);  // v sides follow u
        const Interval domain = along_u ? du : dv;
        const double fixed = s == 0 ? dv.min : s == 1 ? du.max : s == 2 ? dv.max : du.min;
        const bool traversal_increasing = (s == 0 || s == 1);
        // The coedge runs the edge forward unless reversed; the face runs the side with increasing
        // parameter on v_min and u_max. The edge's parameter agrees with the surface's exactly when both
        // directions agree.
        const bool edge_with_parameter = traversal_increasing != coedge.reversed;
        const NurbsCurve& curve = coedge.edge->curve;
        const Interval edge_domain = curve.domain();
        const double width = domain.max - domain.min;
        require(std::abs(edge_domain.min - domain.min) <= 1e-12 * width &&
                    std::abs(edge_domain.max - domain.max) <= 1e-12 * width,
                "sides", where + "'s edge must be parameterised over the surface's domain [" +
                             exact_number(domain.min) + ", " + exact_number(domain.max) + "]");
        double side_length = 0;
        Vec3 previous{};
        for (int k = 0; k < kSideSamples; ++k) {
            const double t = k == kSideSamples - 1 ? domain.max : domain.min + width * k / (kSideSamples - 1);
            const Vec3 on_surface = along_u ? surface.point(t, fixed) : surface.point(fixed, t);
            const double edge_t = edge_with_parameter ? t : edge_domain.min + edge_domain.max - t;
            const Vec3 on_edge = curve.point(std::clamp(edge_t, edge_domain.min, edge_domain.max));
            require(distance(on_surface, on_edge) <= tolerance, "sides", [&] {
                return where + "'s edge is " + exact_number(distance(on_surface, on_edge)) +
                       " away from the surface's boundary at parameter " + exact_number(t);
            });
            if (k > 0) side_length += distance(previous, on_surface);
            previous = on_surface;
        }
        const bool collapsed = side_length <= tolerance;
        require(collapsed == coedge.edge->degenerate, "sides",
                where + (collapsed ? " collapses to a point and needs a degenerate edge"
                                   : " has a degenerate edge but does not collapse to a point"));
    }

    // Counterclockwise corners in (u, v): side s starts at corner s.
    const std::array<Vec3, 4> corners{surface.point(du.min, dv.min), surface.point(du.max, dv.min),
                                      surface.point(du.max, dv.max), surface.point(du.min, dv.max)};
    for (int s = 0; s < 4; ++s) {
        const Coedge& here = sides[static_cast<std::size_t>(s)];
        const Coedge& next = sides[static_cast<std::size_t>((s + 1) % 4)];
        require(traversal_end(here) == traversal_start(next), "sides",
                std::string("side ") + side_name(s) + " must end at the Vertex object where side " +
                    side_name((s + 1) % 4) + " starts");
        require(distance(traversal_start(here)->point, corners[static_cast<std::size_t>(s)]) <= tolerance, "sides",
                std::string("side ") + side_name(s) + " starts at a vertex away from the surface's corner");
    }

    Face face(Kind::surface, std::move(surface));
    face.sides_ = sides;
    return face;
}

Face Face::from_surface(NurbsSurface surface) {
    const double size = surface.control_box().diagonal();
    require(size > 0 && std::isfinite(size), "surface", "must not collapse to a single point");
    const double tolerance = detail::consistency_tolerance(surface.control_box());
    const Interval du = surface.domain_u(), dv = surface.domain_v();
    // The points of side s (Side order) at the validation's sample parameters, in increasing parameter.
    auto side_points = [&](int s) {
        const bool along_u = (s == 0 || s == 2);
        const Interval domain = along_u ? du : dv;
        const double fixed = s == 0 ? dv.min : s == 1 ? du.max : s == 2 ? dv.max : du.min;
        std::array<Vec3, kSideSamples> points;
        for (int k = 0; k < kSideSamples; ++k) {
            const double t = k == kSideSamples - 1 ? domain.max : domain.min + (domain.max - domain.min) * k / (kSideSamples - 1);
            points[static_cast<std::size_t>(k)] = along_u ? surface.point(t, fixed) : surface.point(fixed, t);
        }
        return points;
    };
    std::array<std::array<Vec3, kSideSamples>, 4> samples{side_points(0), side_points(1), side_points(2), side_points(3)};
    std::array<bool, 4> collapsed{};
    for (std::size_t s = 0; s < 4; ++s) {
        double length = 0;
        for (std::size_t k = 1; k < kSideSamples; ++k) length += distance(samples[s][k - 1], samples[s][k]);
        collapsed[s] = length <= tolerance;  // as from_surface(surface, sides) decides it
    }
    auto coincide = [&](std::size_t a, std::size_t b) {
        if (collapsed[a] || collapsed[b]) return false;
        for (std::size_t k = 0; k < kSideSamples; ++k)
            if (distance(samples[a][k], samples[b][k]) > tolerance) return false;
        return true;
    };
    const bool closed_u = coincide(1, 3), closed_v = coincide(0, 2);

    // Corners counterclockwise, side s running from corner s to corner s + 1; corners joined by a
    // collapsed side or by a shared (closing) side pair are one vertex.
    std::array<std::size_t, 4> root{0, 1, 2, 3};
    auto find = [&](std::size_t c) {
        while (root[c] != c) c = root[c];
        return c;
    };
    auto join = [&](std::size_t a, std::size_t b) { root[find(a)] = find(b); };
    for (std::size_t s = 0; s < 4; ++s)
        if (collapsed[s]) join(s, (s + 1) % 4);
    if (closed_u) join(0, 1), join(3, 2);
    if (closed_v) join(0, 3), join(1, 2);
    const std::array<Vec3, 4> corners{samples[0].front(), samples[0].back(), samples[2].back(), samples[2].front()};
    std::array<VertexPtr, 4> vertices;
    for (std::size_t c = 0; c < 4; ++c)
        if (!vertices[find(c)]) vertices[find(c)] = std::make_shared<const Vertex>(Vertex{corners[find(c)]});
    auto vertex = [&](std::size_t c) { return vertices[find(c)]; };

    // Each side's edge runs with the surface parameter from its lower-parameter corner: v_min from corner
    // 0 to 1, u_max from 1 to 2, v_max from 3 to 2 and u_min from 0 to 3 (the last two traversed reversed).
    auto edge = [&](NurbsCurve curve, std::size_t start, std::size_t end, bool degenerate) {
        return std::make_shared<const Edge>(Edge{std::move(curve), vertex(start), vertex(end), degenerate});
    };
    const EdgePtr v_min = edge(surface.isocurve_v(dv.min), 0, 1, collapsed[0]);
    const EdgePtr u_min = edge(surface.isocurve_u(du.min), 0, 3, collapsed[3]);
    const EdgePtr u_max = closed_u ? u_min : edge(surface.isocurve_u(du.max), 1, 2, collapsed[1]);
    const EdgePtr v_max = closed_v ? v_min : edge(surface.isocurve_v(dv.max), 3, 2, collapsed[2]);
    return from_surface(std::move(surface), {Coedge{v_min, false}, Coedge{u_max, false}, Coedge{v_max, true},
                                             Coedge{u_min, true}});
}

Face Face::planar(const Plane& plane, std::vector<std::vector<Coedge>> loops, double tolerance) {
    require(std::isfinite(tolerance) && tolerance >= 0, "tolerance", "must be a finite number >= 0");
    require(is_finite(plane.origin) && is_finite(plane.x_axis) && is_finite(plane.y_axis) && is_finite(plane.normal),
            "plane", "must have finite coordinates");
    constexpr double frame_tolerance = 1e-12;
    require(std::abs(norm(plane.x_axis) - 1) <= frame_tolerance && std::abs(norm(plane.y_axis) - 1) <= frame_tolerance &&
                std::abs(dot(plane.x_axis, plane.y_axis)) <= frame_tolerance,
            "plane", "x_axis and y_axis must be orthonormal");
    require(distance(cross(plane.x_axis, plane.y_axis), plane.normal) <= 1e-9, "plane",
            "normal must equal cross(x_axis, y_axis)");
    require(!loops.empty(), "loops", "a planar face needs an outer loop");

    Box box;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const std::string where = "loop " + std::to_string(l);
        require(!loops[l].empty(), "loops", where + " is empty");
        for (std::size_t k = 0; k < loops[l].size(); ++k) {
            const Coedge& c = loops[l][k];
            require(c.edge != nullptr && c.edge->start != nullptr && c.edge->end != nullptr, "loops",
                    where + " has a missing edge or vertex at position " + std::to_string(k));
            require(!c.edge->degenerate, "loops", where + " must not contain degenerate edges");
            require(traversal_end(c) == traversal_start(loops[l][(k + 1) % loops[l].size()]), "loops",
                    where + ": coedge " + std::to_string(k) + " does not end at the Vertex object where the next starts");
            box.add(c.edge->curve.control_box());
        }
    }
    const double size = box.diagonal();
    require(size > 0, "loops", "enclose no area");
    const double off_plane = std::max(tolerance, detail::consistency_tolerance(box));

    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        double signed_area = 0;
        for (const Coedge& c : loops[l]) {
            // Exact constructions keep their control points in the plane (so the curve, by the convex hull
            // property); a file's tolerance bounds how far the curve itself strays, and its control points may
            // stray further (a B-spline fitted to an intersection): then the curve is held to it at samples.
            const NurbsCurve& curve = c.edge->curve;
            if (tolerance > 0) {
                const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
                for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
                    for (int j = 0; j < 8; ++j) {
                        const double away = std::abs(dot(curve.point(breaks[k] + (breaks[k + 1] - breaks[k]) * j / 8.0) - plane.origin, plane.normal));
                        require(away <= off_plane, "loops", [&] {
                            return "loop " + std::to_string(l) + " leaves the plane (a point of it is " + detail::number(away) +
                                   " away from it, more than the tolerance " + detail::number(off_plane) + ")";
                        });
                    }
            }
            for (const Vec4& pw : curve.homogeneous_points()) {
                const Vec3 r = project(pw) - plane.origin;
                require(tolerance > 0 || std::abs(dot(r, plane.normal)) <= off_plane, "loops", [&] {
                    return "loop " + std::to_string(l) + " leaves the plane (a control point is " +
                           detail::number(std::abs(dot(r, plane.normal))) + " away from it, more than the tolerance " +
                           detail::number(off_plane) + ")";
                });
                x0 = std::min(x0, dot(r, plane.x_axis));
                x1 = std::max(x1, dot(r, plane.x_axis));
                y0 = std::min(y0, dot(r, plane.y_axis));
                y1 = std::max(y1, dot(r, plane.y_axis));
            }
            // The sign is judged against a margin of 1e-12 size^2: resolve each edge well below it.
            const double a = detail::green_area(c.edge->curve, plane.origin, plane.x_axis, plane.y_axis,
                                                1e-13 * size * size, "loops");
            signed_area += c.reversed ? -a : a;
        }
        // A file's curves may end a tolerance short of their vertices (a keyboard case's sliver triangle of area
        // 0.03: 0.0097 at one end). The pieces' sum then moves with the plane's origin, by about a gap times its
        // distance (30 mm there: it read -0.086, clockwise). Straight bridges from each curve's end to the next
        // one's start close the loop; they add nothing where the curves meet.
        for (std::size_t k = 0; k < loops[l].size(); ++k) {
            const Coedge& here = loops[l][k];
            const Coedge& next = loops[l][(k + 1) % loops[l].size()];
            const Vec3 from = (here.reversed ? here.edge->curve.start_point() : here.edge->curve.end_point()) - plane.origin;
            const Vec3 to = (next.reversed ? next.edge->curve.end_point() : next.edge->curve.start_point()) - plane.origin;
            signed_area += 0.5 * (dot(from, plane.x_axis) * dot(to, plane.y_axis) - dot(from, plane.y_axis) * dot(to, plane.x_axis));
        }
        const double area_tolerance = 1e-12 * size * size;
        if (l == 0)
            require(signed_area > area_tolerance, "loops",
                    "the outer loop must run counterclockwise seen from plane.normal and enclose an area");
        else
            require(signed_area < -area_tolerance, "loops",
                    "hole loop " + std::to_string(l) + " must run clockwise seen from plane.normal");
    }

    // S(u, v) = origin + u x_axis + v y_axis over [x0, x1] x [y0, y1]: S_u x S_v = x_axis x y_axis = normal.
    std::vector<std::vector<Vec3>> net(2, std::vector<Vec3>(2));
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            net[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
                plane.origin + plane.x_axis * (i == 0 ? x0 : x1) + plane.y_axis * (j == 0 ? y0 : y1);
    NurbsSurface patch(1, 1, {x0, x0, x1, x1}, {y0, y0, y1, y1}, std::move(net));
    Face face(Kind::planar, std::move(patch));
    face.plane_ = plane;
    face.loops_ = std::move(loops);
    face.tolerance_ = tolerance;
    return face;
}

namespace {

template <class Visitor>
void for_each_coedge(std::span<const Face> faces, Visitor visit) {
    for (const Face& face : faces) ratbez::for_each_coedge(face, visit);
}

// The faces connected through shared (non-degenerate) edges, each component's face indices ascending,
// components ordered by their first face (union-find over the edges' users).
std::vector<std::vector<std::size_t>> connected_shells(std::span<const Face> faces) {
    std::vector<std::size_t> root(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) root[i] = i;
    const auto find = [&](std::size_t i) {
        while (root[i] != i) i = root[i] = root[root[i]];
        return i;
    };
    std::map<const Edge*, std::size_t> first_user;
    for (std::size_t i = 0; i < faces.size(); ++i)
        ratbez::for_each_coedge(faces[i], [&](const Coedge& c) {
            if (c.edge->degenerate) return;
            const auto [it, inserted] = first_user.try_emplace(c.edge.get(), i);
            if (!inserted) root[find(i)] = find(it->second);
        });
    std::map<std::size_t, std::size_t> component_of_root;
    std::vector<std::vector<std::size_t>> shells;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const auto [it, inserted] = component_of_root.try_emplace(find(i), shells.size());
        if (inserted) shells.emplace_back();
        shells[it->second].push_back(i);
    }
    return shells;
}

std::string describe_shell(const std::vector<std::size_t>& shell) {
    return "the shell of face " + std::to_string(shell.front()) + " (" + std::to_string(shell.size()) + " face" +
           (shell.size() == 1 ? "" : "s") + ")";
}

}  // namespace

Solid::Solid(std::vector<Face> faces, Construction construction) : construction_(std::move(construction)) {
    require(!faces.empty(), "faces", "a solid needs at least one face");
    // Closure: count the uses of every edge in each direction, in first-seen order for the messages.
    std::map<const Edge*, std::pair<int, int>> uses;
    std::vector<const Edge*> order;
    for_each_coedge(faces, [&](const Coedge& c) {
        auto [it, inserted] = uses.try_emplace(c.edge.get(), 0, 0);
        if (inserted) order.push_back(c.edge.get());
        (c.reversed ? it->second.second : it->second.first) += 1;
    });
    for (std::size_t k = 0; k < order.size(); ++k) {
        const Edge* edge = order[k];
        if (edge->degenerate) continue;
        const auto [forward, backward] = uses[edge];
        require(forward == 1 && backward == 1, "faces",
                "edge " + std::to_string(k) + " (from " + detail::format_point(edge->start->point) + ") is used " +
                    std::to_string(forward) + " time(s) forward and " + std::to_string(backward) +
                    " time(s) reversed; a closed shell uses every edge once in each direction");
    }
    // A solid too large or too small to measure (limits.hpp) would fail the check below for the wrong reason.
    Box box;
    for (const Face& face : faces) box.add(face.surface().control_box());
    detail::require_solid_scale(box.diagonal(), detail::reach_of(box), "faces", "faces", detail::largest_box_diagonal);
    // Coherent edge directions make each shell consistently oriented; the sign of the volume it encloses
    // tells outward from inward: positive for the outer shell, negative for a void (its normals point into it).
    std::vector<std::vector<std::size_t>> shells = connected_shells(faces);
    std::vector<double> volumes;
    std::vector<Box> boxes;
    for (const auto& shell : shells) {
        std::vector<Face> shell_faces;
        Box shell_box;
        for (std::size_t i : shell) {
            shell_faces.push_back(faces[i]);
            shell_box.add(faces[i].surface().control_box());
        }
        const std::vector<Face>& measured = shells.size() == 1 ? faces : shell_faces;
        double volume = detail::faces_volume(measured, "faces", /*quick=*/true);
        // The quick rule's sign holds for a shell of some bulk. A shell that encloses next to nothing for its size
        // is measured properly: a fuzzed sphere with one control point at 1e100 is a needle that long, which the
        // quick rule called positive and the adaptive rule -2.9e99 (a shell folded through itself).
        const double size = shell_box.diagonal();
        if (!(std::abs(volume) >= kQuickVolumeShare * size * size * size)) volume = detail::faces_volume(measured, "faces");
        volumes.push_back(volume);
        boxes.push_back(shell_box);
    }
    const auto outer = static_cast<std::size_t>(std::max_element(volumes.begin(), volumes.end()) - volumes.begin());
    require(volumes[outer] > 0, "faces",
            shells.size() == 1 ? "the shell is oriented inward (its enclosed volume is negative); normals must point out of the solid"
                               : "every shell is oriented inward (encloses a negative volume); the outer shell's normals must point out of the solid");
    for (std::size_t k = 0; k < shells.size(); ++k) {
        if (k == outer) continue;
        require(volumes[k] < 0, "faces", [&] {
            return describe_shell(shells[k]) + " encloses a positive volume beside " + describe_shell(shells[outer]) +
                   ": a Solid has one outer shell, any others are voids inside it with their normals pointing into the void";
        });
        // A void's edges lie inside the outer shell's control box (which holds the outer shell), within its faces'
        // tolerances. Its own control box need not: a plane patch spans its loops' rectangle, a trimmed face its
        // surface, and a void that touches the skin (at a vertex of both, as in pythonocc's 11752.stp) reaches
        // past the skin with them. Its edges at 9 points each: a void sphere's vertices are its two poles only.
        Box inner;
        double tolerance = 0;
        for (std::size_t i : shells[k]) {
            ratbez::for_each_coedge(faces[i], [&](const Coedge& c) {
                const Interval d = c.edge->curve.domain();
                for (int j = 0; j <= 8; ++j) inner.add(c.edge->curve.point(std::min(d.max, d.min + d.width() * j / 8)));
            });
            tolerance = std::max(tolerance, faces[i].tolerance());
        }
        const double slack = tolerance + 1e-9 * boxes[k].diagonal();
        const Box& hull = boxes[outer];
        require(inner.min.x >= hull.min.x - slack && inner.min.y >= hull.min.y - slack && inner.min.z >= hull.min.z - slack &&
                    inner.max.x <= hull.max.x + slack && inner.max.y <= hull.max.y + slack && inner.max.z <= hull.max.z + slack,
                "faces", [&] { return describe_shell(shells[k]) + " is a void but lies outside the outer shell's box"; });
    }
    std::rotate(shells.begin(), shells.begin() + static_cast<std::ptrdiff_t>(outer), shells.begin() + static_cast<std::ptrdiff_t>(outer) + 1);
    shells_ = std::move(shells);
    faces_ = std::move(faces);
}

std::vector<EdgePtr> distinct_edges(std::span<const Face> faces) {
    std::vector<EdgePtr> result;
    std::set<const Edge*> seen;
    for_each_coedge(faces, [&](const Coedge& c) {
        if (seen.insert(c.edge.get()).second) result.push_back(c.edge);
    });
    return result;
}

// The measures of properties.hpp (brep/properties.cpp).
double Solid::area() const { return surface_area(*this); }
double Solid::volume() const { return enclosed_volume(*this); }

std::vector<EdgePtr> Solid::edges() const { return distinct_edges(faces_); }

std::vector<VertexPtr> Solid::vertices() const {
    std::vector<VertexPtr> result;
    std::set<const Vertex*> seen;
    for (const EdgePtr& edge : edges())
        for (const VertexPtr& v : {edge->start, edge->end})
            if (seen.insert(v.get()).second) result.push_back(v);
    return result;
}

int Solid::euler_characteristic() const {
    const std::vector<EdgePtr> all = edges();
    const auto proper = std::count_if(all.begin(), all.end(), [](const EdgePtr& e) { return !e->degenerate; });
    // A face with holes is not a disc: each hole loop (a ring) lowers V - E + F by one (the Euler-Poincaré
    // formula V - E + F - R = 2 (S - G) with R rings), so the rings are subtracted to keep 2 - 2 genus.
    std::size_t rings = 0;
    for (const Face& face : faces_)
        if (face.kind() != Face::Kind::surface) rings += face.loops().size() - 1;
    return static_cast<int>(vertices().size()) - static_cast<int>(proper) + static_cast<int>(faces_.size()) -
           static_cast<int>(rings);
}

Box Solid::bounding_box() const {
    Box box;
    for (const Face& face : faces_) {
        if (face.kind() != Face::Kind::planar) {
            box.add(face.surface().control_box());
        } else {
            // The plane patch spans the loops' rectangle; the loops themselves bound the face tighter.
            for (const auto& loop : face.loops())
                for (const Coedge& c : loop) box.add(c.edge->curve.control_box());
        }
    }
    return box;
}

}  // namespace ratbez
