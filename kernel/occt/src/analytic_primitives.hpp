#pragma once
// Cylinders, cones, spheres and tori handed over as OpenCASCADE's own primitives (BRepPrimAPI), on its
// analytic surfaces, as Part's Cylinder, Cone, Sphere and Torus are. Internal to kernel/occt.
//
// Why: OpenCASCADE treats its analytic surfaces better than the same shape as B-splines, in ways FreeCAD users
// meet at once: "Run BOP check" (BOPAlgo_ArgumentAnalyzer) leaves them out of its face self-intersection
// search, which flags a B-spline sphere's pole patches at some placements (its own toNurbs() sphere too: a
// RatBez sphere r = 3 at (0, -40, 0) or (100, 0, 0), and a Part sphere written to STEP and read back by ratbez);
// its booleans on them are several times faster; Thickness need not extend them. The shape is the same and exact
// either way (a circle is a circle); the kernel keeps its own rational solid for its measures and meshes.
// Which solids: those whose construction record names a cylinder, cone, sphere or torus (construction.hpp;
// kept through moves, turns and uniform scalings), and a solid of one face whose surface is, exactly, a sphere
// or a torus (a sphere read from a file has no record): recognised on the kernel's control net (smooth_arcs.hpp:
// one direction an arc about one axis in every row, the meridian of the rows' heights and radii an arc), then
// checked at 9 x 9 points of the surface to 1e-10 of its size. Extrusions and revolutions (lines and arcs of the
// profile sweeping analytic faces) go over as OCCT's prism or revolution of their profile, where its rule reads
// them (swept_solids.hpp), as Part's Extrusion and Revolution do.
// ConvertOptions::analytic_primitives (default true) turns it on; the FreeCAD workbench's preference for
// B-spline primitives turns it off.

#include <Geom_ElementarySurface.hxx>
#include <TopoDS_Solid.hxx>

#include <optional>

#include "ratbez/brep.hpp"

namespace ratbez::occt::detail {

// OCCT's primitive (or sweep) with its faces in the order of ours (face i of `solid` is the i-th face of the result), each
// checked to lie on ours (a record that does not describe the faces gives nullopt, as does any other solid).
std::optional<TopoDS_Solid> analytic_primitive(const Solid& solid);

// The sphere, torus, cylinder or cone the surface is, exactly (recognised as above, a cylinder's and a cone's
// meridian a line; checked to 1e-10 of `size`), on OCCT's surface of that kind with the kernel's axis and start
// direction; null for any other surface (elementary_faces.hpp uses it for faces trimmed on one).
Handle(Geom_ElementarySurface) exact_elementary(const NurbsSurface& surface, double size);

}  // namespace ratbez::occt::detail
