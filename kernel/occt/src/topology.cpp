// ratbez::Solid -> TopoDS_Solid (see topology.hpp for the construction and its conventions).

#include "ratbez/occt/topology.hpp"

#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_Plane.hxx>
#include <Precision.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax3.hxx>
#include <gp_Dir.hxx>
#include <gp_Dir2d.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <string>
#include <utility>

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

class Converter {
public:
    explicit Converter(const Solid& solid) : solid_(solid) {
        const Box box = solid.bounding_box();
        // Our geometry is exact to rounding, but OCCT evaluates an edge's 3D curve and the face
        // surface through its pcurve by different routes, and with rational weights 10^+-3 these
        // differ by several 1e-12 of the size (seed 20261992 of the round trip test: 3e-12, which a
        // tolerance of 1e-12 of the size flagged as BRepCheck_InvalidCurveOnSurface). 1e-10 leaves a
        // margin and is still far below OCCT's default confusion tolerance unless the solid is huge.
        out_.tolerance = std::max(Precision::Confusion(), 1e-10 * box.diagonal());
    }

    ConvertedSolid run() {
        builder_.MakeShell(out_.shell);
        const auto& faces = solid_.faces();
        for (std::size_t i = 0; i < faces.size(); ++i) {
            TopoDS_Face face;
            try {
                face = faces[i].kind() == Face::Kind::surface ? surface_face(faces[i]) : planar_face(faces[i]);
            } catch (const Error& e) {
                throw Error("solid", "face " + std::to_string(i) + ": " + e.what());
            }
            builder_.Add(out_.shell, face);
            out_.faces.push_back(face);
        }
        // Pcurves were added after the 3D ranges: give every representation the edge's range again.
        for (auto& [edge, occt_edge] : out_.edges) {
            const Interval domain = edge->curve.domain();
            builder_.Range(occt_edge, domain.min, domain.max);
            builder_.SameRange(occt_edge, Standard_True);
            builder_.SameParameter(occt_edge, Standard_True);
        }
        out_.shell.Closed(Standard_True);
        builder_.MakeSolid(out_.solid);
        builder_.Add(out_.solid, out_.shell);
        return std::move(out_);
    }

private:
    TopoDS_Vertex vertex(const VertexPtr& v) {
        auto it = out_.vertices.find(v.get());
        if (it != out_.vertices.end()) return it->second;
        TopoDS_Vertex made;
        builder_.MakeVertex(made, to_occt_point(v->point), out_.tolerance);
        out_.vertices.emplace(v.get(), made);
        return made;
    }

    // The shared TopoDS_Edge of a non-degenerate Edge: 3D curve, range, start vertex FORWARD and end
    // vertex REVERSED (OCCT's convention; a closed edge has the same vertex twice).
    TopoDS_Edge edge(const EdgePtr& e) {
        auto it = out_.edges.find(e.get());
        if (it != out_.edges.end()) return it->second;
        TopoDS_Edge made;
        builder_.MakeEdge(made, to_occt(e->curve), out_.tolerance);
        builder_.Add(made, vertex(e->start).Oriented(TopAbs_FORWARD));
        builder_.Add(made, vertex(e->end).Oriented(TopAbs_REVERSED));
        const Interval domain = e->curve.domain();
        builder_.Range(made, domain.min, domain.max);
        out_.edges.emplace(e.get(), made);
        return made;
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
                builder_.UpdateEdge(use.edge, use.pcurve, face, out_.tolerance);
            } else if (use.orientation == TopAbs_FORWARD) {
                require(twin->orientation == TopAbs_REVERSED, "solid",
                        "an edge is used twice by one face in the same direction");
                builder_.UpdateEdge(use.edge, use.pcurve, twin->pcurve, face, out_.tolerance);
            }
        }
    }

    TopoDS_Face surface_face(const Face& face) {
        const NurbsSurface& surface = face.surface();
        const Interval du = surface.domain_u(), dv = surface.domain_v();
        TopoDS_Face made;
        builder_.MakeFace(made, to_occt(surface), out_.tolerance);

        std::vector<Use> uses;
        for (int s = 0; s < 4; ++s) {
            const Coedge& coedge = face.sides()[static_cast<std::size_t>(s)];
            const bool along_u = s == static_cast<int>(Side::v_min) || s == static_cast<int>(Side::v_max);
            const Interval domain = along_u ? du : dv;
            const double fixed = s == 0 ? dv.min : s == 1 ? du.max : s == 2 ? dv.max : du.min;
            // The face runs v_min and u_max with increasing parameter, v_max and u_min decreasing; the edge
            // runs with the surface's parameter exactly when both directions agree (brep.hpp).
            const bool traversal_increasing = s == 0 || s == 1;
            const bool edge_with_parameter = traversal_increasing != coedge.reversed;
            Use use;
            use.orientation = coedge.reversed ? TopAbs_REVERSED : TopAbs_FORWARD;
            if (coedge.edge->degenerate) {
                use.edge = degenerate_edge(*coedge.edge);
                use.pcurve = side_pcurve(s, fixed, domain.min, domain.max, edge_with_parameter);
            } else {
                use.edge = edge(coedge.edge);
                const Interval edge_domain = coedge.edge->curve.domain();
                use.pcurve = side_pcurve(s, fixed, edge_domain.min, edge_domain.max, edge_with_parameter);
            }
            uses.push_back(use);
        }
        attach_pcurves(made, uses);
        // A degenerate edge had no representation to take its range from when its pcurve was added.
        for (std::size_t s = 0; s < 4; ++s)
            if (face.sides()[s].edge->degenerate) {
                const Interval domain = (s % 2 == 0) ? du : dv;
                builder_.Range(uses[s].edge, domain.min, domain.max);
            }
        builder_.Add(made, wire(uses));
        builder_.NaturalRestriction(made, Standard_True);
        return made;
    }

    TopoDS_Face planar_face(const Face& face) {
        const Plane& plane = face.plane();
        // gp_Ax3(P, N, Vx): main direction N, X direction Vx, Y = N ^ Vx = y_axis for our right-handed frame,
        // so the plane's (u, v) are the coordinates along x_axis and y_axis.
        const gp_Ax3 frame(to_occt_point(plane.origin), gp_Dir(plane.normal.x, plane.normal.y, plane.normal.z),
                           gp_Dir(plane.x_axis.x, plane.x_axis.y, plane.x_axis.z));
        TopoDS_Face made;
        builder_.MakeFace(made, new Geom_Plane(frame), out_.tolerance);
        std::vector<std::vector<Use>> loops;
        std::vector<Use> all;
        for (const auto& loop : face.loops()) {
            auto& uses = loops.emplace_back();
            for (const Coedge& coedge : loop) {
                Use use;
                use.edge = edge(coedge.edge);
                use.orientation = coedge.reversed ? TopAbs_REVERSED : TopAbs_FORWARD;
                use.pcurve = to_occt_2d(coedge.edge->curve, plane.origin, plane.x_axis, plane.y_axis);
                uses.push_back(use);
                all.push_back(use);
            }
        }
        attach_pcurves(made, all);
        for (const auto& uses : loops) builder_.Add(made, wire(uses));
        return made;
    }

    const Solid& solid_;
    BRep_Builder builder_;
    ConvertedSolid out_;
};

}  // namespace

ConvertedSolid convert(const Solid& solid) { return Converter(solid).run(); }

}  // namespace ratbez::occt
