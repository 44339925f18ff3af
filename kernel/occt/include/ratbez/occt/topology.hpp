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
//  - a trimmed face is its Geom_BSplineSurface bounded by one wire per loop, the outer one first; the
//    pcurves are the coedges' own p-curves (Geom2d_BSplineCurve, sharing the edge's parameter), a
//    degenerate coedge a Degenerated edge with its p-curve along the pole;
//  - coedges that run against their edge are TopAbs_REVERSED in the wire; all faces are
//    TopAbs_FORWARD, because ours are outward (S_u x S_v, and the plane normal, point out of the solid),
//    so every shell is closed and the solid has positive volume. One TopoDS_Shell per shell of the Solid
//    (Solid::shells), the outer one first; a void's faces point into the void, as OCCT wants.
// Arcs: a direction of a surface face that is an arc of a circle in the kernel's piecewise quadratic form (the
// turning direction of every revolution and primitive, a sphere's meridian), and the edges along it, go over in
// the exact one-span rational form of the same arc (src/smooth_arcs.hpp): the same points, another parameter
// along the arc (ConvertedSolid::face_parameters / edge_parameters map it back). OpenCASCADE's fixed Gauss rule
// (FreeCAD's Shape.Volume) then reads the face to ~1e-9 instead of ~1e-2, and no C0 knot is left for FreeCAD's
// BOP check to flag, with one OCCT face per face of ours. A face that is C1 at some knots of one direction only
// (a revolved rational profile, an extruded quadratic) stays one face with the edges of its sides along that
// direction cut there (a vertex at each such knot; u and v exchanged when it is u): OCCT's rule runs along each
// edge piece on its own, smooth. A surface face that still has a C0 direction which is not an arc (a crease, a
// loft through a polygon) or both directions C1 goes over one face per Bézier patch, as with bezier_faces below,
// and only that face; should OCCT refuse those patches (seen on faces read back from files) every face goes over
// whole instead.
// Straight and one-span directions are degree-elevated and knot-refined (exact) for OCCT's rule as well
// (src/gprop_faces.hpp). A flat surface face (a disc or an annulus a profile line square to the axis sweeps)
// goes over as a plane face without seam or pole, as Part's.
// Tolerance: 1e-10 of the solid's size (exact geometry), or the largest tolerance of its faces (what an
// imported model's edges carry, Face::tolerance) when that is larger.
// Errors: ratbez::Error naming "solid" when the geometry cannot be represented (degree 0 or > 25).
//
// With ConvertOptions::bezier_faces the same solid is handed over with one face per rational Bézier
// patch of every surface face (the face cut along its distinct knots, halved further where extreme
// weights need it), each patch refined in v by knot insertion (after degree elevation of a linear v), and
// every edge cut where the faces beside it are cut. All exact: the points are the kernel's to rounding.
// Why: OpenCASCADE's fixed Gauss rule — what FreeCAD's Shape.Volume, Shape.Area and CenterOfMass use —
// integrates a face with one rule over its whole parameter rectangle, which the C0/C1 joints at the knots
// of a multi-span face spoil (+0.93 % on a sphere); on a patch it converges geometrically. The patches are
// refined until OCCT's fixed rule reads each one's area to kGPropTolerance of the kernel's certified value
// (src/gprop_patches.hpp has the details). No surface or edge curve then has a C0 knot, so FreeCAD's
// "Run BOP check" no longer flags GeomAbs_C0. Costs more faces (a sphere: 8; a cylinder: 4 + 2 caps) and
// more poles; the file sizes and Part Cut times are in the README.

#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>

#include <array>
#include <functional>
#include <map>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/progress.hpp"
#include "ratbez/occt/convert_options.hpp"

namespace ratbez::occt {

// The OCCT solid and where each of our topological entities went.
struct ConvertedSolid {
    TopoDS_Solid solid;
    TopoDS_Shell shell;                // the outer shell
    std::vector<TopoDS_Shell> shells;  // every shell, the outer one first (Solid::shells)
    // Every OCCT face in order; solid.faces()[i] became faces[first_face[i]] .. faces[first_face[i + 1] - 1]
    // (one face each unless bezier_faces). first_face has solid.faces().size() + 1 entries.
    std::vector<TopoDS_Face> faces;
    std::vector<std::size_t> first_face;
    // face_domains[k]: the rectangle (u0, u1, v0, v1) of our parameters that faces[k] covers. A Bézier patch's
    // own parameters run over [0, 1]^2 there, affinely; otherwise OCCT's parameters are ours. Either may be moved
    // along OCCT's u on a B-spline face, so that faces beside each other do not share parameters (topology.cpp,
    // u_shift_of): OCCT's u = ours + a shift, taken off by face_parameters where it maps, else by the affine map.
    std::vector<std::array<double, 4>> face_domains;
    // face_parameters[k]: OCCT's u and v on faces[k] -> ours, where they differ by more than the affine map of
    // face_domains (an arc direction in its one-span form, src/smooth_arcs.hpp); empty where they do not.
    std::vector<std::array<std::function<double(double)>, 2>> face_parameters;
    // face_exchanged[k]: on faces[k] OCCT's v is our u and its u our v run backwards, u_occt = v0 + v1 - v (a face
    // rough in u: topology.cpp's cut_on_sides; a quarter turn of the parameters keeps the face's orientation).
    std::vector<bool> face_exchanged;
    // The pieces of each non-degenerate edge in increasing parameter (one unless bezier_faces).
    std::map<const Edge*, std::vector<TopoDS_Edge>> edges;
    // OCCT's parameter on an edge -> ours, for the edges handed over as an arc in its one-span form.
    std::map<const Edge*, std::function<double(double)>> edge_parameters;
    std::map<const Vertex*, TopoDS_Vertex> vertices;
    // The largest tolerance a vertex, edge or face may need: the base one (1e-10 of the size, at least OCCT's
    // confusion) or a read face's own (Face::tolerance); the edges and vertices of read faces carry what they
    // measure (topology.cpp, measure_read_tolerances).
    double tolerance = 0;
    bool gprop_tolerance_reached = true;              // bezier_faces: every patch met kGPropTolerance
};

// `progress` is polled before each face (the fraction of faces done) and may throw to stop the conversion.
ConvertedSolid convert(const Solid& solid, const ConvertOptions& options = {}, const Progress& progress = {});
// The solid as handed out (files, brep_string): convert's, with any face still C0 inside (a face trimmed on a
// cylinder, cone or sphere read from a file) split at those knots for OpenCASCADE's fixed Gauss rule
// (src/c0_split.hpp); convert's maps then no longer name its faces one to one.
TopoDS_Solid to_occt(const Solid& solid, const ConvertOptions& options = {});

}  // namespace ratbez::occt
