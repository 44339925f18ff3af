// The checks and measurements of a closed planar profile; see planar_profile.hpp.
#include "planar_profile.hpp"

#include <cmath>

#include "cubature.hpp"
#include "numeric_internal.hpp"
#include "profile_crossings.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez::detail {

PlanarProfile analyse_planar_profile(const Profile& profile, const std::string& argument) {
    require(profile.is_closed(), argument, "must be closed to bound a planar cap");
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
            component += green_area(piece, reference, x, y, 1e-15 * size * size, argument);
        (a == 0 ? area_vector.x : a == 1 ? area_vector.y : area_vector.z) = component;
    }
    require(std::isfinite(norm(area_vector)), argument, "is too large: its area overflows double precision");
    require(norm(area_vector) > 1e-12 * size * size, argument, "encloses no area");
    const Vec3 normal = area_vector / norm(area_vector);
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points())
            require(std::abs(dot(project(pw) - reference, normal)) <= tol, argument, [&] {
                return "must be planar (a control point is " + number(std::abs(dot(project(pw) - reference, normal))) +
                       " off the profile's plane)";
            });
    const Frame plane = frame_from_axis(reference, normal);
    try {
        require_no_crossings(profile, reference, plane.x_axis, plane.y_axis);
    } catch (const Error& e) {
        // The crossing test names its argument "profile"; say which profile it was.
        const std::string message = e.what();
        const std::string prefix = "profile: ";
        if (argument == "profile" || message.rfind(prefix, 0) != 0) throw;
        throw Error(argument + ": " + message.substr(prefix.size()));
    }
    return PlanarProfile{reference, normal, norm(area_vector)};
}

}  // namespace ratbez::detail
