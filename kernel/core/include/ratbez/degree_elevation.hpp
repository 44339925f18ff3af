#pragma once
// Degree elevation of NURBS curves and surfaces (The NURBS Book §5.5, A5.9 DegreeElevateCurve): the same
// curve or surface written with a higher degree. Each Bézier span is raised t degrees; an interior knot of
// multiplicity s becomes one of multiplicity s + t, so the continuity at every knot is kept; everything runs
// on the homogeneous points P^w, so rational geometry is elevated exactly. An unclamped knot vector is
// first clamped at the domain's ends (A5.1; the same curve).
// Surfaces: A5.9 on every row (for u) or column (for v) of the homogeneous net; the lines share the knots,
// so they share the new knots too.

#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez {

// The same curve with degree + times (times >= 0). Throws Error naming "times" when negative.
NurbsCurve elevate_degree(const NurbsCurve& curve, int times);
// The same surface with degree_u + times (degree_v + times). Throw Error naming "times_u" ("times_v").
NurbsSurface elevate_degree_u(const NurbsSurface& surface, int times);
NurbsSurface elevate_degree_v(const NurbsSurface& surface, int times);

}  // namespace ratbez
