#pragma once
// Arcs of a circle handed over on OpenCASCADE's circle, as Part's edges are. Internal to kernel/occt.
//
// Why: OCCT's fillet and chamfer work along the edges beside the one they are given, and where two of the kernel's
// rational arcs meet at a vertex they lose their way. A chamfer of a ruled solid's corner ruling (a circle ruled to a
// square, the ruling from a point of the circle to a corner) left a corner face of negative area, "Bad orientation
// of sub-shape", with the rims as B-splines in any rational form, degree or knots tried, and Part's own polynomial
// approximations as well; with the rims on OCCT's circles it is valid, on the same exact side surfaces.
// The circle runs on the angle; the kernel's arc does not (its parameter is a tangent of half the angle), so an
// edge's p-curve on a B-spline face is refitted to the angle by BRepLib::SameParameter, within the edge's tolerance;
// the 3D curve and every surface stay exact, as does the kernel's own solid (its measures and meshes).
// Which edges: those the kernel holds as one arc of a circle (exact_edges.hpp) on the rim of a face that does not
// turn with them (a circle ruled to a polygon, as Part's ruled Loft has its circles; a loft through a circle, a
// square and a circle, whose Chamfer worked at 23 of 49 sizes with its rims as B-splines and at 41 so; not the
// cylinders, cones and tori of files, whose rows along the rim are all arcs: their refitted p-curves slowed OCCT's
// adaptive measures 5 times), each piece as handed over, used once by each of their faces (not a seam), none of
// which is C0 inside (handed_out splits those afterwards). The solid is used only when it is valid and every
// refitted p-curve lies within 1e-6 of the size of its edge (the edge's tolerance then covers it); otherwise the
// B-spline edges stay.
// OpenCASCADE's fixed rule (FreeCAD's Shape.Volume and Area) reads the p-curves refitted to a hundredth of the
// tolerance as it read the kernel's (examples/ruled.json to 2.4e-11: bench/freecad_part_comparison.py); measuring
// that on each solid took three quarters of the conversion's time on FreeCAD's models, and is left to the tests.

#include <optional>

#include "c0_split.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/occt/topology.hpp"

namespace ratbez::occt::detail {

// convert's solid with its arcs on OCCT's circles, every face traced to convert's; nullopt when it has no such arc or
// the result is refused.
std::optional<SplitSolid> with_circle_edges(const Solid& solid, const ConvertedSolid& converted);

}  // namespace ratbez::occt::detail
