#pragma once
// Extrusions and revolutions handed over as OpenCASCADE builds them (BRepPrimAPI_MakePrism / BRepPrimAPI_MakeRevol
// of the profile's face), as Part's Extrusion and Revolution of a sketch are: a segment or circular arc of the
// profile sweeps a plane, cylinder, cone, sphere or torus, any other piece OCCT's swept surface of its B-spline.
// Internal to kernel/occt.
//
// Why: Part's Thickness extends the faces beside the one it removes before it offsets them; a B-spline face is
// extended with a C1 joint whose offset is C0, which "Run BOP check" flags (BOPAlgo GeomAbs_C0); an analytic
// face is extended as itself. The shape is the same and exact either way (a circle is a circle).
// Which solids: those whose construction record is an extrusion or a revolution (extrude, revolve, and sweep along
// a line or an arc: sweep.hpp; kept through moves, turns and uniform scalings), and sweeps along lines and arcs as
// sweep() lays them out (a face per path piece and profile piece, then the caps: OCCT's pipe along the path of a
// profile vertex, BRepOffsetAPI_MakePipe), whose profile pieces have no C0 knot inside, and which OCCT's fixed
// integration rule (FreeCAD's Shape.Volume and Area) reads as the kernel measures them, to kGPropTolerance:
// measured on each, and chosen. It reads its analytic surfaces to rounding, but
// some swept ones far worse (an oblique extrusion of a circle: Area 2.5e-4 off; examples/vase.json's revolved
// rational cubic 1.2e-8); those go over as the B-spline conversion, refined until the rule reads it.

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

// Whether u is the parameter that turns about the axis on a face of a revolution, as revolve() lays its faces out
// (u round the axis, v along the profile); a mirror image swaps a face's parameters (solid_transform.hpp), and
// then v turns. The direction whose curve through the face's middle keeps its height along the axis and its
// distance from it better, at five points each (a face that is no revolution about the axis still gets one).
bool turns_along_u(const NurbsSurface& surface, const Vec3& axis_point, const Vec3& axis_dir);

// The extrusion, revolution or pipe rebuilt by OCCT from our profile's edges, or nullopt (another record, a piece
// with a C0 knot, a sweep OCCT's rule misreads, or OCCT refused).
std::optional<FacesInOrder> swept_solid(const Solid& solid);

}  // namespace ratbez::occt::detail
