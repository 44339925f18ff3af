#pragma once
// OpenCASCADE's own loft (BRepOffsetAPI_ThruSections) and sweep (BRepOffsetAPI_MakePipeShell) built from the
// same ratbez profiles and paths: the references that the tests and benchmarks hold ratbez's loft and sweep
// against (validity, volume, control points, time). Exposes OCCT types (see geometry.hpp): do not include it
// beside CGAL.

#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>

#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/profile.hpp"

namespace ratbez::occt {

// The profile's pieces as B-spline edges of one wire (exact conversions, geometry.hpp).
TopoDS_Wire to_occt_wire(const std::vector<NurbsCurve>& pieces);

// ThruSections through the profiles' wires as a solid (isSolid), smooth (approximated B-spline skinning)
// or ruled. Throws Error naming "profiles" when OCCT fails to build it.
TopoDS_Shape thru_sections(const std::vector<Profile>& profiles, bool ruled);

// MakePipeShell of the profile along the path (its spine wire) with the corrected Frenet trihedron (OCCT's
// rotation-minimising-like mode), made solid; `tolerance` is its 3D approximation tolerance (SetTolerance;
// OCCT's default 1e-4). Throws Error naming "path" when OCCT fails to build it.
TopoDS_Shape pipe_shell(const Profile& profile, const NurbsCurve& path, double tolerance = 1e-4);

// What the comparisons report of a shape: BRepCheck validity, volume (BRepGProp with eps 1e-9) and the
// number of control points of its B-spline faces (planes count 0).
struct ShapeFacts {
    bool valid = false;
    double volume = 0;
    long control_points = 0;
};
ShapeFacts shape_facts(const TopoDS_Shape& shape);
// The same count for our solid: rows x columns of every surface face.
long control_points(const Solid& solid);

}  // namespace ratbez::occt
