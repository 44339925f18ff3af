#pragma once
// Boundary representation: a Solid is a closed shell of Faces. Faces meet along Edges that are shared
// objects (one Edge, used by exactly two face boundaries in opposite directions), so that anything
// derived from an edge — its samples in a mesh, its TopoDS_Edge in OpenCASCADE — is computed once and
// used by both faces. That sharing is what makes meshes watertight by construction.
//
// Three kinds of face:
//  - surface: an untrimmed NURBS surface whose parameter rectangle's four sides are its boundary. A side
//    may be a degenerate edge (a pole of a sphere, the apex of a cone, a point on a revolution axis).
//  - planar: a plane patch trimmed by closed loops of edges (caps of cylinders and cones, the end
//    faces of a partial revolution, the ends of an extrusion, the flat faces of imported models).
//  - trimmed: any NURBS surface bounded by closed loops of coedges that carry p-curves, the edges in the
//    face's (u, v): what CAD models are made of (a cylinder cut by a plane, a fillet's corner, a sphere
//    with a hole). Seams (an edge used twice by one face, once at each end of a closed direction) and poles
//    (degenerate edges, with a p-curve along the collapsed side) are allowed.
// Orientation: for surface and trimmed faces S_u x S_v points out of the solid; a trimmed face's outer loop
// runs counterclockwise in (u, v), holes clockwise (so, seen from outside, counterclockwise too); for a
// planar face the outer loop runs counterclockwise seen from outside (from the tip of the outward normal),
// holes clockwise.
// A Solid may have voids: further closed shells inside the outer one, oriented like every shell so that the
// normals point out of the material (into the void).

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ratbez/box.hpp"
#include "ratbez/construction.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/vec.hpp"

namespace ratbez {

struct Vertex {
    Vec3 point;
};

struct Edge {
    NurbsCurve curve;                      // the 3D geometry; constant for a degenerate edge
    std::shared_ptr<const Vertex> start;   // shared with the neighbouring edges of a loop;
    std::shared_ptr<const Vertex> end;     // start == end for a closed edge (full circle, seam of a torus)
    bool degenerate = false;               // collapses to a point (pole, apex)
};

using EdgePtr = std::shared_ptr<const Edge>;
using VertexPtr = std::shared_ptr<const Vertex>;

// One use of an edge by a face boundary; reversed: the face runs the edge against its parameter.
// A trimmed face's coedges carry the p-curve too: the edge in the face's (u, v), a 2D NURBS curve (z = 0)
// over the edge's own parameter domain, so that surface(pcurve(t)) is edge.curve(t) to the face's
// tolerance (OpenCASCADE's SameParameter). Immutable and shared by copies of the Coedge; null elsewhere
// (a surface face's sides and a planar face's loops have their (u, v) implied).
struct Coedge {
    Coedge() = default;
    Coedge(EdgePtr edge_, bool reversed_ = false, std::shared_ptr<const NurbsCurve> pcurve_ = nullptr)
        : edge(std::move(edge_)), reversed(reversed_), pcurve(std::move(pcurve_)) {}

    EdgePtr edge;
    bool reversed = false;
    std::shared_ptr<const NurbsCurve> pcurve;
};

// A plane with an orthonormal frame; normal = cross(x_axis, y_axis).
struct Plane {
    Vec3 origin, x_axis, y_axis, normal;
};

// Index of the four sides of a surface face, counterclockwise around its parameter rectangle.
enum class Side { v_min = 0, u_max = 1, v_max = 2, u_min = 3 };

class Face {
public:
    enum class Kind { surface, planar, trimmed };

    // An untrimmed surface face. sides[Side::v_min] runs u increasing along v = v_min, sides[u_max] v increasing
    // along u = u_max, sides[v_max] u decreasing along v = v_max, sides[u_min] v decreasing along u = u_min:
    // counterclockwise in (u, v). The edge of a side is the surface's isocurve with the SAME parameter
    // (edge parameter t = the surface's u on v sides, its v on u sides), so a coedge on v_min has
    // reversed = false when the edge runs with u. Validated: each side's edge matches the surface there
    // (at 9 parameters, to 1e-9 of the surface's control-box diagonal; an edge running against the
    // surface parameter must be the isocurve reparameterised by t -> a + b - t over the same domain),
    // a side collapsed to a point carries a degenerate edge and only there, and consecutive sides meet
    // in the same Vertex object, which lies at the surface's corner.
    static Face from_surface(NurbsSurface surface, std::array<Coedge, 4> sides);
    // A surface face bounded by its own four sides, for a surface on its own (face.tessellate of a bare
    // surface): each edge is the surface's isocurve there; a side that collapses to a point gets a
    // degenerate edge, and opposite sides that coincide (a closed direction, as a full revolution's seam)
    // share one edge, so the face is closed across them. Corners that such sides join are one vertex.
    static Face from_surface(NurbsSurface surface);
    // A planar face bounded by loops (loops[0] outer, counterclockwise seen from plane.normal, which
    // points out of the solid; further loops are holes). Its surface() is the bilinear plane patch
    // spanning the loops' bounding rectangle in the plane frame, with S_u x S_v along plane.normal.
    // The patch is parameterised by the plane coordinates themselves: S(u, v) = origin + u x_axis + v y_axis,
    // its knots are {x0, x0, x1, x1} and {y0, y0, y1, y1} for the rectangle [x0, x1] x [y0, y1] that
    // contains the loops' control points (convex hull property).
    // Validated: an orthonormal right-handed plane frame; every loop closes through shared vertex
    // objects; every loop curve lies in the plane (its control points, to 1e-9 of the loops' size; with a
    // `tolerance` > 0, a file's, the curve at 8 points per knot span to that tolerance); the outer loop encloses
    // positive area seen from the normal and every hole negative area; no degenerate edges.
    static Face planar(const Plane& plane, std::vector<std::vector<Coedge>> loops, double tolerance = 0);
    // A trimmed face: `surface` bounded by loops of coedges with p-curves (loops[0] the outer loop,
    // counterclockwise in (u, v); further loops holes, clockwise). `tolerance` (finite, >= 0) is how far the
    // boundary may keep from the surface: what a file's edges carry, or a fitted p-curve's error; the floor is
    // the kernel's own 1e-9 of the surface's control-box diagonal, which exact constructions meet.
    // Validated (trimmed_face.cpp): every coedge has an edge with vertices and a p-curve that is 2D (z = 0),
    // runs over the edge's domain and stays inside the surface's domain; surface(pcurve(t)) is within the
    // tolerance of edge.curve(t) (of the vertex for a degenerate edge) at 4 parameters per knot span;
    // each loop closes through shared vertex objects and, in (u, v), every p-curve starts where the
    // previous one ends (to 1e-9 of the domain's size); the outer loop encloses positive (u, v) area, every
    // hole negative area.
    static Face trimmed(NurbsSurface surface, std::vector<std::vector<Coedge>> loops, double tolerance = 0);

    Kind kind() const { return kind_; }
    const NurbsSurface& surface() const { return surface_; }
    const std::array<Coedge, 4>& sides() const { return sides_; }           // surface faces
    const std::vector<std::vector<Coedge>>& loops() const { return loops_; } // planar and trimmed faces
    const Plane& plane() const { return plane_; }                            // planar faces
    // The distance the face's boundary may keep from its surface (plane): 0 for exact constructions, the
    // tolerance given to planar() or trimmed() otherwise.
    double tolerance() const { return tolerance_; }

    Vec3 point(double u, double v) const { return surface_.point(u, v); }
    Vec3 normal(double u, double v) const { return surface_.normal(u, v); }  // outward

private:
    Face(Kind kind, NurbsSurface surface) : kind_(kind), surface_(std::move(surface)) {}
    Kind kind_;
    NurbsSurface surface_;
    std::array<Coedge, 4> sides_{};
    std::vector<std::vector<Coedge>> loops_;
    Plane plane_{};
    double tolerance_ = 0;
};

// The largest distance between `surface` along the coedge's p-curve and its edge, at the parameters Face::trimmed
// checks (the knots of both curves and 4 points in each span between them): the least tolerance a trimmed face
// of such coedges takes.
double pcurve_gap(const NurbsSurface& surface, const Coedge& coedge);

// Every coedge of a face's boundary: the four sides of a surface face, the loops of the others.
template <class Visitor>
void for_each_coedge(const Face& face, Visitor&& visit) {
    if (face.kind() == Face::Kind::surface) {
        for (const Coedge& c : face.sides()) visit(c);
    } else {
        for (const auto& loop : face.loops())
            for (const Coedge& c : loop) visit(c);
    }
}

// Each distinct edge of the faces once, in order of first use (degenerate ones included).
std::vector<EdgePtr> distinct_edges(std::span<const Face> faces);

class Solid {
public:
    // Validates closure: every non-degenerate edge is used exactly twice, once in each direction; and
    // orientation, shell by shell (the faces connected through shared edges): one outer shell whose
    // enclosed volume (a low-order quadrature, enough for its sign) is positive, and any number of voids,
    // shells of negative enclosed volume within the outer shell's box.
    // `construction` records what the faces were built as (the builders of primitives.hpp, revolve.hpp
    // and extrude.hpp pass theirs); a Solid assembled from faces alone is of kind none.
    explicit Solid(std::vector<Face> faces, Construction construction = {});

    const std::vector<Face>& faces() const { return faces_; }
    // The indices of the faces of each shell, the outer shell first, then the voids; each in face order.
    const std::vector<std::vector<std::size_t>>& shells() const { return shells_; }
    const Construction& construction() const { return construction_; }
    // What a file calls the solid (a STEP product's name), or "": a label only, carried by copies and
    // transforms, never part of the geometry.
    const std::string& name() const { return name_; }
    void set_name(std::string name) { name_ = std::move(name); }
    std::vector<EdgePtr> edges() const;       // each distinct edge once, degenerate ones included
    std::vector<VertexPtr> vertices() const;  // each distinct vertex once
    // V - E + F - R with degenerate edges not counted (their vertex is counted) and R the hole loops of planar
    // and trimmed faces: 2 - 2 genus per shell, so 2 for a ball, 0 for a torus, -2 for a prism with two holes,
    // 4 for a box with a spherical void.
    int euler_characteristic() const;

    // Axis-aligned box of all control points: it contains the solid (convex hull property), but may be
    // larger than the solid's tight box (a sphere's control net reaches out to its circumscribed cube).
    Box bounding_box() const;

    // Measured by properties.hpp (defined there: building a Solid does not measure it).
    double area() const;    // Gauss quadrature on the exact surfaces
    double volume() const;  // divergence theorem, (1/3) of the integral of S . (S_u x S_v)

private:
    std::vector<Face> faces_;
    std::vector<std::vector<std::size_t>> shells_;
    Construction construction_;
    std::string name_;
};

}  // namespace ratbez
