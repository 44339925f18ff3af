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
//
// Faces: one surface face per profile piece (u = rotation, v = the piece's parameter as Profile holds
// it); neighbouring pieces share the circle (arc) their joint traces; a full turn has one seam edge per piece (the piece
// itself, used by the face's u_min and u_max sides); a piece end on the axis gives a degenerate edge.
// A partial turn adds two planar end faces bounded by the profile at angle 0 and at angle_deg, plus
// (open profile) the segment of the axis between its ends, shared by both end faces.
// The profile may be drawn in either direction: it is reversed when needed so that normals point out.
//
// The rules, with tol = profile.tolerance() (1e-9 of the profile's size):
//  - every control point lies within tol of one plane containing the axis, all on one side of it (by
//    the convex hull property the whole profile then lies in that half-plane);
//  - an open profile starts and ends within tol of the axis (the ends are then put on it exactly);
//  - nowhere else does the profile come within tol of the axis: each Bézier segment of each piece is
//    sampled at 65 points (a sample on the far side "crosses the axis", a sample within tol "touches the
//    axis"), and then certified by its control polygon: the signed distances of its control points,
//    with values within tol counted as 0, must all be >= 0, not all 0, and > 0 at every end that is not
//    an allowed profile end; a segment the hull cannot certify is halved (deCasteljau) up to 20 times and
//    is rejected as touching the axis if it still cannot be certified.
//  - the profile must not cross or touch itself (within tol) away from the joints of its pieces, nor turn
//    back at a joint (a cusp); see profile_crossings.hpp for the certified Bézier subdivision test.
Solid revolve(const Profile& profile, const Vec3& axis_point = {}, const Vec3& axis_dir = {0, 0, 1},
              double angle_deg = 360.0);

}  // namespace ratbez
