// Arcs of a circle on OpenCASCADE's circle (see circle_edges.hpp).

#include "circle_edges.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Curve.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

#include "exact_edges.hpp"
#include "ratbez/occt/convert_options.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt::detail {
namespace {

// How far a refitted p-curve may be from its edge, relative to the size (the edge's tolerance then covers it).
constexpr double kRefit = 1e-6;

struct Reading {
    double volume = 0, area = 0;
};

// OpenCASCADE's fixed rule (BRepGProp without eps: FreeCAD's Shape.Volume and Area).
Reading fixed_rule(const TopoDS_Shape& shape) {
    GProp_GProps volume, area;
    BRepGProp::VolumeProperties(shape, volume);
    BRepGProp::SurfaceProperties(shape, area);
    return {volume.Mass(), area.Mass()};
}

// The OCCT edge (a piece of an edge of ours on `circle`) on OCCT's circle between its own vertices, its p-curves on
// each face refitted to the circle's angle; null when its ends do not make an arc of the circle or OCCT cannot refit.
TopoDS_Edge on_circle(const gp_Circ& circle, const TopoDS_Edge& edge, const TopTools_ListOfShape& faces, double tolerance) {
    const TopoDS_Edge forward = TopoDS::Edge(edge.Oriented(TopAbs_FORWARD));
    TopoDS_Vertex start, end;
    TopExp::Vertices(forward, start, end);
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(forward, first, last);
    if (start.IsNull() || end.IsNull() || curve.IsNull()) return {};
    const std::optional<std::pair<double, double>> range =
        arc_range(circle, BRep_Tool::Pnt(start), curve->Value((first + last) / 2), BRep_Tool::Pnt(end), start.IsSame(end));
    if (!range) return {};
    BRep_Builder builder;
    TopoDS_Edge made;
    builder.MakeEdge(made, new Geom_Circle(circle), tolerance);
    builder.Add(made, start.Oriented(TopAbs_FORWARD));
    builder.Add(made, end.Oriented(TopAbs_REVERSED));
    builder.Range(made, range->first, range->second);
    for (const TopoDS_Shape& face : faces) {
        double from = 0, to = 0;
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(forward, TopoDS::Face(face), from, to);
        if (pcurve.IsNull()) return {};
        builder.UpdateEdge(made, pcurve, TopoDS::Face(face), tolerance);
        builder.Range(made, TopoDS::Face(face), from, to);
    }
    builder.SameRange(made, Standard_False);
    builder.SameParameter(made, Standard_False);
    // Fitted to a hundredth of the tolerance (the edge keeps the tolerance): OCCT's fixed rule integrates over the
    // p-curves, and reads the loft through a circle, a square and a circle to 4e-12 so (1e-10 fitted to it).
    BRepLib::SameParameter(made, 1e-2 * tolerance);
    return BRep_Tool::SameParameter(made) ? made : TopoDS_Edge();
}

}  // namespace

std::optional<SplitSolid> with_circle_edges(const Solid& solid, const ConvertedSolid& converted) {
    try {
        const double fit = exact_fit(solid);
        const double size = std::max(1.0, solid.bounding_box().diagonal());
        BRepBuilderAPI_Copy copier(converted.solid);  // convert's solid stays as it is: the fallback
        TopTools_IndexedDataMapOfShapeListOfShape faces_of;
        TopExp::MapShapesAndUniqueAncestors(copier.Shape(), TopAbs_EDGE, TopAbs_FACE, faces_of);
        const Handle(ShapeBuild_ReShape) context = new ShapeBuild_ReShape;
        int replaced = 0;
        for (const auto& [edge, pieces] : converted.edges) {
            if (edge->degenerate) continue;
            const std::optional<EdgeCircle> arc = edge_circle(*edge, fit);
            if (!arc) continue;
            const gp_Circ circle(gp_Ax2(to_occt_point(arc->centre), to_occt_direction(arc->normal), to_occt_direction(arc->x)),
                                 arc->radius);
            for (const TopoDS_Edge& piece : pieces) {
                const TopoDS_Edge copy = TopoDS::Edge(copier.ModifiedShape(piece));
                const int index = faces_of.FindIndex(copy);
                if (index == 0) continue;
                const TopTools_ListOfShape& faces = faces_of(index);
                const bool seam = std::any_of(faces.begin(), faces.end(),
                                              [&](const TopoDS_Shape& f) { return BRep_Tool::IsClosed(copy, TopoDS::Face(f)); });
                if (seam) continue;
                const TopoDS_Edge made = on_circle(circle, copy, faces, converted.tolerance);
                if (made.IsNull() || BRep_Tool::Tolerance(made) > kRefit * size) continue;
                context->Replace(copy.Oriented(TopAbs_FORWARD), made);
                ++replaced;
            }
        }
        if (replaced == 0) return std::nullopt;
        const TopoDS_Shape result = context->Apply(copier.Shape());
        if (result.ShapeType() != TopAbs_SOLID) return std::nullopt;
        // Each edge given what its p-curves measure (BOPAlgo's measure, honest_tolerances), the vertices then covering
        // their edges. (BRepLib::UpdateTolerances verifying faces raised every tolerance of the loft to 3.2e-6.)
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer it(result, TopAbs_FACE); it.More(); it.Next()) faces.push_back(TopoDS::Face(it.Current()));
        if (!honest_tolerances(faces, kRefit * size)) return std::nullopt;
        BRepLib::UpdateTolerances(result);
        if (!BRepCheck_Analyzer(result).IsValid()) return std::nullopt;
        // The fixed rule reads the result as it read convert's solid, or to kGPropTolerance.
        const Reading before = fixed_rule(converted.solid), after = fixed_rule(result);
        const double v = solid.volume(), a = solid.area();
        const auto reads = [](double now, double then, double exact) {
            return std::abs(now - exact) <= std::max(std::abs(then - exact), kGPropTolerance * std::abs(exact));
        };
        if (!reads(after.volume, before.volume, v) || !reads(after.area, before.area, a)) return std::nullopt;
        SplitSolid circles{TopoDS::Solid(result), {}};
        for (TopExp_Explorer faces(converted.solid, TopAbs_FACE); faces.More(); faces.Next())
            for (TopExp_Explorer now(context->Apply(copier.ModifiedShape(faces.Current())), TopAbs_FACE); now.More(); now.Next())
                circles.original_face.Bind(now.Current(), faces.Current());
        return circles;
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

}  // namespace ratbez::occt::detail
