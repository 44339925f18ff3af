#pragma once
// Faces of no area between two edges, taken out of a solid read from a file before it is converted. Internal
// to kernel/occt.
//
// Exporters leave such a face where two faces meet along one edge that they wrote twice: a Fusion 360 mount of
// the Xol toolhead has a planar face bounded by two lines between the same two vertices, 6e-4 apart within the
// file's tolerance, a cone on one side and a cylinder on the other. OpenCASCADE's BRepCheck calls it valid, but
// no mesh closes across it: each line is sampled on its own, and the sliver's triangles face whichever way the
// samples put them.
// OpenCASCADE's shape analysis finds the case (ShapeAnalysis_CheckSmallFace::CheckSingleStrip: two vertices, two
// edges within tolerance of each other): the face goes, its second edge becomes the first wherever it is used,
// and the face beside it gets its curve on that edge projected (ShapeFix_Edge).
// A flat triangle is the same with one of the two edges written as two: a face of three edges and three vertices
// whose two short edges (and so their vertex) keep within twice its tolerance of the long one (an endgame
// trackball's shell, Fusion 360: a cylinder's face 0.057 long whose loop ran clockwise). The long edge becomes the
// two short ones wherever it is used, and the face beside it gets its curves on them.
// Thin faces of four edges are left: OpenCASCADE's own ShapeFix_FixSmallFace::FixStripFace also takes those, which
// on the Xol file moved volumes by 1e-4 and left a solid invalid.

#include <TopoDS_Shape.hxx>

namespace ratbez::occt::detail {

// `solid` without its sliver faces (above), the faces beside them sharing one edge; `solid` itself when it has
// none, or when the healed solid is invalid to OpenCASCADE's BRepCheck.
TopoDS_Shape without_sliver_faces(const TopoDS_Shape& solid);

}  // namespace ratbez::occt::detail
