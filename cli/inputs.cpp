// Loading a command's input: a JSON spec through spec.cpp, a model file through OpenCASCADE's readers.

#include "inputs.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

#include "ratbez/occt/files.hpp"

namespace ratbez::cli {
namespace {

std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// Product names where the file gives them, else the stem, then repeats numbered: instances of one part in an
// assembly share their product's name, and the reports and module names must tell them apart.
void name_solids(std::vector<spec::ShapeSpec>& shapes, const std::string& stem) {
    std::map<std::string, int> seen;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        spec::ShapeSpec& shape = shapes[i];
        shape.named = !shape.solid.name().empty();
        std::string name = shape.named ? shape.solid.name() : stem;
        if (!shape.named && shapes.size() > 1) name.append("_").append(std::to_string(i + 1));
        if (const int count = ++seen[name]; count > 1) name.append("_").append(std::to_string(count));
        shape.name = name;
    }
}

}  // namespace

bool is_model_file(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    return extension == ".step" || extension == ".stp" || extension == ".brep";
}

Input load_input(const std::string& path, const Progress& progress) {
    if (!is_model_file(path)) return Input{{spec::load_spec(path)}, false};
    const bool brep = lowercase_extension(path) == ".brep";
    std::vector<Solid> solids = brep ? occt::read_brep_all(path, progress) : occt::read_step_all(path, progress);
    Input input{{}, true};
    input.shapes.reserve(solids.size());
    for (Solid& solid : solids) {
        input.shapes.push_back(spec::ShapeSpec{.type = brep ? "BREP solid" : "STEP solid", .solid = std::move(solid)});
    }
    name_solids(input.shapes, std::filesystem::path(path).stem().string());
    return input;
}

}  // namespace ratbez::cli
