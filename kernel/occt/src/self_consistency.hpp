#pragma once
// A solid read from a file held against itself before it is converted (issue 29 item 2): OpenCASCADE reads
// whatever the file says, and a vertex moved off its edges, a p-curve that leaves its edge's 3D curve, a loop
// that does not close or a shell that does not close or is not oriented would otherwise become a Solid whose
// exact measures and mesh describe different shapes. Everything is held to the file's own tolerances (an edge's
// tolerance bounds its curves' distance, a vertex's its distance from its edges); a gap beyond them by no more
// than the file's slack (file_slack) raises the edge's or vertex's tolerance to it.

#include <vector>

#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include "ratbez/occt/shape_import.hpp"

namespace ratbez::occt::detail {

// Throws Error("shape", "solid s: face f: edge e: ...") naming the first inconsistency and its distance (solids,
// faces and edges numbered from 0 in the order OpenCASCADE's explorer meets them, as the importer numbers them);
// then BRepCheck's verdict on each solid. Shapes without solids (surface models, sewn later) are checked face
// by face only. Raises the tolerances of the shape's edges and vertices where it keeps a gap (above).
void check_self_consistency(const TopoDS_Shape& shape);
// Every solid of the shape that check_self_consistency refuses, each checked on its own (not stopping at the
// first), its fault without the "solid s: " prefix: what a file of several solids can be read without.
std::vector<SolidLeftOut> solid_faults(const TopoDS_Shape& shape);

// How far beyond its stated tolerances a file may hold two things it puts together and still be read, the
// tolerance raised to the gap: its rounding (1e-9 of `coordinate_scale`, the largest coordinate there, at least 1)
// or a ten-thousandth of the solid's `size`.
double file_slack(double size, double coordinate_scale);

// The largest tolerance OpenCASCADE gives the face, its edges and its vertices: how far the file lets its
// boundary curves keep from the surface and from each other.
double file_tolerance(const TopoDS_Face& face);

}  // namespace ratbez::occt::detail
