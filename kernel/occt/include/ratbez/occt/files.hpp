#pragma once
// Writing and reading solids through OpenCASCADE. This header includes no OCCT header, so the Python module and
// the CLI can use it beside CGAL (whose headers clash with OCCT's Handle macro).

#include <span>
#include <string>
#include <vector>

#include "ratbez/brep.hpp"
#include "ratbez/occt/convert_options.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::occt {

// AP214 STEP file of the solid's exact B-spline B-rep, a product named after Solid::name; throws ratbez::Error
// naming "path" if unwritable.
void write_step(const Solid& solid, const std::string& path, const ConvertOptions& options = {});
// OpenCASCADE's native .brep text.
void write_brep(const Solid& solid, const std::string& path, const ConvertOptions& options = {});
// Several solids in one file, as read_step_all / read_brep_all read them back: one STEP product per solid (in
// order, named), or a .brep compound. Error "solids" when empty.
void write_step(std::span<const Solid> solids, const std::string& path, const ConvertOptions& options = {});
void write_brep(std::span<const Solid> solids, const std::string& path, const ConvertOptions& options = {});
// The same .brep text as a string (what FreeCAD's Part.Shape.importBrepFromString reads).
std::string brep_string(const Solid& solid, const ConvertOptions& options = {});

// The one solid of a STEP file or a .brep file, converted exactly (shape_import.hpp says which faces convert
// and which are refused), named as read_step_all names it (the file's name for it, else the file's stem).
// Throws ratbez::Error naming "path" for a missing or unreadable file, a file that is not STEP / .brep, a file
// with no solid or several (pointing at read_step_all), and a face that does not convert ("'a.step': face 7:
// ..."). `progress` gets the fraction done (reading the file is the first half, the faces the second) and may
// throw to cancel; OpenCASCADE's reader is stopped at its next check.
// `left_out`, if given, gets what of the file no solid holds ("left out 12 face(s) outside every solid: ...",
// from_occt), or "".
Solid read_step(const std::string& path, const Progress& progress = {}, std::string* left_out = nullptr);
Solid read_brep(const std::string& path, const Progress& progress = {}, std::string* left_out = nullptr);
// Every solid of the file, in file order: a STEP assembly is flattened with each instance's placement (the
// product structure through OpenCASCADE's XCAF reader) and each solid named after its product; a .brep file's
// solids in the order its shape holds them. Every solid has a name and no two alike (Solid::name): the file's,
// else the file's stem (stem_k among several), repeats numbered _2, _3 (instances of one part). Errors as
// above, a solid's prefixed "solid k: " (from 0, in file order). With `left_out` given, a solid OpenCASCADE finds
// invalid or that does not convert is left out when others are read, and `left_out` says so ("left out 1 of 3
// solids: solid 1 ('Idler'): face 57: ..."): one bad part does not cost an assembly's others. Without it, or
// when no solid is read, the file is refused.
std::vector<Solid> read_step_all(const std::string& path, const Progress& progress = {}, std::string* left_out = nullptr);
std::vector<Solid> read_brep_all(const std::string& path, const Progress& progress = {}, std::string* left_out = nullptr);

}  // namespace ratbez::occt
