#pragma once
// Exact conversions between ratbez curves and surfaces and OpenCASCADE's Geom classes, both ways.
// This header exposes OCCT types: include it only from translation units that do not include CGAL
// (OCCT's Handle macro breaks CGAL); files.hpp and check.hpp are the OCCT-free entry points.
//
// Representation differences the conversions bridge:
//  - knots: ours are flat (u_0 .. u_m, repeated); OCCT stores distinct knots plus multiplicities.
//    Grouping is by exact equality, so a flat vector converts back bit for bit.
//  - control points: ours are homogeneous (w P, w); OCCT stores Euclidean poles P and weights w
//    separately. P = (wP)/w and back w*P, so a round trip reproduces the Euclidean points to the last
//    bit or two (the homogeneous product is recomputed), and knots, multiplicities, degrees and weights
//    exactly.
//  - rational flag: OCCT decides rationality itself: poles whose weights are all equal make a
//    non-rational curve (the weights are dropped). Such a curve comes back non-rational with weights 1,
//    which is the same curve.
//  - periodic OCCT B-splines (and OCCT's unclamped non-periodic ones) are handled: a periodic one is
//    unperiodized first (Geom_BSplineCurve::SetNotPeriodic on a copy), which changes its knots and poles
//    but not its geometry or parameterization. Ours are never periodic.
//  - degree: OCCT needs degree >= 1 (and <= Geom_BSplineCurve::MaxDegree() = 25); degree 0 throws.

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez::occt {

inline gp_Pnt to_occt_point(const Vec3& p) { return gp_Pnt(p.x, p.y, p.z); }
inline gp_Vec to_occt_vector(const Vec3& v) { return gp_Vec(v.x, v.y, v.z); }
inline gp_Dir to_occt_direction(const Vec3& v) { return gp_Dir(v.x, v.y, v.z); }  // normalised; v must not be 0
inline Vec3 from_occt(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Vec3 from_occt(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

// ratbez -> OCCT. Throw ratbez::Error naming the argument when OCCT cannot hold the data (degree 0,
// degree above 25).
Handle(Geom_BezierCurve) to_occt(const BezierCurve& curve);
Handle(Geom_BSplineCurve) to_occt(const NurbsCurve& curve);
Handle(Geom_BezierSurface) to_occt(const BezierSurface& surface);
Handle(Geom_BSplineSurface) to_occt(const NurbsSurface& surface);

// OCCT -> ratbez. Throw ratbez::Error naming the argument for a null handle.
BezierCurve from_occt(const Handle(Geom_BezierCurve)& curve);
NurbsCurve from_occt(const Handle(Geom_BSplineCurve)& curve);
BezierSurface from_occt(const Handle(Geom_BezierSurface)& surface);
NurbsSurface from_occt(const Handle(Geom_BSplineSurface)& surface);

// A 2D B-spline (a pcurve) as our NurbsCurve with z = 0.
NurbsCurve from_occt_2d(const Handle(Geom2d_BSplineCurve)& curve);

// The same NURBS curve in a plane's coordinates: every control point P becomes
// (dot(P - origin, x_axis), dot(P - origin, y_axis)) with the same knots and weights. For a curve lying in
// the plane (and orthonormal axes) this is the exact parameter-space curve of the plane (a pcurve).
Handle(Geom2d_BSplineCurve) to_occt_2d(const NurbsCurve& curve, const Vec3& origin, const Vec3& x_axis,
                                       const Vec3& y_axis);

}  // namespace ratbez::occt
