#pragma once
// ratbez::Solid -> TopoDS_Solid: a valid, closed OpenCASCADE B-rep of the same exact geometry.
// Exposes OCCT types (see geometry.hpp): do not include it beside CGAL.
//
// The construction follows the B-rep one to one:
//  - one TopoDS_Vertex per Vertex and one TopoDS_Edge per shared Edge (both mapped by pointer), with the
//    edge's NURBS as its Geom_BSplineCurve and its parameter domain as the range;
//  - a surface face is its Geom_BSplineSurface bounded by one wire of its four sides (counterclockwise in
//    (u, v), as OCCT wants for a forward face) with NaturalRestriction set. The pcurve of a side is a
//    Geom2d_Line in (u, v) whose parameter is the edge's (brep.hpp: edge parameter t = the surface's u on v
//    sides, v on u sides; run backwards when the edge runs against the surface's parameter), so 3D curve
//    and pcurve agree exactly (SameParameter, SameRange). An edge used twice by one face (the seams of a
//    cylinder, sphere or torus) gets both pcurves through BRep_Builder::UpdateEdge(E, C1, C2, F, tol),
//    C1 for its forward use. A degenerate side (pole, apex) becomes a BRep_Builder::Degenerated edge
//    with no 3D curve, one per use;
//  - a planar face is a Geom_Plane (gp_Ax3 from the face's plane frame) bounded by one wire per loop;
//    the pcurves are the exact plane coordinates of the edges' NURBS (to_occt_2d);
//  - coedges that run against their edge are TopAbs_REVERSED in the wire; all faces are
//    TopAbs_FORWARD, because ours are outward (S_u x S_v, and the plane normal, point out of the solid),
//    so the shell is closed and the solid has positive volume.
// Errors: ratbez::Error naming "solid" when the geometry cannot be represented (degree 0 or > 25).

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>

#include <map>
#include <vector>

#include "ratbez/brep.hpp"

namespace ratbez::occt {

// The OCCT solid and where each of our topological entities went.
struct ConvertedSolid {
    TopoDS_Solid solid;
    TopoDS_Shell shell;
    std::vector<TopoDS_Face> faces;                   // faces[i] is solid.faces()[i]
    std::map<const Edge*, TopoDS_Edge> edges;         // non-degenerate edges
    std::map<const Vertex*, TopoDS_Vertex> vertices;
    double tolerance = 0;                             // the tolerance given to every vertex, edge and face
};

ConvertedSolid convert(const Solid& solid);
inline TopoDS_Solid to_occt(const Solid& solid) { return convert(solid).solid; }

}  // namespace ratbez::occt
