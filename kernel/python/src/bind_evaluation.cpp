// Bulk evaluation: numpy in, numpy out, the GIL released while the kernel computes (bulk_evaluation.hpp).
// curve.evaluate(us, order=0); surface.evaluate(us, vs, du=0, dv=0), evaluate_at(uv, du=0, dv=0) and
// evaluate_partials(us, vs, order=1) and normals(us, vs) on BezierSurface, NurbsSurface and Face (through its
// surface).

#include <string>

#include "convert.hpp"
#include "numpy_arrays.hpp"
#include "ratbez/brep.hpp"
#include "ratbez/bulk_evaluation.hpp"
#include "ratbez/error.hpp"

namespace ratbez::python {

DoubleArray real_array(py::handle value, const std::string& argument, int ndim, py::ssize_t last) {
    if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value))
        throw Error(argument, "expected an array of numbers");
    const py::array array = py::array::ensure(value);
    if (!array) throw Error(argument, "expected an array of numbers (not ragged)");
    const char kind = array.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw Error(argument, "expected real numbers, got dtype " + py::str(array.dtype()).cast<std::string>());
    auto shape_text = [&] {
        std::string text = "(";
        for (py::ssize_t k = 0; k < array.ndim(); ++k) text += (k ? ", " : "") + std::to_string(array.shape(k));
        return text + (array.ndim() == 1 ? ",)" : ")");
    };
    if (array.ndim() != ndim || (last >= 0 && array.shape(ndim - 1) != last)) {
        const std::string expected = ndim == 1 ? "a 1-D array (N,)" : "an array of shape (N, " + std::to_string(last) + ")";
        throw Error(argument, "expected " + expected + ", got shape " + shape_text());
    }
    return DoubleArray::ensure(array);
}

namespace {

DoubleArray parameters(const py::object& value, const char* argument) { return real_array(value, argument, 1); }

py::array_t<double> points_array(py::ssize_t rows) { return py::array_t<double>({rows, py::ssize_t{3}}); }

py::array_t<double> grid_array(const DoubleArray& us, const DoubleArray& vs) {
    return py::array_t<double>({us.size(), vs.size(), py::ssize_t{3}});
}

template <class Curve>
py::array_t<double> curve_evaluate(const Curve& curve, const py::object& us, int order) {
    const DoubleArray u = parameters(us, "us");
    auto out = points_array(u.size());
    {
        py::gil_scoped_release release;
        evaluate_curve(curve, values(u), order, values(out));
    }
    return out;
}

py::array_t<double> surface_evaluate(const NurbsSurface& surface, const py::object& us, const py::object& vs, int du,
                                     int dv) {
    const DoubleArray u = parameters(us, "us"), v = parameters(vs, "vs");
    auto out = grid_array(u, v);
    {
        py::gil_scoped_release release;
        evaluate_surface_grid(surface, values(u), values(v), du, dv, values(out));
    }
    return out;
}

py::array_t<double> surface_partials(const NurbsSurface& surface, const py::object& us, const py::object& vs,
                                     int order) {
    const DoubleArray u = parameters(us, "us"), v = parameters(vs, "vs");
    const py::ssize_t per_point = order == 2 ? 6 : 3;  // any other order is refused by the kernel
    auto out = py::array_t<double>({u.size(), v.size(), per_point, py::ssize_t{3}});
    {
        py::gil_scoped_release release;
        evaluate_surface_partials(surface, values(u), values(v), order, values(out));
    }
    return out;
}

py::array_t<double> surface_normals(const NurbsSurface& surface, const py::object& us, const py::object& vs) {
    const DoubleArray u = parameters(us, "us"), v = parameters(vs, "vs");
    auto out = grid_array(u, v);
    {
        py::gil_scoped_release release;
        evaluate_surface_normals(surface, values(u), values(v), values(out));
    }
    return out;
}

py::array_t<double> surface_evaluate_at(const NurbsSurface& surface, const py::object& uv, int du, int dv) {
    const DoubleArray pairs = real_array(uv, "uv", 2, 2);
    auto out = points_array(pairs.shape(0));
    {
        py::gil_scoped_release release;
        evaluate_surface_at(surface, values(pairs), du, dv, values(out));
    }
    return out;
}

constexpr const char* curve_doc =
    "The points (order 0) or the order-th derivatives at every parameter of us (any order, repeats\n"
    "allowed, each inside the domain): a float64 array of shape (len(us), 3). The GIL is released.";
constexpr const char* grid_doc =
    "The (du, dv) partial d^(du+dv) S / du^du dv^dv (du = dv = 0: the points) at every (us[i], vs[j]):\n"
    "a float64 array of shape (len(us), len(vs), 3). us and vs in any order, inside the domain.";
constexpr const char* at_doc =
    "The (du, dv) partial at each (u, v) row of uv, an array of shape (N, 2): shape (N, 3).";
constexpr const char* partials_doc =
    "Every partial up to `order` (1 or 2) at every (us[i], vs[j]) in one pass (the bases computed once, as\n"
    "OpenCASCADE's D1 / D2): a float64 array of shape (len(us), len(vs), 3, 3) for order 1, whose [i, j, 0],\n"
    "[i, j, 1] and [i, j, 2] are S, S_u and S_v; shape (len(us), len(vs), 6, 3) for order 2, then S_uu, S_uv\n"
    "and S_vv. Equal to evaluate(us, vs, du, dv) for each partial; about twice as fast as those calls.";
constexpr const char* normals_doc =
    "The unit normals at every (us[i], vs[j]): shape (len(us), len(vs), 3); at poles and apexes, where\n"
    "S_u x S_v vanishes, the limit direction (as normal(u, v)).";

// The five surface methods on a class whose surface is `surface_of(object)`.
template <class T, class SurfaceOf>
void def_surface_methods(py::class_<T>& cls, SurfaceOf surface_of) {
    cls.def(
           "evaluate",
           [surface_of](const T& self, const py::object& us, const py::object& vs, int du, int dv) {
               return surface_evaluate(surface_of(self), us, vs, du, dv);
           },
           py::arg("us"), py::arg("vs"), py::arg("du") = 0, py::arg("dv") = 0, grid_doc)
        .def(
            "evaluate_at",
            [surface_of](const T& self, const py::object& uv, int du, int dv) {
                return surface_evaluate_at(surface_of(self), uv, du, dv);
            },
            py::arg("uv"), py::arg("du") = 0, py::arg("dv") = 0, at_doc)
        .def(
            "evaluate_partials",
            [surface_of](const T& self, const py::object& us, const py::object& vs, int order) {
                return surface_partials(surface_of(self), us, vs, order);
            },
            py::arg("us"), py::arg("vs"), py::arg("order") = 1, partials_doc)
        .def(
            "normals",
            [surface_of](const T& self, const py::object& us, const py::object& vs) {
                return surface_normals(surface_of(self), us, vs);
            },
            py::arg("us"), py::arg("vs"), normals_doc);
}

}  // namespace

void bind_evaluation(py::module_&) {
    reopen<BezierCurve>().def("evaluate", &curve_evaluate<BezierCurve>, py::arg("us"), py::arg("order") = 0, curve_doc);
    reopen<NurbsCurve>().def("evaluate", &curve_evaluate<NurbsCurve>, py::arg("us"), py::arg("order") = 0, curve_doc);

    auto bezier = reopen<BezierSurface>();
    def_surface_methods(bezier, [](const BezierSurface& s) { return NurbsSurface::from_bezier(s); });
    auto nurbs = reopen<NurbsSurface>();
    def_surface_methods(nurbs, [](const NurbsSurface& s) -> const NurbsSurface& { return s; });
    auto face = reopen<Face>();
    def_surface_methods(face, [](const Face& f) -> const NurbsSurface& { return f.surface(); });
}

}  // namespace ratbez::python
