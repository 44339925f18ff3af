// Bindings of the file writers and checks: OpenSCAD / STL export with CGAL mesh checks (openscad_export)
// and STEP / BREP output and the OpenCASCADE cross-check (kernel/occt). Each half is compiled only when
// its library is part of the build; the ratbez/occt and ratbez/export headers include neither OCCT nor
// CGAL, so both halves can share this translation unit.

#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <string>

#include "convert.hpp"
#include "python_progress.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/error.hpp"
#include "ratbez/mesh.hpp"
#include "ratbez/output_file.hpp"
#include "ratbez/tessellate.hpp"

#if RATBEZ_PYTHON_WITH_EXPORT
#include "ratbez/export/export.hpp"
#include "ratbez/export/mesh_checks.hpp"
#endif
#if RATBEZ_PYTHON_WITH_OCCT
#include "ratbez/occt/check.hpp"
#include "ratbez/occt/files.hpp"
#endif

namespace ratbez::python {

namespace {

[[maybe_unused]] bool has_extension(const std::string& path, const std::string& extension) {
    if (path.size() < extension.size()) return false;
    for (std::size_t i = 0; i < extension.size(); ++i) {
        const char c = path[path.size() - extension.size() + i];
        if (static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c) != extension[i]) return false;
    }
    return true;
}

// Writes a Solid tessellated at `tolerance` (default: default_tolerance(solid)) through
// export_tessellation (rounded coordinates checked as written, the .scad header with the measured
// deviation), or a Mesh as it is; `options` carry the format's own settings.
// The tessellation of a Solid counts as this share of the export's progress.
[[maybe_unused]] constexpr double kTessellationShare = 0.3;

[[maybe_unused]] void export_shape(const py::object& shape, const std::string& file, const py::object& tolerance,
                                   const py::object& max_triangles, const py::object& progress,
                                   exporter::ExportOptions options) {
    options.source = "Python";
    const Progress poll = python_progress(progress);
    if (py::isinstance<Solid>(shape)) {
        const auto& solid = shape.cast<const Solid&>();
        const std::optional<double> requested =
            tolerance.is_none() ? std::nullopt : std::optional<double>(to_double(tolerance, "tolerance"));
        TessellationOptions tessellation;
        if (!max_triangles.is_none()) {
            const int budget = to_int(max_triangles, "max_triangles");
            if (budget <= 0) throw Error("max_triangles", "must be a positive whole number");
            tessellation.max_triangles = static_cast<std::size_t>(budget);
        }
        py::gil_scoped_release release;
        tessellation.tolerance = requested ? *requested : default_tolerance(solid);
        tessellation.progress = progress_part(poll, 0, kTessellationShare);
        const double used = tessellation.tolerance;
        // Refused from the plan when the mesh would exceed what the checks (or the memory) take (issue 29).
        const Mesh mesh = exporter::tessellate_for_export(solid, tessellation);
        options.checks = exporter::tessellation_checks(solid, mesh, used);
        options.progress = progress_part(poll, kTessellationShare, 1);
        exporter::export_tessellation(solid, mesh, used, file, options);
        return;
    }
    if (py::isinstance<Mesh>(shape)) {
        const Mesh mesh = shape.cast<Mesh>();
        py::gil_scoped_release release;
        options.progress = poll;
        exporter::export_mesh(mesh, file, options);
        return;
    }
    throw Error("solid_or_mesh", "expected a ratbez.Solid or a ratbez.Mesh");
}

// The module name: `module` when given (an OpenSCAD identifier that shadows no built-in), else the file's
// stem made one (a built-in stem gets exporter::builtin_suffix).
[[maybe_unused]] std::string module_for(const py::object& module, const std::string& file) {
    if (module.is_none()) return exporter::openscad_identifier(std::filesystem::path(file).stem().string());
    if (!py::isinstance<py::str>(module)) throw Error("module", "must be a str or None");
    const std::string name = module.cast<std::string>();
    exporter::require_module_name(name, "module");
    return name;
}

#if RATBEZ_PYTHON_WITH_OCCT
const char* const read_doc =
    "Surfaces convert exactly: planes, B-spline and Bezier surfaces, and cylinders, cones, spheres, tori,\n"
    "revolutions and extrusions through their exact rational forms, trimmed by any loops (holes, seams,\n"
    "poles); edges and vertices stay shared, voids stay voids. Rounding in the file (a full turn one ulp\n"
    "over 2 pi, knots that dip) is snapped, loops off their surface are accepted within the file's own\n"
    "tolerance (Face.tolerance). Raises ratbez.Error naming path for a missing or unreadable file, a file of\n"
    "another format, a file with no solid, and a face that does not convert (\"face 7: a\n"
    "Geom_OffsetSurface face has no exact NURBS form ...\"). Faces no solid holds (open shells, loose faces)\n"
    "bound no volume: they are left out with a ratbez.ReadWarning that says how many.\n";

// ratbez.ReadWarning: a reader left part of the file out (faces no solid holds), set by bind_io.
PyObject* read_warning = nullptr;

// A file reader called with the GIL released: the path and the progress callback checked first. What the file
// holds outside its solids (open shells, loose faces) is left out, and said: a ratbez.ReadWarning, which
// `warnings.simplefilter("error", ratbez.ReadWarning)` turns into an exception.
template <class Read>
auto read_released(const py::object& path, const py::object& progress, Read read) {
    const std::string file = to_path(path, "path");
    const Progress polled = python_progress(progress);
    std::string left_out;
    auto result = [&] {
        py::gil_scoped_release release;
        return read(file, polled, &left_out);
    }();
    if (!left_out.empty() && PyErr_WarnEx(read_warning, ("'" + file + "': " + left_out).c_str(), 1) != 0)
        throw py::error_already_set();
    return result;
}
#endif

#if RATBEZ_PYTHON_WITH_EXPORT
// `color=`: None, or "#rrggbb" / "#rrggbbaa" for one solid; for a dict of solids a dict of such strings by name.
std::optional<exporter::Color> color_for(const py::object& color, const std::string& argument) {
    if (color.is_none()) return std::nullopt;
    if (!py::isinstance<py::str>(color)) throw Error(argument, "must be a str \"#rrggbb\" or \"#rrggbbaa\", or None");
    return exporter::parse_color(color.cast<std::string>(), argument);
}

// export_openscad of a dict {name: Solid}: one module per name (each must be a safe module name), one module
// after the file (or `module`) placing them all; write_3mf of a dict (module_names false): one object per
// name (any non-empty text).
void export_library(const py::dict& solids, const std::string& file, const py::object& tolerance, const py::object& color,
                    exporter::ExportOptions options, bool module_names = true) {
    if (solids.empty()) throw Error("solids", "is empty");
    if (module_names && solids.contains(py::str(options.openscad.module_name)))
        throw Error("module", "'" + options.openscad.module_name +
                                  "' is also the name of a solid: the module placing them all needs its own (module= "
                                  "names it; by default the file's stem)");
    if (!color.is_none() && !py::isinstance<py::dict>(color))
        throw Error("color", "for a dict of solids must be a dict {name: \"#rrggbb\"}");
    const py::dict colors = color.is_none() ? py::dict() : color.cast<py::dict>();
    for (const auto& [key, value] : colors)
        if (!solids.contains(key)) throw Error("color", "names '" + py::str(key).cast<std::string>() + "', which is not one of the solids");
    std::vector<Mesh> meshes;
    std::vector<exporter::LibraryPart> parts;
    meshes.reserve(solids.size());
    for (const auto& [key, value] : solids) {
        if (!py::isinstance<py::str>(key)) throw Error("solids", "keys must be module names (str)");
        const std::string name = key.cast<std::string>();
        if (module_names)
            exporter::require_module_name(name, "solids['" + exporter::comment_text(name) + "']");
        else if (name.empty())
            throw Error("solids", "a name is empty");
        if (!py::isinstance<Solid>(value)) throw Error("solids['" + name + "']", "expected a ratbez.Solid");
        exporter::LibraryPart part;
        part.module_name = name;
        part.solid = &value.cast<const Solid&>();
        part.tolerance = tolerance.is_none() ? default_tolerance(*part.solid) : to_double(tolerance, "tolerance");
        part.color = color_for(colors.contains(key) ? py::object(colors[key]) : py::object(py::none()), "color['" + name + "']");
        parts.push_back(std::move(part));
    }
    options.source = "Python";
    // As export_shape: the tessellations take the first kTessellationShare of the progress (each part its
    // share, so Ctrl-C lands inside a long one), the checks and the writing the rest.
    const Progress poll = options.progress;
    const double share = kTessellationShare / static_cast<double>(parts.size());
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        exporter::LibraryPart& part = parts[i];
        TessellationOptions tessellation;
        tessellation.tolerance = part.tolerance;
        tessellation.progress = progress_part(poll, share * static_cast<double>(i), share * static_cast<double>(i + 1));
        try {
            meshes.push_back(exporter::tessellate_for_export(*part.solid, tessellation));
            part.mesh = &meshes.back();
            part.checks = exporter::tessellation_checks(*part.solid, *part.mesh, part.tolerance);
        } catch (const TooFine&) {
            throw;  // about the tolerance asked
        } catch (const Error& e) {
            // Which solid of the dict: the FreeCAD workbench passes each object's Label as its name.
            throw e.renamed("solid", "solids['" + exporter::comment_text(part.module_name) + "']");
        }
    }
    options.progress = progress_part(poll, kTessellationShare, 1);
    exporter::export_library(parts, file, options);
}
#endif

[[maybe_unused]] const Solid& solid_of(const py::object& shape) {
    if (!py::isinstance<Solid>(shape)) throw Error("solid", "expected a ratbez.Solid");
    return shape.cast<const Solid&>();
}

// A Solid, or a list or tuple of them (what read_step_all returns), for the writers of several solids.
[[maybe_unused]] std::vector<Solid> solids_of(const py::object& shapes) {
    std::vector<Solid> solids;
    if (py::isinstance<Solid>(shapes)) {
        solids.push_back(shapes.cast<const Solid&>());
        return solids;
    }
    if (!py::isinstance<py::list>(shapes) && !py::isinstance<py::tuple>(shapes))
        throw Error("solid", "expected a ratbez.Solid or a list of them");
    for (const py::handle item : shapes) {
        if (!py::isinstance<Solid>(item))
            throw Error("solid[" + std::to_string(solids.size()) + "]", "expected a ratbez.Solid");
        solids.push_back(item.cast<const Solid&>());
    }
    if (solids.empty()) throw Error("solid", "is an empty list");
    return solids;
}

#if RATBEZ_PYTHON_WITH_EXPORT
// A list or tuple of solids (read_step_all's) as a dict by their names, for the writers whose objects are named
// by any text (3MF, STL, OFF): an unnamed solid is "solid", a repeated name gets _2, _3, ...
py::dict solids_by_name(const py::object& list) {
    py::dict named;
    for (const Solid& solid : solids_of(list)) {
        const std::string base = solid.name().empty() ? "solid" : solid.name();
        std::string name = base;
        for (int k = 2; named.contains(py::str(name)); ++k) name = base + "_" + std::to_string(k);
        named[py::str(name)] = py::cast(solid);
    }
    return named;
}

// The solids of a writer's first argument when it holds several (a dict {name: Solid} or a list of them), else
// nothing: one Solid or Mesh is written as export_shape writes it.
std::optional<py::dict> several_solids(const py::object& given, const py::object& max_triangles) {
    const bool list = py::isinstance<py::list>(given) || py::isinstance<py::tuple>(given);
    if (!list && !py::isinstance<py::dict>(given)) return std::nullopt;
    if (!max_triangles.is_none()) throw Error("max_triangles", "applies to one solid, not several");
    return list ? solids_by_name(given) : given.cast<py::dict>();
}
#endif

}  // namespace

void bind_io(py::module_& m) {
#if RATBEZ_PYTHON_WITH_OCCT
    read_warning = PyErr_NewExceptionWithDoc(
        "ratbez.ReadWarning",
        "A reader left part of a file out: faces no solid holds (open shells, loose faces) bound no volume.",
        PyExc_UserWarning, nullptr);
    if (read_warning == nullptr) throw py::error_already_set();
    m.attr("ReadWarning") = py::reinterpret_borrow<py::object>(read_warning);
#endif
    m.def(
        "write_text_file",
        [](const py::object& path, const std::string& text) {
            const std::string file = to_path(path, "path");
            py::gil_scoped_release release;
            output::write_file(file, [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
        },
        py::arg("path"), py::arg("text"),
        "Write `text` (UTF-8) to `path` the way every ratbez writer does: a new temporary file beside it,\n"
        "renamed over it (atomic); a read-only file, a symbolic link or a folder at `path` is refused.");
#if RATBEZ_PYTHON_WITH_EXPORT
    m.attr("has_cgal") = true;
    m.def(
        "export_openscad",
        [](const py::object& solid_or_mesh, const py::object& path, const py::object& tolerance,
           const py::object& module, const py::object& max_triangles, bool import_stl, const py::object& progress,
           const py::object& color) {
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".scad")) throw Error("path", "an OpenSCAD file name must end in .scad");
            exporter::ExportOptions options;
            options.openscad.module_name = module_for(module, file);
            options.import_stl = import_stl;
            if (py::isinstance<py::list>(solid_or_mesh) || py::isinstance<py::tuple>(solid_or_mesh)) {
                // Solids (read_step_all's): a module each, named after solid.name made an identifier, as the CLI's.
                const std::vector<Solid> solids = solids_of(solid_or_mesh);
                std::vector<std::string> names;
                for (const Solid& solid : solids) names.push_back(solid.name());
                const std::vector<std::string> modules =
                    exporter::library_module_names(names, options.openscad.module_name);
                py::dict named;
                for (std::size_t i = 0; i < solids.size(); ++i) named[py::str(modules[i])] = py::cast(solids[i]);
                if (!color.is_none()) throw Error("color", "for a list of solids is not taken: pass a dict {name: Solid}");
                if (!max_triangles.is_none()) throw Error("max_triangles", "applies to one solid, not a list of solids");
                options.progress = python_progress(progress);
                return export_library(named, file, tolerance, color, options);
            }
            if (py::isinstance<py::dict>(solid_or_mesh)) {
                if (!max_triangles.is_none()) throw Error("max_triangles", "applies to one solid, not a dict of solids");
                options.progress = python_progress(progress);
                return export_library(solid_or_mesh.cast<py::dict>(), file, tolerance, color, options);
            }
            options.openscad.color = color_for(color, "color");
            export_shape(solid_or_mesh, file, tolerance, max_triangles, progress, options);
        },
        py::arg("solid_or_mesh"), py::arg("path"), py::arg("tolerance") = py::none(), py::arg("module") = py::none(),
        py::arg("max_triangles") = py::none(), py::arg("import_stl") = false, py::arg("progress") = py::none(),
        py::arg("color") = py::none(),
        (std::string(
            "Write an OpenSCAD library file, `module NAME() { polyhedron(...); }` then `NAME();` (NAME: module, else\n"
            "the file's stem made an identifier), after the CGAL mesh checks. A Solid is tessellated at tolerance\n"
            "first and written with the fewest decimals that keep the written mesh within tolerance; the header\n"
            "states the tolerance, the measured deviation, counts, bounding box and volumes.\n"
            "import_stl=True: the mesh goes to a binary STL beside the file (same name, .stl; float32 coordinates,\n"
            "checked as written) and the module is `import(\"NAME.stl\")`, which OpenSCAD loads several times\n"
            "faster for large meshes.\n"
            "A dict {name: Solid} writes one module per name (each a safe module name) and the module NAME placing\n"
            "them all; the header lists each module with its triangles, deviation and volumes. A list of solids\n"
            "(read_step_all's) does the same, each module named after solid.name made an identifier (repeats _2, ...).\n"
            "color: \"#rrggbb\" or \"#rrggbbaa\" (for a dict: a dict of them by name) wraps the module's body in\n"
            "color([r, g, b, a]).") +
         "\n\n" + progress_doc).c_str());
    m.def(
        "write_3mf",
        [](const py::object& solid, const py::object& path, const py::object& tolerance, const py::object& name,
           const py::object& color, const py::object& max_triangles, const py::object& progress) {
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".3mf")) throw Error("path", "a 3MF file name must end in .3mf");
            exporter::ExportOptions options;
            if (const std::optional<py::dict> several = several_solids(solid, max_triangles)) {
                if (!name.is_none()) throw Error("name", "applies to one solid; several are named by their keys or names");
                options.progress = python_progress(progress);
                return export_library(*several, file, tolerance, color, options, false);
            }
            if (!py::isinstance<Solid>(solid)) throw Error("solid", "expected a ratbez.Solid, a dict {name: Solid} or a list of solids");
            if (!name.is_none() && !py::isinstance<py::str>(name)) throw Error("name", "must be a str or None");
            options.openscad.module_name = name.is_none() ? std::filesystem::path(file).stem().string() : name.cast<std::string>();
            if (options.openscad.module_name.empty()) throw Error("name", "is empty");
            options.openscad.color = color_for(color, "color");
            export_shape(solid, file, tolerance, max_triangles, progress, options);
        },
        py::arg("solid"), py::arg("path"), py::arg("tolerance") = py::none(), py::arg("name") = py::none(),
        py::arg("color") = py::none(), py::arg("max_triangles") = py::none(), py::arg("progress") = py::none(),
        (std::string(
            "Write a 3MF file (lib3mf; OpenSCAD's import() and slicers read it) after the CGAL mesh checks: a Solid\n"
            "is tessellated at tolerance (default: as export_openscad) and becomes one object named `name` (default:\n"
            "the file's stem); a dict {name: Solid} gives one object per name, in order, and a list of solids\n"
            "(read_step_all's) one per solid, named after solid.name (repeats _2, ...). lib3mf writes each\n"
            "coordinate as its float32 cut to 6 decimals: the deviation and the checks run on the package read back,\n"
            "and a mesh those coordinates move beyond the tolerance (a part far from the origin, or smaller than a\n"
            "few thousandths at a fine tolerance) is refused with ratbez.Error naming mesh.\n"
            "color: \"#rrggbb\" or \"#rrggbbaa\" (for a dict: a dict of them by name) gives the object a base\n"
            "material of that display colour. The model's metadata: Application \"ratbez VERSION\", Title and a\n"
            "Description with each object's tolerance, measured deviation, counts and volumes.") +
         "\n\n" + progress_doc).c_str());
    m.def(
        "write_stl",
        [](const py::object& solid_or_mesh, const py::object& path, const py::object& tolerance, bool binary,
           const py::object& max_triangles, const py::object& progress) {
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".stl")) throw Error("path", "an STL file name must end in .stl");
            exporter::ExportOptions options;
            options.binary_stl = binary;
            options.openscad.module_name = exporter::openscad_identifier(std::filesystem::path(file).stem().string());
            if (const std::optional<py::dict> several = several_solids(solid_or_mesh, max_triangles)) {
                options.progress = python_progress(progress);
                return export_library(*several, file, tolerance, py::none(), options, false);
            }
            export_shape(solid_or_mesh, file, tolerance, max_triangles, progress, options);
        },
        py::arg("solid_or_mesh"), py::arg("path"), py::arg("tolerance") = py::none(), py::arg("binary") = true,
        py::arg("max_triangles") = py::none(), py::arg("progress") = py::none(),
        (std::string(
            "Write an STL after the CGAL mesh checks (a Solid is tessellated at tolerance first): binary (float32),\n"
            "or ASCII text (binary=False) with the fewest decimals that keep the written mesh within tolerance.\n"
            "Several solids (a dict {name: Solid} or a list, as read_step_all returns) become one mesh of them all,\n"
            "each checked on its own.") +
         "\n\n" + progress_doc).c_str());
    m.def(
        "write_off",
        [](const py::object& solid_or_mesh, const py::object& path, const py::object& tolerance,
           const py::object& max_triangles, const py::object& progress) {
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".off")) throw Error("path", "an OFF file name must end in .off");
            exporter::ExportOptions options;
            if (const std::optional<py::dict> several = several_solids(solid_or_mesh, max_triangles)) {
                options.progress = python_progress(progress);
                return export_library(*several, file, tolerance, py::none(), options, false);
            }
            export_shape(solid_or_mesh, file, tolerance, max_triangles, progress, options);
        },
        py::arg("solid_or_mesh"), py::arg("path"), py::arg("tolerance") = py::none(), py::arg("max_triangles") = py::none(),
        py::arg("progress") = py::none(),
        (std::string(
            "Write an OFF file after the CGAL mesh checks (a Solid is tessellated at tolerance first, written with\n"
            "the fewest decimals that keep the written mesh within tolerance). Several solids (a dict {name: Solid}\n"
            "or a list) become one mesh of them all, each checked on its own.") +
         "\n\n" + progress_doc).c_str());
    m.def(
        "check_mesh",
        [](const Mesh& mesh, bool check_self_intersections, const py::object& progress) {
            exporter::MeshCheckOptions options;
            options.check_self_intersections = check_self_intersections;
            options.progress = python_progress(progress);
            exporter::MeshReport report;
            {
                py::gil_scoped_release release;
                report = exporter::check_mesh(mesh, options);
            }
            py::dict result;
            result["ok"] = report.ok();
            result["closed"] = report.closed;
            result["manifold"] = report.manifold;
            result["outward"] = report.outward;
            result["self_intersection_free"] = report.self_intersection_free;
            result["volume"] = report.volume;
            result["problems"] = report.problems;
            return result;
        },
        py::arg("mesh"), py::arg("check_self_intersections") = true, py::arg("progress") = py::none(),
        (std::string("The CGAL checks every exported mesh passes: closed, manifold, outward, no self-intersections.\n\n") +
         progress_doc).c_str());
#else
    m.attr("has_cgal") = false;
#endif

#if RATBEZ_PYTHON_WITH_OCCT
    m.attr("has_occt") = true;
    m.def(
        "write_step",
        [](const py::object& solid, const py::object& path, bool bezier_faces, bool analytic_primitives) {
            const std::vector<Solid> solids = solids_of(solid);
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".step") && !has_extension(file, ".stp"))
                throw Error("path", "a STEP file name must end in .step or .stp");
            py::gil_scoped_release release;
            occt::write_step(solids, file, occt::ConvertOptions{bezier_faces, analytic_primitives});
        },
        py::arg("solid"), py::arg("path"), py::arg("bezier_faces") = false, py::arg("analytic_primitives") = true,
        "Write the exact B-rep as an AP214 STEP file, its name ending in .step or .stp (bezier_faces,\n"
        "analytic_primitives: as brep_string). A list of solids (what read_step_all returns) writes one product\n"
        "each, named after solid.name, read back by read_step_all.");
    m.def(
        "write_brep",
        [](const py::object& solid, const py::object& path, bool bezier_faces, bool analytic_primitives) {
            const std::vector<Solid> solids = solids_of(solid);
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".brep") && !has_extension(file, ".brp"))
                throw Error("path", "an OpenCASCADE .brep file name must end in .brep or .brp");
            py::gil_scoped_release release;
            occt::write_brep(solids, file, occt::ConvertOptions{bezier_faces, analytic_primitives});
        },
        py::arg("solid"), py::arg("path"), py::arg("bezier_faces") = false, py::arg("analytic_primitives") = true,
        "Write OpenCASCADE's native .brep text to a file whose name ends in .brep or .brp (bezier_faces,\n"
        "analytic_primitives: as brep_string); a list of solids writes a compound of them, read back by\n"
        "read_brep_all.");
    m.def(
        "read_step",
        [](const py::object& path, const py::object& progress) { return read_released(path, progress, occt::read_step); },
        py::arg("path"), py::arg("progress") = py::none(),
        ("The one solid of a STEP file (AP203 / AP214, read in millimetres) as an exact Solid.\n" +
         std::string(read_doc) + progress_doc)
            .c_str());
    m.def(
        "read_brep",
        [](const py::object& path, const py::object& progress) { return read_released(path, progress, occt::read_brep); },
        py::arg("path"), py::arg("progress") = py::none(),
        ("The one solid of an OpenCASCADE .brep file as an exact Solid; read_brep of write_brep's output is the\n"
         "same solid (volume and points to 1e-12).\n" +
         std::string(read_doc) + progress_doc)
            .c_str());
    m.def(
        "read_step_all",
        [](const py::object& path, const py::object& progress) { return read_released(path, progress, occt::read_step_all); },
        py::arg("path"), py::arg("progress") = py::none(),
        ("Every solid of a STEP file, in file order, as a list of exact Solids: assemblies flattened with each\n"
         "instance's placement, each solid named after its product (Solid.name). A solid OpenCASCADE finds\n"
         "invalid or that does not convert is left out while others read, with a ratbez.ReadWarning naming it.\n" +
         std::string(read_doc) + progress_doc)
            .c_str());
    m.def(
        "read_brep_all",
        [](const py::object& path, const py::object& progress) { return read_released(path, progress, occt::read_brep_all); },
        py::arg("path"), py::arg("progress") = py::none(),
        ("Every solid of an OpenCASCADE .brep file, in the order its shape holds them; one that is invalid or\n"
         "does not convert is left out while others read, with a ratbez.ReadWarning naming it.\n" + std::string(read_doc) +
         progress_doc)
            .c_str());
    m.def(
        "brep_string",
        [](const py::object& solid, bool bezier_faces, bool analytic_primitives) {
            const Solid& s = solid_of(solid);
            std::string text;
            {
                py::gil_scoped_release release;
                text = occt::brep_string(s, occt::ConvertOptions{bezier_faces, analytic_primitives});
            }
            return text;
        },
        py::arg("solid"), py::arg("bezier_faces") = false, py::arg("analytic_primitives") = true,
        "The .brep text as a string (for FreeCAD's Part.Shape.importBrepFromString).\n"
        "bezier_faces=True: one face per rational Bezier patch of every face, refined (exactly: knot insertion,\n"
        "degree elevation) until OpenCASCADE's fixed Gauss rule -- FreeCAD's Shape.Volume, Area and\n"
        "CenterOfMass -- reads each face's area to 1e-9; no C0 knot is left, so FreeCAD's 'Run BOP check'\n"
        "passes. More faces and poles; the same exact geometry.\n"
        "analytic_primitives=True (the default): a cylinder, cone, sphere or torus (by solid.kind, or a lone sphere\n"
        "or torus face read from a file) goes over as OpenCASCADE's own primitive on its analytic surfaces, as\n"
        "Part's: FreeCAD's BOP check flags a B-spline sphere's poles at some placements, never an analytic one.\n"
        "An extrusion, revolution or sweep along a line or arc goes over as OpenCASCADE's prism or revolution of\n"
        "its profile (lines and arcs sweep planes, cylinders, cones, spheres, tori), as Part's Extrusion and\n"
        "Revolution, where OpenCASCADE's rule reads its volume and area to 1e-9: Part's Thickness works on them.\n"
        "False: the kernel's B-spline faces.");
    m.def(
        "occt_check",
        [](const py::object& solid, int grid, double deviation_limit, double volume_limit, bool bezier_faces,
           bool analytic_primitives, const py::object& progress) {
            const Solid& s = solid_of(solid);
            occt::CheckOptions options;
            options.progress = python_progress(progress);
            options.grid = grid;
            options.deviation_limit = deviation_limit;
            options.volume_limit = volume_limit;
            options.convert.bezier_faces = bezier_faces;
            options.convert.analytic_primitives = analytic_primitives;
            occt::CheckReport report;
            {
                py::gil_scoped_release release;
                report = occt::check(s, options);
            }
            py::dict result;
            occt::for_each_entry(report, [&](const char* name, const auto& value) { result[name] = value; });
            result["report"] = occt::format_report(report);
            return result;
        },
        py::arg("solid"), py::arg("grid") = 50, py::arg("deviation_limit") = 1e-9, py::arg("volume_limit") = 1e-6,
        py::arg("bezier_faces") = false, py::arg("analytic_primitives") = true, py::arg("progress") = py::none(),
        (std::string("Convert to an OpenCASCADE solid (bezier_faces, analytic_primitives: as brep_string; the check\n"
                     "runs on the solid as handed out) and compare: validity, evaluation\n"
                     "deviation, volume and area; for a cylinder, cone, sphere, torus or revolution also the distance to\n"
                     "OCCT's analytic surface of that kind (max_analytic_deviation) and, for the four primitives, the\n"
                     "closed-form volume (closed_form_volume); both None otherwise. Also OpenCASCADE's BOP argument analysis\n"
                     "as FreeCAD's 'Run BOP check' runs it: bop_clean, self_intersections, small_edges and bop_findings (one\n"
                     "line each, also in failures); passed only when everything, the BOP analysis included, is clean.\n\n") +
         progress_doc).c_str());
#else
    m.attr("has_occt") = false;
#endif
}

}  // namespace ratbez::python
