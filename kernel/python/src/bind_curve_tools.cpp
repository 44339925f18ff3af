// Bindings of the curve tools of issue 26: interpolation through points (A9.1, surfaces A9.4), least-squares
// approximation within a tolerance (§9.4.1), arc length and its inverse, degree elevation of NURBS curves and
// surfaces (A5.9). Thin: every check and formula lives in kernel/core.

#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "convert.hpp"
#include "ratbez/approximation.hpp"
#include "ratbez/arc_length.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/degree_elevation.hpp"
#include "ratbez/error.hpp"
#include "ratbez/interpolation.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"

namespace ratbez::python {

namespace {

// tangents=None, or (start, end) with either None: the directions of C'(0) and C'(1).
EndTangents to_end_tangents(const py::object& value) {
    EndTangents tangents;
    if (value.is_none()) return tangents;
    if (py::isinstance<py::str>(value) || !PySequence_Check(value.ptr()) || PySequence_Size(value.ptr()) != 2)
        throw Error("tangents", "expected None or a pair (start, end) of vectors, either of them None");
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(value);
    if (!pair[0].is_none()) tangents.start = to_vec3(pair[0], "tangents[0]");
    if (!pair[1].is_none()) tangents.end = to_vec3(pair[1], "tangents[1]");
    return tangents;
}

template <class Curve>
NurbsCurve as_nurbs_curve(const Curve& c) {
    if constexpr (std::is_same_v<Curve, NurbsCurve>) return c;
    else return NurbsCurve::from_bezier(c);
}

template <class Curve>
void add_arc_length(py::module_& m, const char* name) {
    auto cls = py::reinterpret_borrow<py::class_<Curve>>(m.attr(name));
    cls.def(
        "length",
        [](const Curve& c, const py::object& u0, const py::object& u1) {
            const NurbsCurve curve = as_nurbs_curve(c);
            const Interval d = curve.domain();
            const double a = u0.is_none() ? d.min : to_double(u0, "u0"), b = u1.is_none() ? d.max : to_double(u1, "u1");
            py::gil_scoped_release release;
            return length(curve, a, b);
        },
        py::arg("u0") = py::none(), py::arg("u1") = py::none(),
        "The arc length from u0 to u1 (defaults: the domain's ends; negative when u1 < u0), by adaptive "
        "Gauss-Legendre quadrature on every knot span (about 1e-14 relative: a circle reads 2 pi r).");
    cls.def(
        "parameter_at_length",
        [](const Curve& c, double s) {
            const NurbsCurve curve = as_nurbs_curve(c);
            py::gil_scoped_release release;
            return parameter_at_length(curve, s);
        },
        py::arg("s"),
        "The parameter u at which the arc length from the domain's start reaches s (0 <= s <= length()), "
        "to the same accuracy (Newton on the length, bracketed).");
}

}  // namespace

void bind_curve_tools(py::module_& m) {
    m.def(
        "interpolate",
        [](const py::object& points, int degree, const std::string& parameterization, const py::object& tangents,
           bool closed) {
            return interpolate(to_points(points, "points"), degree, parse_parameterization(parameterization),
                               to_end_tangents(tangents), closed);
        },
        py::arg("points"), py::arg("degree") = 3, py::arg("parameterization") = "chord", py::arg("tangents") = py::none(),
        py::arg("closed") = false,
        "The B-spline curve of the given degree through every point (The NURBS Book A9.1): parameters by "
        "\"chord\" length (Eq. 9.5), \"centripetal\" (Eq. 9.6) or \"uniform\" (Eq. 9.3), knots averaged (Eq. 9.8), "
        "the banded system solved exactly; C(t_k) = points[k] to rounding, the domain [0, 1]. tangents=(start, "
        "end), either None: C'(0) and C'(1) along them, as long as the total chord (Eq. 9.22 knots). closed=True: "
        "the periodic curve through the points and back to the first (C^(p-1) there too), starting at it.");
    m.def(
        "approximate",
        [](const py::object& points, double tolerance, int degree) {
            const std::vector<Vec3> q = to_points(points, "points");
            py::gil_scoped_release release;
            return approximate(q, tolerance, degree);
        },
        py::arg("points"), py::arg("tolerance"), py::arg("degree") = 3,
        "The least-squares B-spline (The NURBS Book 9.4.1: chord-length parameters, knots by Eq. 9.68-9.69, the "
        "end points interpolated) with the fewest control points that brings every point within `tolerance` "
        "of the curve at its parameter (found by bisection; one control point fewer misses the tolerance).");
    m.def(
        "interpolate_surface",
        [](const py::object& grid, int degree_u, int degree_v) {
            return interpolate_surface(to_net(grid, "grid"), degree_u, degree_v);
        },
        py::arg("grid"), py::arg("degree_u") = 3, py::arg("degree_v") = 3,
        "The B-spline surface through every grid point (The NURBS Book A9.4): grid[i][j], i along u, j along v; "
        "parameters averaged over the columns (u) and rows (v) from chord lengths, knots averaged; S(u_i, v_j) = "
        "grid[i][j] to rounding, the domain [0, 1] x [0, 1].");

    add_arc_length<NurbsCurve>(m, "NurbsCurve");
    add_arc_length<BezierCurve>(m, "BezierCurve");
    auto curve = py::reinterpret_borrow<py::class_<NurbsCurve>>(m.attr("NurbsCurve"));
    curve.def(
        "elevated", [](const NurbsCurve& c, int times) { return elevate_degree(c, times); }, py::arg("times") = 1,
        "The same curve with degree + times (The NURBS Book A5.9): every knot keeps its continuity (multiplicity "
        "s becomes s + times), rational curves exactly.");
    auto surface = py::reinterpret_borrow<py::class_<NurbsSurface>>(m.attr("NurbsSurface"));
    surface.def(
        "elevated",
        [](const NurbsSurface& s, int times_u, int times_v) { return elevate_degree_v(elevate_degree_u(s, times_u), times_v); },
        py::arg("times_u") = 1, py::arg("times_v") = 1,
        "The same surface with degree_u + times_u and degree_v + times_v (A5.9 on every row and column of the "
        "net; the same surface, rational ones exactly).");
}

}  // namespace ratbez::python
