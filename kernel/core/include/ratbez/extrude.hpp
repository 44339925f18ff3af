#pragma once
// The translational sweep of 004 §1.5: S(u, v) = C(u) + v * d, v in [0, 1].

#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/profile.hpp"

namespace ratbez {

// Any curve, open or closed: u runs along the curve (its own domain), v over [0, 1].
NurbsSurface extrude_surface(const NurbsCurve& curve, const Vec3& displacement);
// The same with displacement = distance * direction / |direction| (distance > 0, direction non-zero).
NurbsSurface extrude_surface(const NurbsCurve& curve, const Vec3& direction, double distance);

// A closed planar profile swept by distance along direction (not parallel to the profile's plane):
// one lateral face per piece and two planar caps. The profile must not cross or touch itself (within
// profile.tolerance()) away from the joints of its pieces, nor turn back at a joint.
// Holes: closed profiles in the profile's plane, each inside it and outside the others, none touching
// another loop; each adds one lateral face per piece (facing into the hole) and a hole in both caps.
// Either orientation of the profile and of every hole is accepted. Errors name "profile", "direction",
// "distance" or "holes" (a hole's own problems: "holes[i]").
Solid extrude(const Profile& profile, const Vec3& direction, double distance, const std::vector<Profile>& holes = {});

}  // namespace ratbez
