// The translational sweep of 004 §1.5 (Figure 24): S(u, v) = C(u) + v D. Translating the control
// points of C by D gives the second row of a degree (p, 1) tensor-product net with the same weights,
// which is exact for every rational C (P1.14: translations act on the control points).
#include "ratbez/extrude.hpp"

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "cubature.hpp"
#include "geometry_internal.hpp"
#include "profile_crossings.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

NurbsSurface extrude_surface(const NurbsCurve& curve, const Vec3& displacement) {
    require(is_finite(displacement), "displacement", "must have finite coordinates");
    require(norm(displacement) > 0, "displacement", "must be a non-zero vector");
    const std::vector<Vec4>& points = curve.homogeneous_points();
    std::vector<Vec4> net;
    net.reserve(points.size() * 2);
    for (const Vec4& p : points) {
        net.push_back(p);
        net.push_back(homogenize(project(p) + displacement, p.w));
    }
    return NurbsSurface::from_homogeneous(curve.degree(), 1, curve.knots(), {0.0, 0.0, 1.0, 1.0}, std::move(net),
                                          curve.is_rational());
}

namespace {

// The area vector (1/2) ∮ (C - reference) x C' dt of a closed profile: its direction is the normal of the
// plane about which the profile runs counterclockwise, its length the enclosed area.
Vec3 area_vector(const Profile& profile, const Vec3& reference, const std::string& argument) {
    const double size = profile.size();
    Vec3 result{};
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a) {
        // Component a of the area vector is Green's integral in the coordinate plane normal to axes[a].
        const Vec3& x = axes[(a + 1) % 3];
        const Vec3& y = axes[(a + 2) % 3];
        double component = 0;
        for (const NurbsCurve& piece : profile.pieces())
            component += detail::green_area(piece, reference, x, y, 1e-15 * size * size, argument);
        (a == 0 ? result.x : a == 1 ? result.y : result.z) = component;
    }
    return result;
}

void require_in_plane(const Profile& profile, const Vec3& reference, const Vec3& normal, double tol,
                      const std::string& argument) {
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points()) {
            const double off = std::abs(dot(project(pw) - reference, normal));
            require(off <= tol, argument, [&] {
                return "must be planar (a control point is " + std::to_string(off) + " off the profile's plane)";
            });
        }
}

// The side faces of one loop, running counterclockwise about the sweep for the outer loop and clockwise for
// a hole, so that S_u x S_v = C' x D points out of the solid; and the loop's edges at both ends.
struct SweptLoop {
    std::vector<Face> faces;
    std::vector<EdgePtr> bottom, top;
};

SweptLoop sweep_loop(const Profile& oriented, const Vec3& displacement) {
    const std::vector<NurbsCurve>& pieces = oriented.pieces();
    const std::size_t m = pieces.size();
    std::vector<NurbsSurface> surfaces;
    for (const NurbsCurve& piece : pieces) surfaces.push_back(extrude_surface(piece, displacement));
    std::vector<VertexPtr> bottom_vertices, top_vertices;
    for (std::size_t k = 0; k < m; ++k) {
        bottom_vertices.push_back(detail::make_vertex(project(surfaces[k].homogeneous_point(0, 0))));
        top_vertices.push_back(detail::make_vertex(project(surfaces[k].homogeneous_point(0, 1))));
    }
    SweptLoop out;
    std::vector<EdgePtr> vertical;
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t next = (k + 1) % m;
        out.bottom.push_back(detail::make_edge(surfaces[k].isocurve_v(0.0), bottom_vertices[k], bottom_vertices[next]));
        out.top.push_back(detail::make_edge(surfaces[k].isocurve_v(1.0), top_vertices[k], top_vertices[next]));
        vertical.push_back(
            detail::make_edge(surfaces[k].isocurve_u(surfaces[k].domain_u().min), bottom_vertices[k], top_vertices[k]));
    }
    for (std::size_t k = 0; k < m; ++k)
        out.faces.push_back(Face::from_surface(surfaces[k], {Coedge{out.bottom[k], false}, Coedge{vertical[(k + 1) % m], false},
                                                             Coedge{out.top[k], true}, Coedge{vertical[k], true}}));
    return out;
}

}  // namespace

Solid extrude(const Profile& profile, const Vec3& direction, double distance, const std::vector<Profile>& holes) {
    const Vec3 unit = frame_from_axis({}, direction, "direction").z_axis;
    require_finite(distance, "distance");
    require(distance > 0, "distance", "must be greater than 0");
    require(profile.is_closed(), "profile", "must be closed to bound the caps of an extrusion");
    const double tol = profile.tolerance();
    const double size = profile.size();

    const Vec3 reference = profile.start_point();
    const Vec3 outer_area = area_vector(profile, reference, "profile");
    require(norm(outer_area) > 1e-12 * size * size, "profile", "encloses no area");
    Vec3 normal = outer_area / norm(outer_area);
    require_in_plane(profile, reference, normal, tol, "profile");
    const Frame plane = frame_from_axis(reference, normal);
    for (std::size_t h = 0; h < holes.size(); ++h) {
        const std::string name = "holes[" + std::to_string(h) + "]";
        require(holes[h].is_closed(), name, "must be closed");
        require_in_plane(holes[h], reference, normal, tol, name);
        require(norm(area_vector(holes[h], holes[h].start_point(), name)) > 1e-12 * size * size, name, "encloses no area");
    }
    std::vector<Profile> loops{profile};
    loops.insert(loops.end(), holes.begin(), holes.end());
    detail::require_no_crossings(loops, reference, plane.x_axis, plane.y_axis);
    // Loops that do not touch are nested or apart as one point of each says.
    for (std::size_t h = 0; h < holes.size(); ++h) {
        const std::string name = "holes[" + std::to_string(h) + "]";
        const Vec3 point = holes[h].start_point();
        require(detail::winding_number(profile, point, reference, plane.x_axis, plane.y_axis, "holes") != 0, name,
                "must lie inside the profile");
        for (std::size_t g = 0; g < holes.size(); ++g)
            require(g == h || detail::winding_number(holes[g], point, reference, plane.x_axis, plane.y_axis, "holes") == 0,
                    name, [&] { return "lies inside holes[" + std::to_string(g) + "]; holes must not nest"; });
    }
    const double cosine = dot(unit, normal);
    require(std::abs(cosine) > 1e-9, "direction", "must not be parallel to the profile's plane");

    // Outward lateral faces need the profile counterclockwise about the side the sweep goes to (then
    // S_u x S_v = C' x D points away from the enclosed region) and every hole clockwise.
    if (cosine < 0) normal = -normal;
    const auto counterclockwise = [&](const Profile& loop, bool want) {
        const bool is = dot(area_vector(loop, loop.start_point(), "holes"), normal) > 0;
        return is == want ? loop : loop.reversed();
    };
    const Vec3 displacement = unit * distance;
    std::vector<SweptLoop> swept{sweep_loop(counterclockwise(profile, true), displacement)};
    for (const Profile& hole : holes) swept.push_back(sweep_loop(counterclockwise(hole, false), displacement));

    std::vector<Face> faces;
    for (SweptLoop& loop : swept) std::move(loop.faces.begin(), loop.faces.end(), std::back_inserter(faces));
    // Bottom cap: outward normal -n, every loop backwards; top cap: normal n, every loop forwards. The outer
    // loop comes first in both, as Face::planar wants.
    std::vector<std::vector<Coedge>> bottom_loops, top_loops;
    for (const SweptLoop& loop : swept) {
        auto& bottom = bottom_loops.emplace_back();
        auto& top = top_loops.emplace_back();
        for (std::size_t k = loop.bottom.size(); k-- > 0;) bottom.push_back(Coedge{loop.bottom[k], true});
        for (const EdgePtr& edge : loop.top) top.push_back(Coedge{edge, false});
    }
    const Frame bottom_frame = frame_from_axis(reference, -normal);
    const Frame top_frame = frame_from_axis(reference + displacement, normal);
    faces.push_back(Face::planar(Plane{bottom_frame.origin, bottom_frame.x_axis, bottom_frame.y_axis, bottom_frame.z_axis},
                                 std::move(bottom_loops)));
    faces.push_back(
        Face::planar(Plane{top_frame.origin, top_frame.x_axis, top_frame.y_axis, top_frame.z_axis}, std::move(top_loops)));
    return Solid(std::move(faces), Construction::Extrusion{unit, distance});
}

}  // namespace ratbez
