// Bindings of tessellation: Solid.tessellate (closed meshes), Face.tessellate and the surfaces'
// tessellate (open meshes of one face), with max_triangles, a progress callback and Ctrl-C; and
// max_deviation, how far any mesh of a solid strays from it.

#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "convert.hpp"
#include "numpy_arrays.hpp"
#include "python_progress.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/deviation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/tessellate.hpp"

namespace ratbez::python {

namespace {

constexpr const char* arguments_doc =
    "tolerance: the largest distance from any mesh point to the exact surface (model units, > 0).\n"
    "angle_deg: optional, in (0, 180): the exact normals at the two ends of a mesh edge inside a curved face\n"
    "differ by at most this.\n"
    "max_triangles: a request that would need more raises ratbez.Error naming 'tolerance' with an estimate of\n"
    "the triangles it would need (default 20,000,000).\n";

TessellationOptions options_of(double tolerance, std::optional<double> angle_deg, const py::object& max_triangles,
                               const py::object& progress) {
    TessellationOptions options;
    options.tolerance = tolerance;
    options.angle_deg = angle_deg;
    if (!max_triangles.is_none()) {
        const int count = to_int(max_triangles, "max_triangles");
        require(count > 0, "max_triangles", "must be a positive integer (got " + std::to_string(count) + ")");
        options.max_triangles = static_cast<std::size_t>(count);
    }
    options.progress = python_progress(progress);
    return options;
}

// Tessellates `shape` with the GIL released; the options (holding Python references) are made and
// dropped with the GIL held.
template <class Shape>
Mesh tessellate_released(const Shape& shape, double tolerance, std::optional<double> angle_deg,
                         const py::object& max_triangles, const py::object& progress) {
    const TessellationOptions options = options_of(tolerance, angle_deg, max_triangles, progress);
    py::gil_scoped_release release;
    return tessellate(shape, options);
}

template <class T, class ShapeOf>
void def_tessellate(py::class_<T>& cls, ShapeOf shape_of, const std::string& what) {
    cls.def(
        "tessellate",
        [shape_of](const T& self, double tolerance, std::optional<double> angle_deg, const py::object& max_triangles,
                   const py::object& progress) {
            return tessellate_released(shape_of(self), tolerance, angle_deg, max_triangles, progress);
        },
        py::arg("tolerance"), py::arg("angle_deg") = py::none(), py::arg("max_triangles") = py::none(),
        py::arg("progress") = py::none(), (what + "\n\n" + arguments_doc + progress_doc).c_str());
}

}  // namespace

void bind_tessellation(py::module_& m) {
    m.def(
        "max_deviation",
        [](const Solid& solid, const Mesh& mesh, int samples_per_edge, const py::object& progress) {
            DeviationOptions options;
            options.samples_per_edge = samples_per_edge;
            options.progress = python_progress(progress);
            py::gil_scoped_release release;
            return max_deviation(solid, mesh, options);
        },
        py::arg("solid"), py::arg("mesh"), py::arg("samples_per_edge") = 6, py::arg("progress") = py::none(),
        (std::string("The largest distance from a point of `mesh` to the solid's exact boundary (model units): every\n"
                     "triangle sampled at (n+1)(n+2)/2 barycentric points (n = samples_per_edge, in [1, 1000]; its\n"
                     "vertices included), each projected onto the nearest face. Works for any mesh of the solid, ours or\n"
                     "another mesher's (an OpenSCAD sphere($fn), an STL read back).\n\n") +
         progress_doc)
            .c_str());
    auto solid = reopen<Solid>();
    def_tessellate(solid, [](const Solid& s) -> const Solid& { return s; },
                   "A closed, outward, 2-manifold mesh within `tolerance` of the exact faces.");
    auto face = reopen<Face>();
    def_tessellate(face, [](const Face& f) -> const Face& { return f; },
                   "An open mesh of this face alone, outward as in its solid: its boundary edges sampled as in\n"
                   "the solid's mesh (so the faces' meshes meet there), sides the face shares with itself (a\n"
                   "seam) closed.");
    const char* surface_doc =
        "A mesh of the surface over its whole domain, as a face bounded by its four sides (sides that meet\n"
        "each other, as a full revolution's seam, are joined; sides collapsed to a point, as a pole, are\n"
        "fans); triangles follow S_u x S_v.";
    auto nurbs = reopen<NurbsSurface>();
    def_tessellate(nurbs, [](const NurbsSurface& s) -> const NurbsSurface& { return s; }, surface_doc);
    auto bezier = reopen<BezierSurface>();
    def_tessellate(bezier, [](const BezierSurface& s) { return NurbsSurface::from_bezier(s); }, surface_doc);
}

}  // namespace ratbez::python
