#pragma once
// Curvature of curves and principal curvatures of surfaces, from exact derivatives (rational ones by the
// quotient rule, A4.2 / A4.4).
//
// Curves: kappa = |C' x C''| / |C'|^3 where C' != 0. 000's Ex1.3 names what a cubic can do: an inflection
// (C'' = 0 or C' || C'': kappa = 0) and a cusp (C'(u0) = 0). Where derivatives vanish the value is the
// limit along the curve: with C^(k) the first derivative that does not vanish and C^(l) the first after
// it not parallel to it, the curve is locally (a s^k, b s^l) and kappa -> 0 for l > 2k, 2 b / a^2 for
// l = 2k (a = |C^(k)| / k!, b = |C^(l) normal to C^(k)| / l!), and infinity for l < 2k: a cusp such as
// (u^2, u^3) at u = 0. A derivative "vanishes" when its term C^(k) h^k / k! over the knot span's width h
// is below 1e-12 of the curve's size.
//
// Surfaces: the principal curvatures k1 >= k2 are the eigenvalues of the shape operator (the second
// fundamental form L, M, N taken with the unit normal(u, v), over the first E, F, G), dir1 and dir2 their
// unit directions in space. Signs follow the normal: k > 0 where the surface bends towards it, so a sphere
// with outward normal has k1 = k2 = -1/r. At an umbilic (k1 = k2) the directions are any orthonormal
// pair of the tangent plane. Where the parameterisation degenerates (a pole, an apex: E G - F^2 = 0) the
// value is the limit, extrapolated (to third order) from three points towards the domain's centre, 7e-4,
// 1.4e-3 and 2.8e-3 of the way (nearer points lose digits to the quotient rule's cancellation; measured at
// the poles of a sphere and a spheroid: within 1e-8 relative); a true singular point (a cone's apex) gives
// what the surface tends to there along that line.

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

// kappa(u) >= 0, infinity at a cusp. Throws Error naming "u" outside the domain.
double curvature(const NurbsCurve& curve, double u);

struct PrincipalCurvatures {
    double k1 = 0, k2 = 0;  // k1 >= k2
    Vec3 dir1, dir2;        // unit, tangent to the surface, orthogonal
    Vec3 normal;            // the unit normal the signs refer to (NurbsSurface::normal)
};

// Throws Error naming "u" or "v" outside the domain, "(u, v)" where the surface has no tangent plane.
PrincipalCurvatures principal_curvatures(const NurbsSurface& surface, double u, double v);

}  // namespace ratbez
