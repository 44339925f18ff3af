#pragma once
// Faces split where their surface is only C0 inside, for OpenCASCADE's fixed Gauss rule (FreeCAD's
// Shape.Volume, Area, CenterOfMass). Internal to kernel/occt.
//
// The natural conversion (topology.hpp) leaves no C0 knot inside an untrimmed face: arcs go over in their
// one-span form, rough faces as Bézier patches. A trimmed face keeps its surface, and a face trimmed on a
// cylinder, cone or sphere read from a file holds it in the NURBS Book's circle form (degree 2, double knots:
// C0 in the parameter), which one Gauss rule over the face reads up to 2.5e-3 off; its p-curves cannot follow
// the one-span arc form's parameter exactly. Split at those knots (ShapeUpgrade_ShapeDivideContinuity, C1
// criterion: the face's trim loops cut along the knot lines, exactly, and edges with C0 curves at their
// knots), each piece reads to 1e-7 or better (FreeCAD's sphere minus a box: volume 2.2e-4 off whole, 6e-10
// split; tests/freecad/test_step_in_freecad.py measures every corpus solid).

#include <TopTools_DataMapOfShapeShape.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <vector>

#include "ratbez/progress.hpp"

namespace ratbez::occt::detail {

// The edges of `faces` whose p-curve there lies further from the 3D curve than the edge's tolerance (the measure
// of BOPAlgo_ArgumentAnalyzer's CurveOnSurfaceMode, FreeCAD's BOP check) given that distance as tolerance, if
// it is at most `limit`; false when one is further. For p-curves made by OpenCASCADE (SameParameter, projection).
// `progress` (optional) is polled before each face and may throw to stop.
bool honest_tolerances(const std::vector<TopoDS_Face>& faces, double limit, const Progress& progress = {});
// The same for one edge on one face.
bool honest_tolerance(const TopoDS_Edge& edge, const TopoDS_Face& face, double limit);

// The solid split, and for every face of the result the face of the input it is (a piece of): what check()
// needs to name our faces in its findings on the solid as handed out.
struct SplitSolid {
    TopoDS_Solid solid;
    TopTools_DataMapOfShapeShape original_face;
};

// When a face's surface is C0 inside, or an edge's curve: `solid` with those faces and edges split at their C0
// knots, where a knot line passing within the solid's largest edge tolerance of a vertex cuts no sliver edge (the
// piece is dropped and its ends merged). An edge alone does not matter to the fixed rule, but BOPAlgo's analysis
// (FreeCAD's Check geometry) flags it. Otherwise `solid` itself, and also when OpenCASCADE fails or leaves an invalid shape or other than one solid, or raises an
// edge's tolerance more than kToleranceGrowth times above `reach` (the largest tolerance a face of the solid may
// need, ConvertedSolid::tolerance) or its largest edge tolerance.
// `progress` is polled while the split faces' edges are measured (most of the time on a large part) and may throw.
SplitSolid split_at_c0_knots(const TopoDS_Solid& solid, double reach, const Progress& progress = {});

}  // namespace ratbez::occt::detail
