#pragma once
// Surfaces of revolution (004 §1.5; the quarter cylinder of Ex1.15 and the sphere are special cases):
// the profile's control points are rotated about the axis as the control points of an arc, and their
// weights multiplied by the arc's weights, which gives an exact NURBS surface for any rational profile.

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/profile.hpp"

namespace ratbez {

// S(u, v): u runs along the rotation (the arc's parameter, [0, 1]), v along the profile (its own domain).
// angle_deg in (0, 360]. The profile's start point rotates counterclockwise about axis_dir.
NurbsSurface revolve_surface(const NurbsCurve& profile, const Vec3& axis_point, const Vec3& axis_dir,
                             double angle_deg);

// A closed solid: a closed profile (a ring), or an open one whose two ends lie on the axis; it must not
// cross the axis nor touch it anywhere else. A partial angle adds two planar end faces.
Solid revolve(const Profile& profile, const Vec3& axis_point = {}, const Vec3& axis_dir = {0, 0, 1},
              double angle_deg = 360.0);

}  // namespace ratbez
