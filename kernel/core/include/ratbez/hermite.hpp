#pragma once
// The cubic Hermite form (003, "Hermite Curves"): the cubic with C(0) = p0, C'(0) = t0, C(1) = p1,
// C'(1) = t1, C(t) = [p0 p1 t0 t1] M_Hermite [1 t t^2 t^3]^T, and its conversion to and from Bézier form
// by G_Bezier = G_Hermite M_Hermite M_Bezier^-1 (003, "Changing Representations"; 003 prints M_Bezier with a
// -3 where +3 belongs: see DESIGN.md's errata). Worked out, since C'(0) = 3 (b1 - b0) and C'(1) = 3 (b3 - b2)
// (003, "Derivatives"):
//     b0 = p0,  b1 = p0 + t0 / 3,  b2 = p1 - t1 / 3,  b3 = p1.

#include "ratbez/bezier_curve.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

struct HermiteForm {
    Vec3 p0, t0, p1, t1;  // end points and end derivatives (in the curve's parameter on [0, 1])
};

// Throws Error naming the argument with a non-finite coordinate, or the tangent that puts an inner control
// point beyond the double range.
BezierCurve hermite_to_bezier(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1);
// The inverse for a polynomial Bézier curve of degree <= 3 (lower degrees are elevated: the same curve);
// throws Error naming "curve" for a rational curve or a degree above 3 (no cubic Hermite form), and for end
// tangents beyond the double range (control points near it, far apart).
HermiteForm bezier_to_hermite(const BezierCurve& curve);

}  // namespace ratbez
