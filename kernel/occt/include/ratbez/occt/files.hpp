#pragma once
// Writing solids through OpenCASCADE. This header includes no OCCT header, so the Python module and
// the CLI can use it beside CGAL (whose headers clash with OCCT's Handle macro).

#include <string>

#include "ratbez/brep.hpp"
#include "ratbez/occt/convert_options.hpp"

namespace ratbez::occt {

// AP214 STEP file of the solid's exact B-spline B-rep; throws ratbez::Error naming "path" if unwritable.
void write_step(const Solid& solid, const std::string& path, const ConvertOptions& options = {});
// OpenCASCADE's native .brep text.
void write_brep(const Solid& solid, const std::string& path, const ConvertOptions& options = {});
// The same .brep text as a string (what FreeCAD's Part.Shape.importBrepFromString reads).
std::string brep_string(const Solid& solid, const ConvertOptions& options = {});

}  // namespace ratbez::occt
