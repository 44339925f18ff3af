#pragma once
// Lofting (skinning) through section curves, The NURBS Book §10.3:
//  0. with `align` (the default), the sections are matched by normalised arc length (section_alignment.hpp
//     in the modelling sources: closed sections oriented alike and started at the points of least twist,
//     open ones end to end, every corner or joint of a section matched exactly by arc length, each section
//     on its own parameter between them, so smooth sections stay smooth); without it they are joined by
//     their parameters as given;
//  1. the sections are made compatible (one degree p, one clamped knot vector U on [0, 1]; A5.9, A5.4 by
//     compatible_curves.hpp), and each is scaled in homogeneous space so that its first weight is 1 (a
//     curve's weights are only defined up to a common factor, which would otherwise change the loft);
//  2. the parameters across, v_0 = 0 < ... < v_{K-1} = 1, by averaged chord length: for every control
//     point index i the cumulative chord lengths |P_{i,k} - P_{i,k-1}| normalised to [0, 1], averaged over
//     the indices i whose points move (Eq. 10.8 with Eq. 9.5 per column);
//  3. the degree across q = min(degree, K - 1) and the knots V by averaging (Eq. 9.8);
//  4. every column i of homogeneous points P^w_{i,0..K-1} is interpolated at the v_k (A9.1), giving the
//     net Q^w_{i,j}.
// Consequences of interpolating rational sections in homogeneous space:
//  - the surface passes through every section exactly: S^w(u, v_k) = C^w_k(u), so S(u, v_k) = C_k(u)
//    (to rounding, ~1e-15 of the size);
//  - between sections the surface interpolates the homogeneous points, not the Euclidean ones: sections
//    with equal weights (circles and arcs of the same layout, polynomial curves) give isocurves across that
//    are the B-spline interpolants of the Euclidean points; unequal weights pull the surface towards the
//    section with the larger weights;
//  - interpolated weights can overshoot: when sections' weights differ so much that a weight of the net
//    comes out <= 0, the loft is refused (Error naming "curves" / "profiles"); polynomial sections never
//    have this problem, nor do sections with equal weights.
// Polynomial sections give a polynomial surface.

#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/profile.hpp"

namespace ratbez {

// The lofted surface and the parameters v_k at which it passes through the sections.
struct Skin {
    NurbsSurface surface;
    std::vector<double> section_parameters;
};

// At least two sections, degree >= 1 (the degree across: 1 is piecewise ruled); u runs along the sections
// over [0, 1], v across them over [0, 1]. Consecutive sections must not coincide (all their control
// points the same). A surface that meets itself (twisted, pinched, crossing: the certified test of
// analysis/self_intersection.hpp) is refused, the place and the sections it lies between named. Errors name
// "curves" or "degree".
Skin skin(const std::vector<NurbsCurve>& curves, int degree = 3, bool align = true);
inline NurbsSurface loft_surface(const std::vector<NurbsCurve>& curves, int degree = 3, bool align = true) {
    return skin(curves, degree, align).surface;
}

// A solid lofted through closed planar profiles, capped by the first and last profile. Each profile is
// joined into one curve (join.hpp: its pieces end to end, the knots where they meet), turned to run
// counterclockwise about the direction the loft travels (from its control points' centre towards the
// next profile's), and the profiles lofted as above; ruled = true lofts with degree 1 across (straight
// rulings between consecutive profiles). With `align` the profiles are matched by arc length at their corners
// and joints, from the start points of least twist (the first profile's start sets the seam, moved to a crease when every profile has
// a corner at matching places); without it their starting points and parameters are matched as given.
// One side face per smooth run: the side surface is cut only along creases that run through every section
// (a square lofted to a square has four side faces, a circle to a circle one, a circle to a square one).
// Validated (Error naming "profiles[k]" or "degree"): at least two profiles, each closed, planar and simple
// (as for extrude), and every profile strictly in front of the previous one's plane and the previous one
// strictly behind its plane (all control points, so the curves by the convex hull property): sections that
// cut through each other give no solid; and (Error naming "profiles") a side surface that meets itself, as
// skin() refuses it.
Solid loft(const std::vector<Profile>& profiles, int degree = 3, bool ruled = false, bool align = true);

}  // namespace ratbez
