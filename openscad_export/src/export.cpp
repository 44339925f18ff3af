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

#include "ratbez/convex_hull.hpp"
#include "ratbez/convexity.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/export/three_mf.hpp"
#include "ratbez/output_file.hpp"

namespace ratbez::exporter {
namespace {

enum class Format { openscad, stl, off, three_mf };

Format format_from_path(const std::string& path) {
    require(!path.empty(), "path", "is empty");
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".scad") return Format::openscad;
    if (extension == ".stl") return Format::stl;
    if (extension == ".off") return Format::off;
    if (extension == ".3mf") return Format::three_mf;
    throw Error("path", "unknown extension '" + extension + "' in '" + path + "' (expected .scad, .stl, .off or .3mf)");
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

// What a format whose coordinates we cannot choose stores, for messages ("<this>, which leave this mesh ...").
std::string fixed_coordinates(Format format) {
    if (format == Format::three_mf) return "3MF, as lib3mf 1.8 writes it, stores float32 coordinates cut to 6 decimals";
    if (format == Format::openscad) return "the binary STL beside the .scad (import_stl) stores float32 coordinates";
    return "binary STL stores float32 coordinates";
}

// The header's words for such coordinates.
std::string fixed_coordinates_note(Format format) {
    return format == Format::three_mf ? "float32 cut to 6 decimals (3MF as lib3mf writes it)" : "float32 (binary STL)";
}

// The 3MF model's metadata: the version that wrote it, a title and `lines` as its description.
std::vector<std::pair<std::string, std::string>> three_mf_metadata(const std::string& title, const std::vector<std::string>& lines) {
    std::string description;
    for (const std::string& line : lines) description += (description.empty() ? "" : "\n") + line;
    return {{"Application", "ratbez " RATBEZ_VERSION}, {"Title", title}, {"Description", description}};
}

// The objects of a 3MF package as written and read back by lib3mf (what OpenSCAD's import() and slicers
// get), checked to be the objects given: same names, counts and triangles.
std::vector<ThreeMfMesh> written_back(const std::string& package, const std::vector<ThreeMfObject>& objects) {
    std::vector<ThreeMfMesh> read = read_three_mf(package);
    require(read.size() == objects.size(), "3mf", "lib3mf read back a different number of objects than it wrote");
    for (std::size_t i = 0; i < read.size(); ++i)
        require(read[i].name == objects[i].name && read[i].mesh.triangles == objects[i].mesh->triangles &&
                    read[i].mesh.vertices.size() == objects[i].mesh->vertices.size(),
                "3mf", [&] { return "lib3mf read object '" + objects[i].name + "' back with other triangles"; });
    return read;
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
        case Format::three_mf: throw Error("path", "a 3MF file is written by write_three_mf_file");
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
    std::string fixed;  // the format fixes the coordinates (binary STL, 3MF): its words for them
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
                    (measured && !measured->fixed.empty() ? measured->fixed
                     : measured && measured->decimals     ? "rounded to " + std::to_string(*measured->decimals) + " decimals"
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
    Mesh mesh;
    try {
        mesh = tessellate(solid, options);
    } catch (const TooFine& e) {
        if (!checks_bind) throw;
        throw e.reworded(limit.limit, "a tolerance of");
    }
    if (!checks.check_self_intersections) return mesh;
    // A coarse mesh of a face that meets another at a shallow angle can poke through it: a Voron bed carriage's
    // bore, meshed at the body's default tolerance 0.145, put a vertex 0.027 beyond the plane it ends in. Such a
    // solid is meshed again at half the tolerance, up to three times: finer, so still within the tolerance asked.
    // Where that does not help (the solid itself touches itself, or a finer mesh is over the budget or refused),
    // the first mesh goes to the export's checks, which refuse it and say why. The progress reported never goes
    // back (each mesh again reports what was reached) and keeps polling, so Ctrl-C stops the checks too.
    const Progress given = options.progress;
    double reached = 0;
    const Progress monotonic = [&given, &reached](double fraction) {
        reached = std::max(reached, fraction);
        if (given) given(reached);
    };
    options.progress = monotonic;
    MeshCheckOptions intersections;
    intersections.max_triangles = checks.max_triangles;
    intersections.progress = [&monotonic](double) { monotonic(0); };
    const auto intersects_itself = [&](const Mesh& m) {
        const MeshReport report = check_mesh(m, intersections);
        return report.manifold && report.self_intersection_free == false;
    };
    if (!intersects_itself(mesh)) return mesh;
    for (int halving = 1; halving <= 3; ++halving) {
        options.tolerance *= 0.5;
        Mesh finer;
        try {
            finer = tessellate(solid, options);
        } catch (const Cancelled&) {
            throw;
        } catch (const Error&) {
            break;  // TooFine, or a refusal at a tolerance the user did not ask for
        }
        if (!intersects_itself(finer)) return finer;
    }
    return mesh;
}

Mesh rounded_mesh(const Mesh& mesh, int decimals) {
    require(decimals >= 0 && decimals <= 40, "decimals", "must be from 0 to 40");
    Mesh result = mesh;
    for (Vec3& p : result.vertices) p = {rounded(p.x, decimals), rounded(p.y, decimals), rounded(p.z, decimals)};
    return result;
}

namespace {

// Whether rounding kept every triangle of `exact` a triangle facing its way: its area vector, rounded, still
// reaching at least half of itself along itself. Coordinates rounded to a grid coarser than a sliver's height (a
// KiCad capacitor's band 1e-5 wide between two arcs, at 5 decimals: a triangle 1.2e-6 high left 2.6e-16 high)
// flatten it where CGAL's exact predicates still see a triangle, and every check passes; OpenSCAD, whose grid of
// 2^-20 then flattens it altogether, fails in CGAL_Nef_polyhedron3() on `use` of the library. A triangle flat
// already (is_flat_triangle: a sample on the chord of its neighbours) has no shape to keep: any rounding is as
// good for it as the exact coordinates.
bool keeps_triangles(const Mesh& exact, const Mesh& rounded) {
    const auto area_vector = [](const Mesh& m, const std::array<std::uint32_t, 3>& t) {
        const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
        return cross(b - a, c - a);
    };
    for (const auto& t : exact.triangles) {
        if (is_flat_triangle(exact.vertices[t[0]], exact.vertices[t[1]], exact.vertices[t[2]])) continue;
        const Vec3 before = area_vector(exact, t), after = area_vector(rounded, t);
        if (!(dot(before, after) >= 0.5 * dot(before, before))) return false;
    }
    return true;
}

// The solid's volume for a header: the one its checks hold (tessellation_checks measured it), else measured now.
// A solid read from a file takes seconds to integrate (2.4 s for a 51-face screw, whose mesh takes 0.08 s), and
// the export measured it twice.
double volume_of(const Solid& solid, const MeshCheckOptions& checks) {
    return checks.exact_volume ? *checks.exact_volume : solid.volume();
}

}  // namespace

MeshCheckOptions tessellation_checks(const Solid& solid, const Mesh& mesh, double tolerance) {
    const SolidMeasures measured = measure(solid);  // side by side: seconds each for a solid read from a file
    MeshCheckOptions options;
    options.exact_volume = measured.volume;
    options.volume_tolerance = tolerance * std::max(measured.area, mesh.area()) * 1.001 + 1e-12 * std::abs(measured.volume);
    return options;
}

namespace {

// A 3MF package of `objects`, read back (the objects as a reader gets them) with `check` run on each; then
// the package again with the metadata `describe` makes from what was measured, whose objects must read back
// the same; then the file through the one safe writer. (lib3mf writes each coordinate as its float32 cut to
// 6 decimals, which is not idempotent, so the second package is made from the same objects, not from the
// read-back ones.) Progress: the first package and reading to 0.1, the checks to 0.9, the rest to 1.
template <class Check, class Describe>
void write_three_mf_file(const std::vector<ThreeMfObject>& objects, const std::string& path, const Progress& progress,
                         Check check, Describe describe) {
    const std::vector<ThreeMfMesh> read = written_back(write_three_mf(objects, {}, progress_part(progress, 0, 0.05)), objects);
    if (progress) progress(0.1);
    const double share = 0.8 / static_cast<double>(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i)
        check(i, read[i].mesh, progress_part(progress, 0.1 + share * static_cast<double>(i), 0.1 + share * static_cast<double>(i + 1)));
    const std::string package = write_three_mf(objects, describe(), progress_part(progress, 0.9, 0.95));
    const std::vector<ThreeMfMesh> again = written_back(package, objects);
    for (std::size_t i = 0; i < objects.size(); ++i)
        require(again[i].mesh.vertices == read[i].mesh.vertices, "3mf",
                "lib3mf wrote the same coordinates differently the second time");
    output::write_file(path, [&](std::ostream& out) {
        out.write(package.data(), static_cast<std::streamsize>(package.size()));
    });
    if (progress) progress(1.0);
}

}  // namespace

void export_mesh(const Mesh& given, const std::string& path, const ExportOptions& options) {
    const Format format = checked_format(path, options);
    if (format == Format::three_mf) {
        const std::vector<ThreeMfObject> objects = {{&given, options.openscad.module_name, options.openscad.color}};
        std::vector<std::string> lines;
        write_three_mf_file(
            objects, path, options.progress,
            [&](std::size_t, const Mesh& mesh, const Progress& progress) {
                MeshCheckOptions checks = options.checks;
                checks.progress = progress;
                const MeshReport report = check_mesh(mesh, checks);
                if (!report.ok()) refuse(report);
                lines = header_lines(mesh, options.source, std::nullopt);
            },
            [&] {
                lines.front() = "ratbez " RATBEZ_VERSION ", a 3MF file";
                return three_mf_metadata(options.openscad.module_name, lines);
            });
        return;
    }
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

// The coordinates a format fixes itself, as a reader of the file gets them, and the format's words for them
// (fixed_coordinates).
struct FixedMesh {
    const Mesh* mesh = nullptr;
    std::string stores;
};

// The mesh of `solid` as it will be written (the format's own coordinates, or the fewest decimals that
// pass, or exact) with its measured deviation, checked: the work of export_tessellation before the writing.
// `progress` runs to 0.95.
WrittenMesh prepared_mesh(const Solid& solid, const Mesh& mesh, double tolerance, const FixedMesh& fixed,
                          const MeshCheckOptions& base_checks, const Progress& progress) {
    require(std::isfinite(tolerance) && tolerance > 0, "tolerance", "must be a positive number");
    const bool text = fixed.mesh == nullptr;
    WrittenMesh result{text ? mesh : *fixed.mesh, 0, std::nullopt};
    bool chosen = false;
    // The work, in shares of the progress reported: the deviation of the mesh as given, then for each
    // decimal candidate (fewest first) its checks and deviation, which end at the first that passes; then the
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
        // A convex solid's mesh is convex (tessellate.hpp); rounding can lift a vertex above its neighbours'
        // plane, and OpenSCAD's minkowski() then leaves its fast path (minutes for a ball): hulled again.
        const bool convex = is_convex_mesh(mesh) && is_convex(solid);
        for (std::size_t k = 0; k < candidates.size(); ++k) {
            const double from = kFirstDeviation + share * static_cast<double>(k);
            Mesh candidate = rounded_mesh(mesh, candidates[k]);
            if (!keeps_triangles(mesh, candidate)) continue;
            if (convex && !is_convex_mesh(candidate)) candidate = convex_hull(candidate);
            // The checks first: a fraction of the deviation's time (2242 triangles of a lock body of 1481 faces:
            // 7 ms against 4.5 s), and where rounding breaks the mesh the deviation is not measured at all.
            if (!checked(candidate, from, from + share / 3).ok()) continue;
            const double deviation = measured(candidate, from + share / 3, from + share);
            if (!(deviation <= tolerance)) continue;
            result = WrittenMesh{std::move(candidate), deviation, candidates[k]};
            chosen = true;
            break;
        }
    }
    if (!text) {
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
            throw Error("mesh", fixed.stores + ", which leave this mesh " +
                                    (report.ok() ? number_text(result.max_deviation, 4) + " from the surface, beyond the tolerance " +
                                                       number_text(tolerance, 4)
                                                 : "invalid (" + report.problems.front() + ")") +
                                    ": write .scad, .off or ASCII STL text, or use a coarser tolerance");
        }
    } else if (!chosen) {
        const MeshReport report = checked(mesh, kCandidatesEnd, 0.95);
        if (!report.ok()) refuse(report);
        if (!(result.max_deviation <= tolerance))
            throw Error("mesh", "refusing to export a mesh " + number_text(result.max_deviation, 4) +
                                    " from the surface, beyond the tolerance " + number_text(tolerance, 4));
    }
    if (progress) progress(0.95);
    return result;
}

// prepared_mesh for part `index` of a library, a refusal naming the part when there are several (PartRefused,
// "mesh: 'Nut': ...": which of an assembly's solids, by the name its module, object or Label has).
WrittenMesh prepared_part(const std::vector<LibraryPart>& parts, std::size_t index, const FixedMesh& fixed, const Progress& progress) {
    const LibraryPart& part = parts[index];
    try {
        return prepared_mesh(*part.solid, *part.mesh, part.tolerance, fixed, part.checks, progress);
    } catch (const TooFine&) {
        throw;
    } catch (const Error& e) {
        if (parts.size() == 1) throw;
        throw PartRefused(Error(e.argument(), "'" + comment_text(part.module_name) + "': " + std::string(e.reason())), index);
    }
}

// The solids of `parts` in one 3MF file, one object each (named after the part's module_name, any text,
// with its colour), each checked as export_tessellation checks a binary STL: on the coordinates lib3mf
// wrote, read back.
std::vector<WrittenMesh> export_three_mf(const std::vector<LibraryPart>& parts, const std::string& path,
                                         const ExportOptions& options) {
    require(!parts.empty(), "solids", "is empty");
    std::vector<ThreeMfObject> objects;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const LibraryPart& part = parts[i];
        require(part.solid != nullptr && part.mesh != nullptr, "solids", "a part has no solid or mesh");
        require(!part.module_name.empty(), "solids", "a 3MF object needs a name");
        for (std::size_t j = 0; j < i; ++j)
            require(parts[j].module_name != part.module_name, "solids",
                    [&] { return "two solids are named '" + part.module_name + "'"; });
        require(std::isfinite(part.tolerance) && part.tolerance > 0, "tolerance", "must be a positive number");
        objects.push_back({part.mesh, part.module_name, part.color});
    }
    const std::string stores = fixed_coordinates(Format::three_mf);
    std::vector<WrittenMesh> written(parts.size());
    std::vector<std::string> lines = {"ratbez " RATBEZ_VERSION ", a 3MF file of " + std::to_string(parts.size()) +
                                          (parts.size() == 1 ? " solid" : " solids"),
                                      "source: " + options.source};
    write_three_mf_file(
        objects, path, options.progress,
        [&](std::size_t i, const Mesh& mesh, const Progress& progress) {
            const LibraryPart& part = parts[i];
            written[i] = prepared_part(parts, i, FixedMesh{&mesh, stores}, progress);
            const std::vector<std::string> part_lines =
                header_lines(written[i].mesh, options.source,
                             Measured{part.tolerance, written[i].max_deviation, volume_of(*part.solid, part.checks), std::nullopt,
                                      fixed_coordinates_note(Format::three_mf)});
            lines.push_back("object " + part.module_name + ":");
            for (std::size_t k = 2; k < part_lines.size(); ++k) lines.push_back("  " + part_lines[k]);
        },
        [&] { return three_mf_metadata(parts.size() == 1 ? parts.front().module_name : std::filesystem::path(path).stem().string(), lines); });
    return written;
}

}  // namespace

WrittenMesh export_tessellation(const Solid& solid, const Mesh& mesh, double tolerance, const std::string& path,
                                const ExportOptions& options) {
    const Format format = checked_format(path, options);
    if (format == Format::three_mf)
        return export_three_mf({LibraryPart{options.openscad.module_name, &solid, &mesh, tolerance, options.checks, options.openscad.color}},
                               path, options)
            .front();
    const bool float32 = writes_float32(format, options);
    const Mesh rounded = float32 ? float32_mesh(mesh) : Mesh{};
    const std::string stores = float32 ? fixed_coordinates(format) : std::string();
    const WrittenMesh result =
        prepared_mesh(solid, mesh, tolerance, FixedMesh{float32 ? &rounded : nullptr, stores}, options.checks, options.progress);
    ExportOptions written = options;
    written.openscad.header =
        header_lines(result.mesh, options.source,
                     Measured{tolerance, result.max_deviation, volume_of(solid, options.checks), result.decimals,
                              float32 ? fixed_coordinates_note(Format::stl) : std::string()});
    write_files(result.mesh, path, format, written);
    if (options.progress) options.progress(1.0);
    return result;
}

namespace {

// The solids of `parts` as one mesh in one .stl or .off file: each part's mesh prepared as export_tessellation
// prepares it (float32 for binary STL, else the fewest decimals that pass) and checked on its own, then the
// meshes side by side (an assembly's parts may touch or overlap, which separate closed shells in one mesh
// allow; the checks of the whole would call a touch a self-intersection).
std::vector<WrittenMesh> export_merged(const std::vector<LibraryPart>& parts, const std::string& path, Format format,
                                       const ExportOptions& options) {
    require(!parts.empty(), "solids", "is empty");
    const bool float32 = writes_float32(format, options);
    std::vector<WrittenMesh> written;
    ExportOptions file = options;
    file.openscad.header = {"ratbez " RATBEZ_VERSION ", one mesh of " + std::to_string(parts.size()) + " solids",
                            "source: " + options.source};
    Mesh merged;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const LibraryPart& part = parts[i];
        require(part.solid != nullptr && part.mesh != nullptr, "solids", "a part has no solid or mesh");
        const double share = 0.95 / static_cast<double>(parts.size());
        const Mesh rounded = float32 ? float32_mesh(*part.mesh) : Mesh{};
        written.push_back(prepared_part(parts, i, FixedMesh{float32 ? &rounded : nullptr, float32 ? fixed_coordinates(format) : std::string()},
                                        progress_part(options.progress, share * static_cast<double>(i), share * static_cast<double>(i + 1))));
        const WrittenMesh& mesh = written.back();
        const std::vector<std::string> lines =
            header_lines(mesh.mesh, options.source,
                         Measured{part.tolerance, mesh.max_deviation, volume_of(*part.solid, part.checks), mesh.decimals,
                                  float32 ? fixed_coordinates_note(Format::stl) : std::string()});
        file.openscad.header.push_back("solid " + part.module_name + ":");
        for (std::size_t k = 2; k < lines.size(); ++k) file.openscad.header.push_back("  " + lines[k]);
        const auto offset = static_cast<std::uint32_t>(merged.vertices.size());
        merged.vertices.insert(merged.vertices.end(), mesh.mesh.vertices.begin(), mesh.mesh.vertices.end());
        for (const auto& t : mesh.mesh.triangles) merged.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    write_files(merged, path, format, file);
    if (options.progress) options.progress(1.0);
    return written;
}

}  // namespace

std::vector<WrittenMesh> export_library(const std::vector<LibraryPart>& parts, const std::string& path,
                                        const ExportOptions& options) {
    const Format format = checked_format(path, options);
    require(!options.import_stl, "import_stl", "applies to one solid, not a library of several");
    if (format == Format::three_mf) return export_three_mf(parts, path, options);
    if (format == Format::stl || format == Format::off) return export_merged(parts, path, format, options);
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
        written.push_back(prepared_part(parts, i, FixedMesh{},
                                        progress_part(options.progress, share * static_cast<double>(i), share * static_cast<double>(i + 1))));
        const WrittenMesh& mesh = written.back();
        // The module's lines are export_tessellation's header without its first two (version, source).
        const std::vector<std::string> lines =
            header_lines(mesh.mesh, options.source,
                         Measured{part.tolerance, mesh.max_deviation, volume_of(*part.solid, part.checks), mesh.decimals, std::string()});
        file.openscad.header.push_back("module " + part.module_name + "():");
        for (std::size_t k = 2; k < lines.size(); ++k) file.openscad.header.push_back("  " + lines[k]);
    }
    for (std::size_t i = 0; i < parts.size(); ++i) modules.push_back({&written[i].mesh, parts[i].module_name, parts[i].color});
    output::write_file(path, [&](std::ostream& out) { write_openscad_library(modules, out, file.openscad); });
    if (options.progress) options.progress(1.0);
    return written;
}

}  // namespace ratbez::exporter
