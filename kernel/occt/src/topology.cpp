// ratbez::Solid -> TopoDS_Solid (see topology.hpp for the construction and its conventions).

#include "ratbez/occt/topology.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <GeomAPI.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <gp.hxx>
#include <gp_Pln.hxx>
#include <gp_Vec.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapIteratorOfDataMapOfShapeShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax3.hxx>
#include <gp_Dir.hxx>
#include <gp_Trsf2d.hxx>
#include <gp_Vec2d.hxx>
#include <gp_Dir2d.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "analytic_primitives.hpp"
#include "c0_split.hpp"
#include "circle_edges.hpp"
#include "exact_edges.hpp"
#include "handout.hpp"
#include "elementary_faces.hpp"
#include "face_sides.hpp"
#include "gprop_faces.hpp"
#include "gprop_patches.hpp"
#include "smooth_arcs.hpp"
#include "ratbez/error.hpp"
#include "ratbez/occt/geometry.hpp"

namespace ratbez::occt {
namespace {

// One use of an edge by the face being built: the oriented edge for the wire and its pcurve.
struct Use {
    TopoDS_Edge edge;
    TopAbs_Orientation orientation;
    Handle(Geom2d_Curve) pcurve;
};

// The pcurve of side s of a surface face as a function of the edge's parameter t: the line
// (t, fixed) / (fixed, t), or, when the edge runs against the surface's parameter, the same line run
// backwards so that it still reaches the surface point of the edge's parameter t (edge domain [a, b]
// equals the surface side's domain, validated by Face::from_surface).
Handle(Geom2d_Curve) side_pcurve(int side, double fixed, double a, double b, bool edge_with_parameter) {
    const bool along_u = side == static_cast<int>(Side::v_min) || side == static_cast<int>(Side::v_max);
    // Geom2d_Line's parameter is arc length along a unit direction: origin + t * direction.
    const double start = edge_with_parameter ? 0.0 : a + b;
    const double sign = edge_with_parameter ? 1.0 : -1.0;
    if (along_u) return new Geom2d_Line(gp_Pnt2d(start, fixed), gp_Dir2d(sign, 0));
    return new Geom2d_Line(gp_Pnt2d(fixed, start), gp_Dir2d(0, sign));
}

using detail::along_u;
using detail::cut_on_sides;
using detail::refined_for_gauss;
using detail::rough_knots;
using detail::traversal_increasing;
using detail::with_v_rule_as_u;

// The distinct knots of a curve strictly inside its domain.
std::vector<double> interior_knots(const NurbsCurve& curve) {
    // Strictly inside the domain: an unclamped knot vector (as OpenCASCADE reads a full circle back:
    // -0.25, 0, 0, ..., 1, 1.25) has knots at and beyond its domain's ends, where no piece may be cut.
    const Interval domain = curve.domain();
    std::vector<double> values;
    for (double k : curve.knots())
        if (k > domain.min && k < domain.max && (values.empty() || values.back() != k)) values.push_back(k);
    return values;
}

// The straight pcurve from a (at t0) to b (at t1), parameterised by t: a degree 1 B-spline.
Handle(Geom2d_Curve) linear_pcurve(const gp_Pnt2d& a, const gp_Pnt2d& b, double t0, double t1) {
    TColgp_Array1OfPnt2d poles(1, 2);
    poles.SetValue(1, a);
    poles.SetValue(2, b);
    TColStd_Array1OfReal knots(1, 2);
    knots.SetValue(1, t0);
    knots.SetValue(2, t1);
    TColStd_Array1OfInteger multiplicities(1, 2);
    multiplicities.Init(2);
    return new Geom2d_BSplineCurve(poles, knots, multiplicities, 1);
}

class Converter {
public:
    // patch_rough: natural conversion hands rough faces over as Bézier patches (plan_arcs).
    Converter(const Solid& solid, const ConvertOptions& options, bool patch_rough, const Progress& progress)
        : solid_(solid), options_(options), patch_rough_(patch_rough), progress_(progress) {
        const Box box = solid.bounding_box();
        // Our geometry is exact to rounding, but OCCT evaluates an edge's 3D curve and the face
        // surface through its pcurve by different routes, and with rational weights 10^+-3 these
        // differ by several 1e-12 of the size (seed 20261992 of the round trip test: 3e-12, which a
        // tolerance of 1e-12 of the size flagged as BRepCheck_InvalidCurveOnSurface). 1e-10 leaves a
        // margin and is still far below OCCT's default confusion tolerance unless the solid is huge.
        base_tolerance_ = std::max(Precision::Confusion(), 1e-10 * box.diagonal());
        out_.tolerance = base_tolerance_;
        for (const Face& face : solid.faces()) out_.tolerance = std::max(out_.tolerance, face.tolerance());
    }

    ConvertedSolid run() {
        const auto& faces = solid_.faces();
        shell_of_face_.assign(faces.size(), 0);
        out_.shells.resize(solid_.shells().size());
        for (std::size_t k = 0; k < solid_.shells().size(); ++k) {
            builder_.MakeShell(out_.shells[k]);
            for (std::size_t f : solid_.shells()[k]) shell_of_face_[f] = k;
        }
        if (options_.bezier_faces) {
            plan_patches([](std::size_t) { return true; });
        } else {
            plan_arcs();
            plan_lines();
            if (!patched_.empty()) plan_patches([this](std::size_t i) { return patched_.count(i) > 0; });
        }
        for (std::size_t i = 0; i < faces.size(); ++i) {
            // The faces are the first half of the work, the read faces' measures the second; may throw: a stop.
            if (progress_) progress_(0.5 * static_cast<double>(i) / static_cast<double>(faces.size()));
            out_.first_face.push_back(out_.faces.size());
            current_shell_ = shell_of_face_[i];
            try {
                const Interval du = faces[i].surface().domain_u(), dv = faces[i].surface().domain_v();
                if (faces[i].kind() == Face::Kind::planar) {
                    add(planar_face(faces[i]), {du.min, du.max, dv.min, dv.max});
                } else if (faces[i].kind() == Face::Kind::trimmed) {
                    add(trimmed_face(faces[i]), {du.min, du.max, dv.min, dv.max});
                } else if (grids_.count(i)) {
                    patch_faces(faces[i], grids_.at(i));
                } else {
                    add(surface_face(i), {du.min, du.max, dv.min, dv.max}, kernel_parameters(i),
                        exchanged_.count(i) > 0);
                }
            } catch (const Error& e) {
                throw Error("solid", "face " + std::to_string(i) + ": " + e.what());
            } catch (const Standard_Failure& failure) {
                // OpenCASCADE refusing a construction (a curve it cannot hold; found by fuzz_read_brep too: a FreeCAD fillet
                // read back, then bezier_faces): an Error naming the face, never an unknown exception.
                const char* message = failure.GetMessageString();
                throw Error("solid", "face " + std::to_string(i) + ": OpenCASCADE raised " + failure.DynamicType()->Name() +
                                         (message && *message ? std::string(": ") + message : std::string()));
            }
        }
        out_.first_face.push_back(out_.faces.size());
        // Pcurves were added after the 3D ranges: give every representation the edge's range again.
        for (const auto& [occt_edge, range] : ranges_) {
            builder_.Range(occt_edge, range.min, range.max);
            builder_.SameRange(occt_edge, Standard_True);
            builder_.SameParameter(occt_edge, Standard_True);
        }
        measure_read_tolerances(progress_part(progress_, 0.5, 1));
        builder_.MakeSolid(out_.solid);
        for (TopoDS_Shell& shell : out_.shells) {
            shell.Closed(Standard_True);
            builder_.Add(out_.solid, shell);
        }
        out_.shell = out_.shells.front();
        return std::move(out_);
    }

private:
    // A face read from a file keeps its boundary within its own tolerance of its surface (Face::tolerance: 1.5
    // times the largest the file gives the face, its edges and vertices). Each of its edges is given what it
    // measures, the largest distance between its 3D curve and its p-curve on the surface (BOPAlgo's measure,
    // honest_tolerance), and each vertex what covers its edges' ends there: a hotend mount whose median edge
    // OpenCASCADE reads at 1e-7 went out with every tolerance at its worst face's 5.8e-3 before, and the BOP check
    // found short edges elsewhere "TooSmallEdge" and near vertices "SelfIntersect". Faces of exact constructions
    // (tolerance 0) keep the base tolerance.
    // `progress` is polled face by face (the measures took 6 s on a large read part).
    void measure_read_tolerances(const Progress& progress) {
        for_each_read_face([&](const TopoDS_Face& face, double tolerance) {
            for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
                const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
                if (!detail::honest_tolerance(edge, face, std::numeric_limits<double>::infinity()))
                    builder_.UpdateEdge(edge, tolerance);
                cover_ends(edge, face);
            }
        }, progress);
        // Validity first: a face the measured tolerances leave invalid (BRepCheck: a wire whose p-curves cross
        // near a vertex further from it than the vertex's measured tolerance, as on a 3D printer part from the
        // public campaign) gives its edges and vertices its own tolerance, as the file did.
        for_each_read_face([&](const TopoDS_Face& face, double tolerance) {
            if (BRepCheck_Analyzer(face).IsValid()) return;
            for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next())
                builder_.UpdateEdge(TopoDS::Edge(it.Current()), tolerance);
            for (TopExp_Explorer it(face, TopAbs_VERTEX); it.More(); it.Next())
                builder_.UpdateVertex(TopoDS::Vertex(it.Current()), tolerance);
        });
    }

    // visit(OCCT face, its read face's tolerance) for every OCCT face made from a face read with more than the base
    // tolerance.
    template <class Visitor>
    // `progress` (optional) is polled before each face.
    void for_each_read_face(Visitor&& visit, const Progress& progress = {}) const {
        const auto& faces = solid_.faces();
        for (std::size_t i = 0; i < faces.size(); ++i) {
            if (progress) progress(static_cast<double>(i) / static_cast<double>(faces.size()));
            if (!(faces[i].tolerance() > base_tolerance_)) continue;
            for (std::size_t k = out_.first_face[i]; k < out_.first_face[i + 1]; ++k)
                visit(out_.faces[k], faces[i].tolerance());
        }
    }

    // Each vertex of `edge` raised to the edge's tolerance and to its distance from the ends of the edge's 3D
    // curve and of its p-curve on `face` (BRepCheck's InvalidPointOnCurve and InvalidPointOnCurveOnSurface).
    void cover_ends(const TopoDS_Edge& edge, const TopoDS_Face& face) {
        double first = 0, last = 0;
        const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, first, last);
        const Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, first, last);
        const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
        TopoDS_Vertex start, end;
        TopExp::Vertices(edge, start, end);
        for (const auto& [vertex, t] : {std::pair{start, first}, std::pair{end, last}}) {
            if (vertex.IsNull()) continue;
            const gp_Pnt point = BRep_Tool::Pnt(vertex);
            double reach = BRep_Tool::Tolerance(edge);
            if (!curve.IsNull()) reach = std::max(reach, point.Distance(curve->Value(t)));
            if (!pcurve.IsNull()) {
                const gp_Pnt2d uv = pcurve->Value(t);
                reach = std::max(reach, point.Distance(surface->Value(uv.X(), uv.Y())));
            }
            builder_.UpdateVertex(vertex, reach * (1 + 1e-9));
        }
    }

    // `domain`: our parameter rectangle the face covers (u0, u1, v0, v1).
    void add(const TopoDS_Face& face, const std::array<double, 4>& domain,
             std::array<std::function<double(double)>, 2> parameters = {}, bool exchanged = false) {
        // The map of OCCT's u (our v on an exchanged face) to ours takes the placement along u off first; without
        // a map the affine one of face_domains covers it.
        if (const double shift = std::exchange(last_u_shift_, 0.0); shift != 0)
            if (auto& to_ours = parameters[exchanged ? 1 : 0])
                to_ours = [map = std::move(to_ours), shift](double t) { return map(t - shift); };
        builder_.Add(out_.shells[current_shell_], face);
        out_.faces.push_back(face);
        out_.face_domains.push_back(domain);
        out_.face_parameters.push_back(std::move(parameters));
        out_.face_exchanged.push_back(exchanged);
    }

    // The curve an edge is handed over as: its own, or its arc in the one-span form (plan_arcs).
    const NurbsCurve& curve_of(const Edge& e) const {
        auto it = smooth_curves_.find(&e);
        return it == smooth_curves_.end() ? e.curve : it->second;
    }

    // Natural conversion: which arc directions of the surface faces, and which arc edges, go over in the
    // one-span form (smooth_arcs.hpp). A face side and its edge share their parameter (SameParameter), so a
    // direction changes only together with the edges along it, and an edge only where every face using it
    // agrees: a trimmed face's p-curves are in the edge's parameter and keep it; a planar face's p-curves are
    // made from whichever curve the edge has. Dropping one drops its partners until nothing changes.
    // A surface face that keeps a direction OCCT's fixed rule cannot read (rough_knots: a loft through a
    // square, a ruled crease) goes over one face per Bézier patch instead, as bezier_faces hands over every
    // face (gprop_patches.hpp), and its edges keep their parameter; every other face stays one face, one C1 at
    // knots of one direction only with the edges of its sides along that direction cut there (cut_on_sides).
    void plan_arcs() {
        arc_tolerance_ = 1e-11 * std::max(1.0, solid_.bounding_box().diagonal());
        const double tolerance = arc_tolerance_;
        const auto& faces = solid_.faces();
        for (std::size_t i = 0; i < faces.size(); ++i)
            if (faces[i].kind() == Face::Kind::surface) {
                const NurbsSurface& surface = faces[i].surface();
                auto& [u, v] = face_arcs_[i];
                u = detail::find_arc(surface, true, tolerance);
                v = detail::find_arc(surface, false, tolerance);
                // v is smoothed after u: it must be an arc whether u is changed or not (surface_face).
                if (u && v && !detail::find_arc(detail::smooth(surface, true, *u), false, tolerance)) v.reset();
            }
        std::map<const Edge*, detail::ArcDirection> edge_arcs;
        for (const EdgePtr& edge : solid_.edges())
            if (!edge->degenerate)
                if (auto arc = detail::find_arc(edge->curve, tolerance)) edge_arcs.emplace(edge.get(), std::move(*arc));
        for (bool changed = true; changed;) {
            changed = false;
            for (std::size_t i = 0; i < faces.size(); ++i) {
                if (faces[i].kind() == Face::Kind::trimmed) {
                    for (const auto& loop : faces[i].loops())
                        for (const Coedge& coedge : loop) changed = edge_arcs.erase(coedge.edge.get()) > 0 || changed;
                    continue;
                }
                if (faces[i].kind() != Face::Kind::surface) continue;
                auto& [arc_u, arc_v] = face_arcs_[i];
                const bool rough_u = !arc_u && !rough_knots(faces[i].surface(), true).empty();
                const bool rough_v = !arc_v && !rough_knots(faces[i].surface(), false).empty();
                if (patch_rough_ && !patched_.count(i) &&
                    ((rough_u && rough_v) || (rough_u && !cut_on_sides(faces[i], true)) ||
                     (rough_v && !cut_on_sides(faces[i], false)))) {
                    patched_.insert(i);
                    arc_u.reset();
                    arc_v.reset();
                    changed = true;
                }
                for (int s = 0; s < 4; ++s) {
                    const Coedge& coedge = faces[i].sides()[static_cast<std::size_t>(s)];
                    if (coedge.edge->degenerate) continue;
                    std::optional<detail::ArcDirection>& direction = face_arcs_[i][along_u(s) ? 0 : 1];
                    if (direction.has_value() == (edge_arcs.count(coedge.edge.get()) > 0)) continue;
                    direction.reset();
                    edge_arcs.erase(coedge.edge.get());
                    changed = true;
                }
            }
        }
        for (std::size_t i = 0; i < faces.size(); ++i)
            if (faces[i].kind() == Face::Kind::surface && !patched_.count(i))
                for (const bool along : {true, false}) {
                    if (face_arcs_[i][along ? 0 : 1]) continue;  // an arc direction is smooth in its one-span form
                    const std::vector<double> rough = rough_knots(faces[i].surface(), along);
                    if (rough.empty()) continue;
                    (along ? exchanged_ : v_sides_cut_).insert(i);
                    for (int s = 0; s < 4; ++s)
                        if (along_u(s) == along) cut_side(faces[i], s, rough);
                }
        for (const auto& entry : edge_arcs) {  // not a structured binding: clang 14 cannot capture one
            const detail::ArcDirection& arc = entry.second;
            smooth_curves_.emplace(entry.first, detail::smooth(entry.first->curve, arc));
            out_.edge_parameters.emplace(entry.first, [arc](double t) { return arc.to_kernel(t); });
        }
    }

    // Edges between planar faces only that run at constant speed along a segment (a box's edges read from a file):
    // OCCT's line, as Part's edges are (exact_edges.hpp), its parameter ours times the edge's speed
    // (edge_parameters maps it back), the planes' p-curves OCCT's 2D lines.
    void plan_lines() {
        std::map<const Edge*, bool> between_planes;
        for (const Face& face : solid_.faces())
            for_each_coedge(face, [&](const Coedge& c) {
                const auto [entry, first] = between_planes.emplace(c.edge.get(), true);
                entry->second = entry->second && face.kind() == Face::Kind::planar;
            });
        const double fit = detail::exact_fit(solid_);
        for (const auto& [edge, planes] : between_planes)
            if (planes && !edge->degenerate && detail::runs_linearly(*edge, fit)) line_edges_.insert(edge);
    }

    TopoDS_Vertex vertex(const VertexPtr& v) {
        auto it = out_.vertices.find(v.get());
        if (it != out_.vertices.end()) return it->second;
        TopoDS_Vertex made = new_vertex(v->point);
        out_.vertices.emplace(v.get(), made);
        return made;
    }

    TopoDS_Vertex new_vertex(const Vec3& point) {
        TopoDS_Vertex made;
        builder_.MakeVertex(made, to_occt_point(point), base_tolerance_);
        return made;
    }

    // A non-degenerate TopoDS_Edge on `curve` over [first, last]: start vertex FORWARD and end vertex
    // REVERSED (OCCT's convention; a closed edge has the same vertex twice).
    TopoDS_Edge new_edge(const Handle(Geom_Curve)& curve, const Interval& range, const TopoDS_Vertex& start,
                         const TopoDS_Vertex& end) {
        TopoDS_Edge made;
        builder_.MakeEdge(made, curve, base_tolerance_);
        builder_.Add(made, start.Oriented(TopAbs_FORWARD));
        builder_.Add(made, end.Oriented(TopAbs_REVERSED));
        builder_.Range(made, range.min, range.max);
        ranges_.emplace_back(made, range);
        return made;
    }

    // The shared pieces of a non-degenerate Edge, cut at cuts_[e] (none without bezier_faces): each piece
    // is the edge's curve segmented to its range, so that no edge curve keeps a C0 knot.
    const std::vector<TopoDS_Edge>& pieces(const EdgePtr& e) {
        auto it = out_.edges.find(e.get());
        if (it != out_.edges.end()) return it->second;
        const Interval domain = e->curve.domain();
        std::vector<double>& cuts = cut_parameters_[e.get()];
        // Cuts closer than 1e-9 of the edge are one cut (a knot wins, it needs no insertion): a patch grid line of a
        // read-back face lands within rounding of the edge's own knot, and OpenCASCADE refuses knots that close
        // ("Knots interval values too close", found by fuzz_read_brep on FreeCAD's cone_fillet.brep).
        // grid_vertex takes the nearest cut, so a merged line still finds its vertex.
        const double merge = 1e-9 * (domain.max - domain.min);
        const std::vector<double> knots = interior_knots(e->curve);
        const auto is_knot = [&knots](double t) { return std::binary_search(knots.begin(), knots.end(), t); };
        cuts = {domain.min};
        if (auto planned = cuts_.find(e.get()); planned != cuts_.end())
            for (double t : planned->second) {
                if (t - cuts.back() > merge)
                    cuts.push_back(t);
                else if (cuts.size() > 1 && is_knot(t))
                    cuts.back() = t;
            }
        if (cuts.size() > 1 && domain.max - cuts.back() <= merge)
            cuts.back() = domain.max;
        else
            cuts.push_back(domain.max);
        std::vector<TopoDS_Vertex>& at = cut_vertices_[e.get()];
        at.push_back(vertex(e->start));
        for (std::size_t k = 1; k + 1 < cuts.size(); ++k) at.push_back(new_vertex(e->curve.point(cuts[k])));
        at.push_back(vertex(e->end));
        std::vector<TopoDS_Edge> made;
        if (cuts.size() == 2 && line_edges_.count(e.get())) {
            // Unit speed on OCCT's line: s = speed * t, through the start at s = speed * domain.min.
            const Vec3 a = e->start->point, d = e->end->point - a;
            const double speed = norm(d) / domain.width();
            const gp_Lin line(to_occt_point(a - d * (domain.min / domain.width())), to_occt_direction(d));
            out_.edge_parameters.emplace(e.get(), [speed](double s) { return s / speed; });
            made.push_back(new_edge(new Geom_Line(line), Interval{speed * domain.min, speed * domain.max}, at[0], at[1]));
            return out_.edges.emplace(e.get(), std::move(made)).first->second;
        }
        const Handle(Geom_BSplineCurve) whole = to_occt(curve_of(*e));
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            Handle(Geom_BSplineCurve) piece = whole;
            if (cuts.size() > 2) {
                piece = Handle(Geom_BSplineCurve)::DownCast(whole->Copy());
                piece->Segment(cuts[k], cuts[k + 1]);
            }
            made.push_back(new_edge(piece, Interval{cuts[k], cuts[k + 1]}, at[k], at[k + 1]));
        }
        return out_.edges.emplace(e.get(), std::move(made)).first->second;
    }

    // A degenerate edge for one use: no 3D curve, a pcurve only, flagged Degenerated (OCCT's own spheres
    // and cones are built this way). Not shared: OCCT gives each face use its own.
    TopoDS_Edge degenerate_edge(const Edge& e) {
        TopoDS_Edge made;
        builder_.MakeEdge(made);
        const TopoDS_Vertex v = vertex(e.start);
        builder_.Add(made, v.Oriented(TopAbs_FORWARD));
        builder_.Add(made, v.Oriented(TopAbs_REVERSED));
        builder_.Degenerated(made, Standard_True);
        return made;
    }

    // The oriented uses of one loop, in order, as a closed wire.
    TopoDS_Wire wire(const std::vector<Use>& uses) {
        TopoDS_Wire w;
        builder_.MakeWire(w);
        for (const Use& use : uses) builder_.Add(w, use.edge.Oriented(use.orientation));
        w.Closed(Standard_True);
        return w;
    }

    // Pcurves of every use of the face: an edge used twice (a seam) gets both curves in one call.
    void attach_pcurves(const TopoDS_Face& face, const std::vector<Use>& uses) {
        for (std::size_t i = 0; i < uses.size(); ++i) {
            const Use& use = uses[i];
            auto twin = std::find_if(uses.begin(), uses.end(), [&](const Use& other) {
                return &other != &use && other.edge.IsSame(use.edge);
            });
            if (twin == uses.end()) {
                builder_.UpdateEdge(use.edge, use.pcurve, face, base_tolerance_);
            } else if (use.orientation == TopAbs_FORWARD) {
                require(twin->orientation == TopAbs_REVERSED, "solid",
                        "an edge is used twice by one face in the same direction");
                builder_.UpdateEdge(use.edge, use.pcurve, twin->pcurve, face, base_tolerance_);
            }
        }
    }

    // The uses along side s of a surface face between the surface parameters x0 < x1 (its whole side
    // without bezier_faces): the pieces of its edge there in the face's direction of travel, or one
    // degenerate edge. `fixed` is the other parameter of the side. With `unit_cell`, the face is a Bézier
    // patch whose own parameters run over [0, 1]^2 where ours run over the cell: x0 .. x1 along the side,
    // and `fixed` is then 0 or 1 (bounded_face moves the face along u afterwards).
    std::vector<Use> side_uses(const Coedge& coedge, int s, double fixed, double x0, double x1, bool unit_cell) {
        const bool edge_with_parameter = traversal_increasing(s) != coedge.reversed;
        const TopAbs_Orientation orientation = coedge.reversed ? TopAbs_REVERSED : TopAbs_FORWARD;
        if (coedge.edge->degenerate) {
            const Interval range = unit_cell ? Interval{0, 1} : Interval{x0, x1};
            Use use{degenerate_edge(*coedge.edge), orientation,
                    side_pcurve(s, fixed, range.min, range.max, edge_with_parameter)};
            degenerate_ranges_.emplace_back(use.edge, range);
            return {use};
        }
        const std::vector<TopoDS_Edge>& all = pieces(coedge.edge);
        const std::vector<double>& cuts = cut_parameters_.at(coedge.edge.get());
        const Interval domain = coedge.edge->curve.domain();
        // The surface parameter of the edge's parameter t (t -> a + b - t when the edge runs against it).
        const auto along = [&](double t) { return edge_with_parameter ? t : domain.min + domain.max - t; };
        // The point of the unit cell at surface parameter x along the side.
        const auto in_cell = [&](double x) {
            const double w = (x - x0) / (x1 - x0);
            return along_u(s) ? gp_Pnt2d(w, fixed) : gp_Pnt2d(fixed, w);
        };
        const Handle(Geom2d_Curve) pcurve = side_pcurve(s, fixed, domain.min, domain.max, edge_with_parameter);
        std::vector<Use> uses;
        for (std::size_t k = 0; k < all.size(); ++k) {
            const double middle = along(0.5 * (cuts[k] + cuts[k + 1]));
            if (!(middle > x0 && middle < x1)) continue;
            uses.push_back(Use{all[k], orientation,
                               unit_cell ? linear_pcurve(in_cell(along(cuts[k])), in_cell(along(cuts[k + 1])), cuts[k], cuts[k + 1])
                                         : pcurve});
        }
        if (coedge.reversed) std::reverse(uses.begin(), uses.end());
        return uses;
    }

    // A surface face bounded by the four sides of its parameter rectangle (NaturalRestriction), moved by u_shift
    // along u (u_shift_of). `degenerate_before`: how many degenerate edges existed before this face's sides were
    // made.
    TopoDS_Face bounded_face(const Handle(Geom_BSplineSurface)& surface, std::array<std::vector<Use>, 4> sides,
                             std::size_t degenerate_before, double u_shift) {
        TopoDS_Face made;
        builder_.MakeFace(made, moved_along_u(surface, sides, u_shift), base_tolerance_);
        std::vector<Use> uses;
        for (const auto& side : sides) uses.insert(uses.end(), side.begin(), side.end());
        attach_pcurves(made, uses);
        // A degenerate edge had no representation to take its range from when its pcurve was added.
        for (std::size_t k = degenerate_before; k < degenerate_ranges_.size(); ++k)
            builder_.Range(degenerate_ranges_[k].first, degenerate_ranges_[k].second.min, degenerate_ranges_[k].second.max);
        builder_.Add(made, wire(uses));
        builder_.NaturalRestriction(made, Standard_True);
        return made;
    }

    // How far to move a surface face (or a column of Bézier patches) whose u runs over [u0, u1] along u: not at all
    // when that overlaps no other face's range so far, else to one unit past the furthest of them, so that no two
    // of the solid's B-spline faces beside each other along u share parameters; add() maps them back. Why: OCCT's
    // Fillet goes wrong where the faces along an edge have the same parameter rectangle, as the Bézier patches of
    // a face did (every one on [0, 1]^2) and the kernel's faces of a loft or ruled solid do. A
    // loft through a circle, a square and a circle: Fillet of every sharp edge worked at 14 of 49 radii from 0.02
    // to 0.98 (Part's Loft: 37), at all 49 with the four side faces on [0, 1], [2, 3], [4, 5], [6, 7] (or [0,
    // 0.25], [0.25, 0.5]...: any ranges that differ); a ruled solid from a circle to a triangle: 41 (Part's 43) and
    // 45 (bench/freecad_edge_tool_sizes.py). OCCT measures and meshes in whatever parameters a face has. Only along u: the edges between patches of
    // one column keep their parameter on both, which the reader of our files asks of a face to stay untrimmed.
    double u_shift_of(double u0, double u1) {
        const bool overlaps = std::any_of(placed_u_.begin(), placed_u_.end(),
                                          [&](const Interval& placed) { return u0 <= placed.max && placed.min <= u1; });
        const double shift = overlaps ? furthest_u_ + 1 - u0 : 0;
        placed_u_.push_back(Interval{u0 + shift, u1 + shift});
        furthest_u_ = std::max(furthest_u_, u1 + shift);
        return shift;
    }

    double u_shift_of(const Handle(Geom_BSplineSurface)& surface) {
        double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
        surface->Bounds(u0, u1, v0, v1);
        return u_shift_of(u0, u1);
    }

    // The surface moved by `shift` along u, its sides' p-curves with it (exact: a translation of the parameters).
    Handle(Geom_BSplineSurface) moved_along_u(const Handle(Geom_BSplineSurface)& surface,
                                              std::array<std::vector<Use>, 4>& sides, double shift) {
        last_u_shift_ = shift;
        if (shift == 0) return surface;
        const auto moved = Handle(Geom_BSplineSurface)::DownCast(surface->Copy());  // cells make edges later
        TColStd_Array1OfReal knots = moved->UKnots();
        for (int k = knots.Lower(); k <= knots.Upper(); ++k) knots(k) += shift;
        moved->SetUKnots(knots);
        const gp_Vec2d by(shift, 0);
        for (auto& side : sides)
            for (Use& use : side) use.pcurve = Handle(Geom2d_Curve)::DownCast(use.pcurve->Translated(by));
        return moved;
    }

    // The fixed parameter of side s on the rectangle [u0, u1] x [v0, v1].
    static double fixed_of(int s, double u0, double u1, double v0, double v1) {
        return s == 0 ? v0 : s == 1 ? u1 : s == 2 ? v1 : u0;
    }

    // OCCT's (u, v) -> ours on face i (ConvertedSolid::face_parameters): the arc directions plan_arcs changed.
    std::array<std::function<double(double)>, 2> kernel_parameters(std::size_t i) const {
        std::array<std::function<double(double)>, 2> parameters;
        if (auto planned = face_arcs_.find(i); planned != face_arcs_.end())
            for (std::size_t d = 0; d < 2; ++d)
                if (const auto& arc = planned->second[d]) parameters[d] = [a = *arc](double t) { return a.to_kernel(t); };
        return parameters;
    }

    // Face i bounded by its four sides; its arc directions in the one-span form where plan_arcs chose so.
    TopoDS_Face surface_face(std::size_t i) {
        const Face& face = solid_.faces()[i];
        NurbsSurface surface = face.surface();
        if (auto planned = face_arcs_.find(i); planned != face_arcs_.end()) {
            const auto& [u, v] = planned->second;
            if (u) surface = detail::smooth(surface, true, *u);
            // The rows across v are now the smoothed u's: the same arc, found again on them (plan_arcs made sure).
            if (v) surface = detail::smooth(surface, false, *detail::find_arc(surface, false, arc_tolerance_));
        }
        const Interval du = surface.domain_u(), dv = surface.domain_v();
        std::array<std::vector<Use>, 4> sides;
        const std::size_t before = degenerate_ranges_.size();
        for (int s = 0; s < 4; ++s) {
            const Interval range = along_u(s) ? du : dv;
            sides[static_cast<std::size_t>(s)] = side_uses(face.sides()[static_cast<std::size_t>(s)], s,
                                                           fixed_of(s, du.min, du.max, dv.min, dv.max), range.min, range.max,
                                                           false);
        }
        Handle(Geom_BSplineSurface) handed = refined_for_gauss(to_occt(surface));
        // A flat face (a profile line square to a revolution's axis sweeps a disc or an annulus) is a plane face, as
        // Part's: Sketcher attaches to it, and the BOP check flags the B-spline disc of the vase example at some sizes.
        if (const Handle(Geom_Plane) plane = flat_patch_plane(handed); !plane.IsNull()) return plane_face(plane, sides);
        if (!exchanged_.count(i)) {
            // An arc u in its one-span form is smooth and read to rounding as it is (the primitives' B-spline forms),
            // unless the face's sides are cut (the turn of a revolved rational profile).
            const bool arc_u = face_arcs_.count(i) && face_arcs_.at(i)[0];
            if (!arc_u || v_sides_cut_.count(i)) with_v_rule_as_u(*handed);
            return bounded_face(handed, sides, before, u_shift_of(handed));
        }
        // Rough in u (cut_on_sides): u and v exchanged, so that OCCT's rule runs along the cut edges, and the new u
        // reversed, which keeps the surface's normal outward (exchanging alone turns it in, and OCCT's Thickness then
        // failed on a REVERSED face where Part's works): OCCT's (u, v) is our (v0 + v1 - v, u).
        handed->ExchangeUV();
        handed->UReverse();
        with_v_rule_as_u(*handed);
        gp_Trsf2d turn;  // (u, v) -> (v0 + v1 - v, u): a quarter turn, orientation kept
        turn.SetValues(0, -1, dv.min + dv.max, 1, 0, 0);
        for (auto& side : sides)
            for (Use& use : side) use.pcurve = Handle(Geom2d_Curve)::DownCast(use.pcurve->Transformed(turn));
        return bounded_face(handed, sides, before, u_shift_of(handed));
    }

    // bezier_faces: the patch grid of every surface face, and where every edge is cut: at the grid lines
    // of the faces beside it (in its own parameter) and at its own knots.
    // `patched`: which surface faces (all with bezier_faces; the rough ones otherwise, plan_arcs). An edge in
    // its one-span arc form is never cut (its knots are not the kernel's).
    void plan_patches(const std::function<bool(std::size_t)>& patched) {
        const auto& faces = solid_.faces();
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const Face& face = faces[i];
            if (face.kind() != Face::Kind::surface || !patched(i)) continue;
            detail::PatchGrid grid = detail::gprop_patch_grid(face.surface(), kGPropTolerance);
            out_.gprop_tolerance_reached = out_.gprop_tolerance_reached && grid.reached;
            for (int s = 0; s < 4; ++s) {
                const std::vector<double>& lines = along_u(s) ? grid.u : grid.v;
                cut_side(face, s, std::vector<double>(lines.begin() + 1, lines.end() - 1));
            }
            grids_.emplace(i, std::move(grid));
        }
        for (const EdgePtr& edge : solid_.edges())
            if (!edge->degenerate && !smooth_curves_.count(edge.get()))
                for (double knot : interior_knots(edge->curve)) cuts_[edge.get()].insert(knot);
    }

    // Plans cuts of side s's edge at the surface parameters `at` along it (none on a degenerate side).
    void cut_side(const Face& face, int s, const std::vector<double>& at) {
        const Coedge& coedge = face.sides()[static_cast<std::size_t>(s)];
        if (coedge.edge->degenerate) return;
        const Interval domain = coedge.edge->curve.domain();
        const bool edge_with_parameter = traversal_increasing(s) != coedge.reversed;
        for (double x : at) cuts_[coedge.edge.get()].insert(edge_with_parameter ? x : domain.min + domain.max - x);
    }

    // The vertex at grid point (i, j) of a face's patch grid: inside, a new one; on the boundary, the
    // vertex of its side's edge piece there (the face's corner vertex, or a pole).
    TopoDS_Vertex grid_vertex(const Face& face, const detail::PatchGrid& grid, std::size_t i, std::size_t j,
                              std::map<std::pair<std::size_t, std::size_t>, TopoDS_Vertex>& inner) {
        const std::size_t nu = grid.u.size() - 1, nv = grid.v.size() - 1;
        int s = -1;
        double x = 0;
        if (j == 0) s = 0, x = grid.u[i];
        else if (i == nu) s = 1, x = grid.v[j];
        else if (j == nv) s = 2, x = grid.u[i];
        else if (i == 0) s = 3, x = grid.v[j];
        if (s < 0) {
            auto it = inner.find({i, j});
            if (it == inner.end())
                it = inner.emplace(std::pair{i, j}, new_vertex(face.surface().point(grid.u[i], grid.v[j]))).first;
            return it->second;
        }
        const Coedge& coedge = face.sides()[static_cast<std::size_t>(s)];
        if (coedge.edge->degenerate) return vertex(coedge.edge->start);
        pieces(coedge.edge);
        const Interval domain = coedge.edge->curve.domain();
        const double t = traversal_increasing(s) != coedge.reversed ? x : domain.min + domain.max - x;
        const std::vector<double>& cuts = cut_parameters_.at(coedge.edge.get());
        const auto nearest = std::min_element(cuts.begin(), cuts.end(), [t](double a, double b) {
            return std::abs(a - t) < std::abs(b - t);
        });
        return cut_vertices_.at(coedge.edge.get())[static_cast<std::size_t>(nearest - cuts.begin())];
    }

    // bezier_faces: one face per cell of the face's patch grid, on the cell's unit-square patch. Cells on the
    // boundary take the pieces of the face's edges (or degenerate edges); neighbouring cells share the
    // isocurve edges between them, whose curves come from the cell patch (one knot span long in the
    // unrefined u direction; in v at most C1 knots), parameterised over [0, 1].
    void patch_faces(const Face& face, const detail::PatchGrid& grid) {
        const std::size_t nu = grid.u.size() - 1, nv = grid.v.size() - 1;
        std::map<std::pair<std::size_t, std::size_t>, TopoDS_Vertex> inner;
        std::map<std::pair<std::size_t, std::size_t>, TopoDS_Edge> along_u_edges, along_v_edges;
        // The edge along u at grid line v[j] over cell column i, and along v at u[i] over cell row j.
        const auto u_edge = [&](std::size_t j, std::size_t i) {
            auto it = along_u_edges.find({j, i});
            if (it != along_u_edges.end()) return it->second;
            const Handle(Geom_Curve) curve = j < nv ? grid.cell(i, j)->VIso(0.0) : grid.cell(i, j - 1)->VIso(1.0);
            const TopoDS_Edge made = new_edge(curve, Interval{0, 1}, grid_vertex(face, grid, i, j, inner),
                                              grid_vertex(face, grid, i + 1, j, inner));
            return along_u_edges.emplace(std::pair{j, i}, made).first->second;
        };
        const auto v_edge = [&](std::size_t i, std::size_t j) {
            auto it = along_v_edges.find({i, j});
            if (it != along_v_edges.end()) return it->second;
            const Handle(Geom_Curve) curve = i < nu ? grid.cell(i, j)->UIso(0.0) : grid.cell(i - 1, j)->UIso(1.0);
            const TopoDS_Edge made = new_edge(curve, Interval{0, 1}, grid_vertex(face, grid, i, j, inner),
                                              grid_vertex(face, grid, i, j + 1, inner));
            return along_v_edges.emplace(std::pair{i, j}, made).first->second;
        };
        for (std::size_t i = 0; i < nu; ++i) {
            const double column_shift = u_shift_of(0, 1);  // every cell of the column on [0, 1] in u
            for (std::size_t j = 0; j < nv; ++j) {
                const double u0 = grid.u[i], u1 = grid.u[i + 1], v0 = grid.v[j], v1 = grid.v[j + 1];
                const std::size_t before = degenerate_ranges_.size();
                std::array<std::vector<Use>, 4> sides;
                // An inner side: its isocurve edge, with the cell's parameter, travelled as the side goes.
                const auto inner_side = [&](int s, const TopoDS_Edge& edge) {
                    return std::vector<Use>{Use{edge, traversal_increasing(s) ? TopAbs_FORWARD : TopAbs_REVERSED,
                                                side_pcurve(s, fixed_of(s, 0, 1, 0, 1), 0, 1, true)}};
                };
                const auto outer_side = [&](int s) {
                    const double a = along_u(s) ? u0 : v0, b = along_u(s) ? u1 : v1;
                    return side_uses(face.sides()[static_cast<std::size_t>(s)], s, fixed_of(s, 0, 1, 0, 1), a, b, true);
                };
                sides[0] = j == 0 ? outer_side(0) : inner_side(0, u_edge(j, i));
                sides[1] = i + 1 == nu ? outer_side(1) : inner_side(1, v_edge(i + 1, j));
                sides[2] = j + 1 == nv ? outer_side(2) : inner_side(2, u_edge(j + 1, i));
                sides[3] = i == 0 ? outer_side(3) : inner_side(3, v_edge(i, j));
                const Handle(Geom_Plane) plane = flat_patch_plane(grid.cell(i, j));
                add(plane.IsNull() ? bounded_face(grid.cell(i, j), sides, before, column_shift) : plane_face(plane, sides),
                    {u0, u1, v0, v1});
            }
        }
    }

    // The plane of a patch whose control points all lie in one (to rounding: 1e-12 of the solid's size), with
    // the patch's orientation (normal S_u x S_v at its middle); null otherwise. Flat patches (the disc a
    // profile line square to the axis sweeps, a side of a polygon's extrusion) become plane faces: OCCT's
    // self-intersection check (FreeCAD's "Run BOP check") skips planes, and flags the B-spline disc at the
    // top of the vase example at some sizes; Sketcher attaches to plane faces.
    Handle(Geom_Plane) flat_patch_plane(const Handle(Geom_BSplineSurface)& patch) const {
        gp_Pnt middle;
        gp_Vec du, dv;
        patch->D1(0.5, 0.5, middle, du, dv);
        const gp_Vec normal = du.Crossed(dv);
        if (normal.Magnitude() <= gp::Resolution()) return {};
        const gp_Pln plane(middle, gp_Dir(normal));
        const double flatness = 1e-12 * solid_.bounding_box().diagonal();
        for (int i = 1; i <= patch->NbUPoles(); ++i)
            for (int j = 1; j <= patch->NbVPoles(); ++j)
                if (plane.Distance(patch->Pole(i, j)) > flatness) return {};
        return new Geom_Plane(plane);
    }

    // The curve in the plane's coordinates: a B-spline's poles mapped affinely (exact, the same knots and
    // weights; GeomAPI::To2d approximates by projection and throws on the one-span arcs of smooth_arcs.hpp).
    static Handle(Geom2d_Curve) in_plane(const Handle(Geom_Curve)& curve, const gp_Pln& plane) {
        Handle(Geom_BSplineCurve) spline = Handle(Geom_BSplineCurve)::DownCast(curve);
        if (spline.IsNull()) return GeomAPI::To2d(curve, plane);
        if (spline->IsPeriodic()) {  // its knots then do not count its poles: the same curve, clamped
            spline = Handle(Geom_BSplineCurve)::DownCast(spline->Copy());
            spline->SetNotPeriodic();
        }
        const gp_Ax3& frame = plane.Position();
        const gp_Pnt origin = frame.Location();
        const gp_Vec x(frame.XDirection()), y(frame.YDirection());
        TColgp_Array1OfPnt2d poles(1, spline->NbPoles());
        for (int i = 1; i <= spline->NbPoles(); ++i) {
            const gp_Vec d(origin, spline->Pole(i));
            poles.SetValue(i, gp_Pnt2d(d.Dot(x), d.Dot(y)));
        }
        TColStd_Array1OfReal knots(1, spline->NbKnots());
        TColStd_Array1OfInteger multiplicities(1, spline->NbKnots());
        spline->Knots(knots);
        spline->Multiplicities(multiplicities);
        if (!spline->IsRational()) return new Geom2d_BSplineCurve(poles, knots, multiplicities, spline->Degree());
        TColStd_Array1OfReal weights(1, spline->NbPoles());
        spline->Weights(weights);
        return new Geom2d_BSplineCurve(poles, weights, knots, multiplicities, spline->Degree());
    }

    // A plane face bounded by the uses of a flat face's or patch's sides: degenerate uses dropped (a plane has no
    // singular point), and a seam's two uses too (a disc or an annulus that a profile line square to the axis
    // sweeps closes on itself there: on a plane that is no boundary, and Part's faces have none), the rest in
    // their closed wires (an annulus has two); pcurves the edges' 3D curves in the plane's coordinates (exact:
    // GeomAPI::To2d of a B-spline in the plane maps its poles).
    TopoDS_Face plane_face(const Handle(Geom_Plane)& plane, const std::array<std::vector<Use>, 4>& sides) {
        TopoDS_Face made;
        builder_.MakeFace(made, plane, base_tolerance_);
        std::vector<Use> all, uses;
        for (const auto& side : sides) all.insert(all.end(), side.begin(), side.end());
        for (const Use& use : all) {
            const auto same = [&](const Use& other) { return other.edge.IsSame(use.edge); };
            if (BRep_Tool::Degenerated(use.edge) || std::count_if(all.begin(), all.end(), same) > 1) continue;
            double first = 0, last = 0;
            const Handle(Geom_Curve) curve = BRep_Tool::Curve(use.edge, first, last);
            uses.push_back(Use{use.edge, use.orientation, in_plane(curve, plane->Pln())});
        }
        attach_pcurves(made, uses);
        for (const std::vector<Use>& loop : closed_loops(uses)) builder_.Add(made, wire(loop));
        return made;
    }

    // Uses in order around a face, cut into the closed loops they make (each use is followed by the next that
    // starts where it ends, in the orientation the face travels it).
    static std::vector<std::vector<Use>> closed_loops(const std::vector<Use>& uses) {
        const auto travelled = [](const Use& use) { return TopoDS::Edge(use.edge.Oriented(use.orientation)); };
        const auto start = [&](const Use& use) { return TopExp::FirstVertex(travelled(use), true); };
        const auto end = [&](const Use& use) { return TopExp::LastVertex(travelled(use), true); };
        std::vector<std::vector<Use>> loops;
        std::vector<Use> left = uses;
        while (!left.empty()) {
            std::vector<Use> loop{left.front()};
            left.erase(left.begin());
            while (!end(loop.back()).IsSame(start(loop.front()))) {
                const auto next = std::find_if(left.begin(), left.end(),
                                               [&](const Use& use) { return start(use).IsSame(end(loop.back())); });
                require(next != left.end(), "solid", "a flat face's boundary does not close");
                loop.push_back(*next);
                left.erase(next);
            }
            loops.push_back(std::move(loop));
        }
        return loops;
    }

    // A trimmed face: its surface and one wire per loop, each coedge with its own p-curve (cut where the edge
    // is cut, as planar faces do), a degenerate coedge as a Degenerated edge of its own.
    TopoDS_Face trimmed_face(const Face& face) {
        TopoDS_Face made;
        builder_.MakeFace(made, to_occt(face.surface()), base_tolerance_);
        const std::size_t degenerate_before = degenerate_ranges_.size();
        std::vector<std::vector<Use>> loops;
        std::vector<Use> all;
        for (const auto& loop : face.loops()) {
            auto& uses = loops.emplace_back();
            for (const Coedge& coedge : loop) {
                const TopAbs_Orientation orientation = coedge.reversed ? TopAbs_REVERSED : TopAbs_FORWARD;
                const Handle(Geom2d_BSplineCurve) whole = to_occt_2d(*coedge.pcurve, Vec3{}, Vec3{1, 0, 0}, Vec3{0, 1, 0});
                std::vector<Use> piece_uses;
                if (coedge.edge->degenerate) {
                    piece_uses.push_back(Use{degenerate_edge(*coedge.edge), orientation, Handle(Geom2d_Curve)(whole)});
                    degenerate_ranges_.emplace_back(piece_uses.back().edge, coedge.pcurve->domain());
                } else {
                    const std::vector<TopoDS_Edge>& edge_pieces = pieces(coedge.edge);
                    const std::vector<double>& cuts = cut_parameters_.at(coedge.edge.get());
                    for (std::size_t k = 0; k < edge_pieces.size(); ++k) {
                        Handle(Geom2d_BSplineCurve) pcurve = whole;
                        if (edge_pieces.size() > 1) {
                            pcurve = Handle(Geom2d_BSplineCurve)::DownCast(whole->Copy());
                            pcurve->Segment(cuts[k], cuts[k + 1]);
                        }
                        piece_uses.push_back(Use{edge_pieces[k], orientation, pcurve});
                    }
                    if (coedge.reversed) std::reverse(piece_uses.begin(), piece_uses.end());
                }
                uses.insert(uses.end(), piece_uses.begin(), piece_uses.end());
                all.insert(all.end(), piece_uses.begin(), piece_uses.end());
            }
        }
        attach_pcurves(made, all);
        for (std::size_t k = degenerate_before; k < degenerate_ranges_.size(); ++k)
            builder_.Range(degenerate_ranges_[k].first, degenerate_ranges_[k].second.min, degenerate_ranges_[k].second.max);
        for (const auto& uses : loops) builder_.Add(made, wire(uses));
        return made;
    }

    TopoDS_Face planar_face(const Face& face) {
        const Plane& plane = face.plane();
        // gp_Ax3(P, N, Vx): main direction N, X direction Vx, Y = N ^ Vx = y_axis for our right-handed frame,
        // so the plane's (u, v) are the coordinates along x_axis and y_axis.
        const gp_Ax3 frame(to_occt_point(plane.origin), to_occt_direction(plane.normal), to_occt_direction(plane.x_axis));
        TopoDS_Face made;
        builder_.MakeFace(made, new Geom_Plane(frame), base_tolerance_);
        std::vector<std::vector<Use>> loops;
        std::vector<Use> all;
        for (const auto& loop : face.loops()) {
            auto& uses = loops.emplace_back();
            for (const Coedge& coedge : loop) {
                const std::vector<TopoDS_Edge>& edge_pieces = pieces(coedge.edge);
                const std::vector<double>& cuts = cut_parameters_.at(coedge.edge.get());
                std::vector<Use> piece_uses;
                if (line_edges_.count(coedge.edge.get())) {  // one piece on OCCT's line (plan_lines)
                    double first = 0, last = 0;
                    const Handle(Geom_Curve) line = BRep_Tool::Curve(edge_pieces.front(), first, last);
                    const Use use{edge_pieces.front(), coedge.reversed ? TopAbs_REVERSED : TopAbs_FORWARD, in_plane(line, gp_Pln(frame))};
                    uses.push_back(use);
                    all.push_back(use);
                    continue;
                }
                const Handle(Geom2d_BSplineCurve) whole = to_occt_2d(curve_of(*coedge.edge), plane.origin, plane.x_axis, plane.y_axis);
                for (std::size_t k = 0; k < edge_pieces.size(); ++k) {
                    Handle(Geom2d_BSplineCurve) pcurve = whole;
                    if (edge_pieces.size() > 1) {
                        pcurve = Handle(Geom2d_BSplineCurve)::DownCast(whole->Copy());
                        pcurve->Segment(cuts[k], cuts[k + 1]);
                    }
                    piece_uses.push_back(Use{edge_pieces[k], coedge.reversed ? TopAbs_REVERSED : TopAbs_FORWARD, pcurve});
                }
                if (coedge.reversed) std::reverse(piece_uses.begin(), piece_uses.end());
                uses.insert(uses.end(), piece_uses.begin(), piece_uses.end());
                all.insert(all.end(), piece_uses.begin(), piece_uses.end());
            }
        }
        attach_pcurves(made, all);
        for (const auto& uses : loops) builder_.Add(made, wire(uses));
        return made;
    }

    const Solid& solid_;
    const ConvertOptions& options_;
    const bool patch_rough_;
    const Progress& progress_;  // polled before each face
    BRep_Builder builder_;
    ConvertedSolid out_;
    std::vector<std::pair<TopoDS_Edge, Interval>> ranges_;             // every non-degenerate edge made
    std::vector<std::pair<TopoDS_Edge, Interval>> degenerate_ranges_;  // every degenerate edge made
    std::map<std::size_t, detail::PatchGrid> grids_;                   // bezier_faces: by face index
    std::map<const Edge*, std::set<double>> cuts_;                     // bezier_faces: interior cuts per edge
    std::map<const Edge*, std::vector<double>> cut_parameters_;        // the pieces' ends, domain ends included
    std::map<const Edge*, std::vector<TopoDS_Vertex>> cut_vertices_;   // a vertex per entry of cut_parameters_
    std::map<std::size_t, std::array<std::optional<detail::ArcDirection>, 2>> face_arcs_;  // natural: by face
    std::set<std::size_t> patched_;                                    // natural: faces handed over as patches
    std::set<std::size_t> exchanged_;                                  // natural: rough in u, with u and v exchanged
    std::set<std::size_t> v_sides_cut_;                                // natural: rough in v, its u sides cut
    double base_tolerance_ = 0;  // of every vertex, edge and face; read faces' edges and vertices measured
    double arc_tolerance_ = 0;                                         // natural: find_arc's fit tolerance
    std::vector<Interval> placed_u_;  // the u ranges of the surface faces made so far (u_shift_of)
    double furthest_u_ = 0;           // the largest end of them
    double last_u_shift_ = 0;         // how far the face being added was moved along u
    std::map<const Edge*, NurbsCurve> smooth_curves_;                  // natural: edges in the one-span form
    std::set<const Edge*> line_edges_;                                  // natural: edges on OCCT's line (plan_lines)
    std::vector<std::size_t> shell_of_face_;                           // Solid::shells, by face index
    std::size_t current_shell_ = 0;                                    // the shell the face being built goes to
};

}  // namespace

ConvertedSolid convert(const Solid& solid, const ConvertOptions& options, const Progress& progress) {
    if (options.bezier_faces) return Converter(solid, options, true, progress).run();
    // The rough faces' patches (plan_arcs) go through the Bézier-patch construction, which OpenCASCADE still
    // refuses on some faces read back from files (a patch edge with knots too close): then every face goes over
    // whole, as it did before rough faces were patched, rather than not at all.
    try {
        return Converter(solid, options, true, progress).run();
    } catch (const Error&) {
        return Converter(solid, options, false, progress).run();
    }
}

namespace detail {
namespace {

// Tolerances set to a distance just measured (SameParameter, BRepLib::UpdateTolerances, a file's gap kept) hold
// with no room, and writing the solid moves its vertices and edge ranges by their last digits (BRepTools writes
// them to 15): a read nut's vertex, 1.77e-5 off its edge's end at tolerance 1.77e-5, came back from its .brep
// InvalidPointOnCurve. Tolerances above OpenCASCADE's least get a millionth more, and at least 1e-12 of the
// coordinates (15 digits lose up to 5e-16 of them); the vertices twice that, so that they still cover their
// edges. Far below anything they measure. In place: convert's own solid, where it goes out as it is, too.
SplitSolid with_room_for_rounding(SplitSolid handed) {
    TopTools_IndexedMapOfShape edges, vertices;  // each once (an explorer meets an edge once per face using it)
    TopExp::MapShapes(handed.solid, TopAbs_EDGE, edges);
    TopExp::MapShapes(handed.solid, TopAbs_VERTEX, vertices);
    double scale = 1;  // the largest coordinate written (the vertices'; the curves' ends are at them)
    for (int v = 1; v <= vertices.Extent(); ++v) {
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(vertices(v)));
        scale = std::max({scale, std::abs(p.X()), std::abs(p.Y()), std::abs(p.Z())});
    }
    const auto room = [scale](double tolerance) { return std::max(1e-6 * tolerance, 1e-12 * scale); };
    BRep_Builder builder;
    for (int e = 1; e <= edges.Extent(); ++e) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges(e));
        if (const double tolerance = BRep_Tool::Tolerance(edge); tolerance > Precision::Confusion())
            builder.UpdateEdge(edge, tolerance + room(tolerance));
    }
    for (int v = 1; v <= vertices.Extent(); ++v) {
        const TopoDS_Vertex& vertex = TopoDS::Vertex(vertices(v));
        if (const double tolerance = BRep_Tool::Tolerance(vertex); tolerance > Precision::Confusion())
            builder.UpdateVertex(vertex, tolerance + 2 * room(tolerance));
    }
    return handed;
}

SplitSolid handed_out_as_built(const Solid& solid, const ConvertedSolid& converted, const ConvertOptions& options,
                               const Progress& progress) {
    if (options.analytic_primitives && !options.bezier_faces)
        if (const std::optional<TopoDS_Solid> primitive = analytic_primitive(solid)) {
            SplitSolid handed{*primitive, {}};
            std::size_t i = 0;
            for (TopExp_Explorer faces(*primitive, TopAbs_FACE); faces.More(); faces.Next(), ++i)
                handed.original_face.Bind(faces.Current(), converted.faces[converted.first_face[i]]);
            return handed;
        }
    // Faces on a sphere, cylinder, cone or torus first, whole (such a face trimmed and read from a file is C0 inside
    // in the NURBS Book's circle form; on OCCT's surface it need not be split; its rims on OCCT's circles), else arcs
    // on OCCT's circles;
    // then the rest split; traced through both to convert's.
    if (options.analytic_primitives && !options.bezier_faces) {
        std::optional<SplitSolid> rebuilt = with_elementary_faces(solid, converted, progress_part(progress, 0, 0.5));
        if (!rebuilt) rebuilt = with_circle_edges(solid, converted);
        if (rebuilt) {
            SplitSolid split = split_at_c0_knots(rebuilt->solid, converted.tolerance, progress_part(progress, 0.5, 1));
            for (TopTools_DataMapIteratorOfDataMapOfShapeShape it(split.original_face); it.More(); it.Next())
                split.original_face.ChangeFind(it.Key()) = rebuilt->original_face.Find(it.Value());
            return split;
        }
    }
    return split_at_c0_knots(converted.solid, converted.tolerance, progress);
}

}  // namespace

SplitSolid handed_out(const Solid& solid, const ConvertedSolid& converted, const ConvertOptions& options,
                      const Progress& progress) {
    return with_room_for_rounding(handed_out_as_built(solid, converted, options, progress));
}

}  // namespace detail

TopoDS_Solid to_occt(const Solid& solid, const ConvertOptions& options) {
    return detail::handed_out(solid, convert(solid, options), options).solid;
}

}  // namespace ratbez::occt
