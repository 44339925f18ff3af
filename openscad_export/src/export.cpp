#include "ratbez/export/export.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "ratbez/error.hpp"

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

    // Write beside the target and rename at the end, so a failure never leaves a truncated file that
    // looks like a result (and an existing file is replaced only by a complete one).
    const std::string temporary = path + ".ratbez-partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("path", "cannot open '" + path + "' for writing: " + std::strerror(errno));
        try {
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
            out.close();
            if (!out) throw Error("path", "writing '" + path + "' failed");
        } catch (const Error& e) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            // A write failure of the stream is a failure of the path (disk full, ...); option errors pass as they are.
            if (e.argument() == "out") throw Error("path", "writing '" + path + "' failed");
            throw;
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw Error("path", "cannot write '" + path + "': " + error.message());
    }
}

}  // namespace ratbez::exporter
