#pragma once
// Extrusions and revolutions of lines and circular arcs handed over as OpenCASCADE builds them
// (BRepPrimAPI_MakePrism / BRepPrimAPI_MakeRevol of the profile's face), as Part's Extrusion and Revolution of a
// sketch are: planes, cylinders, cones, spheres and tori, their edges lines and circles. Internal to kernel/occt.
//
// Why: Part's Thickness extends the faces beside the one it removes before it offsets them; a B-spline face is
// extended with a C1 joint whose offset is C0, which "Run BOP check" flags (BOPAlgo GeomAbs_C0); an analytic
// face is extended as itself. The shape is the same and exact either way (a circle is a circle).
// Which solids: those whose construction record is an extrusion or a revolution (extrude, revolve, and sweep along
// a line or an arc: sweep.hpp; kept through moves, turns and uniform scalings) and whose every profile piece is a straight segment or one circular arc (found on its control
// points as smooth_arcs.hpp finds arcs); any other piece (a B-spline, an ellipse) leaves the solid to the
// B-spline conversion, whose faces OCCT's integration reads better than its swept surfaces of such curves.

#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <optional>
#include <vector>

#include "ratbez/brep.hpp"

namespace ratbez::occt::detail {

// OCCT's solid and its faces in the order of ours (faces[i] is face i of `solid`, oriented as in the solid).
// Not yet checked to lie on ours: analytic_primitive() checks every face it hands out.
struct FacesInOrder {
    TopoDS_Solid solid;
    std::vector<TopoDS_Face> faces;
};

// The extrusion or revolution rebuilt by OCCT from our profile's edges, or nullopt (another record, a piece that
// is neither a segment nor an arc, or OCCT refused).
std::optional<FacesInOrder> swept_solid(const Solid& solid);

}  // namespace ratbez::occt::detail
