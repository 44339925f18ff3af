// The translational sweep of 004 §1.5 (Figure 24): S(u, v) = C(u) + v D. Translating the control
// points of C by D gives the second row of a degree (p, 1) tensor-product net with the same weights,
// which is exact for every rational C (P1.14: translations act on the control points).
#include "ratbez/extrude.hpp"

#include <cmath>
#include <string>

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

Solid extrude(const Profile& profile, const Vec3& direction, double distance) {
    const Vec3 unit = frame_from_axis({}, direction, "direction").z_axis;
    require_finite(distance, "distance");
    require(distance > 0, "distance", "must be greater than 0");
    require(profile.is_closed(), "profile", "must be closed to bound the caps of an extrusion");
    const double tol = profile.tolerance();
    const double size = profile.size();

    // The profile's area vector (1/2) ∮ (C - C0) x C' dt: its direction is the plane's normal about
    // which the profile runs counterclockwise, its length the enclosed area.
    const Vec3 reference = profile.start_point();
    Vec3 area_vector{};
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a) {
        // Component a of the area vector is Green's integral in the coordinate plane normal to axes[a].
        const Vec3& x = axes[(a + 1) % 3];
        const Vec3& y = axes[(a + 2) % 3];
        double component = 0;
        for (const NurbsCurve& piece : profile.pieces())
            component += detail::green_area(piece, reference, x, y, 1e-15 * size * size, "profile");
        (a == 0 ? area_vector.x : a == 1 ? area_vector.y : area_vector.z) = component;
    }
    require(norm(area_vector) > 1e-12 * size * size, "profile", "encloses no area");
    Vec3 normal = area_vector / norm(area_vector);
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points())
            require(std::abs(dot(project(pw) - reference, normal)) <= tol, "profile",
                    "must be planar (a control point is " +
                        std::to_string(std::abs(dot(project(pw) - reference, normal))) + " off the profile's plane)");
    const Frame plane = frame_from_axis(reference, normal);
    detail::require_no_crossings(profile, reference, plane.x_axis, plane.y_axis);
    const double cosine = dot(unit, normal);
    require(std::abs(cosine) > 1e-9, "direction", "must not be parallel to the profile's plane");

    // Outward lateral faces need the profile counterclockwise about the side the sweep goes to: then
    // S_u x S_v = C' x D points away from the enclosed region.
    const Profile oriented = cosine > 0 ? profile : profile.reversed();
    if (cosine < 0) normal = -normal;
    const Vec3 displacement = unit * distance;
    const std::vector<NurbsCurve>& pieces = oriented.pieces();
    const std::size_t m = pieces.size();

    std::vector<NurbsSurface> surfaces;
    for (const NurbsCurve& piece : pieces) surfaces.push_back(extrude_surface(piece, displacement));
    std::vector<VertexPtr> bottom_vertices, top_vertices;
    for (std::size_t k = 0; k < m; ++k) {
        const Vec3 corner = project(surfaces[k].homogeneous_point(0, 0));
        bottom_vertices.push_back(detail::make_vertex(corner));
        top_vertices.push_back(detail::make_vertex(project(surfaces[k].homogeneous_point(0, 1))));
    }
    std::vector<EdgePtr> bottom_edges, top_edges, vertical_edges;
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t next = (k + 1) % m;
        bottom_edges.push_back(detail::make_edge(surfaces[k].isocurve_v(0.0), bottom_vertices[k], bottom_vertices[next]));
        top_edges.push_back(detail::make_edge(surfaces[k].isocurve_v(1.0), top_vertices[k], top_vertices[next]));
        vertical_edges.push_back(
            detail::make_edge(surfaces[k].isocurve_u(surfaces[k].domain_u().min), bottom_vertices[k], top_vertices[k]));
    }
    std::vector<Face> faces;
    for (std::size_t k = 0; k < m; ++k)
        faces.push_back(Face::from_surface(surfaces[k], {Coedge{bottom_edges[k], false}, Coedge{vertical_edges[(k + 1) % m], false},
                                                         Coedge{top_edges[k], true}, Coedge{vertical_edges[k], true}}));
    // Bottom cap: outward normal -n, the profile backwards; top cap: normal n, the profile forwards.
    std::vector<Coedge> bottom_loop, top_loop;
    for (std::size_t k = m; k-- > 0;) bottom_loop.push_back(Coedge{bottom_edges[k], true});
    for (std::size_t k = 0; k < m; ++k) top_loop.push_back(Coedge{top_edges[k], false});
    const Frame bottom_frame = frame_from_axis(reference, -normal);
    const Frame top_frame = frame_from_axis(reference + displacement, normal);
    faces.push_back(Face::planar(Plane{bottom_frame.origin, bottom_frame.x_axis, bottom_frame.y_axis, bottom_frame.z_axis},
                                 {bottom_loop}));
    faces.push_back(Face::planar(Plane{top_frame.origin, top_frame.x_axis, top_frame.y_axis, top_frame.z_axis}, {top_loop}));
    return Solid(std::move(faces), Construction::Extrusion{unit, distance});
}

}  // namespace ratbez
