#pragma once
// Whether a construction record describes the faces it is attached to (construction.hpp). The builders
// promise it; a record that arrives from outside (a pickle, a file) is checked, since exact_volume(),
// exact_area() and the OpenCASCADE check take it at its word: a crafted pickle gave a unit cube the
// record of a sphere of radius 100 (exact_volume 4.19e6 beside volume() 1), and re-pickling kept it
// (issue 29). Every surface face is sampled on a 9 x 9 grid of its parameters and every planar face
// along its loops' edges; the samples must lie on what the record names, to 1e-9 of the solid's size
// (and the rounding of its coordinates):
//  - sphere: on the sphere; torus: on the torus (no planar faces for either);
//  - cylinder, cone: on the lateral surface between its end planes, or on a cap (a plane across the axis
//    at either end, within that end's radius);
//  - revolution: every surface face keeps its distance from the axis and its height along it along one of
//    its parameter directions (its circles about the axis); planar faces contain the axis (the caps of a
//    partial revolution);
//  - extrusion: every surface face is swept by the record's displacement along one of its parameter
//    directions; every planar face has a partner displaced by it (the caps).

#include <span>
#include <string_view>

#include "ratbez/brep.hpp"
#include "ratbez/construction.hpp"

namespace ratbez {

// Throws Error naming `argument` (with the face and the distance) when `construction` does not describe
// `faces`; a record of kind none describes anything.
void require_describes(const Construction& construction, std::span<const Face> faces, std::string_view argument);

}  // namespace ratbez
