// Cylinder, cone, sphere and torus as exact rational B-reps, built in the frame of their axis
// (frame_from_axis) by revolving one exact profile piece (004 §1.5; the lateral patch of the cylinder is
// Ex1.15's cylindrical surface, four of them around).
#include "ratbez/primitives.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>

#include "geometry/arcs.hpp"
#include "math/degrees.hpp"
#include "math/numeric_internal.hpp"
#include "math/solid_scale.hpp"
#include "modelling/revolve_internal.hpp"
#include "ratbez/curves.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez {

namespace {

void require_positive(double value, const std::string& argument) {
    require_finite(value, argument);
    require(value > 0, argument, "must be greater than 0");
}

Frame placed_frame(const Vec3& center, const Vec3& axis) {
    require(is_finite(center), "center", "must have finite coordinates");
    return frame_from_axis(center, axis, "axis");
}

// The scale rule (limits.hpp) for a primitive of size `size` (set by `size_argument`) about `center`.
void require_scale(double size, const Vec3& center, std::string_view size_argument) {
    require(is_finite(center), "center", "must have finite coordinates");
    const double reach = std::max({std::abs(center.x), std::abs(center.y), std::abs(center.z)}) + size;
    detail::require_solid_scale(size, reach, size_argument, "center");
}

// The Solid of a primitive whose size passed require_scale. The Solid checks the scale again on the box of
// its control points (up to about 3.5x the radius for a sphere): a primitive just under the limit by its
// radius can exceed it there, and that Error ("faces: gives a solid of size ...") is about the primitive's
// size argument.
template <class Build>
Solid scaled_solid(std::string_view size_argument, Build build) {
    try {
        return build();
    } catch (const Error& e) {
        if (e.argument() == "faces" && e.reason().starts_with("gives a solid")) throw Error(size_argument, e.reason());
        throw;
    }
}

// The meridian frame of a primitive: x radial (the seam direction), y along the axis. A profile drawn
// counterclockwise in it runs counterclockwise in (ρ, h), which makes the revolved faces outward.
Frame meridian_frame(const Frame& frame, const Vec3& origin) {
    return Frame{origin, frame.x_axis, frame.z_axis, cross(frame.x_axis, frame.z_axis)};
}

// The lateral face of a cylinder or cone (the segment from radius r1 at the base to r2 at height h,
// revolved), and planar caps where the radius is not zero; a zero radius is an apex (degenerate edge).
Solid conical_solid(const Frame& frame, double radius1, double radius2, double height, Construction construction) {
    const Vec3 bottom = frame.origin + frame.x_axis * radius1;
    const Vec3 top = frame.origin + frame.z_axis * height + frame.x_axis * radius2;
    detail::RevolutionShell shell =
        detail::build_revolution({line_segment(bottom, top)}, false, frame.origin, frame.z_axis, 360.0);
    std::vector<Face> faces = std::move(shell.faces);
    if (radius1 > 0)  // the bottom circle runs counterclockwise about the axis: clockwise seen from below
        faces.push_back(Face::planar(Plane{frame.origin, frame.x_axis, -frame.y_axis, -frame.z_axis},
                                     {{Coedge{shell.joint_edges[0], true}}}));
    if (radius2 > 0)
        faces.push_back(Face::planar(Plane{frame.origin + frame.z_axis * height, frame.x_axis, frame.y_axis, frame.z_axis},
                                     {{Coedge{shell.joint_edges[1], false}}}));
    return Solid(std::move(faces), std::move(construction));
}

}  // namespace

Solid cylinder(double radius, double height, const Vec3& center, const Vec3& axis) {
    require_positive(radius, "radius");
    require_positive(height, "height");
    const std::string_view larger = radius >= height ? "radius" : "height";
    require_scale(std::max(radius, height), center, larger);
    detail::require_feature(radius, height, "radius", "a radius");
    detail::require_feature(height, radius, "height", "a height");
    const Frame frame = placed_frame(center, axis);
    return scaled_solid(larger, [&] {
        return conical_solid(frame, radius, radius, height, Construction::Cylinder{center, frame.z_axis, radius, height});
    });
}

Solid cone(double radius1, double radius2, double height, const Vec3& center, const Vec3& axis) {
    require_finite(radius1, "radius1");
    require_finite(radius2, "radius2");
    require(radius1 >= 0, "radius1", "must be at least 0 (0 puts the apex at the base)");
    require(radius2 >= 0, "radius2", "must be at least 0 (0 puts the apex at the top)");
    require(radius1 > 0 || radius2 > 0, "radius1", "radius1 and radius2 cannot both be 0");
    require_positive(height, "height");
    const double radius = std::max(radius1, radius2);
    const std::string_view larger = radius < height ? "height" : radius1 >= radius2 ? "radius1" : "radius2";
    require_scale(std::max(radius, height), center, larger);
    // A radius is 0 (an apex) or a feature of the cone: cone(1, 1e-12, 1)'s top circle is no circle.
    const double size = std::max(radius, height);
    if (radius1 > 0) detail::require_feature(radius1, size, "radius1", "a radius (0 makes an apex)");
    if (radius2 > 0) detail::require_feature(radius2, size, "radius2", "a radius (0 makes an apex)");
    detail::require_feature(height, size, "height", "a height");
    const Frame frame = placed_frame(center, axis);
    return scaled_solid(larger, [&] {
        return conical_solid(frame, radius1, radius2, height, Construction::Cone{center, frame.z_axis, radius1, radius2, height});
    });
}

Solid sphere(double radius, const Vec3& center) {
    require_positive(radius, "radius");
    require_scale(radius, center, "radius");
    const Frame frame = placed_frame(center, {0, 0, 1});
    return scaled_solid("radius", [&] {
        // The meridian semicircle from the south pole through the seam (+x) to the north pole: two rational
        // quarter circles; its ends lie exactly on the axis (cos_deg(±90) == 0), so the poles are exact.
        const NurbsCurve semicircle = detail::arc_in_frame(meridian_frame(frame, center), radius, radius, -90.0, 180.0);
        detail::RevolutionShell shell = detail::build_revolution({semicircle}, false, center, frame.z_axis, 360.0);
        return Solid(std::move(shell.faces), Construction::Sphere{center, radius});
    });
}

Solid torus(double major_radius, double minor_radius, const Vec3& center, const Vec3& axis) {
    require_positive(major_radius, "major_radius");
    require_positive(minor_radius, "minor_radius");
    require(minor_radius < major_radius, "minor_radius", "must be less than major_radius (else the tube meets the axis)");
    require_scale(major_radius, center, "major_radius");
    require_scale(minor_radius, center, "minor_radius");
    detail::require_feature(minor_radius, major_radius, "minor_radius", "a tube radius");
    // The hole at the axis: its equator circle (radius major - minor) is a side of the torus's face.
    detail::require_feature(major_radius - minor_radius, major_radius, "minor_radius",
                            "a hole at the axis (major_radius - minor_radius)");
    const Frame frame = placed_frame(center, axis);
    return scaled_solid("major_radius", [&] {
        // The tube's circle in the meridian plane, starting at its outer equator; revolved it gives one face
        // whose two seams are that circle (u = 0 and u = 1) and the outer equator (v = 0 and v = 1).
        const NurbsCurve tube = detail::arc_in_frame(meridian_frame(frame, center + frame.x_axis * major_radius),
                                                     minor_radius, minor_radius, 0.0, 360.0);
        detail::RevolutionShell shell = detail::build_revolution({tube}, true, center, frame.z_axis, 360.0);
        return Solid(std::move(shell.faces), Construction::Torus{center, frame.z_axis, major_radius, minor_radius});
    });
}

}  // namespace ratbez
