#pragma once
// The check that a planar profile is a simple curve: its pieces meet only where consecutive pieces (and
// consecutive Bézier spans of one piece) join, and there at a non-zero angle. Revolve and extrude call it
// before they build faces, which would otherwise pass through each other (a solid that OCCT calls
// invalid, that no mesh of can be closed, and whose volume means nothing). Extrude with holes checks
// all its loops together, and where each hole lies by the winding number.

#include <span>
#include <string_view>

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

// The same for several loops in one plane: loops[0] the profile, the others closed holes; besides each
// loop being simple, no two loops may come within tol of each other (the larger of their tolerances).
// Crossings between loops throw Error naming "holes" and the pieces ("piece 2 of hole 0").
void require_no_crossings(std::span<const Profile> loops, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis);

// How many times the closed `loop` winds counterclockwise (seen from cross(x_axis, y_axis)) about `point`
// of the plane: +1 or -1 inside a simple loop, 0 outside. `point` must not lie on the loop (require_no_crossings
// of the loop and of the loop holding `point` makes it at least tol away).
// Method: the angle C(t) - point turns through is summed over the loop's Bézier cells (weight-certified
// as above). A cell whose control points all lie in an open half-plane seen from `point` holds the curve
// there (convex hull property), so its angle is the principal angle between its end points; other cells
// are halved (deCasteljau, A1.5). Throws Error naming `argument` if the point is within about 1e-15 of
// the loop's size from it.
int winding_number(const Profile& loop, const Vec3& point, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                   std::string_view argument);

}  // namespace ratbez::detail
