#include "self_consistency.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRepCheck_Status.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <Standard_OutOfMemory.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeReal.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ratbez/error.hpp"

namespace ratbez::occt::detail {
namespace {

// Points compared along each edge (its ends and between).
constexpr int kSamples = 9;

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

std::string point_text(const gp_Pnt& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.X(), p.Y(), p.Z());
    return text;
}

double coordinate_scale(const gp_Pnt& at) { return std::max({1.0, std::abs(at.X()), std::abs(at.Y()), std::abs(at.Z())}); }

// How far apart OpenCASCADE lets two things be that the file puts together: the sum of their tolerances,
// and a few ulps of the coordinates for files written with tolerance 0.
double allowed(double tolerance_a, double tolerance_b, const gp_Pnt& at) {
    return tolerance_a + tolerance_b + 1e-12 * coordinate_scale(at);
}

}  // namespace

// Exporters write tolerances they do not measure. A gap beyond them by no more than this is the file's slack, not
// a fault: its rounding, 1e-9 of the coordinates (exporters write 1e-7, OpenCASCADE's least tolerance, whatever
// the model's size, and a part 600 mm across, 11752.stp of pythonocc-demos, has p-curves 4e-7 off their edges'
// curves between the points OpenCASCADE's own check compares: ShapeAnalysis_Edge finds 2.5e-9 there), or a
// ten-thousandth of the solid's size (Autodesk's translator wrote a Voron bed carriage's nut, 13.5 across, with
// an edge 2e-4 off its B-spline face at tolerance 2e-5, which BRepCheck's 23 points pass; a mains plug panel,
// 116 across, with loops 8e-7 off their planes at tolerance 2e-7). The tolerance of the edge, vertex or face is
// raised to the gap found (kept), so that the conversion, the meshes and the checks downstream allow for what
// the file holds, as ShapeFix's SameParameter would; a hundredth of the 1% a file may declare
// (Importer::plausible_tolerance), so that a vertex or a p-curve moved visibly is still refused.
double file_slack(double size, double coordinate_scale) { return std::max(1e-9 * coordinate_scale, 1e-4 * size); }

double file_tolerance(const TopoDS_Face& face) {
    double tolerance = BRep_Tool::Tolerance(face);
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next())
        tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Edge(it.Current())));
    for (TopExp_Explorer it(face, TopAbs_VERTEX); it.More(); it.Next())
        tolerance = std::max(tolerance, BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())));
    return tolerance;
}

namespace {

bool within_slack(double gap, double limit, const gp_Pnt& at, double size) { return gap <= limit + file_slack(size, coordinate_scale(at)); }

void keep_edge_gap(const TopoDS_Edge& edge, double gap) {
    if (gap <= BRep_Tool::Tolerance(edge)) return;
    BRep_Builder builder;
    builder.UpdateEdge(edge, gap);
    // OpenCASCADE's rule: a vertex's tolerance is at least its edges'.
    for (TopExp_Explorer it(edge, TopAbs_VERTEX); it.More(); it.Next())
        if (BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())) < gap) builder.UpdateVertex(TopoDS::Vertex(it.Current()), gap);
}

void keep_vertex_gap(const TopoDS_Vertex& vertex, double gap) {
    if (gap > BRep_Tool::Tolerance(vertex)) BRep_Builder().UpdateVertex(vertex, gap);
}

// How far a p-curve may keep from its edge's 3D curve where the 3D curve itself lies on the face's surface: a
// thousandth of the model's size. STEP files mostly carry no p-curves (31 of 32 such files of 108 tried from
// public repositories: SolidWorks, Fusion, Inventor, CATIA), and OpenCASCADE's reader fits its own to its 23
// points on the curve, gives the edge a tolerance from those points (1e-7), and between them the fit strays
// (1.3e-3 on a sphere near its pole, a 3D printer part 50 mm across). The file's geometry, the 3D curve on its
// surface, is consistent; the importer fits its own p-curves from the 3D curves (pcurve_fit.hpp), with
// OpenCASCADE's as the first guess only. Beyond this bound a p-curve is the file's fault (a p-curve moved off).
constexpr double kLoosePcurve = 1e-3;

// An edge of a face: its 3D curve passes through its vertices and its p-curve on the face's surface follows
// its 3D curve, within the edge's and the vertices' tolerances, or, where OpenCASCADE made the p-curve loosely,
// the 3D curve lies on the surface within them (kLoosePcurve). `size`: the model's.
void check_edge_on_face(const TopoDS_Edge& edge, const TopoDS_Face& face, double size) {
    const double edge_tolerance = BRep_Tool::Tolerance(edge);
    TopoDS_Vertex first_vertex, last_vertex;
    TopExp::Vertices(edge, first_vertex, last_vertex);
    require(!first_vertex.IsNull() && !last_vertex.IsNull(), "shape", "the edge has no vertices (its loop is open)");
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    require(!surface.IsNull(), "shape", "the face has no surface");
    double p_first = 0, p_last = 0;
    const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, p_first, p_last);
    require(!pcurve.IsNull(), "shape", "the edge has no curve on the face's surface");
    require(std::isfinite(p_first) && std::isfinite(p_last), "shape", "the edge's p-curve has an infinite range");
    if (BRep_Tool::Degenerated(edge)) {
        // A collapsed edge (a pole): its p-curve stays at its vertex.
        const gp_Pnt vertex = BRep_Tool::Pnt(first_vertex);
        for (int k = 0; k < kSamples; ++k) {
            const double t = p_first + (p_last - p_first) * k / (kSamples - 1);
            const gp_Pnt2d uv = pcurve->Value(t);
            const double gap = surface->Value(uv.X(), uv.Y()).Distance(vertex);
            const double limit = allowed(edge_tolerance, BRep_Tool::Tolerance(first_vertex), vertex);
            if (gap > limit && within_slack(gap, limit, vertex, size)) {
                keep_edge_gap(edge, gap);
                continue;
            }
            require(gap <= limit, "shape", [&] {
                return "the collapsed edge's p-curve leaves its vertex " + point_text(vertex) + " by " + number(gap) +
                       ", more than the file's tolerance " + number(limit);
            });
        }
        return;
    }
    double first = 0, last = 0;
    const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
    require(!curve.IsNull(), "shape", "the edge has no 3D curve");
    require(std::isfinite(first) && std::isfinite(last), "shape", "the edge's curve has an infinite range");
    for (const auto& [vertex, t] : {std::pair{first_vertex, first}, std::pair{last_vertex, last}}) {
        const gp_Pnt at = BRep_Tool::Pnt(vertex);
        const double gap = curve->Value(t).Distance(at);
        const double limit = allowed(edge_tolerance, BRep_Tool::Tolerance(vertex), at);
        if (gap > limit && within_slack(gap, limit, at, size)) {
            keep_vertex_gap(vertex, gap);
            continue;
        }
        require(gap <= limit, "shape", [&] {
            return "the vertex " + point_text(at) + " is " + number(gap) + " from the end of its edge's curve, more than the file's tolerance " +
                   number(limit);
        });
    }
    // The p-curve runs its range as the 3D curve runs its own (proportionally where the file does not claim
    // the same parameter).
    std::optional<ShapeAnalysis_Surface> near_surface;  // made for the first loose sample, kept along the edge
    for (int k = 0; k < kSamples; ++k) {
        const double s = static_cast<double>(k) / (kSamples - 1);
        const gp_Pnt on_curve = curve->Value(first + (last - first) * s);
        const gp_Pnt2d uv = pcurve->Value(p_first + (p_last - p_first) * s);
        const gp_Pnt on_surface = surface->Value(uv.X(), uv.Y());
        double gap = on_surface.Distance(on_curve);
        const double limit = allowed(2 * edge_tolerance, 0, on_curve);
        // Same parameters bring the two curves' points together; where a file's p-curve runs at another pace
        // (FreeCAD's Idf parts: 5e-4 apart at equal parameters, on the 3D curve all along) the points must still
        // lie on the 3D curve: what the solid's shape depends on.
        if (gap > limit) {
            GeomAPI_ProjectPointOnCurve projection(on_surface, curve, first, last);
            if (projection.NbPoints() > 0) gap = std::min(gap, projection.LowerDistance());
        }
        if (gap > limit && within_slack(gap, limit, on_curve, 0)) {  // rounding: kept as the vertices' gaps are
            keep_edge_gap(edge, gap);
            continue;
        }
        if (gap > limit && gap <= kLoosePcurve * size) {
            // The 3D curve's point on the surface, found from where the p-curve puts it (a local search). On it,
            // the p-curve is OpenCASCADE's loose fit, which the importer fits again: the edge keeps its tolerance.
            if (!near_surface) near_surface.emplace(surface);
            near_surface->NextValueOfUV(uv, on_curve, limit);
            if (near_surface->Gap() <= limit) continue;
        }
        if (gap > limit && within_slack(gap, limit, on_curve, size)) {  // the 3D curve itself off the surface
            keep_edge_gap(edge, gap);
            continue;
        }
        require(gap <= limit, "shape", [&] {
            return "its p-curve on the face is " + number(gap) + " from its 3D curve at " + point_text(on_surface) +
                   ", more than the file's tolerance " + number(limit);
        });
    }
}

// A face: each edge on it, and each loop closed (every vertex of a wire ends as many of its edges as it starts).
void check_face(const TopoDS_Face& face, double size) {
    int e = 0;
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next(), ++e) {
        try {
            check_edge_on_face(TopoDS::Edge(it.Current()), face, size);
        } catch (const Error& error) {
            throw Error("shape", "edge " + std::to_string(e) + ": " + std::string(error.reason()));
        }
    }
    for (TopExp_Explorer wires(face, TopAbs_WIRE); wires.More(); wires.Next()) {
        std::map<const void*, int> ends;  // a vertex's TShape: +1 where an edge starts, -1 where one ends
        for (TopExp_Explorer it(wires.Current(), TopAbs_EDGE); it.More(); it.Next()) {
            TopoDS_Vertex start, end;
            TopExp::Vertices(TopoDS::Edge(it.Current()), start, end, /*CumOri=*/true);
            if (start.IsNull() || end.IsNull()) continue;  // reported by check_edge_on_face
            ++ends[start.TShape().get()];
            --ends[end.TShape().get()];
        }
        for (const auto& entry : ends)
            require(entry.second == 0, "shape", "a loop of the face is not closed (an edge ends where no edge of the loop starts)");
    }
}

// A shell of a solid: closed (every edge but a collapsed one used twice) and oriented (in opposite directions).
void check_shell(const TopoDS_Shape& shell, const TopTools_IndexedMapOfShape& faces) {
    TopTools_IndexedMapOfShape edges;
    std::vector<int> forward, reversed, first_face;
    for (TopExp_Explorer f(shell, TopAbs_FACE); f.More(); f.Next())
        for (TopExp_Explorer it(f.Current(), TopAbs_EDGE); it.More(); it.Next()) {
            if (BRep_Tool::Degenerated(TopoDS::Edge(it.Current()))) continue;
            const int index = edges.Add(it.Current());
            if (static_cast<std::size_t>(index) > forward.size()) {
                forward.push_back(0);
                reversed.push_back(0);
                first_face.push_back(faces.FindIndex(f.Current()) - 1);
            }
            (it.Current().Orientation() == TopAbs_REVERSED ? reversed : forward)[index - 1]++;
        }
    for (std::size_t k = 0; k < forward.size(); ++k) {
        const std::string where = "face " + std::to_string(first_face[k]) + ": an edge at " +
                                  point_text(BRep_Tool::Pnt(TopExp::FirstVertex(TopoDS::Edge(edges(static_cast<int>(k) + 1)))));
        const int uses = forward[k] + reversed[k];
        require(uses == 2, "shape", [&] {
            return where + " is used by " + std::to_string(uses) + (uses == 1 ? " face (the shell is open)" : " faces (the shell is not a manifold)");
        });
        require(forward[k] == 1, "shape", [&] { return where + ": both faces run it the same way (the shell is not oriented)"; });
    }
}

// The diagonal of the shape's bounding box.
double size_of(const TopoDS_Shape& shape) {
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    return box.IsVoid() ? 0 : std::sqrt(box.SquareExtent());
}

std::string status_name(BRepCheck_Status status) {
    // The names of BRepCheck_Status without the prefix; the enum's own numbering otherwise.
    static const char* const kNames[] = {"NoError", "InvalidPointOnCurve", "InvalidPointOnCurveOnSurface", "InvalidPointOnSurface",
                                         "No3DCurve", "Multiple3DCurve", "Invalid3DCurve", "NoCurveOnSurface",
                                         "InvalidCurveOnSurface", "InvalidCurveOnClosedSurface", "InvalidSameRangeFlag",
                                         "InvalidSameParameterFlag", "InvalidDegeneratedFlag", "FreeEdge", "InvalidMultiConnexity",
                                         "InvalidRange", "EmptyWire", "RedundantEdge", "SelfIntersectingWire", "NoSurface",
                                         "InvalidWire", "RedundantWire", "IntersectingWires", "InvalidImbricationOfWires",
                                         "EmptyShell", "RedundantFace", "InvalidImbricationOfShells", "UnorientableShape",
                                         "NotClosed", "NotConnected", "SubshapeNotInShape", "BadOrientation",
                                         "BadOrientationOfSubshape", "InvalidPolygonOnTriangulation", "InvalidToleranceValue",
                                         "EnclosedRegion", "CheckFail"};
    const auto index = static_cast<std::size_t>(status);
    return index < std::size(kNames) ? kNames[index] : "status " + std::to_string(index);
}

// What a BRepCheck status means for a face, in the words of someone who drew it; empty where the name says enough.
std::string in_words(BRepCheck_Status status) {
    switch (status) {
        case BRepCheck_SelfIntersectingWire: return "a loop of its boundary touches or crosses itself";
        case BRepCheck_NotClosed: return "a loop of its boundary does not close on its surface";
        case BRepCheck_IntersectingWires: return "two loops of its boundary cross";
        case BRepCheck_InvalidImbricationOfWires: return "its loops do not nest as outer boundary and holes";
        case BRepCheck_UnorientableShape: return "its loops do not bound a region";
        default: return {};
    }
}

// The first fault BRepCheck reports for `face`. A loop's fault in the face (a loop touching itself, one that does
// not close on the surface) comes before the face's own: the face's UnorientableShape only follows from it.
std::optional<BRepCheck_Status> first_fault(const BRepCheck_Analyzer& analyzer, const TopoDS_Face& face) {
    const auto first_of = [](const BRepCheck_ListOfStatus& statuses) -> std::optional<BRepCheck_Status> {
        for (BRepCheck_ListIteratorOfListOfStatus it(statuses); it.More(); it.Next())
            if (it.Value() != BRepCheck_NoError) return it.Value();
        return std::nullopt;
    };
    for (TopExp_Explorer wires(face, TopAbs_WIRE); wires.More(); wires.Next()) {
        const Handle(BRepCheck_Result)& result = analyzer.Result(wires.Current());
        if (result.IsNull()) continue;
        if (const auto own = first_of(result->Status())) return own;
        for (result->InitContextIterator(); result->MoreShapeInContext(); result->NextShapeInContext())
            if (result->ContextualShape().IsSame(face))
                if (const auto in_face = first_of(result->StatusOnShape())) return in_face;
    }
    const Handle(BRepCheck_Result)& result = analyzer.Result(face);
    return result.IsNull() ? std::nullopt : first_of(result->Status());
}

// BRepCheck's verdict on a solid: the first face with a fault, the fault in words and by BRepCheck's name.
void check_with_brepcheck(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces) {
    BRepCheck_Analyzer analyzer(solid);
    if (analyzer.IsValid()) return;
    for (int f = 1; f <= faces.Extent(); ++f) {
        const std::optional<BRepCheck_Status> fault = first_fault(analyzer, TopoDS::Face(faces(f)));
        if (!fault) continue;
        const std::string words = in_words(*fault);
        fail("shape", "face " + std::to_string(f - 1) + ": " + (words.empty() ? "" : words + ": ") +
                          "OpenCASCADE's BRepCheck finds it invalid (" + status_name(*fault) + ")");
    }
    fail("shape", "OpenCASCADE's BRepCheck finds the solid invalid");
}

// One solid held against itself: its faces, its shells, then BRepCheck. Errors say "face f: ..." (from 0).
void check_solid(const TopoDS_Shape& solid) {
    TopTools_IndexedMapOfShape faces;
    const double size = size_of(solid);
    int f = 0;
    for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next(), ++f) {
        faces.Add(it.Current());
        try {
            check_face(TopoDS::Face(it.Current()), size);
        } catch (const Error& error) {
            throw Error("shape", "face " + std::to_string(f) + ": " + std::string(error.reason()));
        }
    }
    for (TopExp_Explorer shells(solid, TopAbs_SHELL); shells.More(); shells.Next()) check_shell(shells.Current(), faces);
    check_with_brepcheck(solid, faces);
}

}  // namespace

std::vector<SolidLeftOut> solid_faults(const TopoDS_Shape& shape) {
    std::vector<SolidLeftOut> faults;
    std::size_t s = 0;
    for (TopExp_Explorer solids(shape, TopAbs_SOLID); solids.More(); solids.Next(), ++s) {
        try {
            check_solid(solids.Current());
        } catch (const Error& error) {
            faults.push_back({s, std::string(error.reason())});
        } catch (const Standard_OutOfMemory&) {
            throw;
        } catch (const Standard_Failure& failure) {
            faults.push_back({s, std::string("OpenCASCADE failed checking it: ") + failure.GetMessageString()});
        }
    }
    return faults;
}

void check_self_consistency(const TopoDS_Shape& shape) {
    int s = 0;
    bool any_solid = false;
    for (TopExp_Explorer solids(shape, TopAbs_SOLID); solids.More(); solids.Next(), ++s) {
        any_solid = true;
        try {
            check_solid(solids.Current());
        } catch (const Error& error) {
            throw Error("shape", "solid " + std::to_string(s) + ": " + std::string(error.reason()));
        }
    }
    if (any_solid) return;
    // Faces without a solid: each held to the size of its shell (a pin of a surface-model part, not the whole
    // part: the slack is a ten-thousandth of it), or of itself outside every shell.
    TopTools_DataMapOfShapeReal shell_size;
    for (TopExp_Explorer shells(shape, TopAbs_SHELL); shells.More(); shells.Next()) {
        const double size = size_of(shells.Current());
        for (TopExp_Explorer it(shells.Current(), TopAbs_FACE); it.More(); it.Next()) shell_size.Bind(it.Current(), size);
    }
    int f = 0;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next(), ++f) {
        const double size = shell_size.IsBound(it.Current()) ? shell_size.Find(it.Current()) : size_of(it.Current());
        try {
            check_face(TopoDS::Face(it.Current()), size);
        } catch (const Error& error) {
            throw Error("shape", "face " + std::to_string(f) + ": " + std::string(error.reason()));
        }
    }
}

}  // namespace ratbez::occt::detail
