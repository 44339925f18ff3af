#pragma once
// Sweeping a curve or a profile along a path (004 §1.5: "sweep constructions using any path") with a
// rotation-minimising frame (rotation_minimizing_frame.hpp): the section is carried rigidly, its position
// relative to the frame (t, r, s) at the path's start kept all the way,
//     S(u, v) = x(v) + M(v) M(v_0)^-1 (C(u) - x(v_0)),   M = [r s t] the frame at v.
// The frame does not spin about the tangent, so a section turns only as the path does.
//
// Exact where the exact answer is rational, detected from the path's control points and certified on it:
//  - a straight path (control points on one line, advancing monotonically): the frame is constant and the
//    sweep is the extrusion C(u) + v (x_end - x_start) (extrude.hpp, 004's translational sweep);
//  - a circular arc (the path planar and at one distance from a centre at 2p + 1 points per span, which for
//    a degree-p rational span makes the polynomial |C^w - c w|^2 - R^2 w^2 of degree 2p vanish identically,
//    and turning one way): the RMF of a planar curve turns with it, and the sweep is the revolution of the
//    section about the arc's axis by the arc's angle (revolve.hpp, 004's rotational sweep); a full circle
//    closes it (a torus from a circle);
//  - an open path of lines and arcs end to end (every span one or the other, as a sketch's line and tangent arc
//    give it): the frame is constant along a line and turns with an arc, so the sweep is piece by piece the
//    extrusion or the revolution of the section where the pieces before have carried it; one surface per
//    section, the pieces joined in v with knots of multiplicity p (C0 in parameter, tangent-continuous in shape)
//    and v spread over them in proportion to their lengths.
// Otherwise a NURBS approximation. Each control point P_i (weight w_i) of the section moves along a
// trajectory Q_i(v) = x(v) + M(v) L_i (L_i its coordinates in the start frame); the surface
// S^w = sum_ij N_i(u) M_j(v) w_i Q~_ij with every trajectory approximated by a piecewise quintic Q~_i
// (Hermite data Q_i, Q_i', Q_i'' at the interval ends, the frame's derivatives from r' = -(t' . r) t)
// deviates from the true sweep by at most max_i |Q~_i(v) - Q_i(v)|, since S(u, v) is a convex combination
// of the Q~_i(v) with the section's rational basis functions R_i(u) >= 0. The intervals start as the path's
// knot spans and are halved while that maximum, estimated at 8 points inside each, exceeds the tolerance;
// then the assembled trajectories are measured at 24 points per interval and the intervals still above it
// halved again, until the measurement holds. The frame (double reflection on a reference subdivision of the
// path, its error estimated by Richardson from the half subdivision) is refined first until it contributes
// below a tenth of the tolerance, and that tenth is left out of the trajectories' budget. The pieces join
// with knots of multiplicity 3 (C2) inside a path span and where the path is C3, 4 (C1) where only its
// third derivative jumps and 5 (C0) where its second does (the sweep itself has a crease of speed there);
// the start and end sections are exact rigid images of the section.
// A closed path (ending where it starts, with the same tangent) closes the sweep; on a non-planar closed
// path the RMF comes back turned by the path's holonomy angle, and that angle is spread uniformly over the
// path's parameter so that the sweep closes (the only case where the frame is not strictly
// rotation-minimising).
//
// Refused with Error naming "path": a path with a corner (tangents differing by more than 1e-9 rad at a
// knot) or a point of zero speed, or one that turns back on itself; and, named "profile" or "curve", a
// sweep that would intersect itself: the section reaching farther into a bend than its radius of curvature
// (the control points' extent along the principal normal times the curvature >= 1 at any reference
// point; conservative: the section's control points bound it), or two parts of the path more than half a
// turn (pi rho along the path, rho the section's largest control-point distance from the path's start)
// apart coming closer than 2 rho. Tolerance: finite, > 0 and at least 1e-12 of the sweep's size. Whatever
// passes those checks is certified not to meet itself (analysis/self_intersection.hpp, on the swept surfaces
// side by side, closed round and along as the sections and the path are), else refused naming the section
// and the place.

#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/construction.hpp"
#include "ratbez/frame.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/profile.hpp"

namespace ratbez {

enum class SweepMethod { extrusion, revolution, lines_and_arcs, approximation };

// The swept surfaces of one or more section curves (one per curve, all on the same knots in v), how they
// were built, and the measured bound of their distance to the true sweep (0 for the exact methods).
// u runs along each curve (its own domain), v along the path over [0, 1].
struct Sweep {
    std::vector<NurbsSurface> surfaces;
    SweepMethod method = SweepMethod::approximation;
    double max_error = 0;
    bool closed = false;  // the path is closed: v = 1 is v = 0
    // Along lines and arcs (SweepMethod::lines_and_arcs), the v where one piece of the path meets the next, in
    // order: knots of full multiplicity, where the surfaces are only C0 (the speed along the path may jump).
    // sweep() makes a face of each piece, as Part's Sweep does of each path edge.
    std::vector<double> joints;
    // The frame (origin x, axes r, s, t) at the path's start and where the sweep carries it at the end:
    // a section's point p at the start is at end_frame.to_world(local) at the end, local being p's
    // coordinates in start_frame.
    Frame start_frame, end_frame;
    // What the exact methods built: Construction::Extrusion (the displacement) or Construction::Revolution (the
    // arc's centre, axis and angle); none for the approximation.
    Construction construction;
};

// `argument` names the section in errors ("curve", "profile").
Sweep sweep_surfaces(const std::vector<NurbsCurve>& sections, const NurbsCurve& path, double tolerance = 1e-6,
                     const char* argument = "curve");
inline NurbsSurface sweep_surface(const NurbsCurve& curve, const NurbsCurve& path, double tolerance = 1e-6) {
    return sweep_surfaces({curve}, path, tolerance).surfaces.front();
}

// A closed planar profile swept along the path: one lateral face per piece (and per piece of a path of lines and
// arcs, which meet at the surfaces' joints: Sweep::joints), capped by the profile at the
// start and its rigid image at the end (planar faces), or closed on itself along a closed path. The profile
// must not lie in a plane containing the path's starting tangent; it is turned to run counterclockwise about
// it, so that the faces point out. Along a straight path the solid is the extrusion (recorded as one); along an
// arc, with the profile in a plane through the arc's axis (across the path, as usual), it is revolve()'s solid
// of the profile about that axis (its faces u round the axis, v along the profile, and recorded as a revolution),
// so that both go on as what they are (OpenCASCADE's prism and revolution, the check's analytic surfaces).
Solid sweep(const Profile& profile, const NurbsCurve& path, double tolerance = 1e-6);

}  // namespace ratbez
