#pragma once
// How a ratbez::Solid is handed to OpenCASCADE (topology.hpp has the construction). OCCT-free header, so
// that files.hpp and check.hpp can take it beside CGAL.

namespace ratbez::occt {

// Relative accuracy per face that bezier_faces asks of OCCT's fixed Gauss rule (area, against the kernel).
inline constexpr double kGPropTolerance = 1e-9;

struct ConvertOptions {
    // false: one OCCT face per face of ours. true: one face per rational Bézier patch of every surface face,
    // refined so that OCCT's fixed Gauss rule — FreeCAD's Shape.Volume, Area, CenterOfMass — reads each
    // to kGPropTolerance, with no C0 knot left in any surface or edge curve (topology.hpp says why).
    bool bezier_faces = false;
    // true: a cylinder, cone, sphere or torus of ours (by its construction record, or a lone sphere or torus face
    // read from a file) goes over as OCCT's own primitive on its analytic surfaces, as Part's (the BOP check, its
    // booleans and Thickness treat those better: src/analytic_primitives.hpp); an extrusion or revolution (a sweep
    // along a line or arc too) as OCCT's prism or revolution of its profile, where OCCT's fixed rule reads it
    // (src/swept_solids.hpp). Not with bezier_faces.
    bool analytic_primitives = true;
};

}  // namespace ratbez::occt
