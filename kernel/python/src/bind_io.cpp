// Bindings of the file writers and checks: OpenSCAD / STL export with CGAL mesh checks (openscad_export)
// and STEP / BREP output and the OpenCASCADE cross-check (kernel/occt). Each half is compiled only when
// its library is part of the build; the ratbez/occt and ratbez/export headers include neither OCCT nor
// CGAL, so both halves can share this translation unit.

#include <pybind11/stl.h>

#include <string>

#include "convert.hpp"
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

// A Solid is tessellated at `tolerance` (default: default_tolerance(solid)); a Mesh is taken as it is.
[[maybe_unused]] Mesh mesh_of(const py::object& shape, const py::object& tolerance) {
    if (py::isinstance<Solid>(shape)) {
        const auto& solid = shape.cast<const Solid&>();
        const std::optional<double> requested =
            tolerance.is_none() ? std::nullopt : std::optional<double>(to_double(tolerance, "tolerance"));
        py::gil_scoped_release release;
        return tessellate(solid, requested ? *requested : default_tolerance(solid));
    }
    if (py::isinstance<Mesh>(shape)) return shape.cast<Mesh>();
    throw Error("solid_or_mesh", "expected a ratbez.Solid or a ratbez.Mesh");
}

[[maybe_unused]] const Solid& solid_of(const py::object& shape) {
    if (!py::isinstance<Solid>(shape)) throw Error("solid", "expected a ratbez.Solid");
    return shape.cast<const Solid&>();
}

}  // namespace

void bind_io(py::module_& m) {
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
        [](const py::object& solid_or_mesh, const py::object& path, const py::object& tolerance) {
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".scad")) throw Error("path", "an OpenSCAD file name must end in .scad");
            const Mesh mesh = mesh_of(solid_or_mesh, tolerance);
            py::gil_scoped_release release;
            exporter::export_mesh(mesh, file);
        },
        py::arg("solid_or_mesh"), py::arg("path"), py::arg("tolerance") = py::none(),
        "Write polyhedron(...) text after the CGAL mesh checks (a Solid is tessellated at tolerance first).");
    m.def(
        "write_stl",
        [](const py::object& solid_or_mesh, const py::object& path, const py::object& tolerance) {
            const std::string file = to_path(path, "path");
            if (!has_extension(file, ".stl")) throw Error("path", "an STL file name must end in .stl");
            const Mesh mesh = mesh_of(solid_or_mesh, tolerance);
            py::gil_scoped_release release;
            exporter::export_mesh(mesh, file);
        },
        py::arg("solid_or_mesh"), py::arg("path"), py::arg("tolerance") = py::none(),
        "Write a binary STL after the CGAL mesh checks (a Solid is tessellated at tolerance first).");
    m.def(
        "check_mesh",
        [](const Mesh& mesh, bool check_self_intersections) {
            exporter::MeshCheckOptions options;
            options.check_self_intersections = check_self_intersections;
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
        py::arg("mesh"), py::arg("check_self_intersections") = true,
        "The CGAL checks every exported mesh passes: closed, manifold, outward, no self-intersections.");
#else
    m.attr("has_cgal") = false;
#endif

#if RATBEZ_PYTHON_WITH_OCCT
    m.attr("has_occt") = true;
    m.def(
        "write_step",
        [](const py::object& solid, const py::object& path, bool bezier_faces) {
            const Solid& s = solid_of(solid);
            const std::string file = to_path(path, "path");
            py::gil_scoped_release release;
            occt::write_step(s, file, occt::ConvertOptions{bezier_faces});
        },
        py::arg("solid"), py::arg("path"), py::arg("bezier_faces") = false,
        "Write the exact B-spline B-rep as an AP214 STEP file (bezier_faces: as brep_string).");
    m.def(
        "write_brep",
        [](const py::object& solid, const py::object& path, bool bezier_faces) {
            const Solid& s = solid_of(solid);
            const std::string file = to_path(path, "path");
            py::gil_scoped_release release;
            occt::write_brep(s, file, occt::ConvertOptions{bezier_faces});
        },
        py::arg("solid"), py::arg("path"), py::arg("bezier_faces") = false,
        "Write OpenCASCADE's native .brep text (bezier_faces: as brep_string).");
    m.def(
        "brep_string",
        [](const py::object& solid, bool bezier_faces) {
            const Solid& s = solid_of(solid);
            std::string text;
            {
                py::gil_scoped_release release;
                text = occt::brep_string(s, occt::ConvertOptions{bezier_faces});
            }
            return text;
        },
        py::arg("solid"), py::arg("bezier_faces") = false,
        "The .brep text as a string (for FreeCAD's Part.Shape.importBrepFromString).\n"
        "bezier_faces=True: one face per rational Bezier patch of every face, refined (exactly: knot insertion,\n"
        "degree elevation) until OpenCASCADE's fixed Gauss rule -- FreeCAD's Shape.Volume, Area and\n"
        "CenterOfMass -- reads each face's area to 1e-9; no C0 knot is left, so FreeCAD's 'Run BOP check'\n"
        "passes. More faces and poles; the same exact geometry.");
    m.def(
        "occt_check",
        [](const py::object& solid, int grid, double deviation_limit, double volume_limit, bool bezier_faces) {
            const Solid& s = solid_of(solid);
            occt::CheckOptions options;
            options.grid = grid;
            options.deviation_limit = deviation_limit;
            options.volume_limit = volume_limit;
            options.convert.bezier_faces = bezier_faces;
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
        py::arg("bezier_faces") = false,
        "Convert to an OpenCASCADE solid (bezier_faces: as brep_string) and compare: validity, evaluation\n"
        "deviation, volume and area; for a cylinder, cone, sphere, torus or revolution also the distance to\n"
        "OCCT's analytic surface of that kind (max_analytic_deviation) and, for the four primitives, the\n"
        "closed-form volume (closed_form_volume); both None otherwise.");
#else
    m.attr("has_occt") = false;
#endif
}

}  // namespace ratbez::python
