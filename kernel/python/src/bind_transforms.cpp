// Affine transforms of curves, surfaces, faces and solids (affine_map.hpp, solid_transform.hpp): translated,
// rotated, scaled, mirrored and transformed, each returning a new object of the same type.

#include "convert.hpp"
#include "numpy_arrays.hpp"
#include "ratbez/affine_map.hpp"
#include "ratbez/error.hpp"
#include "ratbez/solid_transform.hpp"

namespace ratbez::python {

namespace {

AffineMap matrix_map(const py::object& matrix) {
    const DoubleArray m = real_array(matrix, "matrix", 2, 4);
    if (m.shape(0) != 3 && m.shape(0) != 4)
        throw Error("matrix", "expected a 3 x 4 or 4 x 4 affine matrix, got " + std::to_string(m.shape(0)) + " x 4");
    return AffineMap::from_matrix(values(m), static_cast<std::size_t>(m.shape(0)));
}

// The five methods on class T; `what` names the object in the docstrings.
template <class T>
void def_transforms(const char* what) {
    // `argument`: the method's name for what the kernel calls the map ("v" of translated, "matrix" of transformed).
    const auto apply = [](const T& x, const AffineMap& map, const char* argument) {
        py::gil_scoped_release release;  // a Solid's faces are mapped and revalidated
        try {
            return transformed(x, map);
        } catch (const Error& e) {
            throw e.renamed("map", argument);
        }
    };
    const std::string noun(what);
    reopen<T>()
        .def(
            "translated",
            [apply](const T& x, const py::object& v) { return apply(x, AffineMap::translation(to_vec3(v, "v")), "v"); },
            py::arg("v"), ("The " + noun + " moved by the vector v (2 or 3 numbers).").c_str())
        .def(
            "rotated",
            [apply](const T& x, const py::object& axis_point, const py::object& axis_dir, double angle_deg) {
                return apply(x, AffineMap::rotation(to_vec3(axis_point, "axis_point"), to_vec3(axis_dir, "axis_dir"),
                                                    angle_deg),
                             "axis_point");
            },
            py::arg("axis_point"), py::arg("axis_dir"), py::arg("angle_deg"),
            ("The " + noun + " rotated by angle_deg degrees (right-handed) about the line through axis_point\n"
             "along axis_dir (any length but 0). Exact at multiples of 90 degrees.").c_str())
        .def(
            "scaled",
            [apply](const T& x, double factor, const py::object& center) {
                return apply(x, AffineMap::scaling(factor, to_vec3(center, "center")), "factor");
            },
            py::arg("factor"), py::arg("center") = py::make_tuple(0.0, 0.0, 0.0),
            ("The " + noun + " scaled by factor (finite, not 0; negative: a point reflection) about center.").c_str())
        .def(
            "mirrored",
            [apply](const T& x, const py::object& plane_point, const py::object& plane_normal) {
                return apply(x, AffineMap::mirror(to_vec3(plane_point, "plane_point"),
                                                  to_vec3(plane_normal, "plane_normal")),
                             "plane_point");
            },
            py::arg("plane_point"), py::arg("plane_normal"),
            ("The mirror image of the " + noun + " in the plane through plane_point with normal plane_normal.").c_str())
        .def(
            "transformed", [apply](const T& x, const py::object& matrix) { return apply(x, matrix_map(matrix), "matrix"); },
            py::arg("matrix"),
            ("The " + noun + " under the affine map x -> L x + t given as a 3 x 4 matrix [L | t] or a 4 x 4 one\n"
             "with last row (0, 0, 0, 1) (nested sequences or a numpy array). Projective rows and singular L\n"
             "are refused. Control points are mapped, weights and knots kept: exact for rational geometry.").c_str());
}

}  // namespace

void bind_transforms(py::module_&) {
    def_transforms<BezierCurve>("curve");
    def_transforms<NurbsCurve>("curve");
    def_transforms<BezierSurface>("surface");
    def_transforms<NurbsSurface>("surface");
    def_transforms<Face>("face (outward normals kept: a mirror reorients it)");
    def_transforms<Solid>(
        "solid (faces kept outward; the kind and its parameters kept where the map preserves them: rigid motions,\n"
        "mirrors and uniform scalings keep a cylinder, cone, sphere, torus or revolution, any affine map an\n"
        "extrusion; otherwise kind 'none')");
}

}  // namespace ratbez::python
