// Sliver faces taken out of a read solid (sliver_faces.hpp).

#include "sliver_faces.hpp"

#include "self_consistency.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <Precision.hxx>
#include <ShapeAnalysis_CheckSmallFace.hxx>
#include <ShapeAnalysis_Curve.hxx>
#include <ShapeAnalysis_Edge.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Edge.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

namespace ratbez::occt::detail {

namespace {

// A face of no area: its edge `first` is the chain `second` (then `third`, for a triangle) within `tolerance`.
struct Sliver {
    TopoDS_Face face;
    TopoDS_Edge first, second, third;  // third: null for a face of two edges
    double tolerance = 0;              // within which they are
};

// How far the points of `edge` (its vertices and 9 points along it) stray from the curve of `along`, at most.
double stray(const TopoDS_Edge& edge, const TopoDS_Edge& along) {
    double first = 0, last = 0, from = 0, to = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(along, first, last);
    const Handle(Geom_Curve) points = BRep_Tool::Curve(edge, from, to);
    if (curve.IsNull() || points.IsNull()) return std::numeric_limits<double>::infinity();
    ShapeAnalysis_Curve project;
    double worst = 0;
    for (int k = 0; k <= 10; ++k) {
        const gp_Pnt p = k == 0 ? BRep_Tool::Pnt(TopExp::FirstVertex(edge))
                         : k == 10 ? BRep_Tool::Pnt(TopExp::LastVertex(edge))
                                   : points->Value(from + (to - from) * (k - 0.5) / 9.0);
        gp_Pnt foot;
        double t = 0;
        worst = std::max(worst, project.Project(curve, p, Precision::Confusion(), foot, t, first, last, false));
    }
    return worst;
}

// A face of three edges and three vertices one of whose edges runs along the other two, within `tolerance`: a
// triangle of no area (an endgame trackball's shell, Fusion 360: a cylinder's face 0.057 long, its third vertex
// within the file's tolerance of the long edge). The long edge is `first`, the others from its first vertex on.
std::optional<Sliver> flat_triangle(const TopoDS_Face& face, const TopTools_IndexedMapOfShape& edges, double tolerance) {
    for (int k = 1; k <= 3; ++k) {
        const TopoDS_Edge longest = TopoDS::Edge(edges(k).Oriented(TopAbs_FORWARD));
        const TopoDS_Vertex start = TopExp::FirstVertex(longest), end = TopExp::LastVertex(longest);
        if (start.IsNull() || end.IsNull() || start.IsSame(end)) continue;
        TopoDS_Edge from_start, to_end;
        for (int j = 1; j <= 3; ++j) {
            if (j == k) continue;
            const TopoDS_Edge e = TopoDS::Edge(edges(j).Oriented(TopAbs_FORWARD));
            if (TopExp::FirstVertex(e).IsSame(start) || TopExp::LastVertex(e).IsSame(start)) from_start = e;
            else if (TopExp::FirstVertex(e).IsSame(end) || TopExp::LastVertex(e).IsSame(end)) to_end = e;
        }
        if (from_start.IsNull() || to_end.IsNull()) continue;
        if (stray(from_start, longest) <= tolerance && stray(to_end, longest) <= tolerance)
            return Sliver{face, longest, from_start, to_end, tolerance};
    }
    return std::nullopt;
}

// The chain `second` then `third` as one wire from `first`'s first vertex to its last, to stand for `first`.
TopoDS_Wire chain_of(const Sliver& sliver) {
    const TopoDS_Vertex start = TopExp::FirstVertex(sliver.first);
    TopoDS_Wire wire;
    BRep_Builder builder;
    builder.MakeWire(wire);
    const bool second_forward = TopExp::FirstVertex(sliver.second).IsSame(start);
    builder.Add(wire, second_forward ? TopoDS_Shape(sliver.second) : sliver.second.Reversed());
    const TopoDS_Vertex middle = second_forward ? TopExp::LastVertex(sliver.second) : TopExp::FirstVertex(sliver.second);
    builder.Add(wire, TopExp::FirstVertex(sliver.third).IsSame(middle) ? TopoDS_Shape(sliver.third) : sliver.third.Reversed());
    return wire;
}

// The faces with two vertices and two edges that keep within twice the face's file tolerance of each other along
// their length (CheckSingleStrip): each edge may keep its tolerance from where the other is, as OpenCASCADE lets
// two things the file puts together be apart by the sum of their tolerances. The check's own choice, the
// vertices' tolerance alone, missed the mount's lines, whose ends lie 8e-4 from their vertices.
std::vector<Sliver> slivers_of(const TopoDS_Shape& solid) {
    std::vector<Sliver> found;
    ShapeAnalysis_CheckSmallFace check;
    for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next()) {
        const TopoDS_Face& face = TopoDS::Face(it.Current());
        TopTools_IndexedMapOfShape edges;
        for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) edges.Add(e.Current());
        if (edges.Extent() == 3) {
            TopTools_IndexedMapOfShape vertices;
            TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
            try {
                if (vertices.Extent() == 3)
                    if (const std::optional<Sliver> triangle = flat_triangle(face, edges, 2 * file_tolerance(face))) found.push_back(*triangle);
            } catch (const Standard_Failure&) {
                // Not measured, so not a flat triangle (the face reads as it is).
            }
            continue;
        }
        if (edges.Extent() != 2) continue;  // a cheap look first: CheckSingleStrip measures the edges apart
        Sliver sliver{face, {}, {}, {}, 2 * file_tolerance(face)};
        try {
            if (check.CheckSingleStrip(face, sliver.first, sliver.second, sliver.tolerance) && !sliver.first.IsSame(sliver.second))
                found.push_back(sliver);
        } catch (const Standard_Failure&) {
            // Not measured, so not a sliver: the check trims each edge's curve to its range within the curve's own
            // bounds, which fails where an arc runs past its circle's period (a KiCad Hammond box's half discs).
        }
    }
    return found;
}

}  // namespace

TopoDS_Shape without_sliver_faces(const TopoDS_Shape& solid) {
    std::vector<Sliver> slivers = slivers_of(solid);
    if (slivers.empty()) return solid;
    try {
        // Healed on a copy: the projection adds to the edge it projects and may raise its tolerance, which the
        // solid as read, taken when the healing is not, should not carry. The slivers found are the copy's own.
        BRepBuilderAPI_Copy copier(solid);
        const TopoDS_Shape copy = copier.Shape();
        for (Sliver& sliver : slivers) {
            sliver.face = TopoDS::Face(copier.ModifiedShape(sliver.face));
            sliver.first = TopoDS::Edge(copier.ModifiedShape(sliver.first));
            sliver.second = TopoDS::Edge(copier.ModifiedShape(sliver.second));
            if (!sliver.third.IsNull()) sliver.third = TopoDS::Edge(copier.ModifiedShape(sliver.third));
        }
        // The second edge becomes the first wherever it is used, turned to run the same way between the two
        // vertices: the face beside it then runs along the first as it ran along the second. Only that face
        // changes, where ShapeFix_FixSmallFace::ReplaceInCaseOfStrip also makes a new edge and vertices and heals
        // the faces beside with all of ShapeFix_Face.
        Handle(ShapeBuild_ReShape) reshape = new ShapeBuild_ReShape;
        std::vector<TopoDS_Edge> joined;
        for (const Sliver& sliver : slivers) {
            const TopoDS_Edge first = TopoDS::Edge(sliver.first.Oriented(TopAbs_FORWARD));
            const TopoDS_Edge second = TopoDS::Edge(sliver.second.Oriented(TopAbs_FORWARD));
            reshape->Remove(sliver.face);
            if (sliver.third.IsNull()) {
                const bool same_way = TopExp::FirstVertex(first).IsSame(TopExp::FirstVertex(second));
                reshape->Replace(second, same_way ? first : TopoDS::Edge(first.Reversed()));
                joined.push_back(first);
                continue;
            }
            // A flat triangle: its long edge becomes the other two wherever it is used (ShapeBuild_ReShape puts a
            // wire's edges in place of an edge, as ShapeUpgrade_WireDivide has it do).
            reshape->Replace(first, chain_of(sliver));
            joined.push_back(second);
            joined.push_back(TopoDS::Edge(sliver.third.Oriented(TopAbs_FORWARD)));
        }
        const TopoDS_Shape healed = reshape->Apply(copy);
        // The faces beside a sliver now run along the edge that was only the other's: each gets its curve on it,
        // projected (ShapeFix_Edge), and the edge the tolerance that curve keeps from it.
        ShapeFix_Edge fix;
        for (TopExp_Explorer it(healed, TopAbs_FACE); it.More(); it.Next()) {
            const TopoDS_Face& face = TopoDS::Face(it.Current());
            for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
                const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
                if (std::none_of(joined.begin(), joined.end(), [&](const TopoDS_Edge& j) { return j.IsSame(edge); })) continue;
                if (ShapeAnalysis_Edge().HasPCurve(edge, face)) continue;
                fix.FixAddPCurve(edge, face, false, file_tolerance(face));
                fix.FixSameParameter(edge);
            }
        }
        // Healing that leaves the solid invalid is not taken: the solid goes on as read, and its mesh says why.
        return !healed.IsNull() && BRepCheck_Analyzer(healed).IsValid() ? healed : solid;
    } catch (const Standard_Failure&) {
        return solid;  // as read: the conversion and the mesh say what is wrong with it
    }
}

}  // namespace ratbez::occt::detail
