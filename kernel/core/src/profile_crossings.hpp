#pragma once
// The check that a planar profile is a simple curve: its pieces meet only where consecutive pieces (and
// consecutive Bézier spans of one piece) join, and there at a non-zero angle. Revolve and extrude call it
// before they build faces, which would otherwise pass through each other (a solid that OCCT calls
// invalid, that no mesh of can be closed, and whose volume means nothing).

#include "ratbez/profile.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::detail {

// Throws Error naming "profile" when, with tol = profile.tolerance() (1e-9 of the profile's size):
//  - two pieces come within tol of each other away from a joint they share ("cross or touch"),
//  - one piece does so with itself (a loop),
//  - two consecutive pieces leave their joint in the same direction (a cusp, or a piece folding back
//    over the previous one), so that they stay within tol of each other beside the joint.
// The message names the piece or pieces and a point near where it happens. Features smaller than
// 1000 tol along the curve (a loop that small, the two sides of a turn that tight) are below the check's
// resolution: they pass.
// The profile lies in the plane through `origin` spanned by the orthonormal `x_axis` and `y_axis`.
//
// Method: Bézier subdivision. Each span is first cut into cells whose weights vary by at most 4x (the
// weight certificate of properties.cpp), so that halving a cell's parameter roughly halves its geometry.
// Cells are deCasteljau-halved (A1.5 on the homogeneous points) and tested pairwise by their control
// points, which bound them for positive weights (convex hull property, 000 §1.4): axis-aligned boxes,
// then the strip around each one's chord (the "fat line" of Bézier clipping). A cell whose control
// points advance monotonically along its chord cannot meet itself (its derivative is a positive
// combination of the differences P_j - P_i, j > i). Two arcs joined at J meet nowhere else when a line
// through J has all other control points of one strictly on one side and of the other on the other
// side. A pair still unresolved when both arcs are below tol is reported, unless the curve between them
// is within the resolution. A profile that needs more than a fixed budget of subdivision steps (64 per
// cell plus a million) is refused as too intricate to certify, rather than accepted unchecked.
void require_no_crossings(const Profile& profile, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis);

}  // namespace ratbez::detail
