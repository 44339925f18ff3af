#pragma once
// Faces on a sphere, cylinder, cone or torus handed over on OpenCASCADE's surface of that kind, as Part's
// features and OpenCASCADE's reading of a file leave them. Internal to kernel/occt.
//
// Why: the kernel holds such a face (read from a file, or trimmed on a sphere) as a rational B-spline, and
// OpenCASCADE treats the B-spline far worse:
//  - "Run BOP check" (BOPAlgo_ArgumentAnalyzer) searches a B-spline face for self-intersections and leaves
//    analytic surfaces out: it flagged a sphere's pole patches at some placements (OCCT's own NURBS sphere too),
//    FreeCAD's sphere minus a box read from STEP as "BOPAlgo SelfIntersect";
//  - its face-face intersections (the BOP check, booleans) on B-splines are dearer by orders: FreeCAD's BOP check of
//    a real bracket read from STEP (030_bmg_astrosyn_mount.step, 136 faces on cylinders, cones and tori) took 166 s
//    and 2 GB with every face a B-spline, 4.2 s with 46 of them back on OCCT's surfaces (OpenCASCADE's own reading
//    of the file, 1.8 s); the bracket's other solid, all of its faces back, 0.8 s and clean.
// Which faces: a sphere's in any solid; a cylinder's, cone's or torus's in a solid read from a file, told by its
// trimmed faces or a face's tolerance (the kernel's builders make neither: their solids go over as they did; a cone
// ruled between two circles came out of OCCT's Thickness invalid on OCCT's cone). OCCT's fixed rule takes 18
// points across such a face (BRepGProp_Face), so FreeCAD's Shape.Volume of it is as close as of OCCT's own reading
// of the file (cylinder_cut_cylinder: 3.5e-6, its own 1.6e-6), not the 1e-8 the B-spline faces are refined to.
// Recognised on the kernel's control net and checked (exact_elementary); each such OCCT face (or the Bézier patches
// a rough face went over in, taken as one) is rebuilt on OCCT's surface from its own edges (their 3D curves stay the
// kernel's exact ones, its segments, circles and ellipses OCCT's lines, circles and ellipses): ShapeFix_Face projects
// the p-curves onto it (seams and poles included; those it projects loosely are fitted again in closed form) and the
// face keeps the side of its material, its edges their own tolerances. A face is taken only when every
// projected p-curve lies within 1e-6 of the size of its edge, or 1.5 times the largest tolerance of its edges and
// its own as read from a file (edges a file tolerance off the surface project that far from it; the B-spline's
// p-curves were the file's own); the others stay B-splines and the rest is tried again. The rebuilt solid is used
// only when it is valid and OpenCASCADE's adaptive volume is the kernel's to 1e-7 (to area x the file's tolerance
// for read faces: their trims may move the boundary that far); otherwise the B-spline faces stay.

#include <optional>

#include "c0_split.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/occt/topology.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::occt::detail {

// convert's solid with its faces on a sphere, cylinder, cone or torus rebuilt on OCCT's, every face traced to
// convert's; nullopt when no face is on one or the rebuilt solid is refused (handed_out then splits convert's
// solid as before). `progress` (optional) is polled face by face and may throw to stop.
std::optional<SplitSolid> with_elementary_faces(const Solid& solid, const ConvertedSolid& converted,
                                                const Progress& progress = {});

}  // namespace ratbez::occt::detail
