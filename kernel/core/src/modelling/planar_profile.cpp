// The checks and measurements of a closed planar profile; see planar_profile.hpp.
#include "modelling/planar_profile.hpp"

#include <cmath>

#include "analysis/cubature.hpp"
#include "math/numeric_internal.hpp"
#include "modelling/profile_crossings.hpp"
#include "ratbez/error.hpp"
#include "ratbez/frame.hpp"

namespace ratbez::detail {

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
            component += green_area(piece, reference, x, y, 1e-15 * size * size, argument);
        (a == 0 ? result.x : a == 1 ? result.y : result.z) = component;
    }
    return result;
}

void require_in_plane(const Profile& profile, const Vec3& reference, const Vec3& normal, double tol,
                      const std::string& argument) {
    for (const NurbsCurve& piece : profile.pieces())
        for (const Vec4& pw : piece.homogeneous_points()) {
            const double off = std::abs(dot(project(pw) - reference, normal));
            require(off <= tol, argument,
                    [&] { return "must be planar (a control point is " + number(off) + " off the profile's plane)"; });
        }
}

PlanarProfile analyse_planar_profile(const Profile& profile, const std::string& argument) {
    require(profile.is_closed(), argument, "must be closed to bound a planar cap");
    const double size = profile.size();
    const Vec3 reference = profile.start_point();
    const Vec3 area = area_vector(profile, reference, argument);
    require(std::isfinite(norm(area)), argument, "is too large: its area overflows double precision");
    require(norm(area) > 1e-12 * size * size, argument, "encloses no area");
    const Vec3 normal = area / norm(area);
    require_in_plane(profile, reference, normal, profile.tolerance(), argument);
    const Frame plane = frame_from_axis(reference, normal);
    try {
        require_no_crossings(profile, reference, plane.x_axis, plane.y_axis);
    } catch (const Error& e) {
        // The crossing test names its argument "profile"; say which profile it was.
        throw e.renamed("profile", argument);
    }
    return PlanarProfile{reference, normal, norm(area)};
}

}  // namespace ratbez::detail
