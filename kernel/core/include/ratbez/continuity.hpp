#pragma once
// How smoothly two curves or two patches meet: the parametric order C^k and the geometric order G^k reached
// (k up to 2; -1 when they do not meet), with the gaps measured.
//
// Curves a, b meeting end to start, each in its own parameter (b's domain shifted to begin where a's ends,
// which changes no derivative):
//  - C^k: a^(j)(end) = b^(j)(start) for j = 0..k (001's definition at a breakpoint). For Bézier pieces this
//    is 004's control-point rule, n (p_n - p_{n-1}) = m (q_1 - q_0) for C1 and
//    n (n-1) (p_n - 2 p_{n-1} + p_{n-2}) = m (m-1) (q_0 - 2 q_1 + q_2) for C2; on breakpoints u0 < u1 < u2
//    (pieces on [u0, u1], [u1, u2]) the C1 cubic joint is 001's P_3 = ((u2 - u1) P_2 + (u1 - u0) P'_1) / (u2 - u0).
//  - G^1: the same unit tangent (004: the first derivatives proportional with a positive factor); where a
//    derivative vanishes, the limit tangent (the first non-vanishing derivative, with the sign the curve
//    moves in). G^2: G^1 and the same curvature vector kappa n (004: "curvature ... match").
// Patches a, b sharing a boundary (one of a's four sides and one of b's, in either direction, found by
// matching points): at points along the shared boundary
//  - C^k: the boundary has the same parameterisation on both (points agree at corresponding parameters)
//    and the cross-boundary derivatives of orders 1..k agree, a's taken towards the boundary, b's away
//    from it (an interior patch boundary of one NURBS surface is C^k in this sense exactly when its knot
//    allows it);
//  - G^1: the same tangent plane (normals parallel; 004's L1/L2 rule for Bézier patches, a constant ratio
//    of the collinear control segments across the boundary, is the control-net form of it); G^2: G^1 and
//    the same normal curvature in every direction (the second fundamental forms agree).
// Judged with relative tolerances: positions to 1e-9 of the size of both control nets, derivatives to 1e-9
// of the larger (plus 1e-12 of size / width^k), angles to 1e-9 rad, curvatures to 1e-9 of the larger
// (plus 1e-12 / size). The gaps are absolute.

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez {

struct Continuity {
    int parametric = -1;  // C^k reached: -1 (apart), 0, 1 or 2
    int geometric = -1;   // G^k reached: -1, 0, 1 or 2
    // The measured gaps (largest along a shared boundary):
    double position = 0;      // |a - b| at the joint (curves) / max distance between the boundaries (patches)
    double derivative1 = 0;   // |a' - b'| (cross-boundary first derivatives for patches)
    double derivative2 = 0;   // |a'' - b''|
    double tangent_angle = 0; // radians between the unit tangents (curves) or the normals (patches)
    double curvature = 0;     // |kappa_a n_a - kappa_b n_b| (curves); max |II_a - II_b| over unit directions (patches)
};

// Throws Error naming "a" or "b" for a curve that is a single point (no tangent to compare).
Continuity continuity(const NurbsCurve& a, const NurbsCurve& b);
// The shared boundary is the pair of sides (and directions) whose points match best; when even that pair
// is apart (position gap above the tolerance) the result is C^-1, G^-1 with that gap.
Continuity continuity(const NurbsSurface& a, const NurbsSurface& b);

}  // namespace ratbez
