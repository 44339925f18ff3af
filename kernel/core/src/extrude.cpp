// The translational sweep of 004 §1.5 (Figure 24): S(u, v) = C(u) + v D. Translating the control
// points of C by D gives the second row of a degree (p, 1) tensor-product net with the same weights,
// which is exact for every rational C (P1.14: translations act on the control points).
#include "ratbez/extrude.hpp"

#include <cmath>
#include <string>

#include "planar_profile.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"
#include "tube_shell.hpp"

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

NurbsSurface extrude_surface(const NurbsCurve& curve, const Vec3& direction, double distance) {
    const Vec3 unit = frame_from_axis({}, direction, "direction").z_axis;
    require_finite(distance, "distance");
    require(distance > 0, "distance", "must be greater than 0");
    return extrude_surface(curve, unit * distance);
}

Solid extrude(const Profile& profile, const Vec3& direction, double distance) {
    const Vec3 unit = frame_from_axis({}, direction, "direction").z_axis;
    require_finite(distance, "distance");
    require(distance > 0, "distance", "must be greater than 0");
    require(profile.is_closed(), "profile", "must be closed to bound the caps of an extrusion");
    const detail::PlanarProfile planar = detail::analyse_planar_profile(profile);
    const double cosine = dot(unit, planar.normal);
    require(std::abs(cosine) > 1e-9, "direction", "must not be parallel to the profile's plane");

    // Outward lateral faces need the profile counterclockwise about the side the sweep goes to: then
    // S_u x S_v = C' x D points away from the enclosed region.
    const Profile oriented = cosine > 0 ? profile : profile.reversed();
    const Vec3 normal = cosine > 0 ? planar.normal : -planar.normal;
    const Vec3 displacement = unit * distance;
    std::vector<NurbsSurface> surfaces;
    for (const NurbsCurve& piece : oriented.pieces()) surfaces.push_back(extrude_surface(piece, displacement));
    // Bottom cap: outward normal -n, the profile backwards; top cap: normal n, the profile forwards.
    return detail::tube_solid(surfaces, detail::CapNormals{-normal, normal});
}

}  // namespace ratbez
