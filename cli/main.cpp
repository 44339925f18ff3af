// The `ratbez` command: a JSON shape spec or a STEP/BREP model file in, files and reports out.
//
//   ratbez export INPUT -o OUT.{scad,stl,off,3mf,step,brep} [--tolerance T] [--angle A] [--module NAME] [--ascii]
//                [--import-stl] [--max-triangles N] [--skip-self-intersection-check] [--strict]
//   ratbez check INPUT [--json] [--strict]
//   ratbez info INPUT [--json] [--strict]
//
// INPUT is SPEC.json (one solid) or a .step/.stp/.brep file (every solid in it: several export into one library,
// check and info report each; inputs.hpp).
//   ratbez demo [DIR] [--examples DIR] [--no-render]
//   ratbez --version
//
// Exit codes: 0 success; 1 a check failed (or an internal error); 2 bad input (spec, arguments, paths).
// Every error is ONE line on stderr that names the field or argument at fault.
//
// This file includes neither OCCT nor CGAL headers: it reaches both through their OCCT-free and
// CGAL-free headers (ratbez/occt/*.hpp, ratbez/export/*.hpp).

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "ratbez/deviation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/export/export.hpp"
#include "ratbez/occt/check.hpp"
#include "ratbez/occt/files.hpp"
#include "ratbez/output_file.hpp"
#include "ratbez/properties.hpp"
#include "ratbez/tessellate.hpp"
#include "inputs.hpp"
#include "spec.hpp"

extern char** environ;

namespace ratbez::build_paths {
extern const char* const examples_dir;  // examples/ of this checkout, `ratbez demo`'s default (cli/CMakeLists.txt)
}

namespace {

namespace fs = std::filesystem;
using ratbez::spec::ShapeSpec;

constexpr const char* usage_text =
    "usage: ratbez <command> ...\n"
    "  ratbez export INPUT -o OUT.{scad,stl,off,3mf,step,brep} [--tolerance T] [--angle A] [--module NAME] [--ascii]\n"
    "                [--max-triangles N] [--import-stl] [--skip-self-intersection-check] [--strict]\n"
    "                --import-stl: a .scad whose module import()s the mesh from a binary STL beside it (faster in\n"
    "                OpenSCAD for large meshes); --skip-self-intersection-check: for very large meshes\n"
    "  ratbez check INPUT [--json] [--strict]  check against OpenCASCADE; exit 1 when a check fails\n"
    "  ratbez info INPUT [--json] [--strict]   faces, edges, vertices, shells, Euler characteristic, area, volume, box\n"
    "  ratbez demo [DIR] [--examples DIR] [--no-render]\n"
    "                                       build, export and check every example into DIR (default ratbez-demo)\n"
    "  ratbez --version                     the version of ratbez\n"
    "INPUT is a JSON shape spec (documented in examples/README.md) or a .step/.stp/.brep file: every solid in it\n"
    "is read (an assembly with its placements); several export into one library (.scad: a module each and one\n"
    "placing them all) and check and info report each (--json: an array). Faces that bound no volume and solids\n"
    "of several that cannot be read (or, by export, meshed and checked) are left out with a note; --strict\n"
    "refuses such a file instead (exit 2, or 1 for a mesh that fails the checks).\n";

// Bad command-line arguments: exit 2, reported as "usage error: <argument>: <reason>".
class UsageError : public std::runtime_error {
public:
    UsageError(const std::string& argument, const std::string& reason) : std::runtime_error(argument + ": " + reason) {}
};

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

std::string lowercase_extension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

std::string format_number(double value, int digits = 10) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

// ---- arguments -------------------------------------------------------------------------------------

struct Arguments {
    std::vector<std::string> positional;
    std::map<std::string, std::string> values;  // option -> value
    std::set<std::string> flags;

    std::optional<std::string> value(const std::string& option) const {
        const auto it = values.find(option);
        return it == values.end() ? std::nullopt : std::optional(it->second);
    }
    bool flag(const std::string& option) const { return flags.count(option) != 0; }
};

// Options with values accept "--name VALUE" and "--name=VALUE"; "-o" is "--output".
Arguments parse_arguments(const std::string& command, const std::vector<std::string>& args,
                          const std::set<std::string>& value_options, const std::set<std::string>& flag_options) {
    Arguments parsed;
    for (std::size_t i = 0; i < args.size(); ++i) {
        std::string arg = args[i];
        // Errors name the option as the user spelled it.
        const std::string spelled = arg;
        if (arg == "-o") arg = "--output";
        if (arg.size() < 2 || arg.rfind("--", 0) != 0) {
            if (!arg.empty() && arg[0] == '-' && arg != "-")
                throw UsageError(arg, "unknown option for '" + command + "'");
            parsed.positional.push_back(arg);
            continue;
        }
        std::string name = arg, value;
        bool has_value = false;
        if (const auto eq = arg.find('='); eq != std::string::npos) {
            name = arg.substr(0, eq);
            value = arg.substr(eq + 1);
            has_value = true;
        }
        if (value_options.count(name)) {
            if (!has_value) {
                if (i + 1 >= args.size()) throw UsageError(spelled, "needs a value");
                value = args[++i];
            }
            if (parsed.values.count(name)) throw UsageError(spelled == "-o" ? "-o" : name, "given more than once");
            parsed.values[name] = value;
        } else if (flag_options.count(name)) {
            if (has_value) throw UsageError(name, "takes no value");
            parsed.flags.insert(name);
        } else {
            throw UsageError(spelled == "-o" ? "-o" : name, "unknown option for '" + command + "'");
        }
    }
    return parsed;
}

double parse_positive(const std::string& option, const std::string& text) {
    double value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || !std::isfinite(value) ||
        !(value > 0))
        throw UsageError(option, "must be a positive number, not '" + text + "'");
    return value;
}

const std::string& single_input(const Arguments& args, const std::string& command) {
    if (args.positional.empty())
        throw UsageError("SPEC.json", "missing (usage: ratbez " + command + " SPEC.json|MODEL.step|MODEL.brep ...)");
    if (args.positional.size() > 1) throw UsageError(args.positional[1], "unexpected argument for '" + command + "'");
    return args.positional.front();
}

std::string joined(const std::vector<std::string>& words, const char* separator = ", ") {
    std::string text;
    for (const auto& w : words) text += (text.empty() ? "" : separator) + w;
    return text;
}

// ---- shared steps ----------------------------------------------------------------------------------

// The tolerance and budget as the user gave them, so that a failure blames the option actually passed.
struct MeshRequest {
    double tolerance = 0;
    std::optional<double> angle;
    std::optional<std::size_t> max_triangles;
    bool tolerance_from_option = false;  // --tolerance, else the spec's `tolerance` or the default
    ratbez::Progress progress;           // optional
    bool check_self_intersections = true;  // and mesh finer where the mesh intersects itself (tessellate_for_export)
};

ratbez::Mesh tessellate_for(const ShapeSpec& spec, const MeshRequest& request) {
    ratbez::TessellationOptions options;
    options.tolerance = request.tolerance;
    options.angle_deg = request.angle;
    if (request.max_triangles) options.max_triangles = *request.max_triangles;
    options.progress = request.progress;
    try {
        // Refused from the plan, before the mesh is built, when it would exceed what the export's mesh checks
        // (or the memory limit) take, as well as the budget (issue 29).
        ratbez::exporter::MeshCheckOptions checks;
        checks.check_self_intersections = request.check_self_intersections;
        return ratbez::exporter::tessellate_for_export(spec.solid, options, checks);
    } catch (const ratbez::TooFine& e) {
        // The limit as the user knows it: their --max-triangles, the default budget, or the checks' limit
        // (already worded by tessellate_for_export); the tolerance that fits as the option that sets it.
        const bool own_budget = e.budget() == "max_triangles = " + std::to_string(e.max_triangles());
        const std::string budget =
            !own_budget             ? e.budget()
            : request.max_triangles ? "--max-triangles " + std::to_string(e.max_triangles())
                                    : "the default limit of " + std::to_string(e.max_triangles()) + " (--max-triangles)";
        const std::string reason(e.reworded(budget, "--tolerance").reason());
        if (request.tolerance_from_option) throw UsageError("--tolerance", reason);
        if (spec.tolerance) throw ratbez::spec::SpecError("tolerance", reason);
        throw UsageError(own_budget ? "--max-triangles" : "--tolerance", reason);
    } catch (const ratbez::Error& e) {
        if (e.argument() == "tolerance") throw UsageError("--tolerance", std::string(e.reason()));
        if (e.argument() == "angle_deg") throw UsageError("--angle", std::string(e.reason()));
        throw;
    }
}

std::size_t parse_count(const std::string& option, const std::string& text) {
    unsigned long long value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() || value == 0)
        throw UsageError(option, "must be a positive whole number, not '" + text + "'");
    return static_cast<std::size_t>(value);
}

// ---- export ----------------------------------------------------------------------------------------

// `text` made a module name. A built-in gets a suffix, and stderr says so: the user then calls a name they
// did not write (other characters made _ are what they would expect, and pass silently).
std::string derived_module_name(const std::string& text, const std::string& from) {
    const std::string name = ratbez::exporter::openscad_identifier(text);
    const std::string base = name.ends_with(ratbez::exporter::builtin_suffix)
                                 ? name.substr(0, name.size() - ratbez::exporter::builtin_suffix.size())
                                 : name;
    if (name != text && ratbez::exporter::is_openscad_builtin(base))
        std::cerr << "note: module " << name << "() (" << from << " '" << base
                  << "' is an OpenSCAD built-in, which the library must not shadow)\n";
    return name;
}

// One line on a terminal's stderr, rewritten in place ("\r") when its percent changes, once an export has
// run for more than a second: percent done and the time left at the rate so far. Not on a redirected stderr,
// where every "\r" would be one more line of a log, unless RATBEZ_PROGRESS_AFTER sets the seconds (tests use
// 0). finish() (or the destructor) ends the line if one was printed.
class ProgressLine {
public:
    explicit ProgressLine(std::string what) : what_(std::move(what)), start_(std::chrono::steady_clock::now()) {
        if (const char* after = std::getenv("RATBEZ_PROGRESS_AFTER")) {
            char* end = nullptr;
            const double seconds = std::strtod(after, &end);
            if (end != after && std::isfinite(seconds)) after_ = seconds;
        } else if (!isatty(STDERR_FILENO)) {
            after_ = std::numeric_limits<double>::infinity();
        }
    }
    void operator()(double fraction) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (elapsed < after_ || fraction <= 0) return;
        const int percent = static_cast<int>(std::lround(100 * std::min(fraction, 1.0)));
        if (percent == percent_) return;
        percent_ = percent;
        const double left = elapsed * (1 - fraction) / fraction;
        std::fprintf(stderr, "\r%s: %3d%% (about %.0f s left)   ", what_.c_str(), percent, std::ceil(left));
        std::fflush(stderr);
        shown_ = true;
    }
    void finish() {
        if (shown_) std::fputc('\n', stderr);
        shown_ = false;
    }
    // An error unwinding past the line ends it, so the message starts on a line of its own.
    ~ProgressLine() { finish(); }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

private:
    std::string what_;
    std::chrono::steady_clock::time_point start_;
    double after_ = 1;
    int percent_ = -1;
    bool shown_ = false;
};

// The input of a command, with a progress line while a large model file is read.
ratbez::cli::Input load_for(const std::string& path, bool strict) {
    ProgressLine progress("reading " + path);
    return ratbez::cli::load_input(path, [&progress](double fraction) { progress(fraction); }, strict);
}

// The tessellation's share of an export's progress line (it is usually less than the checks').
constexpr double kTessellationShare = 0.3;

// The export options as parsed and checked against the output format, before anything is read.
struct ExportRequest {
    std::string input, output, extension;
    std::optional<double> tolerance, angle;
    std::optional<std::size_t> max_triangles;
    std::optional<std::string> module_name;
    bool ascii = false, import_stl = false, skip_self_intersection_check = false, strict = false;
    bool exact() const { return extension == ".step" || extension == ".stp" || extension == ".brep"; }
};

ExportRequest parse_export(const std::vector<std::string>& raw) {
    const Arguments args = parse_arguments("export", raw, {"--output", "--tolerance", "--angle", "--module", "--max-triangles"},
                                            {"--ascii", "--import-stl", "--skip-self-intersection-check", "--strict"});
    ExportRequest request;
    request.input = single_input(args, "export");
    const auto output = args.value("--output");
    if (!output || output->empty()) throw UsageError("-o", "the output file is required (-o OUT.scad|stl|off|3mf|step|brep)");
    request.output = *output;
    const std::string& extension = request.extension = lowercase_extension(*output);
    const bool mesh_format = extension == ".scad" || extension == ".stl" || extension == ".off" || extension == ".3mf";
    if (!mesh_format && !request.exact())
        throw UsageError("-o", "unknown extension '" + extension + "' in '" + *output +
                                   "' (expected .scad, .stl, .off, .3mf, .step or .brep)");
    // Options that cannot apply are errors rather than silently ignored (they are usually typos).
    if (args.value("--module") && extension != ".scad") throw UsageError("--module", "applies only to .scad output");
    if (args.flag("--ascii") && extension != ".stl") throw UsageError("--ascii", "applies only to .stl output");
    if (args.flag("--import-stl") && extension != ".scad") throw UsageError("--import-stl", "applies only to .scad output");
    for (const char* option : {"--tolerance", "--angle", "--max-triangles"})
        if (request.exact() && args.value(option)) throw UsageError(option, "does not apply to exact " + extension + " output");
    if (auto m = args.value("--max-triangles")) request.max_triangles = parse_count("--max-triangles", *m);
    if (auto t = args.value("--tolerance")) request.tolerance = parse_positive("--tolerance", *t);
    if (auto a = args.value("--angle")) {
        request.angle = parse_positive("--angle", *a);
        if (*request.angle >= 180) throw UsageError("--angle", "must be less than 180 degrees");
    }
    request.module_name = args.value("--module");
    if (request.module_name)
        if (const std::string problem = ratbez::exporter::module_name_problem(*request.module_name); !problem.empty())
            throw UsageError("--module", problem);
    request.ascii = args.flag("--ascii");
    request.import_stl = args.flag("--import-stl");
    request.skip_self_intersection_check = args.flag("--skip-self-intersection-check");
    request.strict = args.flag("--strict");
    return request;
}

// The tolerance a shape is meshed at: --tolerance, else the spec's, else the default for its size.
double tolerance_for(const ShapeSpec& spec, const ExportRequest& request) {
    return request.tolerance ? *request.tolerance : spec.tolerance ? *spec.tolerance : ratbez::default_tolerance(spec.solid);
}

ratbez::Mesh tessellate_for(const ShapeSpec& spec, const ExportRequest& request, const ratbez::Progress& progress) {
    return tessellate_for(spec, MeshRequest{tolerance_for(spec, request), request.angle ? request.angle : spec.tessellation_angle,
                                            request.max_triangles, request.tolerance.has_value(), progress,
                                            !request.skip_self_intersection_check});
}

std::optional<ratbez::exporter::Color> color_of(const ShapeSpec& spec) {
    if (!spec.color) return std::nullopt;
    try {
        return ratbez::exporter::parse_color(*spec.color, "color");
    } catch (const ratbez::Error& e) {
        throw ratbez::spec::SpecError(e);
    }
}

// Runs the mesh export; a mesh refused by the CGAL checks is our failure (exit 1), not the user's input.
template <class Export>
int checked_export(ProgressLine& progress, Export&& write) {
    try {
        write();
        progress.finish();
        return 0;
    } catch (const ratbez::Error& e) {
        progress.finish();
        if (e.argument() == "mesh") {
            std::cerr << "error: " << one_line(e.what()) << '\n';
            return 1;
        }
        throw;
    }
}

// One solid: a spec's, or a model file's only one.
int export_one(const ShapeSpec& spec, bool model_file, const ExportRequest& request) {
    const double used_tolerance = tolerance_for(spec, request);
    ProgressLine progress("exporting " + request.output);
    const ratbez::Progress line = [&progress](double fraction) { progress(fraction); };
    const ratbez::Mesh mesh = tessellate_for(spec, request, ratbez::progress_part(line, 0, kTessellationShare));
    ratbez::exporter::ExportOptions options;
    // The module is named by --module, else by the spec's `name`, else after the file written (a model file's
    // product name is whatever the CAD program chose: the output's name is the one the user picked). A 3MF
    // object's name is any text: the name or the file's stem as they are.
    const bool by_name = spec.named && !model_file;
    options.openscad.module_name =
        request.extension == ".3mf" ? (spec.named ? spec.name : fs::path(request.output).stem().string())
        : request.module_name       ? *request.module_name
        : by_name ? derived_module_name(spec.name, "the spec's name")
                  : derived_module_name(fs::path(request.output).stem().string(), "the file name");
    options.binary_stl = !request.ascii;
    options.import_stl = request.import_stl;
    options.openscad.color = color_of(spec);
    options.source = (model_file ? "file " : "spec ") + request.input;
    options.checks = ratbez::exporter::tessellation_checks(spec.solid, mesh, used_tolerance);
    // Closure, manifoldness, orientation and volume are still checked; only the O(n log n) but
    // heavy CGAL self-intersection test is skipped, at the user's explicit request.
    options.checks.check_self_intersections = !request.skip_self_intersection_check;
    options.progress = ratbez::progress_part(line, kTessellationShare, 1);
    if (const int failed = checked_export(progress, [&] {
            ratbez::exporter::export_tessellation(spec.solid, mesh, used_tolerance, request.output, options);
        }))
        return failed;
    std::cout << "wrote " << request.output
              << (options.import_stl ? " and " + fs::path(request.output).replace_extension(".stl").string() : std::string())
              << " (" << mesh.triangles.size() << " triangles, " << mesh.vertices.size()
              << " vertices, tolerance " << format_number(used_tolerance, 6) << ")\n";
    return 0;
}

// OpenSCAD module names for the parts of a library: each name made an identifier, repeats numbered, none equal
// to the module that places them all.
std::vector<std::string> part_module_names(const std::vector<ShapeSpec>& shapes, const std::string& placing) {
    std::vector<std::string> derived;  // (each with its note where a built-in got the suffix)
    for (const ShapeSpec& shape : shapes) derived.push_back(derived_module_name(shape.name, "the solid's name"));
    return ratbez::exporter::library_module_names(derived, placing);
}

// Several solids of a model file into one library (.scad: one module each and one placing them all; .3mf: one
// object each; .stl/.off: one mesh of them all), each meshed at its own tolerance unless --tolerance is given.
int export_several(const std::vector<ShapeSpec>& shapes, const ExportRequest& request) {
    if (request.import_stl) throw UsageError("--import-stl", "applies to one solid, and '" + request.input + "' holds " +
                                                                 std::to_string(shapes.size()));
    ProgressLine progress("exporting " + request.output);
    const ratbez::Progress line = [&progress](double fraction) { progress(fraction); };
    ratbez::exporter::ExportOptions options;
    options.openscad.module_name =
        request.module_name ? *request.module_name : derived_module_name(fs::path(request.output).stem().string(), "the file name");
    const std::vector<std::string> module_names = request.extension == ".scad"
                                                      ? part_module_names(shapes, options.openscad.module_name)
                                                      : std::vector<std::string>();
    std::vector<ratbez::Mesh> meshes;
    meshes.reserve(shapes.size());  // the parts point into it
    std::vector<ratbez::exporter::LibraryPart> parts;
    std::vector<std::string> left_out;
    std::optional<ratbez::Error> first_refusal;
    const double share = kTessellationShare / static_cast<double>(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const ShapeSpec& shape = shapes[i];
        ratbez::exporter::LibraryPart part;
        part.module_name = module_names.empty() ? shape.name : module_names[i];
        try {
            meshes.push_back(tessellate_for(shape, request,
                                            ratbez::progress_part(line, share * static_cast<double>(i), share * static_cast<double>(i + 1))));
        } catch (const ratbez::TooFine&) {
            throw;
        } catch (const ratbez::Error& e) {
            // Which of the file's solids, as the export's own refusals name them ("solid: 'Nut': ...").
            ratbez::Error named(e.argument(), "'" + ratbez::exporter::comment_text(part.module_name) + "': " + std::string(e.reason()));
            // A solid of several that does not mesh (a part that touches itself) is left out with a note, as a
            // solid the reader cannot take is; --strict refuses the file instead. The note follows the export.
            if (request.strict) throw named;
            left_out.push_back(std::string(named.what()));
            if (!first_refusal) first_refusal = named;
            continue;
        }
        part.solid = &shape.solid;
        part.mesh = &meshes.back();
        part.tolerance = tolerance_for(shape, request);
        part.checks = ratbez::exporter::tessellation_checks(shape.solid, meshes.back(), part.tolerance);
        part.checks.check_self_intersections = !request.skip_self_intersection_check;
        part.color = color_of(shape);
        parts.push_back(std::move(part));
    }
    if (parts.empty()) throw *first_refusal;
    options.binary_stl = !request.ascii;
    options.source = "file " + request.input;
    options.progress = ratbez::progress_part(line, kTessellationShare, 1);
    std::vector<ratbez::exporter::WrittenMesh> written;
    const auto write_library = [&] {
        for (;;) {
            try {
                written = ratbez::exporter::export_library(parts, request.output, options);
                return;
            } catch (const ratbez::exporter::PartRefused& e) {
                // A part whose mesh the export's checks refuse (a file's part that intersects itself) is left out
                // the same way, and the others are written without it.
                if (request.strict || parts.size() == 1) throw;
                left_out.push_back(std::string(e.what()));
                parts.erase(parts.begin() + static_cast<std::ptrdiff_t>(e.part()));
            }
        }
    };
    const int failed = checked_export(progress, write_library);
    if (!left_out.empty()) {
        std::cerr << "note: '" << request.input << "': left out " << left_out.size() << " of " << shapes.size()
                  << " solids that do not mesh or whose meshes fail the export's checks:";
        for (const std::string& why : left_out) std::cerr << (left_out.size() > 1 ? "\n  " : " ") << why;
        std::cerr << '\n';
    }
    if (failed) return failed;
    std::size_t triangles = 0;
    for (const auto& w : written) triangles += w.mesh.triangles.size();
    std::vector<std::string> modules;
    for (const auto& part : parts) modules.push_back(part.module_name);
    const bool one = parts.size() == 1;  // the others left out
    std::cout << "wrote " << request.output << " (" << parts.size() << (one ? " solid" : " solids")
              << (request.extension == ".scad"
                      ? (one ? " in module " : " in modules ") + joined(modules) + " placed by " + options.openscad.module_name + "()"
                      : std::string())
              << ", " << triangles << " triangles)\n";
    return 0;
}

int command_export(const std::vector<std::string>& raw) {
    const ExportRequest request = parse_export(raw);
    const ratbez::cli::Input input = load_for(request.input, request.strict);
    if (request.exact()) {
        std::vector<ratbez::Solid> solids;
        std::size_t faces = 0;
        for (const ShapeSpec& shape : input.shapes) {
            solids.push_back(shape.solid);
            faces += shape.solid.faces().size();
        }
        if (request.extension == ".brep")
            ratbez::occt::write_brep(solids, request.output);
        else
            ratbez::occt::write_step(solids, request.output);
        std::cout << "wrote " << request.output << " (exact B-rep, "
                  << (solids.size() > 1 ? std::to_string(solids.size()) + " solids, " : std::string()) << faces << " faces)\n";
        return 0;
    }
    if (input.shapes.size() == 1) return export_one(input.shapes.front(), input.model_file, request);
    return export_several(input.shapes, request);
}

// ---- check -----------------------------------------------------------------------------------------

nlohmann::json report_json(const ratbez::occt::CheckReport& report) {
    nlohmann::json j;
    ratbez::occt::for_each_entry(report, [&]<class Value>(const char* name, const Value& value) {
        if constexpr (std::is_same_v<Value, std::optional<double>>)
            j[name] = value ? nlohmann::json(*value) : nlohmann::json();  // null when absent
        else
            j[name] = value;
    });
    return j;
}

// check and info print one block per solid; --json prints the spec's object, or a model file's array of them.
void print_json(const std::vector<nlohmann::json>& reports, bool model_file) {
    std::cout << (model_file ? nlohmann::json(reports) : reports.front()).dump(2) << '\n';
}

int command_check(const std::vector<std::string>& raw) {
    const Arguments args = parse_arguments("check", raw, {}, {"--json", "--strict"});
    const ratbez::cli::Input input = load_for(single_input(args, "check"), args.flag("--strict"));
    bool passed = true;
    std::vector<nlohmann::json> reports;
    for (const ShapeSpec& spec : input.shapes) {
        const ratbez::occt::CheckReport report = ratbez::occt::check(spec.solid);
        passed = passed && report.passed;
        if (args.flag("--json")) {
            nlohmann::json j = report_json(report);
            j["name"] = spec.name;
            reports.push_back(std::move(j));
            continue;
        }
        if (&spec != &input.shapes.front()) std::cout << '\n';
        std::cout << ratbez::printable(spec.name) << " (" << spec.type << ")\n" << ratbez::occt::format_report(report);
        if (!report.passed) std::cout << "FAILED\n";
    }
    if (args.flag("--json")) print_json(reports, input.model_file);
    return passed ? 0 : 1;
}

// ---- info ------------------------------------------------------------------------------------------

struct Facts {
    std::size_t faces = 0, edges = 0, degenerate_edges = 0, vertices = 0, shells = 0;
    int euler = 0;
    double area = 0, volume = 0;
    ratbez::Box box;
};

Facts facts_of(const ratbez::Solid& solid) {
    Facts facts;
    const auto edges = solid.edges();
    facts.degenerate_edges =
        static_cast<std::size_t>(std::count_if(edges.begin(), edges.end(), [](const auto& e) { return e->degenerate; }));
    facts.edges = edges.size() - facts.degenerate_edges;
    facts.faces = solid.faces().size();
    facts.vertices = solid.vertices().size();
    facts.shells = solid.shells().size();
    facts.euler = solid.euler_characteristic();
    const ratbez::SolidMeasures measured = ratbez::measure(solid);
    facts.area = measured.area;
    facts.volume = measured.volume;
    facts.box = solid.bounding_box();
    return facts;
}

int command_info(const std::vector<std::string>& raw) {
    const Arguments args = parse_arguments("info", raw, {}, {"--json", "--strict"});
    const ratbez::cli::Input input = load_for(single_input(args, "info"), args.flag("--strict"));
    std::vector<nlohmann::json> reports;
    for (const ShapeSpec& spec : input.shapes) {
        const Facts f = facts_of(spec.solid);
        if (args.flag("--json")) {
            nlohmann::json j;
            j["name"] = spec.name;
            j["type"] = spec.type;
            j["faces"] = f.faces;
            j["edges"] = f.edges;
            j["degenerate_edges"] = f.degenerate_edges;
            j["vertices"] = f.vertices;
            j["shells"] = f.shells;
            j["euler_characteristic"] = f.euler;
            j["area"] = f.area;
            j["volume"] = f.volume;
            j["bounding_box"] = {{"min", {f.box.min.x, f.box.min.y, f.box.min.z}}, {"max", {f.box.max.x, f.box.max.y, f.box.max.z}}};
            reports.push_back(std::move(j));
            continue;
        }
        const auto point = [](const ratbez::Vec3& p) {
            return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
        };
        if (&spec != &input.shapes.front()) std::cout << '\n';
        std::cout << "name:                 " << ratbez::printable(spec.name) << '\n'
                  << "type:                 " << spec.type << '\n'
                  << "faces:                " << f.faces << '\n'
                  << "edges:                " << f.edges << " (+" << f.degenerate_edges << " degenerate)\n"
                  << "vertices:             " << f.vertices << '\n'
                  << "shells:               " << f.shells << (f.shells > 1 ? " (the outer one and voids)" : "") << '\n'
                  << "euler characteristic: " << f.euler << '\n'
                  << "area:                 " << format_number(f.area, 15) << '\n'
                  << "volume:               " << format_number(f.volume, 15) << '\n'
                  << "bounding box:         " << point(f.box.min) << " .. " << point(f.box.max) << '\n';
    }
    if (args.flag("--json")) print_json(reports, input.model_file);
    return 0;
}

// ---- demo ------------------------------------------------------------------------------------------

struct ProcessResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs a program found on PATH without a shell (no quoting pitfalls), collecting everything it prints.
ProcessResult run_process(const std::vector<std::string>& argv) {
    ProcessResult result;
    int pipe_ends[2];
    if (pipe(pipe_ends) != 0) throw std::runtime_error(std::string("pipe failed: ") + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
    posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::vector<char*> c_argv;
    for (const auto& a : argv) c_argv.push_back(const_cast<char*>(a.c_str()));
    c_argv.push_back(nullptr);
    pid_t pid = 0;
    const int spawn_error = posix_spawnp(&pid, c_argv[0], &actions, nullptr, c_argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipe_ends[1]);
    if (spawn_error != 0) {
        close(pipe_ends[0]);
        result.exit_code = 127;
        result.output = argv[0] + ": " + std::strerror(spawn_error);
        return result;
    }
    char buffer[4096];
    for (;;) {
        const ssize_t n = read(pipe_ends[0], buffer, sizeof buffer);
        if (n > 0) {
            result.output.append(buffer, static_cast<std::size_t>(n));
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            break;
        }
    }
    close(pipe_ends[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    return result;
}

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream dirs(path);
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
    return false;
}

// The first line of OpenSCAD's output that reports a problem. OpenSCAD exits 0 even when CGAL drops
// the mesh ("ERROR: The given mesh is not closed!"), so the output is what tells.
std::optional<std::string> openscad_problem(const std::string& output) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
        if (line.find("WARNING:") != std::string::npos || line.find("ERROR:") != std::string::npos) return line;
    return std::nullopt;
}

struct DemoRow {
    std::string shape;
    double tolerance = 0;
    std::size_t triangles = 0;
    double deviation = 0;
    double volume_exact = 0, volume_mesh = 0;
    std::string cgal = "-", occt = "-", openscad = "-";
    std::vector<std::string> failures;
};

DemoRow demo_one(const fs::path& spec_path, const fs::path& out_dir, bool render) {
    DemoRow row;
    row.shape = spec_path.stem().string();
    try {
        const ShapeSpec spec = ratbez::spec::load_spec(spec_path.string());
        row.shape = spec.name;
        row.tolerance = spec.tolerance ? *spec.tolerance : ratbez::default_tolerance(spec.solid);
        ratbez::TessellationOptions options;
        options.tolerance = row.tolerance;
        options.angle_deg = spec.tessellation_angle;
        const ratbez::Mesh mesh = ratbez::exporter::tessellate_for_export(spec.solid, options);
        row.triangles = mesh.triangles.size();
        row.volume_exact = spec.solid.volume();
        row.volume_mesh = mesh.volume();

        const auto mesh_report = ratbez::exporter::check_mesh(mesh, ratbez::exporter::tessellation_checks(spec.solid, mesh, row.tolerance));
        row.cgal = mesh_report.ok() ? "ok" : "FAIL";
        for (const auto& p : mesh_report.problems) row.failures.push_back("CGAL: " + p);

        row.deviation = ratbez::max_deviation(spec.solid, mesh);
        if (!(row.deviation <= row.tolerance))
            row.failures.push_back("deviation " + format_number(row.deviation, 4) + " exceeds the tolerance " +
                                   format_number(row.tolerance, 4));

        const fs::path scad = out_dir / (spec.name + ".scad");
        ratbez::exporter::ExportOptions scad_options;
        scad_options.openscad.module_name = ratbez::exporter::openscad_identifier(spec.name);  // examples' names are safe
        scad_options.source = "spec " + spec_path.string();
        scad_options.checks = ratbez::exporter::tessellation_checks(spec.solid, mesh, row.tolerance);
        ratbez::exporter::export_tessellation(spec.solid, mesh, row.tolerance, scad.string(), scad_options);
        ratbez::occt::write_step(spec.solid, (out_dir / (spec.name + ".step")).string());

        const auto occt_report = ratbez::occt::check(spec.solid);
        row.occt = occt_report.passed ? "ok" : "FAIL";
        for (const auto& f : occt_report.failures) row.failures.push_back("OCCT: " + f);

        if (render) {
            // Inside a boolean operation OpenSCAD converts the polyhedron to a CGAL Nef polyhedron and
            // complains about any open or non-manifold mesh; a bare polyhedron would not be checked.
            const auto box = spec.solid.bounding_box();
            const double far = box.diagonal();
            const fs::path wrapper = out_dir / (spec.name + "_check.scad");
            ratbez::output::write_file(wrapper.string(), [&](std::ostream& out) {
                out << "// Renders " << spec.name << ".scad through CGAL (a boolean operation checks the mesh).\n"
                    << "use <" << spec.name << ".scad>\ndifference() {\n  " << scad_options.openscad.module_name
                    << "();\n  translate(["
                    << format_number(box.max.x + far, 17) << ", " << format_number(box.max.y + far, 17) << ", "
                    << format_number(box.max.z + far, 17) << "]) cube(" << format_number(far * 1e-3, 17) << ");\n}\n";
            });
            const fs::path png = out_dir / (spec.name + ".png");
            std::error_code ignored;
            fs::remove(png, ignored);
            std::vector<std::string> command = {"timeout", "600"};
            const char* display = std::getenv("DISPLAY");
            if (!display || !*display) command.insert(command.end(), {"xvfb-run", "-a", "-s", "-screen 0 1024x768x24"});
            command.insert(command.end(), {"openscad", "--render", "--autocenter", "--viewall", "--imgsize=640,480",
                                           "-o", png.string(), wrapper.string()});
            const ProcessResult result = run_process(command);
            if (result.exit_code != 0) {
                row.openscad = "FAIL";
                row.failures.push_back("openscad exited with " + std::to_string(result.exit_code) + ": " +
                                       one_line(result.output.substr(0, 300)));
            } else if (const auto problem = openscad_problem(result.output)) {
                row.openscad = "FAIL";
                row.failures.push_back("openscad: " + *problem);
            } else if (!fs::exists(png) || fs::file_size(png) == 0) {
                row.openscad = "FAIL";
                row.failures.push_back("openscad wrote no " + png.string());
            } else {
                row.openscad = "ok";
            }
        } else {
            row.openscad = "skipped";
        }
    } catch (const std::exception& e) {
        row.failures.push_back(one_line(e.what()));
    }
    return row;
}

int command_demo(const std::vector<std::string>& raw) {
    const Arguments args = parse_arguments("demo", raw, {"--examples"}, {"--no-render"});
    if (args.positional.size() > 1) throw UsageError(args.positional[1], "unexpected argument for 'demo'");
    const fs::path out_dir = args.positional.empty() ? fs::path("ratbez-demo") : fs::path(args.positional.front());
    fs::path examples = ratbez::build_paths::examples_dir;
    if (auto e = args.value("--examples")) examples = *e;
    std::error_code error;
    if (!fs::is_directory(examples, error)) throw UsageError("--examples", "'" + examples.string() + "' is not a directory");
    std::vector<fs::path> specs;
    for (const auto& entry : fs::directory_iterator(examples, error))
        if (entry.is_regular_file() && entry.path().extension() == ".json") specs.push_back(entry.path());
    std::sort(specs.begin(), specs.end());
    if (specs.empty()) throw UsageError("--examples", "no *.json specs in '" + examples.string() + "'");
    fs::create_directories(out_dir, error);
    if (error || !fs::is_directory(out_dir)) throw UsageError("DIR", "cannot create '" + out_dir.string() + "'");

    const bool render = !args.flag("--no-render");
    if (render && !on_path("openscad")) throw UsageError("--no-render", "openscad is not on PATH; install it or pass --no-render");

    std::vector<DemoRow> rows;
    std::map<std::string, std::string> file_of_name;  // a spec's name names its files: two alike would overwrite
    for (const auto& spec : specs) {
        std::cerr << "building " << spec.filename().string() << " ...\n";
        rows.push_back(demo_one(spec, out_dir, render));
        const auto [first, fresh] = file_of_name.emplace(rows.back().shape, spec.filename().string());
        if (!fresh)
            rows.back().failures.push_back("the name '" + rows.back().shape + "' is also the name of " + first->second +
                                           ": its files were overwritten");
    }

    const char* header_format = "%-22s %10s %9s %11s %14s %14s %5s %5s %8s\n";
    std::printf(header_format, "shape", "tolerance", "triangles", "max dev", "volume exact", "volume mesh", "CGAL",
                "OCCT", "openscad");
    bool all_ok = true;
    for (const auto& r : rows) {
        std::printf("%-22s %10.3g %9zu %11.3e %14.8g %14.8g %5s %5s %8s\n", r.shape.c_str(), r.tolerance, r.triangles,
                    r.deviation, r.volume_exact, r.volume_mesh, r.cgal.c_str(), r.occt.c_str(), r.openscad.c_str());
        all_ok = all_ok && r.failures.empty();
    }
    for (const auto& r : rows)
        for (const auto& f : r.failures) std::printf("FAIL %s: %s\n", r.shape.c_str(), f.c_str());
    std::printf("%zu shapes, %s; files in %s\n", rows.size(), all_ok ? "all passed" : "SOME FAILED",
                out_dir.string().c_str());
    return all_ok ? 0 : 1;
}

int run(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty()) {
        std::cerr << "usage error: command: missing (export, check, info or demo; see ratbez --help)\n";
        return 2;
    }
    const std::string command = args.front();
    args.erase(args.begin());
    if (command == "--help" || command == "-h" || command == "help") {
        std::cout << usage_text;
        return 0;
    }
    // `ratbez export --help` (or -h anywhere among a command's arguments): the usage, not an unknown option.
    const bool known = command == "export" || command == "check" || command == "info" || command == "demo";
    if (known && std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; })) {
        std::cout << usage_text;
        return 0;
    }
    if (command == "--version" || command == "version") {
        if (!args.empty()) throw UsageError(args.front(), "unexpected argument for '" + command + "'");
        std::cout << "ratbez " RATBEZ_VERSION "\n";
        return 0;
    }
    if (command == "export") return command_export(args);
    if (command == "check") return command_check(args);
    if (command == "info") return command_info(args);
    if (command == "demo") return command_demo(args);
    throw UsageError("command", "unknown command '" + command + "' (expected export, check, info or demo)");
}

}  // namespace

int main(int argc, char** argv) {
    ratbez::output::remove_temporaries_on_signals();  // Ctrl-C or kill leave no half-written temporary behind
    try {
        return run(argc, argv);
    } catch (const ratbez::spec::SpecError& e) {
        std::cerr << "spec error: " << one_line(e.what()) << '\n';
        return 2;
    } catch (const UsageError& e) {
        std::cerr << "usage error: " << one_line(e.what()) << '\n';
        return 2;
    } catch (const ratbez::Error& e) {
        std::cerr << "error: " << one_line(e.what()) << '\n';
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "error: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "internal error: " << one_line(e.what()) << '\n';
        return 1;
    } catch (...) {
        std::cerr << "internal error: unknown exception\n";
        return 1;
    }
}
