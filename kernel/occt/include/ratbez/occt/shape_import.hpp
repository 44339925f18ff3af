#pragma once
// TopoDS_Shape -> ratbez::Solid: the inverse of topology.hpp, for shapes read from STEP and .brep files
// (files.hpp) and made by OpenCASCADE itself. Exposes OCCT types (see geometry.hpp): do not include it
// beside CGAL.
//
// The shape must hold exactly one solid. Its topology is kept one to one: one Vertex per TopoDS_Vertex and one
// shared Edge per TopoDS_Edge (by TopoDS identity, orientation aside), so the Solid is closed where the shell was.
// Each face becomes
//  - a planar face when its surface is a Geom_Plane: the plane's frame (its y axis flipped for a REVERSED face,
//    so that the normal points out), one loop per wire (outer wire first), the edges' 3D curves converted
//    exactly (lines, conics, B-splines, Béziers; GeomConvert);
//  - a surface face when the face is the natural rectangle of its surface's parameters: one wire whose edges'
//    pcurves are the four sides of the (u, v) rectangle they span, one edge per side (degenerate at a pole,
//    one seam edge for both sides of a closed direction). The surface over that rectangle becomes one exact
//    NURBS: B-spline faces segmented to it, Bézier faces as they are, and cylinders, cones, spheres, tori,
//    surfaces of revolution and of linear extrusion (of lines, conics, B-splines or Béziers) through
//    GeomConvert's rational conversions, which are exact (rational quadratic arcs). A REVERSED face has its
//    u direction reversed so that S_u x S_v points out. The sides' edges are the NURBS surface's own
//    boundary isocurves (brep.hpp: edge parameter = surface parameter), from the first surface face that
//    uses each edge; the exact conversions may parameterise an arc differently from OCCT's edge curve.
// Anything else — a trimmed (non-rectangular) non-planar face, a face with holes, offset or other surfaces
// without an exact conversion, two surface faces that parameterise a shared edge differently — is refused with
// ratbez::Error naming "shape" and the face: "face 7: a trimmed Geom_BSplineSurface face is not supported ...".
// Face and Solid validation (brep.hpp) then check closure and orientation. `progress` is called with the
// fraction of faces done, and may throw to cancel (progress.hpp).

#include <TopoDS_Shape.hxx>

#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::occt {

Solid from_occt(const TopoDS_Shape& shape, const Progress& progress = {});

}  // namespace ratbez::occt
