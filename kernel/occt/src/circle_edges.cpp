// Arcs of a circle on OpenCASCADE's circle (see circle_edges.hpp).

#include "circle_edges.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <gp_Pnt2d.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax2.hxx>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "exact_edges.hpp"
#include "ratbez/occt/geometry.hpp"
#include "smooth_arcs.hpp"

namespace ratbez::occt::detail {
namespace {

// How far a refitted p-curve may be from its edge, relative to the size (the edge's tolerance then covers it).
constexpr double kRefit = 1e-6;

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
    // p-curves, and reads examples/ruled.json to 2.4e-11 so (2.1e-11 with the kernel's arcs; a loft through a
    // circle, a square and a circle 1e-10 with them fitted to the tolerance itself).
    BRepLib::SameParameter(made, 1e-2 * tolerance);
    return BRep_Tool::SameParameter(made) ? made : TopoDS_Edge();
}

// Whether the edge's p-curve on the face keeps within a tenth of the edge's tolerance of its 3D curve at 64 points:
// the refit is then certainly within the tolerance, and the exact measure (BRepLib_CheckCurveOnSurface, a global
// search: 0.14 s for the 18 arcs of FreeCAD's drilled plate) is not needed.
bool well_within_tolerance(const TopoDS_Edge& edge, const TopoDS_Face& face) {
    double first = 0, last = 0, from = 0, to = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, from, to);
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    if (curve.IsNull() || pcurve.IsNull() || surface.IsNull() || from != first || to != last) return false;
    const double bound = 0.1 * BRep_Tool::Tolerance(edge);
    for (int k = 0; k <= 64; ++k) {
        const double t = first + (last - first) * k / 64;
        const gp_Pnt2d uv = pcurve->Value(t);
        if (!(surface->Value(uv.X(), uv.Y()).Distance(curve->Value(t)) <= bound)) return false;
    }
    return true;
}

// The kernel's edges that are arcs on the rim of a face that does not turn with them: every face of each is a plane
// or a surface face whose rows of control points along that side are not all arcs (a circle ruled to a polygon, a
// loft through a circle, a square and a circle), and one at least is such a surface face. A face that turns with its
// rims, all its rows along them arcs (cylinders, cones, spheres, tori and revolutions, as files hold them), keeps the
// kernel's arcs: refitted p-curves there made OCCT's adaptive measures of FreeCAD's drilled plate 5 times slower
// (3 s to 17 s). (The rule first took faces ruled toward a curve that is not an arc only; the loft's rims then
// stayed B-splines, and Part Chamfer of its sharp edges worked at 23 of 49 sizes, 41 with them on circles.)
std::unordered_set<const Edge*> rims_of_faces_not_turning_with_them(const Solid& solid, double fit) {
    std::unordered_map<const Edge*, bool> rim;
    for (const Face& face : solid.faces()) {
        if (face.kind() == Face::Kind::planar) continue;
        if (face.kind() != Face::Kind::surface) {
            for_each_coedge(face, [&](const Coedge& c) { rim[c.edge.get()] = false; });
            continue;
        }
        // Whether every row along u (along v) is an arc: the face turns with its v_min and v_max (u_min, u_max) sides.
        const bool turns_along_u = find_arc(face.surface(), true, fit).has_value();
        const bool turns_along_v = find_arc(face.surface(), false, fit).has_value();
        for (std::size_t s = 0; s < 4; ++s) {
            const bool along_u = s == static_cast<std::size_t>(Side::v_min) || s == static_cast<std::size_t>(Side::v_max);
            const bool turns = along_u ? turns_along_u : turns_along_v;
            const auto [it, inserted] = rim.try_emplace(face.sides()[s].edge.get(), !turns);
            if (!inserted) it->second = it->second && !turns;
        }
    }
    std::unordered_set<const Edge*> rims;
    for (const auto& [edge, on_rim] : rim)
        if (on_rim) rims.insert(edge);
    return rims;
}

}  // namespace

std::optional<SplitSolid> with_circle_edges(const Solid& solid, const ConvertedSolid& converted) {
    try {
        const double fit = exact_fit(solid);
        const double size = std::max(1.0, solid.bounding_box().diagonal());
        const std::unordered_set<const Edge*> rims = rims_of_faces_not_turning_with_them(solid, fit);
        if (rims.empty()) return std::nullopt;
        BRepBuilderAPI_Copy copier(converted.solid);  // convert's solid stays as it is: the fallback
        TopTools_IndexedDataMapOfShapeListOfShape faces_of;
        TopExp::MapShapesAndUniqueAncestors(copier.Shape(), TopAbs_EDGE, TopAbs_FACE, faces_of);
        const Handle(ShapeBuild_ReShape) context = new ShapeBuild_ReShape;
        std::vector<TopoDS_Edge> made_edges;
        for (const auto& [edge, pieces] : converted.edges) {
            if (edge->degenerate || !rims.contains(edge)) continue;
            const std::optional<EdgeCircle> arc = edge_circle(*edge, fit);
            if (!arc) continue;
            const gp_Circ circle(gp_Ax2(to_occt_point(arc->centre), to_occt_direction(arc->normal), to_occt_direction(arc->x)),
                                 arc->radius);
            for (const TopoDS_Edge& piece : pieces) {
                const TopoDS_Edge copy = TopoDS::Edge(copier.ModifiedShape(piece));
                const int index = faces_of.FindIndex(copy);
                if (index == 0) continue;
                const TopTools_ListOfShape& faces = faces_of(index);
                // Not a seam, and not beside a face C0 inside, which handed_out splits at its knots afterwards
                // (c0_split.hpp): the split's own p-curves of such an edge came out beyond its tolerance (FreeCAD's
                // RLF_7030 inductor: its face then went out whole, misread by the fixed rule).
                const bool keep = std::any_of(faces.begin(), faces.end(), [&](const TopoDS_Shape& f) {
                    return BRep_Tool::IsClosed(copy, TopoDS::Face(f)) || BRep_Tool::Surface(TopoDS::Face(f))->Continuity() == GeomAbs_C0;
                });
                if (keep) continue;
                const TopoDS_Edge made = on_circle(circle, copy, faces, converted.tolerance);
                if (made.IsNull() || BRep_Tool::Tolerance(made) > kRefit * size) continue;
                context->Replace(copy.Oriented(TopAbs_FORWARD), made);
                made_edges.push_back(made);
            }
        }
        if (made_edges.empty()) return std::nullopt;
        const TopoDS_Shape result = context->Apply(copier.Shape());
        if (result.ShapeType() != TopAbs_SOLID) return std::nullopt;
        // Each circle given what its refitted p-curves measure (BOPAlgo's measure, honest_tolerance), the vertices
        // then covering their edges. (BRepLib::UpdateTolerances verifying faces raised every tolerance of the loft
        // to 3.2e-6.)
        TopTools_IndexedDataMapOfShapeListOfShape faces_now;
        TopExp::MapShapesAndUniqueAncestors(result, TopAbs_EDGE, TopAbs_FACE, faces_now);
        for (const TopoDS_Edge& made : made_edges) {
            const int index = faces_now.FindIndex(made);
            if (index == 0) return std::nullopt;
            for (const TopoDS_Shape& face : faces_now(index))
                if (!well_within_tolerance(made, TopoDS::Face(face)) && !honest_tolerance(made, TopoDS::Face(face), kRefit * size))
                    return std::nullopt;
        }
        BRepLib::UpdateTolerances(result);
        if (!BRepCheck_Analyzer(result).IsValid()) return std::nullopt;
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
