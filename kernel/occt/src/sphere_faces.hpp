#pragma once
// Faces trimmed on a sphere handed over on OpenCASCADE's spherical surface, as Part's booleans leave them.
// Internal to kernel/occt.
//
// Why: "Run BOP check" (BOPAlgo_ArgumentAnalyzer) searches a B-spline face for self-intersections and flags a
// sphere's pole patches at some placements (OCCT's own NURBS sphere too); it leaves analytic surfaces out. A whole
// sphere already goes over as OCCT's own (analytic_primitives.hpp), but a face trimmed on one (FreeCAD's sphere
// minus a box, read from STEP: the kernel holds it as a NURBS face) went over as a B-spline and was flagged
// "BOPAlgo SelfIntersect". Recognised on the kernel's control net and checked (exact_sphere); each such OCCT face
// is rebuilt on the sphere from its own edges (their 3D curves stay the kernel's exact ones): ShapeFix_Face
// projects the p-curves onto the sphere (seams and poles included) and the face keeps the side of its material.
// The rebuilt solid is used only when it is valid, every projected p-curve lies within 1e-6 of the size of its
// edge (the edge's tolerance then covers it: 1e-5 on the sphere minus a box of size 30, where OCCT's own Cut
// leaves 1e-7), and OpenCASCADE's adaptive volume is the kernel's to 1e-7; otherwise the B-spline faces stay.
// (Cylinders, cones and tori were tried the same way, on untrimmed faces: their projected rims came out 3e-7 of
// the size off, and their B-spline faces pass the BOP check.)

#include <optional>

#include "c0_split.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/occt/topology.hpp"

namespace ratbez::occt::detail {

// convert's solid with its faces on a sphere rebuilt on OCCT's, every face traced to convert's; nullopt when no
// face is on a sphere or the rebuilt solid is refused (handed_out then splits convert's solid as before).
std::optional<SplitSolid> with_sphere_faces(const Solid& solid, const ConvertedSolid& converted);

}  // namespace ratbez::occt::detail
