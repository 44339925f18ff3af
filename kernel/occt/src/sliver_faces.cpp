// Sliver faces taken out of a read solid (sliver_faces.hpp).

#include "sliver_faces.hpp"

#include "self_consistency.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <ShapeAnalysis_CheckSmallFace.hxx>
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

#include <algorithm>
#include <vector>

namespace ratbez::occt::detail {

namespace {

struct Sliver {
    TopoDS_Face face;
    TopoDS_Edge first, second;  // the two edges that are one
    double tolerance = 0;       // within which they are
};

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
        if (edges.Extent() != 2) continue;  // a cheap look first: CheckSingleStrip measures the edges apart
        Sliver sliver{face, {}, {}, 2 * file_tolerance(face)};
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
            const bool same_way = TopExp::FirstVertex(first).IsSame(TopExp::FirstVertex(second));
            reshape->Replace(second, same_way ? first : TopoDS::Edge(first.Reversed()));
            reshape->Remove(sliver.face);
            joined.push_back(first);
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
