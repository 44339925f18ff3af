// Faces split at C0 knots (see c0_split.hpp).

#include "c0_split.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRepLib.hxx>
#include <BRepLib_CheckCurveOnSurface.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Wireframe.hxx>
#include <ShapeUpgrade_ShapeDivideContinuity.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <utility>
#include <vector>

namespace ratbez::occt::detail {
namespace {

// How far above the solid's largest edge tolerance a split piece's edges may be. SameParameter leaves some new
// edges' p-curves further from their curves than the tolerance it gives them, which FreeCAD's BOP check reports
// (InvalidCurveOnSurface: Idf's CAP_50SGV_8_10.stp, split, had 7 such edges, up to 8e-5 in a file of 2.3e-4):
// such an edge gets the distance as its tolerance; beyond this the split costs more than it gains.
constexpr double kToleranceGrowth = 10;

// Whether a face's surface is C0 inside, or an edge's curve over its range (as BOPAlgo's analysis reads it). A read
// solid whose faces all go back on the file's cylinders and planes has none of the first, and may still hold an
// arc the kernel keeps in its rational form, C0 at its knots by multiplicity, beside a face that stays a B-spline
// (FreeCAD's drilled plate: "BOPAlgo GeomAbs_C0" on the ellipses beside its extrusions).
bool has_c0_geometry(const TopoDS_Solid& solid) {
    for (TopExp_Explorer faces(solid, TopAbs_FACE); faces.More(); faces.Next()) {
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(faces.Current()));
        if (!surface.IsNull() && surface->Continuity() == GeomAbs_C0) return true;
    }
    for (TopExp_Explorer edges(solid, TopAbs_EDGE); edges.More(); edges.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
        if (!BRep_Tool::Degenerated(edge) && BRep_Tool::IsGeometric(edge) && BRepAdaptor_Curve(edge).Continuity() == GeomAbs_C0)
            return true;
    }
    return false;
}

// `split` without the slivers its division cut: a knot line passing closer to a vertex than `precision` (the
// solid's largest edge tolerance) cuts a piece that short off the edge there. 061_Maybe_Tophat_assm.STEP: a knot
// 2.8e-8 rad before the quarter point where two arcs meet gave two edges 6.5e-8 long that the BOP check flags
// (TooSmallEdge, SelfIntersect). Each such new edge is dropped and its ends merged (ShapeFix_Wireframe, recorded
// in `context`, so the division's record of each face's pieces still applies); a limit angle below 0 makes every
// merge a drop, where ShapeFix would otherwise join the sliver to its neighbour into one curve C0 at the join
// (GeomAbs_C0 in the BOP check). Edges the division left as they were keep theirs, short or not.
TopoDS_Shape without_slivers(const TopoDS_Shape& split, const TopoDS_Shape& divided, double precision,
                             const Handle(ShapeBuild_ReShape)& context) {
    TopTools_IndexedMapOfShape kept;
    TopExp::MapShapes(divided, TopAbs_EDGE, kept);
    ShapeFix_Wireframe fix(split);
    fix.SetContext(context);
    fix.SetPrecision(precision);
    TopTools_MapOfShape small, multiple;
    TopTools_DataMapOfShapeListOfShape edge_faces, face_small;
    fix.CheckSmallEdges(small, edge_faces, face_small, multiple);
    TopTools_MapOfShape slivers;
    for (TopTools_MapIteratorOfMapOfShape edge(small); edge.More(); edge.Next())
        if (!kept.Contains(edge.Key())) slivers.Add(edge.Key());
    if (slivers.IsEmpty()) return split;
    constexpr double kAlwaysDrop = -0.5;  // radians; ShapeFix reads -1 as no limit
    fix.MergeSmallEdges(slivers, edge_faces, face_small, multiple, Standard_True, kAlwaysDrop);
    return fix.Shape();
}

}  // namespace

bool honest_tolerance(const TopoDS_Edge& edge, const TopoDS_Face& face, double limit) {
    if (BRep_Tool::Degenerated(edge)) return true;
    BRepLib_CheckCurveOnSurface measure(edge, face);
    measure.Perform();
    if (!measure.IsDone() || measure.MaxDistance() > limit) return false;
    if (measure.MaxDistance() > BRep_Tool::Tolerance(edge)) BRep_Builder().UpdateEdge(edge, 1.01 * measure.MaxDistance());
    return true;
}

bool honest_tolerances(const std::vector<TopoDS_Face>& faces, double limit, const Progress& progress) {
    // Polled edge by edge: one face of a large part (a plate with its holes) held 5 s of the measures.
    std::vector<std::pair<TopoDS_Edge, const TopoDS_Face*>> uses;
    for (const TopoDS_Face& face : faces)
        for (TopExp_Explorer edges(face, TopAbs_EDGE); edges.More(); edges.Next())
            uses.emplace_back(TopoDS::Edge(edges.Current()), &face);
    for (std::size_t k = 0; k < uses.size(); ++k) {
        if (progress) progress(static_cast<double>(k) / static_cast<double>(uses.size()));
        if (!honest_tolerance(uses[k].first, *uses[k].second, limit)) return false;
    }
    return true;
}

SplitSolid split_at_c0_knots(const TopoDS_Solid& solid, double reach, const Progress& progress) {
    SplitSolid unchanged{solid, {}};
    for (TopExp_Explorer faces(solid, TopAbs_FACE); faces.More(); faces.Next())
        unchanged.original_face.Bind(faces.Current(), faces.Current());
    if (!has_c0_geometry(solid)) return unchanged;
    try {
        // On a copy: the division keeps the uncut faces' edges, and SameParameter and honest_tolerances below change
        // them in place, so a split given up would hand back `solid` altered (a read solid's measured tolerances
        // then left one of its faces with a self-intersecting wire).
        BRepBuilderAPI_Copy copier(solid);
        ShapeUpgrade_ShapeDivideContinuity divide(copier.Shape());
        divide.SetBoundaryCriterion(GeomAbs_C1);
        divide.SetPCurveCriterion(GeomAbs_C1);
        divide.SetSurfaceCriterion(GeomAbs_C1);
        if (!divide.Perform()) return unchanged;
        const double largest_edge = BRep_Tool::MaxTolerance(solid, TopAbs_EDGE);
        TopoDS_Shape result = without_slivers(divide.Result(), copier.Shape(), largest_edge, divide.GetContext());
        // The new edges along the knot lines come without SameParameter: computed here, they make the
        // pieces valid (BRepCheck flagged every split face before).
        const double tolerance = std::max(largest_edge, reach);
        BRepLib::SameParameter(result, largest_edge, Standard_True);
        if (result.ShapeType() != TopAbs_SOLID) return unchanged;
        // Each face of the input became itself, or a compound / shell of its pieces (the reshape's record);
        // SameParameter changes tolerances in place, not the faces' identity.
        SplitSolid split{TopoDS::Solid(result), {}};
        // Every face's edges measured, not only the pieces': SameParameter, forced, recomputes the p-curves of the
        // uncut faces' edges too, and gives them its sampled deviation, which BOPAlgo's measure can exceed (a read
        // solid's edges carry their own measured tolerances, topology.cpp).
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next()) {
            const TopoDS_Shape pieces = divide.GetContext()->Apply(copier.ModifiedShape(face.Current()));
            for (TopExp_Explorer piece(pieces, TopAbs_FACE); piece.More(); piece.Next()) {
                split.original_face.Bind(piece.Current(), face.Current());
                faces.push_back(TopoDS::Face(piece.Current()));
            }
        }
        if (BRep_Tool::MaxTolerance(result, TopAbs_EDGE) > kToleranceGrowth * tolerance ||
            !honest_tolerances(faces, kToleranceGrowth * tolerance, progress))
            return unchanged;
        BRepLib::UpdateTolerances(split.solid, Standard_True);  // vertices and faces cover their raised edges
        // Valid only now: SameParameter's sampled tolerances can be short of BRepCheck's too until measured.
        if (!BRepCheck_Analyzer(split.solid).IsValid()) return unchanged;
        return split;
    } catch (const Standard_Failure&) {
        return unchanged;
    }
}

}  // namespace ratbez::occt::detail
