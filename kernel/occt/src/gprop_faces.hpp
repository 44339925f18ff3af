#pragma once
// Whole faces for OpenCASCADE's fixed Gauss rule (FreeCAD's Shape.Volume, Shape.Area, CenterOfMass), as the
// natural conversion hands them over (topology.hpp); gprop_patches.hpp cuts up the faces that cannot stay whole.
// Internal to kernel/occt.
//
// The rule (BRepGProp_Gauss, the domain overloads FreeCAD calls) is Green's theorem: one Gauss rule along each
// edge of the face's wire in the edge's own parameter, times one across u from the surface's first u to the
// edge's p-curve point. Only edges along which v changes count, and of a rectangle's sides only u_max (at u_min
// the inner integral is empty). Its sizes follow degree and spans (gprop_integration_order): it reads a face
// well where the surface is smooth across u, and along v between the vertices of the edges.

#include <Geom_BSplineSurface.hxx>

#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez::occt::detail {

// The rough knots of a direction: interior knots of multiplicity degree - 1 or more, where the surface is C1
// or less (C0 by multiplicity: a crease, or the joint of two rational arcs that is not an arc direction; C1:
// the second derivative jumps, at a rational joint or a quadratic's knot). The rule converges slowly across
// one (0.9 % on the kernel's own circle joints, 9 % on the ruled example, 0.09 % on the partial revolve
// example's rational C1 profile, 0.1 % on the area of an extruded closed quadratic interpolation; a cubic's C2
// knots cost 7e-6 there), and BOPAlgo flags a C0 one.
std::vector<double> rough_knots(const NurbsSurface& surface, bool along_u);

// Whether a face rough in one direction only (`along_u`: u) stays one face, the edges of its sides along that
// direction cut at the rough knots: a vertex at each rough v knot on the u_max side splits the rule's outer
// integral there, so each span is read on its own, smooth. A revolved rational profile is one face, as Part's
// Revolution makes it, its side edges cut where the profile's pieces meet (u_min's too: on a full revolution it
// is the same seam, and a planar neighbour reads its own rule along the pieces alike). A face rough in u goes
// over with u and v exchanged (topology.cpp's surface_face), its v sides cut: an extruded closed quadratic is
// one side face, its sections cut at the knots. Not for a C0 knot (a crease: BOPAlgo flags a C0 face, so that
// one goes over as patches), nor a pole on the side the rule reads (no edge to cut there).
bool cut_on_sides(const Face& face, bool along_u);

// The same surface with a richer representation for the rule, which it sizes by degree and spans: a straight
// direction (a cylinder's or an extrusion's, degree 1, one span) gets 8 points, and reads a cylinder's centre of
// mass to only 8e-5 of its size. Degree elevation and knot insertion are exact and keep the parameter, so the
// edges along the direction keep theirs. Elevated to cubic (a straight direction, or a quadratic one of one span:
// a 3-section loft's v), not left quadratic, before the simple knots go in: the face is C2, so OCCT's offset of
// it (Part Offset, Thickness: an offset surface is one order less continuous) is C1, which FreeCAD's BOP check
// accepts; at quadratic the offsets of every cylinder, cone, revolution, extrusion and 3-section loft were
// flagged GeomAbs_C0.
Handle(Geom_BSplineSurface) refined_for_gauss(Handle(Geom_BSplineSurface) surface);

// The rule takes as many points across u as along v for the volume (the volume's rule counts v alone, the
// area's both: gprop_patches.hpp), so a face of few spans in v is read with too few across u: an extruded
// closed cubic interpolation (C2 knots in u, one span in v) read 1.7e-4 off with 32 points (7e-6 with 61), a
// full turn of the revolve example's rational profile (its sides cut) 2.8e-7 with 12. Simple knots go into v,
// each span cut alike, until v's rule is u's (exact: the new knots are C-infinity), v first raised to cubic as
// in refined_for_gauss, so that the face stays C2 for OCCT.
void with_v_rule_as_u(Geom_BSplineSurface& surface);

}  // namespace ratbez::occt::detail
