// Extrusions and revolutions as OpenCASCADE builds them (see swept_solids.hpp).

#include "swept_solids.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeSegment.hxx>
#include <Geom_Circle.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax3.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>

#include "ratbez/construction.hpp"
#include "ratbez/occt/convert_options.hpp"
#include "ratbez/occt/geometry.hpp"
#include "ratbez/properties.hpp"
#include "exact_edges.hpp"

namespace ratbez::occt::detail {
namespace {

// The profile's edges as OCCT lines, circles and B-splines, each built once on vertices shared as ours are, so
// that OCCT's sweep history (Generated) finds the face each one sweeps.
class ProfileEdges {
public:
    // `record`: the sweep's, which its arcs' circles are set square to (below).
    ProfileEdges(double tolerance, const Construction& record)
        : tolerance_(tolerance), extrusion_(record.get<Construction::Extrusion>()), axis_(record.get<Construction::Revolution>()) {}

    // The coedge as an oriented OCCT edge, or nullopt when its edge has a C0 knot inside.
    std::optional<TopoDS_Edge> coedge(const Coedge& c) {
        const std::optional<TopoDS_Edge> e = edge(*c.edge);
        if (!e) return std::nullopt;
        return c.reversed ? TopoDS::Edge(e->Reversed()) : *e;
    }
    // The segment of the axis between two vertices of ours that lie on it (closes a profile that ends there).
    TopoDS_Edge axis_segment(const Vertex& from, const Vertex& to) {
        return BRepBuilderAPI_MakeEdge(vertex(from), vertex(to)).Edge();
    }
    // The coedge as an OCCT line or circle, or nullopt when its edge is neither (a path piece of a pipe).
    std::optional<TopoDS_Edge> line_or_arc(const Coedge& c) {
        const std::optional<TopoDS_Edge> e = coedge(c);
        if (!e) return std::nullopt;
        const GeomAbs_CurveType type = BRepAdaptor_Curve(*e).GetType();
        return type == GeomAbs_Line || type == GeomAbs_Circle ? e : std::nullopt;
    }
    // The edge built for ours, if it was.
    std::optional<TopoDS_Edge> built(const Edge& e) const {
        const auto it = edges_.find(&e);
        return it == edges_.end() ? std::nullopt : std::optional<TopoDS_Edge>(it->second);
    }

private:
    std::optional<TopoDS_Edge> edge(const Edge& e) {
        if (const auto it = edges_.find(&e); it != edges_.end()) return it->second;
        if (e.degenerate) return std::nullopt;
        std::optional<TopoDS_Edge> made = segment(e);
        if (!made) made = arc(e);
        if (!made) made = spline(e);
        if (made) edges_.emplace(&e, *made);
        return made;
    }

    TopoDS_Vertex vertex(const Vertex& v) {
        const auto it = vertices_.find(&v);
        if (it != vertices_.end()) return it->second;
        return vertices_.emplace(&v, BRepBuilderAPI_MakeVertex(to_occt_point(v.point)).Vertex()).first->second;
    }

    // A piece whose image is the segment between its ends.
    std::optional<TopoDS_Edge> segment(const Edge& e) {
        if (!is_segment(e, tolerance_)) return std::nullopt;
        BRepBuilderAPI_MakeEdge made(GC_MakeSegment(to_occt_point(e.start->point), to_occt_point(e.end->point)).Value(),
                                     vertex(*e.start), vertex(*e.end));
        return made.IsDone() ? std::optional<TopoDS_Edge>(made.Edge()) : std::nullopt;
    }

    // A piece that is one arc of a circle, turning from its start to its end counterclockwise about the normal.
    std::optional<TopoDS_Edge> arc(const Edge& e) {
        const std::optional<EdgeCircle> found = edge_circle(e, tolerance_);
        if (!found) return std::nullopt;
        // OCCT's sweeps see a cylinder, sphere or torus only when the circle stands to the sweep exactly as it should
        // (to Precision::Angular, 1e-12: BRepSweep_Translation, GeomAdaptor_SurfaceOfRevolution::GetType), which the
        // fitted normal misses far from the origin (1e4 out: 5e-10). So a normal within the fit of the extrusion's
        // direction is taken as it, one within it of square to a revolution's axis is made square to it; and about
        // an axis the circle starts (parameter 0) straight away from it, or OCCT sees no torus either.
        const Vec3 centre = found->centre;
        Vec3 normal = found->normal, x = found->x;
        const double loose = tolerance_ / found->radius;  // the fit, as an angle
        if (extrusion_ && norm(cross(normal, extrusion_->direction)) <= loose)
            normal = dot(normal, extrusion_->direction) > 0 ? extrusion_->direction : -extrusion_->direction;
        if (axis_) {
            const Vec3 square = normal - axis_->axis_dir * dot(normal, axis_->axis_dir);
            if (std::abs(dot(normal, axis_->axis_dir)) <= loose) normal = square / norm(square);
            const Vec3 foot = axis_->axis_point + axis_->axis_dir * dot(centre - axis_->axis_point, axis_->axis_dir);
            if (norm(centre - foot) > tolerance_) x = centre - foot;
        }
        const gp_Circ circle(gp_Ax2(to_occt_point(centre), to_occt_direction(normal), to_occt_direction(x)), found->radius);
        const std::optional<std::pair<double, double>> range = arc_parameters(circle, e, found->sweep);
        if (!range) return std::nullopt;
        BRepBuilderAPI_MakeEdge made(new Geom_Circle(circle), vertex(*e.start), vertex(*e.end), range->first, range->second);
        return made.IsDone() ? std::optional<TopoDS_Edge>(made.Edge()) : std::nullopt;
    }

    // Any other piece as its B-spline curve, unless a knot inside makes it C0: OCCT's sweep would keep the
    // knot in its surface, which "Run BOP check" flags (the B-spline conversion splits the face there).
    std::optional<TopoDS_Edge> spline(const Edge& e) {
        const NurbsCurve& curve = e.curve;
        const std::vector<double>& knots = curve.knots();
        const Interval domain = curve.domain();
        for (const double knot : knots)
            if (knot > domain.min && knot < domain.max && std::count(knots.begin(), knots.end(), knot) >= curve.degree())
                return std::nullopt;
        BRepBuilderAPI_MakeEdge made(to_occt(curve), vertex(*e.start), vertex(*e.end), domain.min, domain.max);
        return made.IsDone() ? std::optional<TopoDS_Edge>(made.Edge()) : std::nullopt;
    }

    double tolerance_;
    const Construction::Extrusion* extrusion_;
    const Construction::Revolution* axis_;
    std::map<const Edge*, TopoDS_Edge> edges_;
    std::map<const Vertex*, TopoDS_Vertex> vertices_;
};

// The coedges as one OCCT wire, in the order given (they chain through shared vertices).
std::optional<TopoDS_Wire> wire(ProfileEdges& edges, const std::vector<Coedge>& loop) {
    BRep_Builder builder;
    TopoDS_Wire result;
    builder.MakeWire(result);
    for (const Coedge& c : loop) {
        const std::optional<TopoDS_Edge> e = edges.coedge(c);
        if (!e) return std::nullopt;
        builder.Add(result, *e);
    }
    result.Closed(Standard_True);
    return result;
}

// A planar face of ours as an OCCT face on the same plane, its loops as wires.
std::optional<TopoDS_Face> planar_face(ProfileEdges& edges, const Face& face) {
    const Plane& plane = face.plane();
    const gp_Pln occt_plane(gp_Ax3(to_occt_point(plane.origin), to_occt_direction(plane.normal), to_occt_direction(plane.x_axis)));
    const std::optional<TopoDS_Wire> outer = wire(edges, face.loops().front());
    if (!outer) return std::nullopt;
    BRepBuilderAPI_MakeFace made(occt_plane, *outer, Standard_True);
    for (std::size_t k = 1; k < face.loops().size() && made.IsDone(); ++k) {
        const std::optional<TopoDS_Wire> hole = wire(edges, face.loops()[k]);
        if (!hole) return std::nullopt;
        made.Add(*hole);
    }
    return made.IsDone() ? std::optional<TopoDS_Face>(made.Face()) : std::nullopt;
}

// The face of `solid` that is (IsSame) `face`, oriented as in the solid.
std::optional<TopoDS_Face> in_solid(const TopoDS_Solid& solid, const TopoDS_Shape& face) {
    for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next())
        if (it.Current().IsSame(face)) return TopoDS::Face(it.Current());
    return std::nullopt;
}

// The swept face of OCCT's solid that an edge of ours generated: what the sweep's history says, else what the sweep
// itself made of it (a full revolution's MakeRevol lists nothing for an edge in its history).
template <class Sweep>
std::optional<TopoDS_Face> generated(Sweep& sweep, const TopoDS_Shape& swept, const TopoDS_Solid& solid, const TopoDS_Edge& edge) {
    const TopTools_ListOfShape& shapes = sweep.Generated(edge);
    const TopoDS_Shape face = shapes.Extent() == 1 ? shapes.First() : swept;
    if (face.IsNull() || face.ShapeType() != TopAbs_FACE) return std::nullopt;
    return in_solid(solid, face);
}

TopoDS_Solid oriented(const TopoDS_Shape& shape) {
    TopoDS_Solid solid;
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More() && solid.IsNull(); it.Next()) solid = TopoDS::Solid(it.Current());
    if (!solid.IsNull()) BRepLib::OrientClosedSolid(solid);
    return solid;
}

// Whether the face of ours uses the edge.
bool uses(const Face& face, const Edge& e) {
    bool found = false;
    for_each_coedge(face, [&](const Coedge& c) { found = found || c.edge.get() == &e; });
    return found;
}

// OCCT's faces in the order of ours: surface face i is what the sweep generated from our edge swept_from[i], the
// planar face `start` is the sweep's first shape (the profile's face) and any other planar face its last.
template <class Sweep>
std::optional<FacesInOrder> in_order(const Solid& solid, Sweep& sweep, auto&& sweep_of, const ProfileEdges& edges,
                                     const std::vector<const Edge*>& swept_from, std::optional<std::size_t> start) {
    if (!sweep.IsDone()) return std::nullopt;
    const TopoDS_Solid occt = oriented(sweep.Shape());
    if (occt.IsNull()) return std::nullopt;
    FacesInOrder result{occt, std::vector<TopoDS_Face>(solid.faces().size())};
    TopTools_MapOfShape used;
    for (std::size_t i = 0; i < solid.faces().size(); ++i) {
        const Face& face = solid.faces()[i];
        std::optional<TopoDS_Face> found;
        if (face.kind() == Face::Kind::surface && swept_from[i]) {
            if (const std::optional<TopoDS_Edge> edge = edges.built(*swept_from[i]))
                found = generated(sweep, sweep_of(*edge), occt, *edge);
        } else if (face.kind() == Face::Kind::planar && start) {
            found = in_solid(occt, i == *start ? sweep.FirstShape() : sweep.LastShape());
        }
        if (!found || !used.Add(*found)) return std::nullopt;
        result.faces[i] = *found;
    }
    int faces = 0;
    for (TopExp_Explorer it(occt, TopAbs_FACE); it.More(); it.Next()) ++faces;
    if (faces != static_cast<int>(solid.faces().size())) return std::nullopt;
    return result;
}

// An extrusion: OCCT's prism of the start cap (the planar face facing against the direction).
std::optional<FacesInOrder> extrusion(const Solid& solid, const Construction::Extrusion& record, ProfileEdges& edges) {
    std::optional<std::size_t> start;
    for (std::size_t i = 0; i < solid.faces().size(); ++i) {
        const Face& face = solid.faces()[i];
        if (face.kind() != Face::Kind::planar || !(dot(face.plane().normal, record.direction) < 0)) continue;
        if (start) return std::nullopt;
        start = i;
    }
    if (!start) return std::nullopt;
    const std::optional<TopoDS_Face> base = planar_face(edges, solid.faces()[*start]);
    if (!base) return std::nullopt;
    // Each lateral face is swept from its side on the start cap: the one side whose edge the cap's face built.
    std::vector<const Edge*> swept_from(solid.faces().size(), nullptr);
    for (std::size_t i = 0; i < solid.faces().size(); ++i)
        if (solid.faces()[i].kind() == Face::Kind::surface)
            for (const Coedge& side : solid.faces()[i].sides())
                if (edges.built(*side.edge)) swept_from[i] = side.edge.get();
    BRepPrimAPI_MakePrism prism(*base, to_occt_vector(record.direction * record.distance));
    return in_order(solid, prism, [&](const TopoDS_Edge& e) {
        return const_cast<BRepSweep_Prism&>(prism.Prism()).Shape(e);  // OCCT's Shape(generator) is not const
    }, edges, swept_from, start);
}

// The coedges chained end to start (each as given), or nullopt when they do not make one path or loop.
std::optional<std::vector<Coedge>> chained(std::vector<Coedge> coedges) {
    const auto first_vertex = [](const Coedge& c) { return c.reversed ? c.edge->end : c.edge->start; };
    const auto last_vertex = [](const Coedge& c) { return c.reversed ? c.edge->start : c.edge->end; };
    // Start where no coedge ends (an open path), else anywhere (a loop).
    std::size_t head = 0;
    for (std::size_t i = 0; i < coedges.size(); ++i)
        if (std::none_of(coedges.begin(), coedges.end(), [&](const Coedge& c) { return last_vertex(c) == first_vertex(coedges[i]); }))
            head = i;
    std::vector<Coedge> path{coedges[head]};
    coedges.erase(coedges.begin() + static_cast<std::ptrdiff_t>(head));
    while (!coedges.empty()) {
        const auto next = std::find_if(coedges.begin(), coedges.end(),
                                       [&](const Coedge& c) { return first_vertex(c) == last_vertex(path.back()); });
        if (next == coedges.end()) return std::nullopt;
        path.push_back(*next);
        coedges.erase(next);
    }
    return path;
}

// A revolution: OCCT's revolution of the profile at angle 0 (the side of every face where the turn starts),
// closed along the axis when it ends there: the start end face of a partial turn, or that face built here.
std::optional<FacesInOrder> revolution(const Solid& solid, const Construction::Revolution& record, ProfileEdges& edges) {
    std::vector<Coedge> profile;
    std::vector<const Edge*> swept_from(solid.faces().size(), nullptr);
    for (std::size_t i = 0; i < solid.faces().size(); ++i) {
        if (solid.faces()[i].kind() != Face::Kind::surface) continue;
        const Face& face = solid.faces()[i];
        const Side start = turns_along_u(face.surface(), record.axis_point, record.axis_dir) ? Side::u_min : Side::v_min;
        const Coedge& side = face.sides()[static_cast<std::size_t>(start)];
        if (side.edge->degenerate || !edges.coedge(side)) return std::nullopt;
        profile.push_back(side);
        swept_from[i] = side.edge.get();
    }
    if (profile.empty()) return std::nullopt;
    std::optional<std::size_t> start;
    for (std::size_t i = 0; i < solid.faces().size(); ++i)
        if (solid.faces()[i].kind() == Face::Kind::planar && uses(solid.faces()[i], *profile.front().edge)) start = i;
    std::optional<TopoDS_Face> base;
    if (start) {
        base = planar_face(edges, solid.faces()[*start]);
    } else {
        const std::optional<std::vector<Coedge>> path = chained(profile);
        if (!path) return std::nullopt;
        std::optional<TopoDS_Wire> outline = wire(edges, *path);
        if (!outline) return std::nullopt;
        const Coedge &head = path->front(), &tail = path->back();
        const Vertex& from = *(tail.reversed ? tail.edge->start : tail.edge->end);
        const Vertex& to = *(head.reversed ? head.edge->end : head.edge->start);
        if (&from != &to) BRep_Builder().Add(*outline, edges.axis_segment(from, to));
        BRepBuilderAPI_MakeFace made(*outline, Standard_True);
        if (made.IsDone()) base = made.Face();
    }
    if (!base) return std::nullopt;
    const double angle = record.angle_deg >= 360 ? 2 * std::numbers::pi : record.angle_deg * std::numbers::pi / 180;
    BRepPrimAPI_MakeRevol revol(*base, gp_Ax1(to_occt_point(record.axis_point), to_occt_direction(record.axis_dir)), angle);
    return in_order(solid, revol, [&](const TopoDS_Edge& e) {
        return const_cast<BRepSweep_Revol&>(revol.Revol()).Shape(e);  // OCCT's Shape(generator) is not const
    }, edges, swept_from, start);
}

// The edges of `solid` at each vertex.
std::map<const Vertex*, std::vector<EdgePtr>> edges_at(const Solid& solid) {
    std::map<const Vertex*, std::vector<EdgePtr>> at;
    for (const EdgePtr& edge : solid.edges()) {
        if (edge->degenerate) continue;
        at[edge->start.get()].push_back(edge);
        if (edge->end != edge->start) at[edge->end.get()].push_back(edge);
    }
    return at;
}

// The unit tangent of the edge leaving (or, `arriving`, reaching) the vertex it starts or ends at, along the travel.
Vec3 travel_tangent(const Edge& e, const Vertex& v, bool arriving) {
    const Interval d = e.curve.domain();
    const bool at_start = e.start.get() == &v;
    const Vec3 t = e.curve.derivative(at_start ? d.min : d.max);
    // Leaving from the start, or arriving at the end, runs with the curve.
    return (at_start != arriving ? t : -t) / norm(t);
}

// A tube swept along lines and arcs (sweep.hpp's SweepMethod::lines_and_arcs, built as tube_solid_in_bands lays it
// out: the lateral faces band by band along the path, piece by piece round the profile, then the start and the end
// cap): OCCT's pipe of the start cap along the path of one profile vertex, its edges OCCT's lines and circles, as
// Part's Sweep of a sketch's line and arc makes it (planes, cylinders, cones, tori). The vertex's path gives the same
// rigid motion as the sweep's own (constant along a line, a turn about the arc's axis), and OCCT's pipe (corrected
// Frenet frame) the same: the rotation-minimising frame of lines and arcs. On B-spline faces a Part Fillet of the
// hexagon's sweep had 54 faces and a corner blend flagged SelfIntersect; on these, Part's 50 and clean.
std::optional<FacesInOrder> pipe(const Solid& solid, ProfileEdges& edges) {
    const auto& faces = solid.faces();
    std::vector<std::size_t> planar;
    for (std::size_t i = 0; i < faces.size(); ++i)
        if (faces[i].kind() == Face::Kind::planar) planar.push_back(i);
        else if (faces[i].kind() != Face::Kind::surface) return std::nullopt;
    if (planar.size() != 2 || planar[0] != faces.size() - 2 || planar[1] != faces.size() - 1) return std::nullopt;
    const Face& start_cap = faces[planar[0]];
    const Face& end_cap = faces[planar[1]];
    if (start_cap.loops().size() != 1 || end_cap.loops().size() != 1) return std::nullopt;
    const std::vector<Coedge>& profile = start_cap.loops().front();
    const std::size_t m = profile.size();
    if (m == 0 || (faces.size() - 2) % m != 0) return std::nullopt;
    const std::size_t bands = (faces.size() - 2) / m;

    // The path of the profile's first vertex: from the start cap to the end cap, each step the edge that runs on
    // tangentially (the path is G1; the ring edges between bands cross it).
    std::set<const Edge*> on_caps;
    for (const Face* cap : {&start_cap, &end_cap})
        for (const Coedge& c : cap->loops().front()) on_caps.insert(c.edge.get());
    std::set<const Vertex*> end_vertices;
    for (const Coedge& c : end_cap.loops().front()) end_vertices.insert({c.edge->start.get(), c.edge->end.get()});
    const auto at = edges_at(solid);
    const Vertex* vertex = profile.front().reversed ? profile.front().edge->end.get() : profile.front().edge->start.get();
    std::vector<Coedge> path;
    while (!end_vertices.count(vertex)) {
        if (path.size() == bands) return std::nullopt;
        EdgePtr next;
        for (const EdgePtr& e : at.at(vertex)) {
            if (on_caps.count(e.get()) || (!path.empty() && e == path.back().edge)) continue;
            if (!path.empty() && dot(travel_tangent(*e, *vertex, false), travel_tangent(*path.back().edge, *vertex, true)) < 1 - 1e-9)
                continue;
            if (next) return std::nullopt;  // two ways on
            next = e;
        }
        if (!next) return std::nullopt;
        const bool reversed = next->start.get() != vertex;
        path.push_back(Coedge{next, reversed});
        vertex = reversed ? next->start.get() : next->end.get();
    }
    if (path.size() != bands) return std::nullopt;

    BRepBuilderAPI_MakeWire spine;
    std::vector<TopoDS_Edge> spine_edges;
    for (const Coedge& c : path) {
        const std::optional<TopoDS_Edge> e = edges.line_or_arc(c);
        if (!e) return std::nullopt;
        spine.Add(*e);
        if (!spine.IsDone()) return std::nullopt;
        spine_edges.push_back(*e);
    }
    const std::optional<TopoDS_Face> base = planar_face(edges, start_cap);
    if (!base) return std::nullopt;
    BRepOffsetAPI_MakePipe made(spine.Wire(), *base);
    if (!made.IsDone()) return std::nullopt;
    const TopoDS_Solid occt = oriented(made.Shape());
    if (occt.IsNull()) return std::nullopt;

    // Face (band b, piece k) is what the pipe made of spine edge b and the profile edge piece k shares with the start
    // cap; the caps are the pipe's first and last shapes. (Checked on ours by analytic_primitive.)
    FacesInOrder result{occt, std::vector<TopoDS_Face>(faces.size())};
    for (std::size_t k = 0; k < m; ++k) {
        const Face& first = faces[k];
        const Coedge* shared = nullptr;
        for (const Coedge& c : profile)
            for (const Coedge& side : first.sides())
                if (side.edge == c.edge) shared = &c;
        if (!shared) return std::nullopt;
        const std::optional<TopoDS_Edge> profile_edge = edges.built(*shared->edge);
        if (!profile_edge) return std::nullopt;
        for (std::size_t b = 0; b < bands; ++b) {
            const TopoDS_Shape generated = made.Generated(spine_edges[b], *profile_edge);
            if (generated.IsNull() || generated.ShapeType() != TopAbs_FACE) return std::nullopt;
            const std::optional<TopoDS_Face> face = in_solid(occt, generated);
            if (!face) return std::nullopt;
            result.faces[b * m + k] = *face;
        }
    }
    const std::optional<TopoDS_Face> first = in_solid(occt, made.FirstShape()), last = in_solid(occt, made.LastShape());
    if (!first || !last) return std::nullopt;
    result.faces[planar[0]] = *first;
    result.faces[planar[1]] = *last;
    int count = 0;
    for (TopExp_Explorer it(occt, TopAbs_FACE); it.More(); it.Next()) ++count;
    if (count != static_cast<int>(faces.size())) return std::nullopt;
    return result;
}

// Whether OCCT's fixed rule (FreeCAD's Shape.Volume and Area) reads the sweep's volume and area as the kernel
// measures the solid, to kGPropTolerance. Planes, cylinders, cones, spheres and tori it reads to rounding; its swept
// surfaces (a revolved B-spline, an oblique extrusion of an arc) sometimes far worse (an oblique extrusion of a
// circle: Area 2.5e-4 off), and then the B-spline conversion, refined until the rule reads it, is handed out.
// Measured about the solid's own centre: about the origin a small solid far out loses digits to cancellation
// whatever its faces are, and that is not the rule's reading. Far out its coordinates hold fewer digits of it in the
// first place (a solid of size 1e-2 at 1e4: 1e-10 of its size), so the tolerance has a floor of 64 ulps of its
// reach relative to its size (there 1.6e-8; OCCT read the ring of swept_solids' tests to 1.04e-9).
bool reads_right(const TopoDS_Solid& occt, const Solid& solid) {
    const Box box = solid.bounding_box();
    GProp_GProps volume(to_occt_point((box.min + box.max) / 2)), area;
    BRepGProp::VolumeProperties(occt, volume);
    BRepGProp::SurfaceProperties(occt, area);
    const double v = enclosed_volume(solid), a = surface_area(solid);
    const double tolerance = std::max(kGPropTolerance, 64 * std::numeric_limits<double>::epsilon() * reach(box) / box.diagonal());
    return std::abs(volume.Mass() - v) <= tolerance * std::abs(v) && std::abs(area.Mass() - a) <= tolerance * a;
}

}  // namespace

bool turns_along_u(const NurbsSurface& surface, const Vec3& axis_point, const Vec3& axis_dir) {
    const auto meridian = [&](const Vec3& p) {  // (height along the axis, distance from it)
        const Vec3 d = p - axis_point;
        const double h = dot(d, axis_dir);
        return Vec3{h, norm(d - axis_dir * h), 0};
    };
    // How far five points of the curve through the face's middle along one direction stray in the meridian.
    const auto spread = [&](bool along_u) {
        const Interval du = surface.domain_u(), dv = surface.domain_v();
        const auto at = [&](double t) {
            return along_u ? surface.point(du.min + du.width() * t, dv.min + dv.width() / 2)
                           : surface.point(du.min + du.width() / 2, dv.min + dv.width() * t);
        };
        const Vec3 first = meridian(at(0));
        double worst = 0;
        for (int k = 1; k <= 4; ++k) worst = std::max(worst, distance(meridian(at(k / 4.0)), first));
        return worst;
    };
    return spread(true) <= spread(false);
}

std::optional<FacesInOrder> swept_solid(const Solid& solid) {
    try {
        const double tolerance = exact_fit(solid);
        std::optional<FacesInOrder> swept;
        if (const auto* e = solid.construction().get<Construction::Extrusion>()) {
            ProfileEdges edges(tolerance, solid.construction());
            swept = extrusion(solid, *e, edges);
        } else if (const auto* r = solid.construction().get<Construction::Revolution>()) {
            ProfileEdges edges(tolerance, solid.construction());
            swept = revolution(solid, *r, edges);
        } else if (solid.construction().kind() == "none") {
            ProfileEdges edges(tolerance, solid.construction());
            swept = pipe(solid, edges);
        }
        if (swept && reads_right(swept->solid, solid)) return swept;
    } catch (const Standard_Failure&) {
    }
    return std::nullopt;
}

}  // namespace ratbez::occt::detail
