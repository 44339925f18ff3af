#include "ratbez/export/export.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "ratbez/deviation.hpp"
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

// The format, with the options it needs checked before any heavy work.
Format checked_format(const std::string& path, const ExportOptions& options) {
    const Format format = format_from_path(path);
    if (format == Format::openscad) require_module_name(options.openscad.module_name);
    return format;
}


// Whether the mesh is written as binary STL (float32 coordinates): an .stl unless ASCII was asked for, and
// the STL beside a .scad that imports it.
bool writes_float32(Format format, const ExportOptions& options) {
    return (format == Format::stl && options.binary_stl) || (format == Format::openscad && options.import_stl);
}

// One writer for every format (output_file.hpp): a new temporary beside the target, renamed over it.
void write_file(const Mesh& mesh, const std::string& path, Format format, const ExportOptions& options) {
    output::write_file(path, [&](std::ostream& out) {
        switch (format) {
        case Format::openscad: write_openscad(mesh, out, options.openscad); break;
        case Format::stl:
            if (options.binary_stl)
                write_stl_binary(mesh, out);
            else
                write_stl_ascii(mesh, out, options.openscad.module_name);
            break;
        case Format::off: write_off(mesh, out); break;
        }
    });
}

// The file or files of an export: with import_stl the mesh goes to the binary STL beside the .scad first,
// then the .scad that imports it (a reader never finds the .scad without its STL).
void write_files(const Mesh& mesh, const std::string& path, Format format, const ExportOptions& options) {
    if (format != Format::openscad || !options.import_stl) return write_file(mesh, path, format, options);
    std::filesystem::path stl(path);
    stl.replace_extension(".stl");
    ExportOptions binary = options;
    binary.binary_stl = true;
    write_file(mesh, stl.string(), Format::stl, binary);
    output::write_file(path, [&](std::ostream& out) { write_openscad_import(stl.filename().string(), out, options.openscad); });
}

std::string number_text(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value + 0.0);
    return text;
}

// Shortest round trip, as the coordinates are written.
std::string point_text(const Vec3& p) {
    std::string text = "[";
    for (int i = 0; i < 3; ++i) {
        char digits[32];
        const double value = (i == 0 ? p.x : i == 1 ? p.y : p.z) + 0.0;
        text.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
        text += i < 2 ? ", " : "]";
    }
    return text;
}

// What the tessellation promised and what was measured; unset for a mesh written as it was given.
struct Measured {
    double tolerance = 0;
    double max_deviation = 0;
    double exact_volume = 0;
    std::optional<int> decimals;
    bool float32 = false;  // the mesh is in a binary STL
};

std::vector<std::string> header_lines(const Mesh& written, const std::string& source, const std::optional<Measured>& measured) {
    std::vector<std::string> lines;
    lines.push_back("ratbez " RATBEZ_VERSION ", an OpenSCAD library file");
    lines.push_back("source: " + source);
    if (measured) {
        lines.push_back("tolerance: " + number_text(measured->tolerance, 6) + "; measured maximum deviation: " +
                        number_text(measured->max_deviation, 4) + " (of the mesh as written)");
    } else {
        lines.push_back("tolerance: none given (a mesh written as it is)");
    }
    lines.push_back(std::to_string(written.triangles.size()) + " triangles, " + std::to_string(written.vertices.size()) +
                    " vertices; coordinates " +
                    (measured && measured->float32    ? std::string("float32 (binary STL)")
                     : measured && measured->decimals ? "rounded to " + std::to_string(*measured->decimals) + " decimals"
                                                      : std::string("exact (shortest round trip)")));
    Vec3 low = written.vertices.empty() ? Vec3{} : written.vertices.front(), high = low;
    for (const Vec3& p : written.vertices) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    }
    lines.push_back("bounding box: " + point_text(low) + " .. " + point_text(high));
    const std::string mesh_volume = number_text(written.volume(), 10);
    lines.push_back(measured ? "volume: exact " + number_text(measured->exact_volume, 10) + ", mesh " + mesh_volume
                             : "volume: mesh " + mesh_volume);
    return lines;
}

void refuse(const MeshReport& report) {
    std::string reason = "refusing to export an invalid mesh: ";
    for (std::size_t i = 0; i < report.problems.size(); ++i) reason += (i ? "; " : "") + report.problems[i];
    throw Error("mesh", reason);
}

double rounded(double value, int decimals) {
    char text[512];  // fixed notation of the largest double with 40 decimals fits
    const auto end = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals);
    if (end.ec != std::errc()) return value;
    double result = value;
    std::from_chars(text, end.ptr, result);
    return result + 0.0;
}

// Decimal places to try, fewest first: from one below those whose rounding (at most half a unit of the
// last place per coordinate, sqrt(3)/2 of it per vertex, and a triangle moves no more than its corners)
// provably keeps deviation + shift within tolerance, to three above it; none where the margin is gone or
// the places fall below a double's precision at the mesh's scale.
std::vector<int> decimal_candidates(const Mesh& mesh, double tolerance, double deviation) {
    const double margin = tolerance - deviation;
    double scale = 0;
    for (const Vec3& p : mesh.vertices) scale = std::max({scale, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    if (!(margin > 0) || !(scale > 0)) return {};
    const int provable = std::max(0, static_cast<int>(std::ceil(-std::log10(margin / (0.5 * std::sqrt(3.0))))));
    const int finest = 16 - static_cast<int>(std::floor(std::log10(scale)));
    std::vector<int> candidates;
    for (int d = std::max(0, provable - 1); d <= provable + 3 && d < finest; ++d) candidates.push_back(d);
    return candidates;
}

}  // namespace

Mesh tessellate_for_export(const Solid& solid, TessellationOptions options, const MeshCheckOptions& checks) {
    const TriangleLimit limit = checked_triangle_limit(checks);
    const bool checks_bind = limit.triangles < options.max_triangles;
    if (checks_bind) options.max_triangles = std::max<std::size_t>(limit.triangles, 1);
    try {
        return tessellate(solid, options);
    } catch (const TooFine& e) {
        if (!checks_bind) throw;
        throw e.reworded(limit.limit, "a tolerance of");
    }
}

Mesh rounded_mesh(const Mesh& mesh, int decimals) {
    require(decimals >= 0 && decimals <= 40, "decimals", "must be from 0 to 40");
    Mesh result = mesh;
    for (Vec3& p : result.vertices) p = {rounded(p.x, decimals), rounded(p.y, decimals), rounded(p.z, decimals)};
    return result;
}

MeshCheckOptions tessellation_checks(const Solid& solid, const Mesh& mesh, double tolerance) {
    MeshCheckOptions options;
    const double volume = solid.volume();
    options.exact_volume = volume;
    options.volume_tolerance = tolerance * std::max(solid.area(), mesh.area()) * 1.001 + 1e-12 * std::abs(volume);
    return options;
}

void export_mesh(const Mesh& given, const std::string& path, const ExportOptions& options) {
    const Format format = checked_format(path, options);
    // Checked as written: binary STL holds float32 coordinates (a copy only then).
    const std::optional<Mesh> rounded =
        writes_float32(format, options) ? std::optional<Mesh>(float32_mesh(given)) : std::nullopt;
    const Mesh& mesh = rounded ? *rounded : given;
    MeshCheckOptions checks = options.checks;
    if (options.progress) checks.progress = progress_part(options.progress, 0, 0.95);
    const MeshReport report = check_mesh(mesh, checks);
    if (!report.ok()) {
        // The mesh as given first: its own problems are its own, not float32's.
        if (rounded) {
            checks.progress = {};
            const MeshReport exact = check_mesh(given, checks);
            if (!exact.ok()) refuse(exact);
            throw Error("mesh", "binary STL stores float32 coordinates, which leave this mesh invalid (" +
                                    report.problems.front() + "): write ASCII STL, .off or .scad text");
        }
        refuse(report);
    }
    ExportOptions written = options;
    written.openscad.header = header_lines(mesh, options.source, std::nullopt);
    write_files(mesh, path, format, written);
    if (options.progress) options.progress(1.0);
}

namespace {

// The mesh of `solid` as it will be written (float32, or the fewest decimals that pass, or exact) with its
// measured deviation, checked: the work of export_tessellation before the writing. `progress` runs to 0.95.
WrittenMesh prepared_mesh(const Solid& solid, const Mesh& mesh, double tolerance, bool float32,
                          const MeshCheckOptions& base_checks, const Progress& progress) {
    require(std::isfinite(tolerance) && tolerance > 0, "tolerance", "must be a positive number");
    const bool text = !float32;
    WrittenMesh result{float32 ? float32_mesh(mesh) : mesh, 0, std::nullopt};
    bool chosen = false;
    // The work, in shares of the progress reported: the deviation of the mesh as given, then for each
    // decimal candidate (fewest first) its deviation and checks, which end at the first that passes; then the
    // checks of the mesh as given when none did, and the writing.
    constexpr double kFirstDeviation = 0.15, kCandidatesEnd = 0.9;
    const auto measured = [&](const Mesh& m, double from, double to) {
        DeviationOptions deviation;
        deviation.progress = progress_part(progress, from, to);
        return max_deviation(solid, m, deviation);
    };
    const auto checked = [&](const Mesh& m, double from, double to) {
        MeshCheckOptions checks = base_checks;
        if (progress) checks.progress = progress_part(progress, from, to);
        return check_mesh(m, checks);
    };
    if (text) {
        result.max_deviation = measured(mesh, 0, kFirstDeviation);
        const std::vector<int> candidates = decimal_candidates(mesh, tolerance, result.max_deviation);
        const double share = (kCandidatesEnd - kFirstDeviation) / static_cast<double>(std::max<std::size_t>(candidates.size(), 1));
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            const double from = kFirstDeviation + share * static_cast<double>(k);
            Mesh candidate = rounded_mesh(mesh, candidates[k]);
            const double deviation = measured(candidate, from, from + share / 3);
            const bool passed = deviation <= tolerance && checked(candidate, from + share / 3, from + share).ok();
            if (!passed) continue;
            result = WrittenMesh{std::move(candidate), deviation, candidates[k]};
            chosen = true;
            break;
        }
    }
    if (float32) {
        result.max_deviation = measured(result.mesh, 0, 0.5);
        const MeshReport report = checked(result.mesh, 0.5, 0.95);
        if (!report.ok() || !(result.max_deviation <= tolerance)) {
            // Blame the rounding only for what it did: a mesh already invalid or off the surface before it
            // is refused as such (issue 29: its problems were reported as float32's).
            const MeshReport exact = checked(mesh, 0.95, 0.95);
            if (!exact.ok()) refuse(exact);
            const double exact_deviation = measured(mesh, 0.95, 0.95);
            if (!(exact_deviation <= tolerance))
                throw Error("mesh", "refusing to export a mesh " + number_text(exact_deviation, 4) +
                                        " from the surface, beyond the tolerance " + number_text(tolerance, 4));
            throw Error("mesh", "binary STL stores float32 coordinates, which leave this mesh " +
                                    (report.ok() ? number_text(result.max_deviation, 4) + " from the surface, beyond the tolerance " +
                                                       number_text(tolerance, 4)
                                                 : "invalid (" + report.problems.front() + ")") +
                                    ": write ASCII STL, .off or .scad text, or use a coarser tolerance");
        }
    } else if (!chosen) {
        const MeshReport report = checked(mesh, text ? kCandidatesEnd : 0, 0.95);
        if (!report.ok()) refuse(report);
        if (!(result.max_deviation <= tolerance))
            throw Error("mesh", "refusing to export a mesh " + number_text(result.max_deviation, 4) +
                                    " from the surface, beyond the tolerance " + number_text(tolerance, 4));
    }
    if (progress) progress(0.95);
    return result;
}

}  // namespace

WrittenMesh export_tessellation(const Solid& solid, const Mesh& mesh, double tolerance, const std::string& path,
                                const ExportOptions& options) {
    const Format format = checked_format(path, options);
    const bool float32 = writes_float32(format, options);
    const WrittenMesh result = prepared_mesh(solid, mesh, tolerance, float32, options.checks, options.progress);
    ExportOptions written = options;
    written.openscad.header = header_lines(result.mesh, options.source,
                                           Measured{tolerance, result.max_deviation, solid.volume(), result.decimals, float32});
    write_files(result.mesh, path, format, written);
    if (options.progress) options.progress(1.0);
    return result;
}

std::vector<WrittenMesh> export_library(const std::vector<LibraryPart>& parts, const std::string& path,
                                        const ExportOptions& options) {
    const Format format = checked_format(path, options);
    require(format == Format::openscad, "path", "a library of several solids is a .scad file");
    require(!options.import_stl, "import_stl", "applies to one solid, not a library of several");
    require(!parts.empty(), "solids", "is empty");
    std::vector<WrittenMesh> written;
    std::vector<LibraryModule> modules;
    ExportOptions file = options;
    file.openscad.header = {"ratbez " RATBEZ_VERSION ", an OpenSCAD library file of " + std::to_string(parts.size()) + " solids",
                            "source: " + options.source};
    written.reserve(parts.size());  // modules point into it
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const LibraryPart& part = parts[i];
        require(part.solid != nullptr && part.mesh != nullptr, "solids", "a part has no solid or mesh");
        require_module_name(part.module_name);
        const double share = 0.95 / static_cast<double>(parts.size());
        written.push_back(prepared_mesh(*part.solid, *part.mesh, part.tolerance, false, part.checks,
                                        progress_part(options.progress, share * static_cast<double>(i),
                                                      share * static_cast<double>(i + 1))));
        const WrittenMesh& mesh = written.back();
        // The module's lines are export_tessellation's header without its first two (version, source).
        const std::vector<std::string> lines =
            header_lines(mesh.mesh, options.source,
                         Measured{part.tolerance, mesh.max_deviation, part.solid->volume(), mesh.decimals, false});
        file.openscad.header.push_back("module " + part.module_name + "():");
        for (std::size_t k = 2; k < lines.size(); ++k) file.openscad.header.push_back("  " + lines[k]);
    }
    for (std::size_t i = 0; i < parts.size(); ++i) modules.push_back({&written[i].mesh, parts[i].module_name, parts[i].color});
    output::write_file(path, [&](std::ostream& out) { write_openscad_library(modules, out, file.openscad); });
    if (options.progress) options.progress(1.0);
    return written;
}

}  // namespace ratbez::exporter
