// Faces on a sphere, cylinder, cone or torus, on OCCT's surface of that kind (see elementary_faces.hpp).

#include "elementary_faces.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_TEdge.hxx>
#include <BRep_Tool.hxx>
#include <ElSLib.hxx>
#include <GProp_GProps.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Precision.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeUpgrade_ShapeDivideAngle.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Dir.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "analytic_primitives.hpp"
#include "exact_edges.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt::detail {
namespace {

// OpenCASCADE's adaptive volume of the rebuilt solid against the kernel's (its p-curves are projections).
constexpr double kVolume = 1e-7;
// How far a projected p-curve may be from its edge (relative to the size; the edge's tolerance then covers it).
constexpr double kProjection = 1e-6;
// How much further than a read face's largest edge tolerance a projected p-curve may be from its edge.
constexpr double kReadSlack = 1.5;
// Attempts, each leaving out the faces the one before refused.
constexpr int kAttempts = 3;

// The face's surface normal at a point of its parameter box away from a pole, and that point.
std::optional<std::pair<gp_Pnt, gp_Vec>> sample_normal(const TopoDS_Face& face) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    for (const double f : {0.5, 0.3, 0.7}) {
        gp_Pnt point;
        gp_Vec du, dv;
        surface->D1(u0 + f * (u1 - u0), v0 + (1 - f) * (v1 - v0), point, du, dv);
        const gp_Vec normal = du.Crossed(dv);
        if (normal.Magnitude() > 1e-12 * du.Magnitude() * dv.Magnitude() && normal.Magnitude() > 0)
            return std::pair{point, normal};
    }
    return std::nullopt;
}

// The seam ShapeFix_Face adds to a face on a sphere gets a 3D curve fitted to its iso line (a polynomial of degree 8,
// 1e-5 off at size 30: FreeCAD's STEP reader then left it InvalidCurveOnSurface). Where its p-curves are the
// meridian u = const run at unit speed in v (t -> v = a + s t, s = +-1), that meridian is the exact 3D curve: the
// circle about the centre through S(u, a), turning towards s dS/dv, whose angle t is the edge's parameter.
void exact_seams(const TopoDS_Face& face, const Handle(Geom_SphericalSurface)& sphere, double tolerance) {
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        if (!BRep_Tool::IsClosed(edge, face) || BRep_Tool::Degenerated(edge)) continue;
        double first = 0, last = 0;
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
        if (pcurve.IsNull() || !(last > first) || !edge.Location().IsIdentity() || !face.Location().IsIdentity()) continue;
        const gp_Pnt2d start = pcurve->Value(first), middle = pcurve->Value((first + last) / 2), end = pcurve->Value(last);
        const double s = (end.Y() - start.Y()) / (last - first);
        constexpr double kLine = 1e-12;  // of the parameters, radians
        if (std::abs(std::abs(s) - 1) > kLine || std::abs(end.X() - start.X()) > kLine || std::abs(middle.X() - start.X()) > kLine ||
            std::abs(middle.Y() - (start.Y() + end.Y()) / 2) > kLine)
            continue;
        const double u = start.X(), a = start.Y() - (s > 0 ? 1 : -1) * first;
        gp_Pnt on;
        gp_Vec du, dv;
        sphere->D1(u, a, on, du, dv);
        const gp_Pnt centre = sphere->Location();
        const gp_Dir x(gp_Vec(centre, on)), y(s > 0 ? dv : -dv);
        BRep_Builder().UpdateEdge(edge, new Geom_Circle(gp_Ax2(centre, x.Crossed(y), x), sphere->Radius()), tolerance);
        Handle(BRep_TEdge)::DownCast(edge.TShape())->Tolerance(tolerance);
    }
}

// `face` (as it lies in the solid) on `surface`, from its own edges: p-curves projected, seams and poles
// made by ShapeFix_Face (edge changes recorded in `context`), the face turned so that its material stays on
// the same side. Where the new parameters run the other way round (the normals disagree), the wires are
// reversed and the face with them, so that every edge is still used once each way in the shell. Null when
// that cannot be decided. The old normal is `normal_from`'s: `face` itself, or the first of the pieces it holds
// the wires of (pieces_as_one).
TopoDS_Face on_surface(const TopoDS_Face& face, const Handle(Geom_Surface)& surface, double tolerance,
                       const Handle(ShapeBuild_ReShape)& context, const TopoDS_Face& normal_from) {
    const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    const auto old_normal = sample_normal(TopoDS::Face(normal_from.Oriented(TopAbs_FORWARD)));
    if (!old_normal) return {};
    GeomAPI_ProjectPointOnSurf foot(old_normal->first, surface);
    if (!foot.IsDone() || foot.NbPoints() == 0) return {};
    double u = 0, v = 0;
    foot.LowerDistanceParameters(u, v);
    gp_Pnt point;
    gp_Vec du, dv;
    surface->D1(u, v, point, du, dv);
    const double agree = du.Crossed(dv).Dot(old_normal->second);
    if (agree == 0) return {};

    BRep_Builder builder;
    TopoDS_Face made;
    builder.MakeFace(made, surface, tolerance);
    for (TopoDS_Iterator wires(forward); wires.More(); wires.Next()) {
        if (wires.Value().ShapeType() != TopAbs_WIRE) continue;
        std::vector<TopoDS_Shape> edges;
        for (TopoDS_Iterator it(wires.Value()); it.More(); it.Next())
            if (!BRep_Tool::Degenerated(TopoDS::Edge(it.Value()))) edges.push_back(agree > 0 ? it.Value() : it.Value().Reversed());
        if (agree < 0) std::reverse(edges.begin(), edges.end());
        TopoDS_Wire wire;
        builder.MakeWire(wire);
        for (const TopoDS_Shape& edge : edges) builder.Add(wire, edge);
        builder.Add(made, wire);
    }
    ShapeFix_Face fix(made);
    fix.SetContext(context);
    fix.SetPrecision(tolerance);
    fix.SetMaxTolerance(std::max(1e-4, 1e3 * tolerance));
    fix.FixOrientationMode() = 0;  // decided above, for the whole shell
    fix.Perform();
    const TopoDS_Face fixed = fix.Face();
    return TopoDS::Face(agree > 0 ? TopoDS_Shape(fixed) : fixed.Reversed());
}

// How far the surface along the p-curve is from the edge's 3D curve at its parameter t (both run on the edge's).
double apart_at(const Handle(Geom_Curve)& curve, const Handle(Geom2d_Curve)& pcurve, const Handle(Geom_Surface)& surface, double t) {
    const gp_Pnt2d uv = pcurve->Value(t);
    return surface->Value(uv.X(), uv.Y()).Distance(curve->Value(t));
}

// (u, v) of a point of the elementary surface (ElSLib's closed forms), u and v moved by whole periods to lie within
// half a period of `near`; nullopt on another kind of surface.
std::optional<gp_Pnt2d> parameters_on(const GeomAdaptor_Surface& surface, const gp_Pnt& point, const gp_Pnt2d& near) {
    double u = 0, v = 0;
    switch (surface.GetType()) {
        case GeomAbs_Cylinder: ElSLib::Parameters(surface.Cylinder(), point, u, v); break;
        case GeomAbs_Cone: ElSLib::Parameters(surface.Cone(), point, u, v); break;
        case GeomAbs_Sphere: ElSLib::Parameters(surface.Sphere(), point, u, v); break;
        case GeomAbs_Torus: ElSLib::Parameters(surface.Torus(), point, u, v); break;
        default: return std::nullopt;
    }
    if (surface.IsUPeriodic()) u += surface.UPeriod() * std::round((near.X() - u) / surface.UPeriod());
    if (surface.IsVPeriodic()) v += surface.VPeriod() * std::round((near.Y() - v) / surface.VPeriod());
    return gp_Pnt2d(u, v);
}

// The edge's p-curve on the elementary surface: its points at n + 1 even steps of its parameter, put on the
// surface in closed form (parameters_on, each within half a period of the one before, the first of `start`) and
// interpolated by a cubic B-spline in the edge's own parameter (Geom2dAPI_Interpolate, The NURBS Book A9.1); n
// doubled until, halfway between the points too, the surface along it lies within `accuracy` of the surface at the
// edge's points put on it so (the fit's own error: a read edge may lie its file's tolerance off the surface). Null
// when it does not get there (an edge through a sphere's pole or a cone's apex, where u is not defined).
Handle(Geom2d_Curve) fitted_pcurve(const Handle(Geom_Curve)& curve, double first, double last,
                                   const Handle(Geom_Surface)& surface, const gp_Pnt2d& start, double accuracy) {
    const GeomAdaptor_Surface adaptor(surface);
    for (int n = 32; n <= 2048; n *= 2) {
        const Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, n + 1);
        const Handle(TColStd_HArray1OfReal) parameters = new TColStd_HArray1OfReal(1, n + 1);
        gp_Pnt2d near = start;
        for (int k = 0; k <= n; ++k) {
            const double t = first + (last - first) * k / n;
            const std::optional<gp_Pnt2d> uv = parameters_on(adaptor, curve->Value(t), near);
            if (!uv) return {};
            points->SetValue(k + 1, *uv);
            parameters->SetValue(k + 1, t);
            near = *uv;
        }
        Geom2dAPI_Interpolate interpolation(points, parameters, Standard_False, Precision::PConfusion());
        interpolation.Perform();
        if (!interpolation.IsDone()) return {};
        const Handle(Geom2d_BSplineCurve) fitted = interpolation.Curve();
        double worst = 0;
        for (int k = 0; k < n && worst <= accuracy; ++k) {
            const double t = first + (last - first) * (k + 0.5) / n;
            const gp_Pnt2d uv = fitted->Value(t);
            const std::optional<gp_Pnt2d> on = parameters_on(adaptor, curve->Value(t), uv);
            if (!on) return {};
            worst = std::max(worst, surface->Value(uv.X(), uv.Y()).Distance(surface->Value(on->X(), on->Y())));
        }
        if (worst <= accuracy) return Handle(Geom2d_Curve)(fitted);
    }
    return {};
}

// The p-curves of `face` (just made by on_surface) that ShapeFix_Face projected further from their edges than a tenth
// of the edge's tolerance as converted (the file's gap the kernel measured; `floor` at least) at 33 points (the
// search of BRepLib_CheckCurveOnSurface finds more between them), fitted again
// (fitted_pcurve, to a tenth of that) and kept where they come closer, and start and end where ShapeFix's did, to
// `limit` (its wire stays closed in the parameters). ShapeFix projects a B-spline edge by interpolating a few of its
// points (ShapeConstruct_ProjectCurveOnSurface): the curves where FreeCAD's drilled holes meet a cylinder came out
// 0.003 to 0.015 off it (tests/corpus/freecad/shipped_drilling_1.step, whose edges the kernel reads within 1.5e-7 of
// the cylinder), and those faces stayed B-splines; ProjLib's approximation (GeomProjLib::Curve2d) still left two of
// them 0.001 off. Held to the face's limit alone (1.5 times its loosest edge's file tolerance), a Fusion 360 part's
// edges took 9e-3 tolerances from one loose edge each, and FreeCAD's BOP check flagged their vertices and short edges
// (Voron-0's Manta_M4P_Din_Mount_2pc.step: a tenth of its edges). Seams are ShapeFix's own, and stay as they are.
void refit_loose_pcurves(const TopoDS_Face& face, double floor, double limit) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
    const GeomAdaptor_Surface adaptor(surface);
    for (TopExp_Explorer edges(face, TopAbs_EDGE); edges.More(); edges.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
        if (BRep_Tool::Degenerated(edge) || BRep_Tool::IsClosed(edge, face)) continue;
        double first = 0, last = 0, from = 0, to = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, from, to);
        if (curve.IsNull() || pcurve.IsNull() || from != first || to != last) continue;
        const double own = std::max(floor, BRep_Tool::Tolerance(edge));
        const auto sampled = [&](const Handle(Geom2d_Curve)& on_face) {
            double worst = 0;
            for (int k = 0; k <= 32; ++k) worst = std::max(worst, apart_at(curve, on_face, surface, first + (last - first) * k / 32));
            return worst;
        };
        const double before = sampled(pcurve);
        if (before <= 0.1 * own) continue;  // sampled: the true distance may be larger
        const Handle(Geom2d_Curve) fitted = fitted_pcurve(curve, first, last, surface, pcurve->Value(first), 0.1 * own);
        if (fitted.IsNull() || !(sampled(fitted) < before)) continue;
        const auto ends_agree = [&](double t) {
            const gp_Vec2d gap(pcurve->Value(t), fitted->Value(t));
            return std::abs(gap.X()) <= adaptor.UResolution(limit) && std::abs(gap.Y()) <= adaptor.VResolution(limit);
        };
        if (ends_agree(first) && ends_agree(last)) BRep_Builder().UpdateEdge(edge, fitted, face, BRep_Tool::Tolerance(edge));
    }
}

// The pieces one face of ours went over in (a rough face goes over as its Bézier patches: topology.cpp's plan_arcs)
// as one face: the wires of their edges not shared between two of them, each edge as its piece uses it, on the first
// piece's surface (only a holder of the wires for on_surface, which puts them on the elementary surface, where
// OpenCASCADE's reading of the file has one face too); null when the edges do not close up into loops. Rebuilt
// piece by piece instead, the piece across the cylinder's seam came out with an open wire in its parameters.
TopoDS_Face pieces_as_one(const std::vector<TopoDS_Face>& pieces) {
    TopTools_MapOfShape seen, shared;
    for (const TopoDS_Face& piece : pieces)
        for (TopExp_Explorer edges(piece, TopAbs_EDGE); edges.More(); edges.Next())
            if (!seen.Add(edges.Current())) shared.Add(edges.Current());
    std::vector<TopoDS_Edge> outer;
    for (const TopoDS_Face& piece : pieces)
        for (TopExp_Explorer edges(piece.Oriented(TopAbs_FORWARD), TopAbs_EDGE); edges.More(); edges.Next())
            if (!shared.Contains(edges.Current()) && !BRep_Tool::Degenerated(TopoDS::Edge(edges.Current())))
                outer.push_back(TopoDS::Edge(edges.Current()));
    BRep_Builder builder;
    TopoDS_Face whole;
    builder.MakeFace(whole, BRep_Tool::Surface(pieces.front()), BRep_Tool::Tolerance(pieces.front()));
    std::vector<bool> used(outer.size(), false);
    for (std::size_t start = 0; start < outer.size(); ++start) {
        if (used[start]) continue;
        TopoDS_Wire wire;
        builder.MakeWire(wire);
        const TopoDS_Vertex first = TopExp::FirstVertex(outer[start], Standard_True);
        std::size_t at = start;
        for (;;) {
            used[at] = true;
            builder.Add(wire, outer[at]);
            const TopoDS_Vertex end = TopExp::LastVertex(outer[at], Standard_True);
            if (end.IsSame(first)) break;
            std::size_t next = outer.size();
            for (std::size_t k = 0; k < outer.size() && next == outer.size(); ++k)
                if (!used[k] && TopExp::FirstVertex(outer[k], Standard_True).IsSame(end)) next = k;
            if (next == outer.size()) return {};
            at = next;
        }
        builder.Add(whole, wire);
    }
    return whole;
}

// The edges of the faces to be rebuilt that are, exactly, segments or arcs of a circle or an ellipse (exact_edges.hpp),
// replaced in `context` by the same piece of OCCT's line, circle or ellipse between the copy's vertices: ShapeFix_Face
// projects a line or a circle that is a meridian or a parallel onto the sphere exactly (a line; on a cylinder, cone or
// torus alike), and so does a STEP reader that gets the file's edges so (with the kernel's rational arcs FreeCAD's
// reader left p-curves 4.4e-6 off: InvalidCurveOnSurface). A slanted hole's rim, an ellipse, goes over as OpenCASCADE
// reads it too, one edge (the kernel's arc is C0 at its knots by multiplicity: BOPAlgo flags it, and
// split_at_c0_knots would cut it up). Only where every face of the edge is rebuilt or a plane, whose p-curves are
// exact too (a B-spline neighbour keeps the edge), and not a seam: a cylinder's seam on OCCT's line drew the BOP
// check's vertex SelfIntersect on FreeCAD's cylinder_cut_cylinder, and left two cylinders of its drilled plate
// B-splines.
// The edges replaced, in the copy's orientation.
std::vector<TopoDS_Edge> analytic_edges(const Solid& solid, const ConvertedSolid& converted,
                                     const TopTools_DataMapOfShapeInteger& on_elementary, const BRepBuilderAPI_Copy& copier,
                                     const Handle(ShapeBuild_ReShape)& context) {
    TopTools_IndexedDataMapOfShapeListOfShape faces_of;
    TopExp::MapShapesAndUniqueAncestors(converted.solid, TopAbs_EDGE, TopAbs_FACE, faces_of);
    const double fit = exact_fit(solid);
    std::vector<TopoDS_Edge> replaced;
    for (const auto& [edge, pieces] : converted.edges) {
        if (edge->degenerate || pieces.empty()) continue;
        const int index = faces_of.FindIndex(pieces.front());
        if (index == 0) continue;
        bool touches_elementary = false, others_planes = true, seam = false;
        for (const TopoDS_Shape& face : faces_of(index)) {
            if (on_elementary.IsBound(face)) touches_elementary = true;
            else others_planes = others_planes && BRep_Tool::Surface(TopoDS::Face(face))->IsKind(STANDARD_TYPE(Geom_Plane));
            seam = seam || BRep_Tool::IsClosed(pieces.front(), TopoDS::Face(face));
        }
        if (!touches_elementary || !others_planes) continue;
        const Edge& e = *edge;
        Handle(Geom_Curve) curve;
        std::optional<std::pair<double, double>> range;
        if (is_segment(e, fit)) {
            if (seam) continue;
            const gp_Vec along(to_occt_point(e.start->point), to_occt_point(e.end->point));
            range = std::pair{0.0, along.Magnitude()};
            curve = new Geom_Line(to_occt_point(e.start->point), gp_Dir(along));
        } else if (const std::optional<EdgeCircle> arc = edge_circle(e, fit)) {
            const gp_Circ circle(gp_Ax2(to_occt_point(arc->centre), to_occt_direction(arc->normal), to_occt_direction(arc->x)),
                                 arc->radius);
            range = arc_parameters(circle, e, arc->sweep);
            curve = new Geom_Circle(circle);
        } else if (const std::optional<EdgeEllipse> arc = edge_ellipse(e, fit)) {
            const gp_Elips ellipse(gp_Ax2(to_occt_point(arc->centre), to_occt_direction(arc->normal), to_occt_direction(arc->x)),
                                   arc->major, arc->minor);
            range = arc_parameters(ellipse, e, arc->sweep);
            curve = new Geom_Ellipse(ellipse);
        }
        if (!range) continue;
        // The copy's pieces, forward, run from our start to our end in order (convert builds them so): one edge
        // between the first's first vertex and the last's last takes the first's place, the others go (a rough face's
        // patches cut a rim where they meet; pieces_as_one takes the patches whole).
        const TopoDS_Edge head = TopoDS::Edge(copier.ModifiedShape(pieces.front()).Oriented(TopAbs_FORWARD));
        const TopoDS_Edge tail = TopoDS::Edge(copier.ModifiedShape(pieces.back()).Oriented(TopAbs_FORWARD));
        const TopoDS_Vertex first = TopExp::FirstVertex(head), last = TopExp::LastVertex(tail);
        if (first.IsNull() || last.IsNull() || BRep_Tool::Pnt(first).Distance(to_occt_point(e.start->point)) > converted.tolerance ||
            BRep_Tool::Pnt(last).Distance(to_occt_point(e.end->point)) > converted.tolerance)
            continue;
        BRepBuilderAPI_MakeEdge made(curve, first, last, range->first, range->second);
        if (!made.IsDone()) continue;
        // The pieces' own tolerance (a read edge's measured gap), not the solid's largest: converted.tolerance on every
        // rebuilt edge gave a Fusion 360 part's lines and circles 9e-3, one face's file tolerance, and FreeCAD's BOP
        // check flagged their vertices and short edges.
        double tolerance = 0;
        for (const TopoDS_Edge& piece : pieces) tolerance = std::max(tolerance, BRep_Tool::Tolerance(piece));
        BRep_Builder().UpdateEdge(made.Edge(), tolerance);
        context->Replace(head, made.Edge());
        for (std::size_t k = 1; k < pieces.size(); ++k) context->Remove(copier.ModifiedShape(pieces[k]));
        replaced.push_back(made.Edge());
    }
    return replaced;
}

// The largest tolerance a face of the solid was given (a file's; 0 for the kernel's own constructions).
double largest_face_tolerance(const Solid& solid) {
    double tolerance = 0;
    for (const Face& face : solid.faces()) tolerance = std::max(tolerance, face.tolerance());
    return tolerance;
}

int count_faces(const TopoDS_Shape& shape) {
    int n = 0;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) ++n;
    return n;
}

// `shape`, or a copy with every face that runs more than a turn round its surface cut at each half turn in u
// (ShapeUpgrade_ShapeDivideAngle, which cuts u only): BRepGProp's adaptive rule misreads such a face (a cylinder's
// side cut open along a helix of 3 turns: 2.4e-4 of the volume), and reads its half turns to rounding. A face of
// several turns in v (round a torus's tube) stays whole; its rebuild is then refused unless BRepGProp reads it.
TopoDS_Shape turns_apart(const TopoDS_Shape& shape) {
    bool turns = false;
    for (TopExp_Explorer faces(shape, TopAbs_FACE); faces.More() && !turns; faces.Next()) {
        const TopoDS_Face& face = TopoDS::Face(faces.Current());
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        turns = surface->IsUPeriodic() && u1 - u0 > surface->UPeriod() * (1 + 1e-9);
    }
    if (!turns) return shape;
    ShapeUpgrade_ShapeDivideAngle halves(M_PI, shape);
    halves.Perform();
    return halves.Result();
}

// One attempt with the faces of ours that have a surface in `surfaces`: the rebuilt solid, or nullopt with the
// faces whose projected p-curves came out too far from their edges added to `refused` (or none, when the solid
// as a whole is not valid or not of the kernel's volume).
std::optional<SplitSolid> rebuilt(const Solid& solid, const ConvertedSolid& converted,
                                  const std::vector<Handle(Geom_Surface)>& surfaces, bool analytic_curves,
                                  std::vector<std::size_t>& refused, const Progress& progress) {
    const Progress projecting = progress_part(progress, 0, 0.5), measuring = progress_part(progress, 0.5, 1);
    const double faces_total = std::max(1, count_faces(converted.solid));
    const double size = std::max(1.0, solid.bounding_box().diagonal());
    // Which face of ours each OCCT face on an elementary surface is (one OCCT face, or the pieces of a rough face).
    TopTools_DataMapOfShapeInteger on_elementary;
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        if (!surfaces[i].IsNull())
            for (std::size_t k = converted.first_face[i]; k < converted.first_face[i + 1]; ++k)
                on_elementary.Bind(converted.faces[k], static_cast<int>(i));
    // How far face `ours`'s projected p-curves may lie from their edges. A read face's edges may lie their file's
    // tolerance off its surface (so far OCCT's p-curves on the B-spline were the file's own): its projections then
    // lie as far from them.
    const auto projection_limit = [&](std::size_t ours, const TopoDS_Shape& original) {
        double face_tolerance = solid.faces()[ours].tolerance();
        for (TopExp_Explorer edges(original, TopAbs_EDGE); edges.More(); edges.Next())
            face_tolerance = std::max(face_tolerance, BRep_Tool::Tolerance(TopoDS::Edge(edges.Current())));
        return std::max(kProjection * size, kReadSlack * face_tolerance);
    };
    // On a copy: the p-curves added to shared edges must not reach the B-spline solid kept as the fallback.
    BRepBuilderAPI_Copy copier(converted.solid);
    const Handle(ShapeBuild_ReShape) context = new ShapeBuild_ReShape;
    struct Traced {
        TopoDS_Shape face;      // of the copy, or rebuilt
        TopoDS_Shape original;  // convert's
        std::size_t ours;       // rebuilt from face `ours` of the solid; solid.faces().size() when not rebuilt
    };
    const std::vector<TopoDS_Edge> analytic =
        analytic_curves ? analytic_edges(solid, converted, on_elementary, copier, context) : std::vector<TopoDS_Edge>{};
    std::vector<Traced> traced;
    std::vector<TopoDS_Face> merged;  // pieces taken into the first of their face's
    for (TopExp_Explorer faces(converted.solid, TopAbs_FACE); faces.More(); faces.Next()) {
        if (projecting) projecting(static_cast<double>(traced.size()) / faces_total);
        const TopoDS_Shape& original = faces.Current();
        const TopoDS_Face piece = TopoDS::Face(copier.ModifiedShape(original));
        if (!on_elementary.IsBound(original)) {
            traced.push_back({piece, original, solid.faces().size()});
            continue;
        }
        const std::size_t ours = static_cast<std::size_t>(on_elementary.Find(original));
        TopoDS_Face made;
        const std::size_t first = converted.first_face[ours], end = converted.first_face[ours + 1];
        if (end - first == 1) {
            made = on_surface(TopoDS::Face(context->Apply(piece)), surfaces[ours], BRep_Tool::Tolerance(piece), context, piece);
        } else if (original.IsSame(converted.faces[first])) {  // the first piece stands for them all
            std::vector<TopoDS_Face> pieces;
            for (std::size_t k = first; k < end; ++k)
                pieces.push_back(TopoDS::Face(context->Apply(copier.ModifiedShape(converted.faces[k]))));
            double tolerance = 0;
            for (const TopoDS_Face& each : pieces) tolerance = std::max(tolerance, BRep_Tool::Tolerance(each));
            if (const TopoDS_Face whole = pieces_as_one(pieces); !whole.IsNull())
                made = on_surface(whole, surfaces[ours], tolerance, context, pieces.front());
        } else {
            merged.push_back(piece);  // removed once every face is made: the first piece's whole takes its edges
            continue;
        }
        if (made.IsNull()) {
            refused.push_back(ours);
            return std::nullopt;
        }
        refit_loose_pcurves(made, kProjection * size, projection_limit(ours, original));
        context->Replace(piece.Oriented(TopAbs_FORWARD), made);
        traced.push_back({made, original, ours});
    }
    for (const TopoDS_Face& piece : merged) context->Remove(piece);
    const TopoDS_Shape result = context->Apply(copier.Shape());
    if (result.ShapeType() != TopAbs_SOLID || count_faces(result) != count_faces(converted.solid) - static_cast<int>(merged.size()))
        return std::nullopt;
    // The analytic edges' p-curves on the planes beside (exact; ShapeFix_Face made those on the rebuilt faces), and
    // the seams' 3D curves.
    for (TopExp_Explorer faces(result, TopAbs_FACE); faces.More(); faces.Next()) {
        const TopoDS_Face& face = TopoDS::Face(faces.Current());
        if (const auto sphere = Handle(Geom_SphericalSurface)::DownCast(BRep_Tool::Surface(face)); !sphere.IsNull())
            exact_seams(face, sphere, converted.tolerance);
        if (!BRep_Tool::Surface(face)->IsKind(STANDARD_TYPE(Geom_Plane))) continue;
        for (TopExp_Explorer edges(face, TopAbs_EDGE); edges.More(); edges.Next())
            for (const TopoDS_Edge& made : analytic)
                if (edges.Current().IsSame(made)) BRepLib::BuildPCurveForEdgeOnPlane(TopoDS::Edge(edges.Current()), face);
    }
    // Only the rebuilt faces' edges (forced over the whole solid, it refitted untouched B-spline faces' p-curves too:
    // a ventilator's blades drew BOPAlgo_InvalidCurveOnSurface).
    for (const Traced& t : traced)
        if (t.ours != solid.faces().size())
            for (TopExp_Explorer edges(context->Apply(t.face), TopAbs_EDGE); edges.More(); edges.Next()) {
                const TopoDS_Edge& edge = TopoDS::Edge(edges.Current());
                BRep_Builder().SameParameter(edge, Standard_False);
                BRepLib::SameParameter(edge, converted.tolerance);
            }
    SplitSolid handed{TopoDS::Solid(result), {}};
    const std::size_t refused_before = refused.size();
    for (std::size_t k = 0; k < traced.size(); ++k) {
        const Traced& t = traced[k];
        if (measuring) measuring(static_cast<double>(k) / static_cast<double>(traced.size()));
        std::vector<TopoDS_Face> finals;
        for (TopExp_Explorer final_faces(context->Apply(t.face), TopAbs_FACE); final_faces.More(); final_faces.Next()) {
            handed.original_face.Bind(final_faces.Current(), t.original);
            finals.push_back(TopoDS::Face(final_faces.Current()));
        }
        if (t.ours == solid.faces().size()) continue;  // not rebuilt
        if (!honest_tolerances(finals, projection_limit(t.ours, t.original))) refused.push_back(t.ours);
    }
    if (refused.size() > refused_before) return std::nullopt;
    BRepLib::UpdateTolerances(result, Standard_True);
    BRepTools::RemoveUnusedPCurves(result);
    if (!BRepCheck_Analyzer(result).IsValid()) return std::nullopt;
    GProp_GProps properties;
    BRepGProp::VolumeProperties(turns_apart(result), properties, 1e-9);
    // A face trimmed by p-curves a file tolerance t off its edges may move its boundary by t: the volume by up to
    // area x t (as OpenCASCADE's reading of the file itself, tests/corpus).
    const double read_tolerance = largest_face_tolerance(solid);
    const double volume = solid.volume();
    const double slack = std::max(kVolume * std::abs(volume), read_tolerance > 0 ? solid.area() * read_tolerance : 0.0);
    if (!(std::abs(properties.Mass() - volume) <= slack)) return std::nullopt;
    return handed;
}

}  // namespace

std::optional<SplitSolid> with_elementary_faces(const Solid& solid, const ConvertedSolid& converted, const Progress& progress) {
    const double size = std::max(1.0, solid.bounding_box().diagonal());
    // The sphere, cylinder, cone or torus of each face of ours handed over whole (not as Bézier patches), trimmed or not.
    std::vector<Handle(Geom_Surface)> surfaces(solid.faces().size());
    const bool read = largest_face_tolerance(solid) > 0 || std::any_of(solid.faces().begin(), solid.faces().end(), [](const Face& face) {
        return face.kind() == Face::Kind::trimmed;
    });
    try {  // OCCT's surface constructors check their arguments
        for (std::size_t i = 0; i < solid.faces().size(); ++i) {
            const Face& face = solid.faces()[i];
            if (face.kind() == Face::Kind::planar) continue;
            Handle(Geom_ElementarySurface) elementary = exact_elementary(face.surface(), size);
            // A sphere's face in any solid; a cylinder's, cone's or torus's in a solid read from a file, told by its
            // trimmed faces or a face's tolerance (the kernel's own builders make neither). The kernel's own solids go
            // over as they did: a cone ruled between two circles came out of OCCT's Thickness invalid on OCCT's cone,
            // and a revolved profile's cylinder was flagged by the BOP check.
            if (!elementary.IsNull() && !elementary->IsKind(STANDARD_TYPE(Geom_SphericalSurface)) && !read)
                elementary.Nullify();
            surfaces[i] = elementary;
        }
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
    // Faces whose p-curves OpenCASCADE cannot project close enough stay B-splines; the rest is tried again. First
    // with the segments, circles and ellipses as OCCT's, then with the kernel's curves: ShapeFix_Face projects a circle that runs along the
    // sphere's seam onto either side of it, and may then take the face for the rest of the sphere (the kernel's
    // octant of FreeCAD's sphere minus a box at (0, -40, 0) came out as the other seven: the volume check refused
    // it); the arcs' projections follow on from their neighbours'.
    int tries = 0;  // each attempt reports its own share of the progress
    for (const bool analytic : {true, false}) {
        std::vector<Handle(Geom_Surface)> tried = surfaces;
        for (int attempt = 0; attempt < kAttempts; ++attempt, ++tries) {
            if (std::all_of(tried.begin(), tried.end(), [](const Handle(Geom_Surface)& s) { return s.IsNull(); })) break;
            std::vector<std::size_t> refused;
            try {
                const Progress share = progress_part(progress, tries / (2.0 * kAttempts), (tries + 1) / (2.0 * kAttempts));
                if (std::optional<SplitSolid> made = rebuilt(solid, converted, tried, analytic, refused, share)) return made;
            } catch (const Standard_Failure&) {
                break;
            }
            if (refused.empty()) break;
            for (const std::size_t i : refused) tried[i].Nullify();
        }
    }
    return std::nullopt;
}

}  // namespace ratbez::occt::detail
