// Loading a command's input: a JSON spec through spec.cpp, a model file through OpenCASCADE's readers.

#include "inputs.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>

#include "ratbez/error.hpp"
#include "ratbez/occt/files.hpp"

namespace ratbez::cli {
namespace {

std::string lowercase_extension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace

bool is_model_file(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    return extension == ".step" || extension == ".stp" || extension == ".brep";
}

Input load_input(const std::string& path, const Progress& progress, bool strict) {
    if (!is_model_file(path)) return Input{{spec::load_spec(path)}, false};
    const bool brep = lowercase_extension(path) == ".brep";
    std::string left_out;
    std::vector<Solid> solids = brep ? occt::read_brep_all(path, progress, &left_out) : occt::read_step_all(path, progress, &left_out);
    // Faces no solid holds bound no volume: the export goes on without them, and says so.
    if (!left_out.empty() && strict) throw Error("path", "'" + path + "': " + left_out + " (--strict: refused)");
    if (!left_out.empty()) std::cerr << "note: '" << path << "': " << left_out << '\n';
    Input input{{}, true};
    input.shapes.reserve(solids.size());
    for (Solid& solid : solids) {
        // Named by the reader: the file's names, else its stem, no two alike (files.hpp).
        std::string name = solid.name();
        input.shapes.push_back(spec::ShapeSpec{
            .name = std::move(name), .type = brep ? "BREP solid" : "STEP solid", .solid = std::move(solid), .named = true});
    }
    return input;
}

}  // namespace ratbez::cli
