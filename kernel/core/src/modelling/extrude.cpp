// The translational sweep of 004 §1.5 (Figure 24): S(u, v) = C(u) + v D. Translating the control
// points of C by D gives the second row of a degree (p, 1) tensor-product net with the same weights,
// which is exact for every rational C (P1.14: translations act on the control points).
#include "ratbez/extrude.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "math/solid_scale.hpp"
#include "modelling/planar_profile.hpp"
#include "modelling/profile_crossings.hpp"
#include "modelling/tube_shell.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

namespace {

// The scale rule (limits.hpp): the profile's size and the distance both set the solid's size.
void require_scale(const Profile& profile, double distance) {
    Box box;
    for (const NurbsCurve& piece : profile.pieces()) box.add(piece.control_box());
    const double reach = detail::reach_of(box) + distance;
    const bool distance_sets_size = distance > profile.size();
    detail::require_solid_scale(std::max(profile.size(), distance), reach, distance_sets_size ? "distance" : "profile",
                                "profile", distance_sets_size ? limits::max_solid_coordinate : detail::largest_box_diagonal);
    // A unit square extruded by 1e9 (or by 1e-12) has faces of sides 1 and 1e9: the short side was taken
    // for a collapsed point ("sides" named).
    detail::require_feature(distance, profile.size(), "distance", "an extrusion distance");
    detail::require_feature_ratio(distance, profile.size(), "distance", "the profile's size");
}

}  // namespace

NurbsSurface extrude_surface(const NurbsCurve& curve, const Vec3& displacement) {
    require(is_finite(displacement), "displacement", "must have finite coordinates");
    // Not norm(): a displacement of 1e-300 squares to 0.
    require(displacement.x != 0 || displacement.y != 0 || displacement.z != 0, "displacement", "must be a non-zero vector");
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

Solid extrude(const Profile& profile, const Vec3& direction, double distance, const std::vector<Profile>& holes) {
    const Vec3 unit = frame_from_axis({}, direction, "direction").z_axis;
    require_finite(distance, "distance");
    require(distance > 0, "distance", "must be greater than 0");
    require(profile.is_closed(), "profile", "must be closed to bound the caps of an extrusion");
    require_scale(profile, distance);
    const detail::PlanarProfile outer = detail::analyse_planar_profile(profile);
    const Vec3 reference = outer.reference;
    Vec3 normal = outer.normal;
    const double tol = profile.tolerance();
    const double size = profile.size();
    const Frame plane = frame_from_axis(reference, normal);
    for (std::size_t h = 0; h < holes.size(); ++h) {
        const std::string name = "holes[" + std::to_string(h) + "]";
        require(holes[h].is_closed(), name, "must be closed");
        detail::require_in_plane(holes[h], reference, normal, tol, name);
        require(norm(detail::area_vector(holes[h], holes[h].start_point(), name)) > 1e-12 * size * size, name,
                "encloses no area");
    }
    if (!holes.empty()) {
        // analyse_planar_profile has checked the profile alone; now no loop may cross or touch another.
        std::vector<Profile> all_loops{profile};
        all_loops.insert(all_loops.end(), holes.begin(), holes.end());
        detail::require_no_crossings(all_loops, reference, plane.x_axis, plane.y_axis);
    }
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
        const bool is = dot(detail::area_vector(loop, loop.start_point(), "holes"), normal) > 0;
        return is == want ? loop : loop.reversed();
    };
    const Vec3 displacement = unit * distance;
    const auto lateral = [&](const Profile& loop) {
        std::vector<NurbsSurface> surfaces;
        for (const NurbsCurve& piece : loop.pieces()) surfaces.push_back(extrude_surface(piece, displacement));
        return surfaces;
    };
    std::vector<std::vector<NurbsSurface>> loops{lateral(counterclockwise(profile, true))};
    for (const Profile& hole : holes) loops.push_back(lateral(counterclockwise(hole, false)));
    // Bottom cap: outward normal -n; top cap: normal n.
    return detail::tube_solid(loops, detail::CapNormals{-normal, normal}, Construction::Extrusion{unit, distance});
}

}  // namespace ratbez
