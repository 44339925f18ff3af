// TopoDS_Shape -> ratbez::Solid (see shape_import.hpp for what is converted and what is refused).

#include "ratbez/occt/shape_import.hpp"

#include <BRepTools.hxx>
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
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
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
#include <optional>
#include <string>
#include <vector>

#include "face_sides.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt {
namespace {

const char* side_name(int side) {
    static const char* names[] = {"v_min", "u_max", "v_max", "u_min"};
    return names[side];
}
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

// A cylinder, cone, sphere or torus over exactly the rectangle r: knots at its bounds, so the corners keep their
// parameters wherever a full turn starts (GeomConvert turns a full turn from angle 0 and segments it, which
// leaves the corner of a seam at angle 1 at 0.995); null for other surfaces.
Handle(Geom_BSplineSurface) elementary_bspline(const Handle(Geom_Surface)& basis, const std::array<double, 4>& r) {
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

class Importer {
public:
    explicit Importer(const TopoDS_Shape& solid) : solid_(solid) {
        TopExp::MapShapes(solid, TopAbs_VERTEX, vertex_index_);
        TopExp::MapShapes(solid, TopAbs_EDGE, edge_index_);
        vertices_.resize(static_cast<std::size_t>(vertex_index_.Extent()));
        edges_.resize(static_cast<std::size_t>(edge_index_.Extent()));
    }

    Solid run(const Progress& progress) {
        std::vector<TopoDS_Face> faces;
        for (TopExp_Explorer it(solid_, TopAbs_FACE); it.More(); it.Next()) faces.push_back(TopoDS::Face(it.Current()));
        require(!faces.empty(), "shape", "the solid has no faces");
        // Surface faces first: their boundary isocurves become the shared edges that planar faces then take
        // as they are (a plane accepts any parameterisation of its edges, a surface face only its own).
        std::vector<std::optional<Face>> made(faces.size());
        std::size_t done = 0;
        for (const bool planar_pass : {false, true})
            for (std::size_t i = 0; i < faces.size(); ++i) {
                if (is_planar(faces[i]) != planar_pass) continue;
                try {
                    made[i] = planar_pass ? planar_face(faces[i]) : surface_face(faces[i]);
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

    VertexPtr vertex(const TopoDS_Vertex& v) {
        VertexPtr& made = vertices_[static_cast<std::size_t>(vertex_index_.FindIndex(v) - 1)];
        if (!made) made = std::make_shared<const Vertex>(Vertex{from_occt(BRep_Tool::Pnt(v))});
        return made;
    }

    // Our edge for an OCCT edge and whether it runs against the OCCT edge's own (FORWARD) direction.
    struct SharedEdge {
        EdgePtr edge;
        bool flipped = false;
    };
    SharedEdge& shared(const TopoDS_Edge& e) { return edges_[static_cast<std::size_t>(edge_index_.FindIndex(e) - 1)]; }

    // The OCCT edge's ends in its FORWARD direction.
    static std::pair<TopoDS_Vertex, TopoDS_Vertex> ends(const TopoDS_Edge& e) {
        TopoDS_Vertex first, last;
        TopExp::Vertices(TopoDS::Edge(e.Oriented(TopAbs_FORWARD)), first, last);
        require(!first.IsNull() && !last.IsNull(), "shape", "an edge has no vertices");
        return {first, last};
    }

    // An edge met first by a planar face: its 3D curve converted exactly, running as the OCCT edge does.
    SharedEdge& edge_from_curve(const TopoDS_Edge& e) {
        SharedEdge& entry = shared(e);
        if (entry.edge) return entry;
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(e, first, last);
        require(!curve.IsNull(), "shape", "an edge of a plane has no 3D curve");
        const Handle(Geom_Curve) basis = exact_basis(curve);
        if (basis.IsNull()) fail("shape", "an edge's " + type_name(curve) + " has no exact NURBS form");
        const Handle(Geom_BSplineCurve) nurbs =
            GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(basis, first, last));
        const auto [start, end] = ends(e);
        entry.edge = std::make_shared<const Edge>(Edge{from_occt(nurbs), vertex(start), vertex(end), false});
        return entry;
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
        return entry;
    }

    // The natural rectangle of a non-planar face, or an Error saying why the face is trimmed.
    static NaturalRectangle natural_rectangle(const TopoDS_Face& face, const std::string& surface_type) {
        const std::string trimmed = "a trimmed " + surface_type + " face is not supported (ratbez faces are ";
        int wires = 0;
        for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next()) ++wires;
        require(wires == 1, "shape", trimmed + "untrimmed surfaces; this one has " + std::to_string(wires) +
                                         " boundary loops)");
        // Each edge's pcurve at its ends and middle.
        std::vector<std::pair<TopoDS_Edge, std::array<gp_Pnt2d, 3>>> uses;
        double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
        for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
            const TopoDS_Edge e = TopoDS::Edge(it.Current());
            double first = 0, last = 0;
            const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(e, face, first, last);
            require(!pcurve.IsNull(), "shape", "an edge has no curve on the face's surface");
            const std::array<gp_Pnt2d, 3> samples{pcurve->Value(first), pcurve->Value(0.5 * (first + last)),
                                                   pcurve->Value(last)};
            for (const gp_Pnt2d& p : samples) {
                u0 = std::min(u0, p.X()), u1 = std::max(u1, p.X());
                v0 = std::min(v0, p.Y()), v1 = std::max(v1, p.Y());
            }
            uses.emplace_back(e, samples);
        }
        require(u1 > u0 && v1 > v0, "shape", "the face's curves on its surface span no area");
        NaturalRectangle out{{u0, u1, v0, v1}, {}};
        // Pcurves made by projection (STEP files without them) sit on the sides to about 1e-7 of the rectangle.
        const double tol_u = 1e-6 * (u1 - u0), tol_v = 1e-6 * (v1 - v0);
        for (const auto& [e, samples] : uses) {
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
            if (side < 0) fail("shape", trimmed + "untrimmed surfaces; an edge runs inside its parameter rectangle)");
            auto& slot = out.sides[static_cast<std::size_t>(side)];
            if (slot) fail("shape", trimmed + "bounded by one edge per side; side " + side_name(side) + " has several)");
            slot = e;
        }
        for (int s = 0; s < 4; ++s)
            require(out.sides[static_cast<std::size_t>(s)].has_value(), "shape",
                    trimmed + "bounded by four sides; side " + side_name(s) + " has no edge)");
        return out;
    }

    // The exact NURBS of a face's surface over the rectangle [u0, u1] x [v0, v1] of its parameters.
    static NurbsSurface exact_surface(const Handle(Geom_Surface)& basis, const std::array<double, 4>& r) {
        // B-splines as they are (a Bézier patch over [0, 1]^2); the quadrics and tori through the Convert_* class
        // over the rectangle; revolutions and extrusions in GeomConvert's rational form over the rectangle.
        Handle(Geom_BSplineSurface) nurbs = elementary_bspline(basis, r);
        const bool spline = basis->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) || basis->IsKind(STANDARD_TYPE(Geom_BezierSurface));
        if (nurbs.IsNull())
            nurbs = GeomConvert::SurfaceToBSplineSurface(
                spline ? basis : Handle(Geom_Surface)(new Geom_RectangularTrimmedSurface(basis, r[0], r[1], r[2], r[3])));
        double a = 0, b = 0, c = 0, d = 0;
        nurbs->Bounds(a, b, c, d);
        const double tol_u = 1e-9 * (r[1] - r[0]), tol_v = 1e-9 * (r[3] - r[2]);
        const bool u_fits = std::abs(r[0] - a) <= tol_u && std::abs(r[1] - b) <= tol_u;
        const bool v_fits = std::abs(r[2] - c) <= tol_v && std::abs(r[3] - d) <= tol_v;
        if (!u_fits || !v_fits) {
            // A part of a B-spline surface (or a period of a periodic one starting elsewhere): segment it there
            // (knot insertion, exact to rounding).
            require((nurbs->IsUPeriodic() || (r[0] >= a - tol_u && r[1] <= b + tol_u)) &&
                        (nurbs->IsVPeriodic() || (r[2] >= c - tol_v && r[3] <= d + tol_v)),
                    "shape", "its parameter rectangle leaves its " + type_name(basis) + "'s domain");
            const auto clamp = [](double x, double lo, double hi, bool periodic) { return periodic ? x : std::clamp(x, lo, hi); };
            nurbs->Segment(u_fits ? a : clamp(r[0], a, b, nurbs->IsUPeriodic()), u_fits ? b : clamp(r[1], a, b, nurbs->IsUPeriodic()),
                           v_fits ? c : clamp(r[2], c, d, nurbs->IsVPeriodic()), v_fits ? d : clamp(r[3], c, d, nurbs->IsVPeriodic()));
        }
        NurbsSurface surface = from_occt(nurbs);
        const Interval du = surface.domain_u(), dv = surface.domain_v();
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

    // `surface` with u running backwards: S'(u, v) = S(a + b - u, v), so S'_u x S'_v = -(S_u x S_v).
    static NurbsSurface reversed_in_u(const NurbsSurface& surface) {
        std::vector<double> knots = surface.knots_u();
        const double a = knots.front(), b = knots.back();
        std::reverse(knots.begin(), knots.end());
        for (double& k : knots) k = a + b - k;
        knots.front() = a, knots.back() = b;
        std::vector<Vec4> points;
        points.reserve(surface.homogeneous_points().size());
        for (int i = surface.rows() - 1; i >= 0; --i)
            for (int j = 0; j < surface.columns(); ++j) points.push_back(surface.homogeneous_point(i, j));
        return NurbsSurface::from_homogeneous(surface.degree_u(), surface.degree_v(), std::move(knots), surface.knots_v(),
                                              std::move(points), surface.is_rational());
    }

    Face surface_face(const TopoDS_Face& face) {
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        const Handle(Geom_Surface) basis = exact_basis(surface);
        if (basis.IsNull())
            fail("shape", "a " + type_name(surface) + " face has no exact NURBS form (supported: B-spline, Bezier, plane, "
                          "cylinder, cone, sphere, torus, revolution and extrusion of lines, conics and B-splines)");
        const NaturalRectangle rectangle = natural_rectangle(face, type_name(basis));
        NurbsSurface nurbs = exact_surface(basis, rectangle.bounds);
        // A REVERSED face's outward normal is -(S_u x S_v): run u backwards, which swaps the u sides.
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        if (reversed) nurbs = reversed_in_u(nurbs);
        const Interval du = nurbs.domain_u(), dv = nurbs.domain_v();
        std::array<Coedge, 4> sides;
        for (int s = 0; s < 4; ++s) {
            const int occt_side = reversed && !along_u(s) ? (s + 2) % 4 : s;
            const TopoDS_Edge& e = *rectangle.sides[static_cast<std::size_t>(occt_side)];
            NurbsCurve isocurve = s == 0 ? nurbs.isocurve_v(dv.min)
                                : s == 1 ? nurbs.isocurve_u(du.max)
                                : s == 2 ? nurbs.isocurve_v(dv.max)
                                         : nurbs.isocurve_u(du.min);
            bool with_parameter = true;
            EdgePtr edge;
            if (BRep_Tool::Degenerated(e)) {
                const VertexPtr pole = vertex(ends(e).first);
                edge = std::make_shared<const Edge>(Edge{std::move(isocurve), pole, pole, true});
            } else if (SharedEdge& entry = shared(e); entry.edge) {
                // Met before: it runs with this side's parameter or against it (validated by Face::from_surface).
                edge = entry.edge;
                const Interval a = edge->curve.domain(), b = isocurve.domain();
                const auto at = [](const NurbsCurve& c, const Interval& d, double f) { return c.point(d.min + f * d.width()); };
                const double with = distance(at(edge->curve, a, 0.25), at(isocurve, b, 0.25)) +
                                    distance(at(edge->curve, a, 0.75), at(isocurve, b, 0.75));
                const double against = distance(at(edge->curve, a, 0.25), at(isocurve, b, 0.75)) +
                                       distance(at(edge->curve, a, 0.75), at(isocurve, b, 0.25));
                with_parameter = with <= against;
            } else {
                edge = edge_from_isocurve(e, std::move(isocurve)).edge;
            }
            sides[static_cast<std::size_t>(s)] = Coedge{edge, traversal_increasing(s) != with_parameter};
        }
        return Face::from_surface(std::move(nurbs), sides);
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
        return Face::planar(plane, std::move(loops));
    }

    TopoDS_Shape solid_;
    TopTools_IndexedMapOfShape vertex_index_, edge_index_;
    std::vector<VertexPtr> vertices_;
    std::vector<SharedEdge> edges_;
};

}  // namespace

Solid from_occt(const TopoDS_Shape& shape, const Progress& progress) {
    require(!shape.IsNull(), "shape", "is empty");
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) solids.push_back(it.Current());
    require(solids.size() == 1, "shape",
            "holds " + std::to_string(solids.size()) + " solids; a ratbez Solid is made from exactly one");
    return Importer(solids.front()).run(progress);
}

}  // namespace ratbez::occt
