#include "ratbez/export/export.hpp"

#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>

#include "ratbez/error.hpp"
#include "ratbez/output_file.hpp"

namespace ratbez::exporter {
namespace {

enum class Format { openscad, stl, off };

Format format_from_path(const std::string& path) {
    require(!path.empty(), "path", "is empty");
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".scad") return Format::openscad;
    if (extension == ".stl") return Format::stl;
    if (extension == ".off") return Format::off;
    throw Error("path", "unknown extension '" + extension + "' in '" + path + "' (expected .scad, .stl or .off)");
}

}  // namespace

void export_mesh(const Mesh& mesh, const std::string& path, const ExportOptions& options) {
    const Format format = format_from_path(path);

    const MeshReport report = check_mesh(mesh, options.checks);
    if (!report.ok()) {
        std::string reason = "refusing to export an invalid mesh: ";
        for (std::size_t i = 0; i < report.problems.size(); ++i)
            reason += (i ? "; " : "") + report.problems[i];
        throw Error("mesh", reason);
    }

    // One writer for every format (output_file.hpp): a new temporary beside the target, renamed over it.
    output::write_file(path, [&](std::ostream& out) {
        switch (format) {
        case Format::openscad: write_openscad(mesh, out, options.openscad); break;
        case Format::stl:
            if (options.binary_stl)
                write_stl_binary(mesh, out);
            else
                write_stl_ascii(mesh, out, options.openscad.module_name.empty() ? "ratbez" : options.openscad.module_name);
            break;
        case Format::off: write_off(mesh, out); break;
        }
    });
}

}  // namespace ratbez::exporter
