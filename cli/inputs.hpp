#pragma once
// What a command reads (DESIGN.md, "The command line"): a JSON shape spec, which builds one solid, or a
// .step/.stp/.brep model file, every solid in it (an assembly flattened with its placements). Each solid becomes
// a ShapeSpec, so that export, check and info treat a spec's solid and a file's solids alike.

#include <string>
#include <vector>

#include "ratbez/progress.hpp"
#include "spec.hpp"

namespace ratbez::cli {

struct Input {
    std::vector<spec::ShapeSpec> shapes;  // a spec's one solid, or a model file's solids in file order
    bool model_file = false;              // reports list every solid (--json: an array, even of one)
};

// True for the extensions read as model files: .step, .stp, .brep (any case).
bool is_model_file(const std::string& path);

// Loads the spec or model file. A model file's solids are named after their STEP products, else after the
// file's stem ("part", or "part_1", "part_2", ... for several); repeated names are numbered ("Screw",
// "Screw_2"), so that every name is unique. Errors: spec::SpecError for a spec, ratbez::Error naming "path" for
// a model file (a face that does not convert is named in it). What a model file holds that bounds no volume, or
// a solid of several that does not read, is left out with a note on stderr; `strict` (--strict) refuses the file
// instead, the note its reason, for scripts that must not go on with part of a model.
Input load_input(const std::string& path, const Progress& progress = {}, bool strict = false);

}  // namespace ratbez::cli
