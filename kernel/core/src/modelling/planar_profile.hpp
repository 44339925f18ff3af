#pragma once
// What the solids with planar caps (extrude, loft, sweep) need to know about a closed profile: that it is
// planar and simple, the normal about which it runs counterclockwise, and the area it encloses. Defined in
// planar_profile.cpp. Not installed, not part of the public API.

#include <string>

#include "ratbez/profile.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

struct PlanarProfile {
    Vec3 reference;  // the profile's start point, a point of its plane
    Vec3 normal;     // unit; the profile runs counterclockwise seen from its tip
    double area = 0; // enclosed area, > 0
};

// The area vector (1/2) ∮ (C - reference) x C' dt of a closed profile: its direction is the normal of the
// plane about which the profile runs counterclockwise, its length the enclosed area (Green's theorem in
// each coordinate plane). Errors name `argument`.
Vec3 area_vector(const Profile& profile, const Vec3& reference, const std::string& argument);

// Throws Error naming `argument` unless every control point lies within `tol` of the plane through
// `reference` with unit `normal` (so, by the convex hull property, the whole profile does).
void require_in_plane(const Profile& profile, const Vec3& reference, const Vec3& normal, double tol,
                      const std::string& argument);

// Throws Error naming `argument` unless the profile is closed, encloses an area (> 1e-12 size^2), has
// every control point within profile.tolerance() of one plane and does not cross or touch itself
// (require_no_crossings).
PlanarProfile analyse_planar_profile(const Profile& profile, const std::string& argument = "profile");

}  // namespace ratbez::detail
