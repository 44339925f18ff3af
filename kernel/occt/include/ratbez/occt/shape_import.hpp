#pragma once
// TopoDS_Shape -> ratbez::Solid: the inverse of topology.hpp, for shapes read from STEP and .brep files
// (files.hpp), made by OpenCASCADE itself or handed over by FreeCAD. Exposes OCCT types (see geometry.hpp): do
// not include it beside CGAL.
//
// Each TopoDS_Solid becomes one Solid, all its shells (voids included). Its topology is kept one to one: one
// Vertex per TopoDS_Vertex and one shared Edge per TopoDS_Edge (by TopoDS identity, orientation aside), so the
// Solid is closed where the shells were. Each face becomes
//  - a planar face when its surface is a Geom_Plane: the plane's frame (its y axis flipped for a REVERSED face,
//    so that the normal points out), one loop per wire (outer wire first), the edges' 3D curves converted
//    exactly (lines, conics, B-splines, Béziers; GeomConvert), with the file's tolerance;
//  - a surface face when the face is the natural rectangle of its surface's parameters: one wire whose edges'
//    pcurves are the four sides of the (u, v) rectangle they span, one edge per side (degenerate at a pole,
//    one seam edge for both sides of a closed direction), its sides' edges the NURBS surface's own boundary
//    isocurves (brep.hpp: edge parameter = surface parameter);
//  - a trimmed face otherwise (any wires, holes, seams, poles; or a rectangle whose sides another surface face
//    parameterised differently): the exact NURBS over the box of its p-curves, the edges' 3D curves converted
//    exactly, the p-curves in our parameters (pcurve_fit.hpp: the file's own where they are exact in ours,
//    else fitted by projection), with the file's tolerance or the fit's, whichever is larger.
// The surfaces convert exactly: B-spline faces segmented to their rectangle (or kept whole), Bézier faces as
// they are, cylinders, cones, spheres, tori, surfaces of revolution and of linear extrusion (of lines, conics,
// B-splines or Béziers) through GeomConvert's rational conversions, which are exact (rational quadratic arcs).
// A REVERSED face has its u direction reversed so that S_u x S_v points out.
// Files are read as they are written: parameter ranges that overshoot a period or a bound by rounding are
// snapped onto it, knots that dip by rounding are levelled (geometry.hpp), loops off their plane and p-curves
// off their edges are accepted within the file's own tolerances and its slack (a ten-thousandth of the solid's
// size; recorded as Face::tolerance). A face may run several turns round a cylinder, cone, sphere or torus (a
// thread's crest): its NURBS runs as many turns.
// Refused with ratbez::Error naming "shape" and the face: offset and other surfaces without an exact NURBS form,
// an edge whose curve misses its vertices by more than the file's tolerances, faces that do not close into
// valid shells (Face and Solid validation, brep.hpp). `progress` is called with the fraction of faces done, and
// may throw to cancel (progress.hpp).

#include <cstddef>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::occt {

// The shape's one solid; Error when it holds none (naming what it holds instead) or several (pointing at
// from_occt_all / read_step_all). `left_out`, if given, gets what of the shape no solid holds, in words
// ("left out 12 face(s) outside every solid: ..."), or "" when nothing: faces of open shells and loose faces
// bound no volume, and a user should hear that they are not in the solid.
Solid from_occt(const TopoDS_Shape& shape, const Progress& progress = {}, std::string* left_out = nullptr);
// A solid of a shape left out of what is read: its place among the shape's solids (from 0, in the order
// TopExp_Explorer meets them) and why, in words.
struct SolidLeftOut {
    std::size_t index = 0;
    std::string reason;
};

// Every solid of the shape in the order the shape holds them (TopExp_Explorer), errors prefixed "solid k: ".
// With `solids_left_out` given, a solid that does not convert is listed there and left out, as long as another
// converts: one bad part of an assembly does not cost the others (the caller tells the user which it left out).
std::vector<Solid> from_occt_all(const TopoDS_Shape& shape, const Progress& progress = {}, std::string* left_out = nullptr,
                                 std::vector<SolidLeftOut>* solids_left_out = nullptr);

}  // namespace ratbez::occt
