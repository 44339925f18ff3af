// TopoDS_Shape -> ratbez::Solid (see shape_import.hpp for what is converted and what is refused).

#include "ratbez/occt/shape_import.hpp"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <ShapeFix_Solid.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <BRepTools.hxx>
#include <Bnd_Box.hxx>
#include <Precision.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Convert_ConeToBSplineSurface.hxx>
#include <Convert_CylinderToBSplineSurface.hxx>
#include <Convert_SphereToBSplineSurface.hxx>
#include <Convert_TorusToBSplineSurface.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Conic.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Sphere.hxx>
#include <gp_Torus.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "face_sides.hpp"
#include "pcurve_fit.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"
#include "self_consistency.hpp"
#include "sliver_faces.hpp"

namespace ratbez::occt {
namespace {

using detail::along_u;
using detail::traversal_increasing;

std::string type_name(const Handle(Standard_Transient)& object) { return object->DynamicType()->Name(); }

// A curve with an exact B-spline form in GeomConvert (lines, conics, B-splines, Béziers), trims removed; null
// for anything else (offset curves), which GeomConvert would approximate.
Handle(Geom_Curve) exact_basis(Handle(Geom_Curve) curve) {
    while (!curve.IsNull() && curve->IsKind(STANDARD_TYPE(Geom_TrimmedCurve)))
        curve = Handle(Geom_TrimmedCurve)::DownCast(curve)->BasisCurve();
    if (curve.IsNull()) return {};
    if (curve->IsKind(STANDARD_TYPE(Geom_Line)) || curve->IsKind(STANDARD_TYPE(Geom_Conic)) ||
        curve->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) || curve->IsKind(STANDARD_TYPE(Geom_BezierCurve)))
        return curve;
    return {};
}

// The surface without its rectangular trims; a surface of revolution or extrusion only when its curve converts
// exactly; null for surfaces without an exact conversion (GeomConvert would approximate them to 1e-4).
Handle(Geom_Surface) exact_basis(Handle(Geom_Surface) surface) {
    while (!surface.IsNull() && surface->IsKind(STANDARD_TYPE(Geom_RectangularTrimmedSurface)))
        surface = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)->BasisSurface();
    if (surface.IsNull()) return {};
    if (surface->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) || surface->IsKind(STANDARD_TYPE(Geom_BezierSurface)) ||
        surface->IsKind(STANDARD_TYPE(Geom_CylindricalSurface)) || surface->IsKind(STANDARD_TYPE(Geom_ConicalSurface)) ||
        surface->IsKind(STANDARD_TYPE(Geom_SphericalSurface)) || surface->IsKind(STANDARD_TYPE(Geom_ToroidalSurface)))
        return surface;
    if (surface->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution)) &&
        !exact_basis(Handle(Geom_SurfaceOfRevolution)::DownCast(surface)->BasisCurve()).IsNull())
        return surface;
    if (surface->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion)) &&
        !exact_basis(Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(surface)->BasisCurve()).IsNull())
        return surface;
    return {};
}

// The B-spline of a Convert_* conversion (what GeomConvert's own builder copies).
Handle(Geom_BSplineSurface) bspline_of(const Convert_ElementarySurfaceToBSplineSurface& c) {
    TColgp_Array2OfPnt poles(1, c.NbUPoles(), 1, c.NbVPoles());
    TColStd_Array2OfReal weights(1, c.NbUPoles(), 1, c.NbVPoles());
    for (int i = 1; i <= c.NbUPoles(); ++i)
        for (int j = 1; j <= c.NbVPoles(); ++j) poles(i, j) = c.Pole(i, j), weights(i, j) = c.Weight(i, j);
    TColStd_Array1OfReal u_knots(1, c.NbUKnots()), v_knots(1, c.NbVKnots());
    TColStd_Array1OfInteger u_multiplicities(1, c.NbUKnots()), v_multiplicities(1, c.NbVKnots());
    for (int i = 1; i <= c.NbUKnots(); ++i) u_knots(i) = c.UKnot(i), u_multiplicities(i) = c.UMultiplicity(i);
    for (int i = 1; i <= c.NbVKnots(); ++i) v_knots(i) = c.VKnot(i), v_multiplicities(i) = c.VMultiplicity(i);
    return new Geom_BSplineSurface(poles, weights, u_knots, v_knots, u_multiplicities, v_multiplicities, c.UDegree(),
                                   c.VDegree(), c.IsUPeriodic(), c.IsVPeriodic());
}

// The end of a full turn from `lo`: lo + period, less an ulp where the rounded sum leaves a difference above the
// period (from 5 pi / 4 it does by 9e-16, where OpenCASCADE seams a sphere it read), which OpenCASCADE's
// conversions refuse (Standard_DomainError).
double full_turn_end(double lo, double period) {
    double hi = lo + period;
    while (hi - lo > period) hi = std::nextafter(hi, lo);
    return hi;
}

// B-splines one after the other in u (or v): each piece's knots as they are (each starts where the one before ends,
// at the pole they share, a knot of multiplicity `degree` there, as the arcs inside a turn meet); the same degree
// and the same knots across.
Handle(Geom_BSplineSurface) joined(const std::vector<Handle(Geom_BSplineSurface)>& pieces, bool in_u) {
    std::vector<Handle(Geom_BSplineSurface)> s;
    for (const auto& piece : pieces) {
        s.push_back(Handle(Geom_BSplineSurface)::DownCast(piece->Copy()));
        if (!in_u) s.back()->ExchangeUV();
    }
    const int m = s[0]->NbVPoles(), degree = s[0]->UDegree();
    int poles_count = 1, knots_count = 1;
    for (const auto& piece : s) poles_count += piece->NbUPoles() - 1, knots_count += piece->NbUKnots() - 1;
    TColgp_Array2OfPnt poles(1, poles_count, 1, m);
    TColStd_Array2OfReal weights(1, poles_count, 1, m);
    TColStd_Array1OfReal knots(1, knots_count);
    TColStd_Array1OfInteger multiplicities(1, knots_count);
    int i0 = 0, k0 = 0;
    for (std::size_t p = 0; p < s.size(); ++p) {
        const Handle(Geom_BSplineSurface)& piece = s[p];
        for (int i = 1; i <= piece->NbUPoles(); ++i)
            for (int j = 1; j <= m; ++j) poles(i0 + i, j) = piece->Pole(i, j), weights(i0 + i, j) = piece->Weight(i, j);
        for (int k = 1; k <= piece->NbUKnots(); ++k) {
            const bool junction = (k == 1 && p > 0) || (k == piece->NbUKnots() && p + 1 < s.size());
            knots(k0 + k) = piece->UKnot(k);
            multiplicities(k0 + k) = junction ? degree : piece->UMultiplicity(k);
        }
        i0 += piece->NbUPoles() - 1, k0 += piece->NbUKnots() - 1;
    }
    TColStd_Array1OfReal v_knots(1, s[0]->NbVKnots());
    TColStd_Array1OfInteger v_multiplicities(1, s[0]->NbVKnots());
    s[0]->VKnots(v_knots);
    s[0]->VMultiplicities(v_multiplicities);
    Handle(Geom_BSplineSurface) whole = new Geom_BSplineSurface(poles, weights, knots, v_knots, multiplicities, v_multiplicities, degree, s[0]->VDegree());
    if (!in_u) whole->ExchangeUV();
    return whole;
}

// A cylinder, cone, sphere or torus over exactly the rectangle r: knots at its bounds, so the corners keep their
// parameters wherever a full turn starts (GeomConvert turns a full turn from angle 0 and segments it, which
// leaves the corner of a seam at angle 1 at 0.995); null for other surfaces. A periodic direction may run
// several turns (the crest of a nut's thread, a strip 15 turns round its cylinder): converted in pieces of less
// than a turn, joined (each piece's rational form meets the surface's parameter at its knots only, so r's ends
// must be the ends of conversions).
Handle(Geom_BSplineSurface) elementary_bspline(const Handle(Geom_Surface)& basis, const std::array<double, 4>& r) {
    for (const bool in_u : {true, false}) {
        const bool periodic = in_u ? basis->IsUPeriodic() : basis->IsVPeriodic();
        const double period = periodic ? (in_u ? basis->UPeriod() : basis->VPeriod()) : 0;
        const double lo = in_u ? r[0] : r[2], hi = in_u ? r[1] : r[3];
        if (!periodic || !(hi - lo > period * (1 + 1e-9))) continue;
        // n equal pieces, each short of a turn by at least 1e-12 of it (rounding cannot carry one past a turn,
        // which the conversions refuse), none a sliver where r runs a hair past whole turns.
        const int n = static_cast<int>(std::ceil((hi - lo) / period * (1 + 1e-12)));
        std::vector<Handle(Geom_BSplineSurface)> turns;
        for (int k = 0; k < n; ++k) {
            const double start = lo + (hi - lo) * k / n, end = k + 1 == n ? hi : lo + (hi - lo) * (k + 1) / n;
            const Handle(Geom_BSplineSurface) turn =
                elementary_bspline(basis, in_u ? std::array<double, 4>{start, end, r[2], r[3]} : std::array<double, 4>{r[0], r[1], start, end});
            if (turn.IsNull()) return turn;
            turns.push_back(turn);
        }
        return joined(turns, in_u);
    }
    if (const auto s = Handle(Geom_CylindricalSurface)::DownCast(basis); !s.IsNull())
        return bspline_of(Convert_CylinderToBSplineSurface(s->Cylinder(), r[0], r[1], r[2], r[3]));
    if (const auto s = Handle(Geom_ConicalSurface)::DownCast(basis); !s.IsNull())
        return bspline_of(Convert_ConeToBSplineSurface(s->Cone(), r[0], r[1], r[2], r[3]));
    if (const auto s = Handle(Geom_SphericalSurface)::DownCast(basis); !s.IsNull())
        return bspline_of(Convert_SphereToBSplineSurface(s->Sphere(), r[0], r[1], r[2], r[3]));
    if (const auto s = Handle(Geom_ToroidalSurface)::DownCast(basis); !s.IsNull())
        return bspline_of(Convert_TorusToBSplineSurface(s->Torus(), r[0], r[1], r[2], r[3]));
    return {};
}

// The parameter rectangle (u0, u1, v0, v1) of a face and the four sides of it that its edges cover.
struct NaturalRectangle {
    std::array<double, 4> bounds{};
    std::array<std::optional<TopoDS_Edge>, 4> sides;  // oriented as the face uses them; OCCT's parameters
};

// A rectangle of OCCT parameters made to fit the surface: a direction that closes with a period (a full turn)
// spans at most that period, and a bounded direction (a sphere's latitude, a B-spline's domain) stays inside
// its bounds. Files overshoot both by rounding: FreeCAD writes a full turn as 6.28318530717959 (one ulp above
// 2 pi in .brep; STEP's 12 digits overshoot by 4e-13) and a sphere's latitude past pi/2 by as much, which
// OpenCASCADE's own conversions then refuse (Standard_DomainError). A bounded direction also comes back inside
// from as far as the face's `tolerance` reaches in its parameter (GeomAdaptor_Surface's resolution): p-curves
// fitted by an exporter overshoot a B-spline's domain (Ventilator.stp, pythonocc-demos: by 2.3e-9 of a v range
// of 0.5, its edges' tolerance 2e-4), and a full turn by as much. A `natural` face's rectangle, whose sides are
// the surface's bounds, may fall short of them by rounding (a Voron blower duct's ends 7e-10 inside a v range of
// 0.3), where OpenCASCADE's Segment cannot cut (it snaps to a knot within Precision::PConfusion): from that near,
// it goes out to them. A rectangle wider than the period by more than 1e-9 of it and that reach is left alone
// (the conversion reports it).
// The resolution is a bound from the surface's largest derivative; near a collapsed end a parameter moves the
// surface far less. So a bounded direction also comes back inside from wherever the face's `boundary` (points
// of its p-curves) stays within `tolerance` on the surface of where it comes back to: a keyboard case's edge
// fillet (Fusion 360, optimus-tkl) runs 4.3e-5 past u = 0 of its B-spline, where the surface moves 8e-13, and a
// servo's strip 7.2e-7 past its u range, within its edges' tolerance.
std::array<double, 4> snapped(const Handle(Geom_Surface)& basis, std::array<double, 4> r, double tolerance, bool natural = false,
                              std::span<const gp_Pnt2d> boundary = {}) {
    double a = 0, b = 0, c = 0, d = 0;
    basis->Bounds(a, b, c, d);
    const GeomAdaptor_Surface adaptor(basis);
    // Does every point of the boundary past [min, max] in the direction `in_u` land within the tolerance when it
    // is brought back to the bound? (OpenCASCADE evaluates a B-spline past its bounds on its end spans.)
    const auto boundary_lands = [&](bool in_u, double min, double max) {
        return !boundary.empty() && std::all_of(boundary.begin(), boundary.end(), [&](const gp_Pnt2d& p) {
                   const double t = in_u ? p.X() : p.Y(), back = std::clamp(t, min, max);
                   if (t == back) return true;
                   const gp_Pnt2d q = in_u ? gp_Pnt2d(back, p.Y()) : gp_Pnt2d(p.X(), back);
                   return basis->Value(p.X(), p.Y()).Distance(basis->Value(q.X(), q.Y())) <= tolerance;
               });
    };
    const auto snap = [&](double& lo, double& hi, bool in_u, bool periodic, double period, double min, double max) {
        const double reach = in_u ? adaptor.UResolution(tolerance) : adaptor.VResolution(tolerance);
        if (periodic) {
            if (hi - lo > period && hi - lo <= period + std::max(1e-9 * period, reach)) hi = full_turn_end(lo, period);
            return;
        }
        const double slack = std::max(1e-9 * std::max(1.0, max - min), reach);
        const double short_by = std::max(1e-9 * (max - min), Precision::PConfusion());  // what Segment cannot cut
        const bool lands = (lo < min - slack || hi > max + slack) && boundary_lands(in_u, min, max);
        if (!Precision::IsInfinite(min) && ((lo < min && (min - lo <= slack || lands)) || (natural && lo >= min && lo - min <= short_by)))
            lo = min;
        if (!Precision::IsInfinite(max) && ((hi > max && (hi - max <= slack || lands)) || (natural && hi <= max && max - hi <= short_by)))
            hi = max;
    };
    snap(r[0], r[1], true, basis->IsUPeriodic(), basis->IsUPeriodic() ? basis->UPeriod() : 0, a, b);
    snap(r[2], r[3], false, basis->IsVPeriodic(), basis->IsVPeriodic() ? basis->VPeriod() : 0, c, d);
    return r;
}

// The rectangle of OCCT parameters a trimmed face's NURBS spans: the box of its p-curves (sampled), widened
// by 1 % where the surface allows (a box from samples can miss a bulge of the curve between them) and fitted
// to the surface (snapped). A face that goes all the way round a periodic direction spans exactly the period, or
// its turns round a cylinder, cone, sphere or torus.
std::array<double, 4> trimmed_rectangle(const TopoDS_Face& face, const Handle(Geom_Surface)& basis) {
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
        double first = 0, last = 0;
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(TopoDS::Edge(it.Current()), face, first, last);
        require(!pcurve.IsNull(), "shape", "an edge has no curve on the face's surface");
        for (int k = 0; k <= 64; ++k) {
            const gp_Pnt2d p = pcurve->Value(first + (last - first) * k / 64.0);
            u0 = std::min(u0, p.X()), u1 = std::max(u1, p.X()), v0 = std::min(v0, p.Y()), v1 = std::max(v1, p.Y());
        }
    }
    require(u1 > u0 && v1 > v0, "shape", "the face's curves on its surface span no area");
    double a = 0, b = 0, c = 0, d = 0;
    basis->Bounds(a, b, c, d);
    // A face may run more than a turn round an elementary surface (elementary_bspline): p-curves a twentieth of a
    // turn beyond one, far beyond a seam's rounding or OpenCASCADE's loose fits, keep their turns (the chamfer of
    // a nut's thread runs 1.15 turns round its cone).
    const bool turns_allowed = basis->IsKind(STANDARD_TYPE(Geom_ElementarySurface)) && !basis->IsKind(STANDARD_TYPE(Geom_Plane));
    const auto widen = [turns_allowed](double& lo, double& hi, bool periodic, double period, double min, double max) {
        const double margin = 0.01 * (hi - lo);
        if (periodic) {
            if (turns_allowed && hi - lo >= 1.05 * period) {
                lo -= margin, hi += margin;
                return;
            }
            if (hi - lo >= period * (1 - 1e-9)) {
                hi = full_turn_end(lo, period);
                return;
            }
            const double room = std::min(margin, 0.5 * (period - (hi - lo)));
            lo -= room, hi += room;
            return;
        }
        lo = Precision::IsInfinite(min) ? lo - margin : std::max(min, lo - margin);
        hi = Precision::IsInfinite(max) ? hi + margin : std::min(max, hi + margin);
    };
    widen(u0, u1, basis->IsUPeriodic(), basis->IsUPeriodic() ? basis->UPeriod() : 0, a, b);
    widen(v0, v1, basis->IsVPeriodic(), basis->IsVPeriodic() ? basis->VPeriod() : 0, c, d);
    return snapped(basis, {u0, u1, v0, v1}, detail::file_tolerance(face));
}

class Importer {
public:
    explicit Importer(const TopoDS_Shape& solid) : solid_(solid) {
        TopExp::MapShapes(solid_, TopAbs_VERTEX, vertex_index_);
        TopExp::MapShapes(solid_, TopAbs_EDGE, edge_index_);
        vertices_.resize(static_cast<std::size_t>(vertex_index_.Extent()));
        edges_.resize(static_cast<std::size_t>(edge_index_.Extent()));
        Bnd_Box box;
        BRepBndLib::Add(solid_, box);
        if (!box.IsVoid()) size_ = std::sqrt(box.SquareExtent());
    }

    Solid run(const Progress& progress) {
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer it(solid_, TopAbs_FACE); it.More(); it.Next()) faces.push_back(TopoDS::Face(it.Current()));
        require(!faces.empty(), "shape", "the solid has no faces");
        // Surface faces first: their boundary isocurves become the shared edges that trimmed and planar faces
        // then take as they are (a trimmed face fits its p-curves to any edge, a plane accepts any
        // parameterisation of its edges, a surface face only its own isocurves). A face that is not its
        // surface's natural rectangle, or whose sides another surface face already parameterised otherwise,
        // is a trimmed face.
        enum class Pass { surface, trimmed, planar };
        std::vector<std::optional<Face>> made(faces.size());
        std::vector<Pass> pass(faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i) pass[i] = is_planar(faces[i]) ? Pass::planar : Pass::surface;
        std::size_t done = 0;
        for (const Pass current : {Pass::surface, Pass::trimmed, Pass::planar})
            for (std::size_t i = 0; i < faces.size(); ++i) {
                if (pass[i] != current) continue;
                try {
                    switch (current) {
                        case Pass::surface:
                            made[i] = surface_face(faces[i]);
                            if (!made[i]) {
                                pass[i] = Pass::trimmed;
                                continue;
                            }
                            break;
                        case Pass::trimmed: made[i] = trimmed_face(faces[i]); break;
                        case Pass::planar: made[i] = planar_face(faces[i]); break;
                    }
                } catch (const Standard_Failure& failure) {
                    throw Error("shape", "face " + std::to_string(i) + ": OpenCASCADE failed converting it (" +
                                             failure.DynamicType()->Name() + ": " + failure.GetMessageString() + ")");
                } catch (const Error& e) {
                    throw Error("shape", "face " + std::to_string(i) + ": " + e.what());
                }
                if (progress) progress(static_cast<double>(++done) / static_cast<double>(faces.size()));
            }
        std::vector<Face> out;
        out.reserve(made.size());
        for (auto& face : made) out.push_back(std::move(*face));
        try {
            return Solid(std::move(out));
        } catch (const Error& e) {
            throw Error("shape", std::string("the faces do not make a valid solid: ") + e.what());
        }
    }

private:
    static Handle(Geom_Surface) plane_basis(const TopoDS_Face& face) {
        Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        while (!surface.IsNull() && surface->IsKind(STANDARD_TYPE(Geom_RectangularTrimmedSurface)))
            surface = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)->BasisSurface();
        return surface;
    }
    static bool is_planar(const TopoDS_Face& face) {
        const Handle(Geom_Surface) surface = plane_basis(face);
        return !surface.IsNull() && surface->IsKind(STANDARD_TYPE(Geom_Plane));
    }

    // The place of an edge or vertex of the solid in its table (a healed edge not mapped would write past it).
    static std::size_t index_in(const TopTools_IndexedMapOfShape& map, const TopoDS_Shape& shape) {
        const int index = map.FindIndex(shape);
        require(index > 0, "shape", "an edge or vertex of a face is not the solid's");
        return static_cast<std::size_t>(index - 1);
    }

    VertexPtr vertex(const TopoDS_Vertex& v) {
        VertexPtr& made = vertices_[index_in(vertex_index_, v)];
        if (!made) made = std::make_shared<const Vertex>(Vertex{from_occt(BRep_Tool::Pnt(v))});
        return made;
    }

    // Our edge for an OCCT edge and whether it runs against the OCCT edge's own (FORWARD) direction.
    struct SharedEdge {
        EdgePtr edge;
        bool flipped = false;
        bool same_parameter = false;  // our curve has OCCT's parameter (the 3D curve converted as it is)
    };
    SharedEdge& shared(const TopoDS_Edge& e) { return edges_[index_in(edge_index_, e)]; }

    // The OCCT edge's ends in its FORWARD direction.
    static std::pair<TopoDS_Vertex, TopoDS_Vertex> ends(const TopoDS_Edge& e) {
        TopoDS_Vertex first, last;
        TopExp::Vertices(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), first, last);
        require(!first.IsNull() && !last.IsNull(), "shape", "an edge has no vertices");
        return {first, last};
    }

    // An edge met first by a trimmed or planar face: its 3D curve converted exactly, running as the OCCT edge
    // does. Its ends must lie on its vertices, to the tolerances the file gives them: a vertex moved away
    // from its edges would give a mesh of another solid than the curves bound.
    SharedEdge& edge_from_curve(const TopoDS_Edge& e) {
        SharedEdge& entry = shared(e);
        if (entry.edge) return entry;
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(e, first, last);
        require(!curve.IsNull(), "shape", "an edge has no 3D curve");
        const Handle(Geom_Curve) basis = exact_basis(curve);
        if (basis.IsNull()) fail("shape", "an edge's " + type_name(curve) + " has no exact NURBS form");
        const Handle(Geom_BSplineCurve) nurbs =
            GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(basis, first, last));
        // Plain variables, not a structured binding: clang 14 (the fuzz build's) cannot capture one in the lambda below.
        const auto vertices = ends(e);
        const TopoDS_Vertex start = vertices.first, end = vertices.second;
        NurbsCurve converted = from_occt(nurbs);
        const double gap_start = distance(converted.start_point(), from_occt(BRep_Tool::Pnt(start)));
        const double gap_end = distance(converted.end_point(), from_occt(BRep_Tool::Pnt(end)));
        const double allowed = BRep_Tool::Tolerance(e) + std::max(BRep_Tool::Tolerance(start), BRep_Tool::Tolerance(end)) +
                               1e-9 * size_;
        const TopoDS_Vertex& farther = gap_start >= gap_end ? start : end;  // (clang 14 cannot capture a binding)
        require(std::max(gap_start, gap_end) <= allowed, "shape", [&] {
            return "an edge's " + std::string(gap_start >= gap_end ? "start" : "end") + " vertex " +
                   detail_point(BRep_Tool::Pnt(farther)) + " is " +
                   std::to_string(std::max(gap_start, gap_end)) + " away from the edge's curve, more than the file's tolerance " +
                   std::to_string(allowed);
        });
        // GeomConvert keeps the parameter of lines, B-splines and Béziers; conics come back at the rational pace.
        const bool same_parameter = basis->IsKind(STANDARD_TYPE(Geom_Line)) || basis->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) ||
                                    basis->IsKind(STANDARD_TYPE(Geom_BezierCurve));
        entry.edge = std::make_shared<const Edge>(Edge{std::move(converted), vertex(start), vertex(end), false});
        entry.same_parameter = same_parameter && std::abs(entry.edge->curve.domain().min - first) <= 1e-12 * (last - first) &&
                               std::abs(entry.edge->curve.domain().max - last) <= 1e-12 * (last - first);
        return entry;
    }

    static std::string detail_point(const gp_Pnt& p) {
        return "(" + std::to_string(p.X()) + ", " + std::to_string(p.Y()) + ", " + std::to_string(p.Z()) + ")";
    }

    // An edge met first by a surface face on side s: that side's isocurve of our surface, with the surface's
    // parameter; its ends are the OCCT edge's vertices nearest to the isocurve's ends.
    SharedEdge& edge_from_isocurve(const TopoDS_Edge& e, NurbsCurve isocurve) {
        SharedEdge& entry = shared(e);
        const auto [first, last] = ends(e);
        const Interval domain = isocurve.domain();
        const Vec3 start_point = isocurve.point(domain.min);
        bool flipped = distance(from_occt(BRep_Tool::Pnt(last)), start_point) <
                       distance(from_occt(BRep_Tool::Pnt(first)), start_point);
        if (first.IsSame(last)) {
            // A closed edge: compare a point a quarter along the OCCT curve with ours a quarter and three quarters along.
            double f = 0, l = 0;
            const Handle(Geom_Curve) curve = BRep_Tool::Curve(e, f, l);
            if (!curve.IsNull()) {
                const Vec3 quarter = from_occt(curve->Value(f + 0.25 * (l - f)));
                flipped = distance(quarter, isocurve.point(domain.min + 0.75 * domain.width())) <
                          distance(quarter, isocurve.point(domain.min + 0.25 * domain.width()));
            }
        }
        const VertexPtr start = vertex(flipped ? last : first), end = vertex(flipped ? first : last);
        entry.edge = std::make_shared<const Edge>(Edge{std::move(isocurve), start, end, false});
        entry.flipped = flipped;
        entry.same_parameter = false;
        return entry;
    }

    // The natural rectangle of a non-planar face, or none when the face is trimmed otherwise.
    static std::optional<NaturalRectangle> natural_rectangle(const TopoDS_Face& face, const Handle(Geom_Surface)& basis) {
        int wires = 0;
        for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next()) ++wires;
        if (wires != 1) return std::nullopt;
        // Each edge's pcurve at 17 parameters: a side is a straight line, and a curve that only meets the side's
        // line at a few points (a slanted hole's ellipse, whose pcurve on the cylinder is a sine) must not pass.
        constexpr int kSamples = 17;
        std::vector<std::pair<TopoDS_Edge, std::array<gp_Pnt2d, kSamples>>> uses;
        double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
        for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
            const TopoDS_Edge e = TopoDS::Edge(it.Current());
            double first = 0, last = 0;
            const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(e, face, first, last);
            require(!pcurve.IsNull(), "shape", "an edge has no curve on the face's surface");
            std::array<gp_Pnt2d, kSamples> samples;
            for (int k = 0; k < kSamples; ++k) samples[static_cast<std::size_t>(k)] = pcurve->Value(first + (last - first) * k / (kSamples - 1.0));
            for (const gp_Pnt2d& p : samples) {
                u0 = std::min(u0, p.X()), u1 = std::max(u1, p.X());
                v0 = std::min(v0, p.Y()), v1 = std::max(v1, p.Y());
            }
            uses.emplace_back(e, samples);
        }
        if (!(u1 > u0 && v1 > v0)) return std::nullopt;
        std::vector<gp_Pnt2d> boundary;
        for (const auto& use : uses) boundary.insert(boundary.end(), use.second.begin(), use.second.end());
        NaturalRectangle out{snapped(basis, {u0, u1, v0, v1}, detail::file_tolerance(face), /*natural=*/true, boundary), {}};
        // Pcurves made by projection (STEP files without them) sit on the sides to about 1e-7 of the rectangle.
        const double tol_u = 1e-6 * (u1 - u0), tol_v = 1e-6 * (v1 - v0);
        for (const auto& use : uses) {
            const auto& samples = use.second;  // (not a structured binding: clang 14 cannot capture one)
            const auto on = [&](int side) {
                return std::all_of(samples.begin(), samples.end(), [&](const gp_Pnt2d& p) {
                    switch (side) {
                        case 0: return std::abs(p.Y() - v0) <= tol_v;
                        case 1: return std::abs(p.X() - u1) <= tol_u;
                        case 2: return std::abs(p.Y() - v1) <= tol_v;
                        default: return std::abs(p.X() - u0) <= tol_u;
                    }
                });
            };
            int side = -1;
            for (int s = 0; s < 4; ++s)
                if (on(s)) side = s;
            if (side < 0) return std::nullopt;  // an edge inside the rectangle
            auto& slot = out.sides[static_cast<std::size_t>(side)];
            if (slot) return std::nullopt;  // a side of several edges
            slot = use.first;
        }
        for (int s = 0; s < 4; ++s)
            if (!out.sides[static_cast<std::size_t>(s)].has_value()) return std::nullopt;
        return out;
    }

    // Knots within rounding of an end of a B-spline's domain (nearer than Segment can cut, PConfusion) are a
    // file's artefact, over whose span the poles often coincide, so that the surface has no tangent plane at that
    // end (a servo's strip, SolidWorks: a first span of 1.6e-10 in a u range of 0.96, its first two poles one
    // point). Knot removal (The NURBS Book A5.8) does not take them: OpenCASCADE's RemoveUKnot refuses the servo's
    // at any tolerance. So the surface is cut at the innermost such knot (Segment) and its knots are stretched
    // back over the whole domain, which keeps the domain and the file's p-curves: taken where no point of the
    // surface moves further than `tolerance` (measured at the knots, the middles of their spans and the ends).
    static Handle(Geom_BSplineSurface) without_end_slivers(const Handle(Geom_BSplineSurface)& s, double tolerance) {
        Handle(Geom_BSplineSurface) out = s;
        for (const bool in_u : {true, false}) {
            if (in_u ? out->IsUPeriodic() : out->IsVPeriodic()) continue;
            TColStd_Array1OfReal knots(1, in_u ? out->NbUKnots() : out->NbVKnots());
            if (in_u) out->UKnots(knots);
            else out->VKnots(knots);
            const int n = knots.Upper();
            const double first = knots(1), last = knots(n);
            const double short_by = std::max(1e-9 * (last - first), Precision::PConfusion());
            int lo = 1, hi = n;
            while (lo + 1 < n && knots(lo + 1) - first <= short_by) ++lo;
            while (hi - 1 > lo && last - knots(hi - 1) <= short_by) --hi;
            if ((lo == 1 && hi == n) || hi - lo < 1) continue;
            const Handle(Geom_BSplineSurface) cut = Handle(Geom_BSplineSurface)::DownCast(out->Copy());
            double a = 0, b = 0, c = 0, d = 0;
            out->Bounds(a, b, c, d);
            if (in_u) cut->Segment(knots(lo), knots(hi), c, d);
            else cut->Segment(a, b, knots(lo), knots(hi));
            TColStd_Array1OfReal stretched(1, in_u ? cut->NbUKnots() : cut->NbVKnots());
            if (in_u) cut->UKnots(stretched);
            else cut->VKnots(stretched);
            const double from = stretched(1), to = stretched(stretched.Upper());
            for (int k = 1; k <= stretched.Upper(); ++k)
                stretched(k) = k == 1 ? first : k == stretched.Upper() ? last : first + (stretched(k) - from) * ((last - first) / (to - from));
            if (in_u) cut->SetUKnots(stretched);
            else cut->SetVKnots(stretched);
            std::vector<double> along;
            for (int k = 1; k <= n; ++k) {
                along.push_back(knots(k));
                if (k < n) along.push_back(0.5 * (knots(k) + knots(k + 1)));
            }
            const double w0 = in_u ? c : a, w1 = in_u ? d : b;
            bool close = true;
            for (const double t : along)
                for (int q = 0; q <= 8 && close; ++q) {
                    const double w = w0 + (w1 - w0) * q / 8.0;
                    close = (in_u ? out->Value(t, w).Distance(cut->Value(t, w)) : out->Value(w, t).Distance(cut->Value(w, t))) <= tolerance;
                }
            if (close) out = cut;
        }
        return out;
    }

    // The exact NURBS of a face's surface over the rectangle [u0, u1] x [v0, v1] of its parameters; a B-spline
    // without its spans a rounding long at its ends (without_end_slivers, within `tolerance`).
    static Handle(Geom_BSplineSurface) exact_surface(const Handle(Geom_Surface)& basis, const std::array<double, 4>& r,
                                                     double tolerance) {
        // B-splines as they are (a Bézier patch over [0, 1]^2); the quadrics and tori through the Convert_* class
        // over the rectangle; revolutions and extrusions in GeomConvert's rational form over the rectangle.
        Handle(Geom_BSplineSurface) nurbs = elementary_bspline(basis, r);
        const bool spline = basis->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) || basis->IsKind(STANDARD_TYPE(Geom_BezierSurface));
        if (nurbs.IsNull())
            nurbs = GeomConvert::SurfaceToBSplineSurface(
                spline ? basis : Handle(Geom_Surface)(new Geom_RectangularTrimmedSurface(basis, r[0], r[1], r[2], r[3])));
        if (spline) {
            nurbs = without_end_slivers(Handle(Geom_BSplineSurface)::DownCast(nurbs->Copy()), tolerance);
        }
        double a = 0, b = 0, c = 0, d = 0;
        nurbs->Bounds(a, b, c, d);
        const double tol_u = 1e-9 * (r[1] - r[0]), tol_v = 1e-9 * (r[3] - r[2]);
        // A conversion may return a periodic direction a whole period away (GeomConvert puts a revolution's
        // angle into [0, 2 pi)): the same rectangle of the surface, shifted back by period_shifted.
        const auto fits = [](double lo, double hi, double want_lo, double want_hi, double tol, bool periodic, double period) {
            const double shift = periodic && period > 0 ? period * std::round((lo - want_lo) / period) : 0.0;
            return std::abs(want_lo - (lo - shift)) <= tol && std::abs(want_hi - (hi - shift)) <= tol;
        };
        const bool u_fits = fits(a, b, r[0], r[1], tol_u, basis->IsUPeriodic(), basis->IsUPeriodic() ? basis->UPeriod() : 0);
        const bool v_fits = fits(c, d, r[2], r[3], tol_v, basis->IsVPeriodic(), basis->IsVPeriodic() ? basis->VPeriod() : 0);
        if (!u_fits || !v_fits) {
            // A part of a B-spline surface (or a period of a periodic one starting elsewhere): segment it there
            // (knot insertion, exact to rounding).
            require((nurbs->IsUPeriodic() || (r[0] >= a - tol_u && r[1] <= b + tol_u)) &&
                        (nurbs->IsVPeriodic() || (r[2] >= c - tol_v && r[3] <= d + tol_v)),
                    "shape", [&] {
                        return "its parameter rectangle [" + exact_number(r[0]) + ", " + exact_number(r[1]) + "] x [" +
                               exact_number(r[2]) + ", " + exact_number(r[3]) + "] leaves its " + type_name(basis) +
                               "'s exact form's domain [" + exact_number(a) + ", " + exact_number(b) + "] x [" +
                               exact_number(c) + ", " + exact_number(d) + "]";
                    });
            const auto clamp = [](double x, double lo, double hi, bool periodic) { return periodic ? x : std::clamp(x, lo, hi); };
            nurbs->Segment(u_fits ? a : clamp(r[0], a, b, nurbs->IsUPeriodic()), u_fits ? b : clamp(r[1], a, b, nurbs->IsUPeriodic()),
                           v_fits ? c : clamp(r[2], c, d, nurbs->IsVPeriodic()), v_fits ? d : clamp(r[3], c, d, nurbs->IsVPeriodic()));
        }
        return nurbs;
    }

    // Our NURBS of `nurbs`, checked to span the rectangle r and to meet the basis surface at its corners.
    static NurbsSurface checked_surface(const Handle(Geom_BSplineSurface)& nurbs, const Handle(Geom_Surface)& basis,
                                        const std::array<double, 4>& r) {
        NurbsSurface surface = period_shifted(from_occt(nurbs), basis, r);
        const Interval du = surface.domain_u(), dv = surface.domain_v();
        const double tol_u = 1e-9 * (r[1] - r[0]), tol_v = 1e-9 * (r[3] - r[2]);
        require(std::abs(du.min - r[0]) <= tol_u && std::abs(du.max - r[1]) <= tol_u && std::abs(dv.min - r[2]) <= tol_v &&
                    std::abs(dv.max - r[3]) <= tol_v,
                "shape", "the exact form of its " + type_name(basis) + " is not parameterised over the face's rectangle");
        // A rational form may run through the surface at another pace (the tangent half-angle of the arcs), but it
        // must meet the face's corners at the face's parameters: then it covers the same rectangle of the surface.
        const double tolerance = 1e-9 * surface.control_box().diagonal();
        for (const auto& [u, v] : {std::pair{r[0], r[2]}, std::pair{r[1], r[2]}, std::pair{r[1], r[3]}, std::pair{r[0], r[3]}})
            require(distance(surface.point(std::clamp(u, du.min, du.max), std::clamp(v, dv.min, dv.max)),
                             from_occt(basis->Value(u, v))) <= tolerance,
                    "shape", "the exact form of its " + type_name(basis) + " misses the face's corners");
        return surface;
    }

    // Segment() of a periodic B-spline may return the segment a whole period away from the rectangle asked for
    // (a face at v in [-0.05, 6.24] came back over [6.24, 12.52]): the same surface, since it is periodic, with
    // its knots a period off from the parameters of the face's p-curves. Shift them back (exact: S(u + P) = S(u)).
    static NurbsSurface period_shifted(const NurbsSurface& surface, const Handle(Geom_Surface)& basis, const std::array<double, 4>& r) {
        const auto shift = [](const Interval& d, double lo, bool periodic, double period) {
            if (!periodic || !(period > 0)) return 0.0;
            const double turns = std::round((lo - d.min) / period);
            return std::abs(d.min + turns * period - lo) <= 1e-9 * std::max(1.0, period) ? turns * period : 0.0;
        };
        const double su = shift(surface.domain_u(), r[0], basis->IsUPeriodic(), basis->IsUPeriodic() ? basis->UPeriod() : 0);
        const double sv = shift(surface.domain_v(), r[2], basis->IsVPeriodic(), basis->IsVPeriodic() ? basis->VPeriod() : 0);
        if (su == 0 && sv == 0) return surface;
        std::vector<double> ku = surface.knots_u(), kv = surface.knots_v();
        for (double& k : ku) k += su;
        for (double& k : kv) k += sv;
        return NurbsSurface::from_homogeneous(surface.degree_u(), surface.degree_v(), std::move(ku), std::move(kv),
                                              surface.homogeneous_points(), surface.is_rational());
    }

    // `surface` with u running backwards: S'(u, v) = S(a + b - u, v), so S'_u x S'_v = -(S_u x S_v).
    static NurbsSurface reversed_in_u(const NurbsSurface& surface) {
        std::vector<double> knots = surface.knots_u();
        const double a = knots.front(), b = knots.back();
        std::reverse(knots.begin(), knots.end());
        for (double& k : knots) k = a + b - k;
        // a + b - k rounds: keep the ends exact and the sequence non-decreasing (a clamped end's repeated
        // knots would otherwise differ in the last bit and dip).
        for (double& k : knots) k = std::clamp(k, a, b);
        for (std::size_t i = 1; i < knots.size(); ++i) knots[i] = std::max(knots[i], knots[i - 1]);
        std::vector<Vec4> points;
        points.reserve(surface.homogeneous_points().size());
        for (int i = surface.rows() - 1; i >= 0; --i)
            for (int j = 0; j < surface.columns(); ++j) points.push_back(surface.homogeneous_point(i, j));
        return NurbsSurface::from_homogeneous(surface.degree_u(), surface.degree_v(), std::move(knots), surface.knots_v(),
                                              std::move(points), surface.is_rational());
    }

    static Handle(Geom_Surface) required_basis(const TopoDS_Face& face) {
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        require(!surface.IsNull(), "shape", "the face has no surface");
        const Handle(Geom_Surface) basis = exact_basis(surface);
        if (basis.IsNull())
            fail("shape", "a " + type_name(surface) + " face has no exact NURBS form (supported: B-spline, Bezier, plane, "
                          "cylinder, cone, sphere, torus, revolution and extrusion of lines, conics and B-splines)");
        return basis;
    }

    // A surface face, or none when the face is trimmed (not its surface's natural rectangle, or a side that
    // another surface face already made an edge of with another parameterisation).
    std::optional<Face> surface_face(const TopoDS_Face& face) {
        const Handle(Geom_Surface) basis = required_basis(face);
        const std::optional<NaturalRectangle> rectangle = natural_rectangle(face, basis);
        if (!rectangle) return std::nullopt;
        NurbsSurface nurbs = checked_surface(exact_surface(basis, rectangle->bounds, detail::file_tolerance(face)), basis, rectangle->bounds);
        // A REVERSED face's outward normal is -(S_u x S_v): run u backwards, which swaps the u sides.
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        if (reversed) nurbs = reversed_in_u(nurbs);
        const Interval du = nurbs.domain_u(), dv = nurbs.domain_v();
        // The sides' edges, checked against what other surface faces made of them before anything is made.
        std::array<NurbsCurve, 4> isocurves{nurbs.isocurve_v(dv.min), nurbs.isocurve_u(du.max), nurbs.isocurve_v(dv.max),
                                            nurbs.isocurve_u(du.min)};
        for (int s = 0; s < 4; ++s) {
            const int occt_side = reversed && !along_u(s) ? (s + 2) % 4 : s;
            const TopoDS_Edge& e = *rectangle->sides[static_cast<std::size_t>(occt_side)];
            if (BRep_Tool::Degenerated(e)) continue;
            const SharedEdge& entry = shared(e);
            if (entry.edge && !(entry.edge->curve.domain() == isocurves[static_cast<std::size_t>(s)].domain() &&
                                parameterised_alike(entry.edge->curve, isocurves[static_cast<std::size_t>(s)])))
                return std::nullopt;
        }
        std::array<Coedge, 4> sides;
        for (int s = 0; s < 4; ++s) {
            const int occt_side = reversed && !along_u(s) ? (s + 2) % 4 : s;
            const TopoDS_Edge& e = *rectangle->sides[static_cast<std::size_t>(occt_side)];
            NurbsCurve& isocurve = isocurves[static_cast<std::size_t>(s)];
            bool with_parameter = true;
            EdgePtr edge;
            if (BRep_Tool::Degenerated(e)) {
                const VertexPtr pole = vertex(ends(e).first);
                edge = std::make_shared<const Edge>(Edge{std::move(isocurve), pole, pole, true});
            } else if (SharedEdge& entry = shared(e); entry.edge) {
                // Met before: it runs with this side's parameter or against it (validated by Face::from_surface).
                edge = entry.edge;
                with_parameter = runs_with(edge->curve, isocurve);
            } else {
                edge = edge_from_isocurve(e, std::move(isocurve)).edge;
            }
            sides[static_cast<std::size_t>(s)] = Coedge{edge, traversal_increasing(s) != with_parameter};
        }
        // A file's vertices may sit off the surface's corners by its tolerance (a sewn surface model), more than
        // a surface face allows: such a face is trimmed, whose p-curves take the file's tolerance.
        try {
            return Face::from_surface(std::move(nurbs), sides);
        } catch (const Error&) {
            return std::nullopt;
        }
    }

    // Whether curve a runs the way b does (by a quarter and three quarters along both).
    // The point a fraction f along a curve's domain (the ends exactly: an affine step can round past them).
    static Vec3 at_fraction(const NurbsCurve& c, double f) {
        const Interval d = c.domain();
        return c.point(f >= 1 ? d.max : f <= 0 ? d.min : std::clamp(d.min + f * d.width(), d.min, d.max));
    }
    static bool runs_with(const NurbsCurve& a, const NurbsCurve& b) {
        const auto at = [](const NurbsCurve& c, const Interval&, double f) { return at_fraction(c, f); };
        const Interval da = a.domain(), db = b.domain();
        const double with = distance(at(a, da, 0.25), at(b, db, 0.25)) + distance(at(a, da, 0.75), at(b, db, 0.75));
        const double against = distance(at(a, da, 0.25), at(b, db, 0.75)) + distance(at(a, da, 0.75), at(b, db, 0.25));
        return with <= against;
    }
    // Whether two curves over one domain are the same curve with the same parameter (or the reversed one, t ->
    // a + b - t), at 9 parameters to 1e-9 of the size: what Face::from_surface accepts for a shared side.
    bool parameterised_alike(const NurbsCurve& a, const NurbsCurve& b) const {
        const bool with = runs_with(a, b);
        const double tolerance = 1e-9 * std::max(size_, b.control_box().diagonal());
        for (int k = 0; k <= 8; ++k)
            if (distance(at_fraction(a, k / 8.0), at_fraction(b, with ? k / 8.0 : 1 - k / 8.0)) > tolerance) return false;
        return true;
    }

    // A trimmed face: the exact NURBS over the box of its p-curves, one loop per wire (the outer wire first),
    // each coedge with its p-curve in our parameters (pcurve_fit.hpp), the loops closed in (u, v) where the
    // fits of neighbouring coedges end a rounding apart, a degenerate coedge's p-curve running along the pole
    // from where the previous p-curve ends to where the next begins. Its tolerance: the file's, or what the
    // p-curves carry if that is more.
    Face trimmed_face(const TopoDS_Face& face) {
        const Handle(Geom_Surface) basis = required_basis(face);
        const bool spline = basis->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) || basis->IsKind(STANDARD_TYPE(Geom_BezierSurface));
        std::array<double, 4> r = trimmed_rectangle(face, basis);
        if (spline) {
            // A B-spline face keeps its whole surface where the p-curves lie inside it: its parameters stay
            // OCCT's, so the file's p-curves are exact in ours.
            double a = 0, b = 0, c = 0, d = 0;
            basis->Bounds(a, b, c, d);
            if (!basis->IsUPeriodic() && !basis->IsVPeriodic()) r = {a, b, c, d};
        }
        const Handle(Geom_BSplineSurface) occt_nurbs = exact_surface(basis, r, detail::file_tolerance(face));
        NurbsSurface nurbs = checked_surface(occt_nurbs, basis, r);
        r = {nurbs.domain_u().min, nurbs.domain_u().max, nurbs.domain_v().min, nurbs.domain_v().max};
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        if (reversed) nurbs = reversed_in_u(nurbs);
        // OCCT's (u, v) on the face as ours, roughly (the pace of a rational form differs inside its spans).
        const auto ours = [&](const gp_Pnt2d& p) { return reversed ? gp_Pnt2d(r[0] + r[1] - p.X(), p.Y()) : p; };
        // Our parameters are OCCT's exactly for a B-spline face (Segment keeps them) not run backwards.
        const bool same_surface_parameters = spline && !reversed;

        const double stated = plausible_tolerance(face);
        double tolerance = stated;
        // What a fit may carry: the file's own gap between an edge and the surface, which the self-consistency
        // check held to the file's tolerances and slack at 9 points an edge (between them a Voron carriage's edge
        // strays twice as far: 1.1e-4 there, 2.0e-4 at the fit's points). A fit further off lost its edge (a nut's
        // thread, a strip 15 turns round a cylinder: 3.5 off), and is refused rather than carried as a tolerance.
        const double carried = 4 * stated + detail::file_slack(size_, 1);
        const auto unfitted = [&](double deviation) {
            return "an edge's curve on its face could not be fitted (the fit keeps " + exact_number(deviation) +
                   " from the edge, more than the file's tolerance " + exact_number(stated) + " allows)";
        };
        detail::PcurveFitter fitter(nurbs, size_);
        std::vector<std::vector<Coedge>> loops;
        const TopoDS_Wire outer = BRepTools::OuterWire(face);
        std::vector<TopoDS_Wire> wires{outer};
        for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next())
            if (!it.Current().IsSame(outer)) wires.push_back(TopoDS::Wire(it.Current()));
        for (const TopoDS_Wire& wire : wires) {
            std::vector<Coedge> loop;
            std::vector<std::optional<gp_Pnt2d>> pole_ends;  // a degenerate coedge's pole value, until its ends are known
            for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
                const TopoDS_Edge& e = it.Current();
                double first = 0, last = 0;
                const Handle(Geom2d_Curve) occt_pcurve = BRep_Tool::CurveOnSurface(e, face, first, last);
                require(!occt_pcurve.IsNull(), "shape", "an edge has no curve on the face's surface");
                if (BRep_Tool::Degenerated(e)) {
                    // Its p-curve is made once its neighbours' ends are known (below).
                    const VertexPtr pole = vertex(ends(e).first);
                    const NurbsCurve point_curve(1, {0, 0, 1, 1}, {pole->point, pole->point});
                    loop.push_back(Coedge{std::make_shared<const Edge>(Edge{point_curve, pole, pole, true}), false, nullptr});
                    continue;
                }
                SharedEdge& entry = edge_from_curve(e);
                const bool coedge_reversed = (e.Orientation() == TopAbs_REVERSED) != entry.flipped;
                const NurbsCurve& curve = entry.edge->curve;
                const Interval domain = curve.domain();
                // OCCT's pcurve follows the OCCT edge's parameter [first, last]; ours runs over `domain`, the
                // other way when flipped: the guess maps linearly, projection does the rest.
                const auto guess = [&, first, last, flipped = entry.flipped](double t) {
                    double f = (t - domain.min) / domain.width();
                    if (flipped) f = 1 - f;
                    return ours(occt_pcurve->Value(first + f * (last - first)));
                };
                std::optional<NurbsCurve> exact;
                if (same_surface_parameters && entry.same_parameter && !entry.flipped) {
                    try {
                        exact = from_occt_2d(Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(occt_pcurve, first, last)));
                    } catch (const Standard_Failure&) {
                    }
                }
                detail::FittedPcurve fitted = fitter.fit(curve, guess, exact ? &*exact : nullptr, tolerance, same_surface_parameters);
                require(fitted.deviation <= carried, "shape", [&] { return unfitted(fitted.deviation); });
                tolerance = std::max(tolerance, fitted.deviation);
                loop.push_back(Coedge{entry.edge, coedge_reversed, std::make_shared<const NurbsCurve>(std::move(fitted.curve))});
            }
            require(!loop.empty(), "shape", "a wire of the face has no edges");
            close_loop(loop, nurbs);
            loops.push_back(std::move(loop));
        }
        // The validation holds the p-curves to the face's tolerance at parameters of its own, between the fit's: a
        // SolidWorks spacer's p-curve fitted within the file's 1e-7 kept 1.8e-7 off its edge there. The face takes
        // what it measures, within what a fit may carry, and a little room above the fit's own measure.
        double gap = 0;
        for (const auto& loop : loops)
            for (const Coedge& c : loop) {
                const double g = pcurve_gap(nurbs, c);
                if (!(g <= gap)) gap = g;  // NaN kept, and refused below
            }
        require(gap <= carried, "shape", [&] { return unfitted(gap); });
        return Face::trimmed(std::move(nurbs), std::move(loops), std::max(1.5 * tolerance, gap));
    }

    // Makes the p-curves of a loop meet end to start in (u, v): where two fits end a rounding apart, both ends
    // move to their middle (the end control point of a clamped curve is its end point, so only the curve's
    // last stretch moves, by that rounding); a degenerate coedge gets the straight p-curve along its pole
    // from where the previous p-curve ends to where the next begins.
    static void close_loop(std::vector<Coedge>& loop, const NurbsSurface& surface) {
        const std::size_t n = loop.size();
        const auto end_of = [](const Coedge& c) { return c.reversed ? c.pcurve->start_point() : c.pcurve->end_point(); };
        const auto start_of = [](const Coedge& c) { return c.reversed ? c.pcurve->end_point() : c.pcurve->start_point(); };
        const auto moved_end = [](const NurbsCurve& curve, bool at_start, const Vec3& to) {
            std::vector<Vec4> points = curve.homogeneous_points();
            Vec4& p = at_start ? points.front() : points.back();
            p = Vec4{to.x * p.w, to.y * p.w, 0, p.w};
            return std::make_shared<const NurbsCurve>(
                NurbsCurve::from_homogeneous(curve.degree(), curve.knots(), std::move(points), curve.is_rational()));
        };
        for (std::size_t k = 0; k < n; ++k) {
            Coedge& here = loop[k];
            Coedge& next = loop[(k + 1) % n];
            if (!here.pcurve || !next.pcurve) continue;
            const Vec3 middle = (end_of(here) + start_of(next)) * 0.5;
            if (&here == &next) {
                here.pcurve = moved_end(*moved_end(*here.pcurve, here.reversed, middle), !here.reversed, middle);
                continue;
            }
            here.pcurve = moved_end(*here.pcurve, here.reversed, middle);
            next.pcurve = moved_end(*next.pcurve, !next.reversed, middle);
        }
        for (std::size_t k = 0; k < n; ++k) {
            Coedge& pole = loop[k];
            if (pole.pcurve) continue;
            const Coedge& previous = loop[(k + n - 1) % n];
            const Coedge& next = loop[(k + 1) % n];
            require(previous.pcurve && next.pcurve, "shape", "two degenerate edges follow each other in a loop");
            const Vec3 from = end_of(previous), to = start_of(next);
            const Interval d = pole.edge->curve.domain();
            pole.pcurve = std::make_shared<const NurbsCurve>(NurbsCurve(1, {d.min, d.min, d.max, d.max}, {from, to}));
        }
        (void)surface;
    }

    Face planar_face(const TopoDS_Face& face) {
        const gp_Ax3 frame = Handle(Geom_Plane)::DownCast(plane_basis(face))->Position();
        // The plane's (u, v) axes; for a REVERSED face y runs the other way, so that x cross y points out.
        const Vec3 x = from_occt(gp_Vec(frame.XDirection()));
        const Vec3 y = from_occt(gp_Vec(frame.YDirection())) * (face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0);
        const Plane plane{from_occt(frame.Location()), x, y, cross(x, y)};
        const TopoDS_Wire outer = BRepTools::OuterWire(face);
        std::vector<TopoDS_Wire> wires{outer};
        for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next())
            if (!it.Current().IsSame(outer)) wires.push_back(TopoDS::Wire(it.Current()));
        std::vector<std::vector<Coedge>> loops;
        for (const TopoDS_Wire& wire : wires) {
            auto& loop = loops.emplace_back();
            // The edges in order along the wire, oriented as the face runs them (the face's orientation composed in).
            for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
                const TopoDS_Edge& e = it.Current();
                if (BRep_Tool::Degenerated(e)) continue;
                const SharedEdge& entry = edge_from_curve(e);
                loop.push_back(Coedge{entry.edge, (e.Orientation() == TopAbs_REVERSED) != entry.flipped});
            }
        }
        const double tolerance = plausible_tolerance(face);
        return Face::planar(plane, std::move(loops), std::max(tolerance, kept_off_plane(loops, plane, tolerance)));
    }

    // How far the loops' curves stray from their plane, where that is beyond the file's `tolerance` by no more than
    // its slack (self_consistency.hpp, file_slack): the face's tolerance is raised to it, as the edges' are for gaps
    // of that size. 0 otherwise (then Face::planar refuses the loops, naming the distance). Sampled at 16 points a
    // span, the 8 of Face::planar's own check and the points between, with a margin for their rounding.
    double kept_off_plane(const std::vector<std::vector<Coedge>>& loops, const Plane& plane, double tolerance) const {
        double farthest = 0, coordinates = 1;
        for (const auto& loop : loops)
            for (const Coedge& c : loop) {
                const NurbsCurve& curve = c.edge->curve;
                const std::vector<double> breaks = breakpoints(curve.degree(), curve.knots());
                for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
                    for (int j = 0; j <= 16; ++j) {
                        const Vec3 p = curve.point(j == 16 ? breaks[k + 1] : breaks[k] + (breaks[k + 1] - breaks[k]) * j / 16.0);
                        farthest = std::max(farthest, std::abs(dot(p - plane.origin, plane.normal)));
                        coordinates = std::max({coordinates, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
                    }
            }
        const bool kept = farthest > tolerance && farthest <= tolerance + detail::file_slack(size_, coordinates);
        return kept ? farthest * (1 + 1e-9) : 0;
    }

    // The file's tolerance of the face (detail::file_tolerance), refused past 1% of the model's size: a boundary that
    // far from its surface is a file whose geometry disagrees with itself, not rounding (the soak: a plane
    // moved 16 off its loops, which OpenCASCADE's reader covered with tolerances of 16 on a 30 x 20 x 8 part;
    // the volume followed the plane and the mesh the loops, 1,587 against 4,552).
    double plausible_tolerance(const TopoDS_Face& face) const {
        const double tolerance = detail::file_tolerance(face);
        require(tolerance <= 1e-2 * size_, "tolerance", [&] {
            return "the file lets the face's boundary keep " + exact_number(tolerance) + " from its surface, more than 1% of "
                   "the model's size " + exact_number(size_) + ": its geometry does not agree with itself";
        });
        return tolerance;
    }

    TopoDS_Shape solid_;
    TopTools_IndexedMapOfShape vertex_index_, edge_index_;
    std::vector<VertexPtr> vertices_;
    std::vector<SharedEdge> edges_;
    double size_ = 1;
};

// The solids a surface model bounds: its faces sewn along the edges they share to within 1e-6 of the model's
// size (BRepBuilderAPI_Sewing, what FreeCAD's "Shape from mesh"/"Convert to solid" and CAD translators do),
// each closed shell made a solid and oriented outward (ShapeFix_Solid). Exporters write pin headers and SMD
// packages as shells of faces with no solid entity (SHELL_BASED_SURFACE_MODEL in STEP); the faces are exact.
// The faces of shells that stay open bound no volume: counted in `open_faces`.
std::vector<TopoDS_Shape> sewn_solids(const TopoDS_Shape& shape, int& open_faces) {
    std::vector<TopoDS_Shape> solids;
    if (!TopExp_Explorer(shape, TopAbs_FACE).More()) return solids;
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    if (box.IsVoid()) return solids;
    try {
        BRepBuilderAPI_Sewing sewing(std::max(1e-6 * std::sqrt(box.SquareExtent()), Precision::Confusion()));
        sewing.Add(shape);
        sewing.Perform();
        for (TopExp_Explorer it(sewing.SewedShape(), TopAbs_SHELL); it.More(); it.Next()) {
            const TopoDS_Shell shell = TopoDS::Shell(it.Current());
            if (!BRep_Tool::IsClosed(shell)) {
                for (TopExp_Explorer faces(shell, TopAbs_FACE); faces.More(); faces.Next()) ++open_faces;
                continue;
            }
            ShapeFix_Solid fix;
            const TopoDS_Solid solid = fix.SolidFromShell(shell);
            if (!solid.IsNull()) solids.push_back(solid);
        }
    } catch (const Standard_Failure&) {
        solids.clear();
    }
    return solids;
}

// The faces of the shape that no solid of it holds.
int faces_outside_solids(const TopoDS_Shape& shape, const std::vector<TopoDS_Shape>& solids) {
    TopTools_IndexedMapOfShape all, in_solids;
    TopExp::MapShapes(shape, TopAbs_FACE, all);
    for (const TopoDS_Shape& solid : solids) TopExp::MapShapes(solid, TopAbs_FACE, in_solids);
    int outside = 0;
    for (int k = 1; k <= all.Extent(); ++k)
        if (!in_solids.Contains(all(k))) ++outside;
    return outside;
}

// The solids of a shape in the order TopExp_Explorer meets them; a shape of faces without solids is sewn.
// `left_out`, if given, says what of the shape no solid holds (empty when nothing).
std::vector<TopoDS_Shape> solids_of(const TopoDS_Shape& shape, std::string* left_out) {
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) solids.push_back(it.Current());
    int open_faces = 0;
    if (solids.empty()) solids = sewn_solids(shape, open_faces);
    else open_faces = faces_outside_solids(shape, solids);
    if (left_out != nullptr)
        *left_out = open_faces == 0 || solids.empty()
                        ? std::string()
                        : "left out " + std::to_string(open_faces) +
                              " face(s) outside every solid: they bound no volume (open shells or loose faces)";
    return solids;
}

// What a shape without solids holds instead, for the message: "75 open shells (a surface model)".
std::string what_instead(const TopoDS_Shape& shape) {
    int shells = 0, faces = 0;
    for (TopExp_Explorer it(shape, TopAbs_SHELL); it.More(); it.Next()) ++shells;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) ++faces;
    const auto count = [](int n, const char* one) { return std::to_string(n) + " " + one + (n == 1 ? "" : "s"); };
    if (shells > 0)
        return "; it holds " + count(shells, "shell") + " of " + count(faces, "face") +
               ", a surface model that does not sew into closed shells";
    if (faces > 0) return "; it holds " + count(faces, "loose face");
    return "";
}

// One solid converted, its sliver faces taken out first (sliver_faces.hpp: no mesh closes across them), an
// OpenCASCADE exception that escapes the steps' own handling said as the shape's error (a Standard_Failure is no
// std::exception: the command reported it as an unknown internal error).
Solid imported(const TopoDS_Shape& solid, const Progress& progress) {
    try {
        const TopoDS_Shape healed = detail::without_sliver_faces(solid);
        if (healed.IsSame(solid)) return Importer(solid).run(progress);
        // Healing that the conversion refuses is not taken, and the solid as read says why (a ploopy trackball
        // part's sliver, within its file's tolerance of 0.056: taken out, a plane of the part failed its loop check).
        try {
            return Importer(healed).run(progress);
        } catch (const Error&) {
            return Importer(solid).run(progress);
        }
    } catch (const Standard_Failure& failure) {
        throw Error("shape", std::string("OpenCASCADE failed reading it (") + failure.DynamicType()->Name() + ": " +
                                 failure.GetMessageString() + ")");
    }
}

}  // namespace

Solid from_occt(const TopoDS_Shape& shape, const Progress& progress, std::string* left_out) {
    require(!shape.IsNull(), "shape", "is empty");
    const std::vector<TopoDS_Shape> solids = solids_of(shape, left_out);
    require(!solids.empty(), "shape", "holds no solid" + what_instead(shape));
    require(solids.size() == 1, "shape",
            "holds " + std::to_string(solids.size()) + " solids; a ratbez Solid is made from exactly one (read them all with read_step_all / read_brep_all)");
    return imported(solids.front(), progress);
}

std::vector<Solid> from_occt_all(const TopoDS_Shape& shape, const Progress& progress, std::string* left_out,
                                 std::vector<SolidLeftOut>* solids_left_out) {
    require(!shape.IsNull(), "shape", "is empty");
    const std::vector<TopoDS_Shape> solids = solids_of(shape, left_out);
    require(!solids.empty(), "shape", "holds no solid" + what_instead(shape));
    std::vector<Solid> out;
    out.reserve(solids.size());
    std::vector<SolidLeftOut> refused;
    for (std::size_t k = 0; k < solids.size(); ++k) {
        const Progress part = [&](double fraction) {
            if (progress) progress((static_cast<double>(k) + fraction) / static_cast<double>(solids.size()));
        };
        try {
            out.push_back(imported(solids[k], part));
        } catch (const Error& e) {
            if (solids.size() == 1) throw;
            if (solids_left_out == nullptr) throw Error("shape", "solid " + std::to_string(k) + ": " + std::string(e.reason()));
            refused.push_back({k, std::string(e.reason())});
        }
    }
    // When no solid converts, the first refusal is the error.
    if (out.empty()) throw Error("shape", "solid " + std::to_string(refused.front().index) + ": " + refused.front().reason);
    if (solids_left_out != nullptr) *solids_left_out = std::move(refused);
    return out;
}

}  // namespace ratbez::occt
