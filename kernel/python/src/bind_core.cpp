// Bindings of the exact core: Bernstein and B-spline bases, Bézier and NURBS curves and surfaces.
// Thin by design: every check and every formula lives in kernel/core; here only Python <-> C++ values.

#include <pybind11/stl.h>

#include <optional>
#include <sstream>

#include "convert.hpp"
#include "ratbez/bernstein.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/bspline_basis.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/power_basis.hpp"

namespace ratbez::python {

namespace {

py::tuple homogeneous_tuple(const Vec4& p) { return py::make_tuple(p.x, p.y, p.z, p.w); }

template <class Curve>
py::list derivative_list(const Curve& curve, double u, int order) {
    return to_list(curve.derivatives(u, order));
}

template <class Surface>
py::list surface_derivative_list(const Surface& surface, double u, double v, int order) {
    py::list result;
    for (const auto& row : surface.derivatives(u, v, order)) result.append(to_list(row));
    return result;
}

std::string describe(const char* kind, int degree, std::size_t count, bool rational) {
    std::ostringstream out;
    out << "<ratbez." << kind << " degree=" << degree << " points=" << count << (rational ? " rational" : "") << ">";
    return out.str();
}

}  // namespace

void bind_core(py::module_& m) {
    m.def("bernstein", &bernstein, py::arg("i"), py::arg("n"), py::arg("u"),
          "B_{i,n}(u) by the recurrence of A1.2; 0 when i < 0 or i > n.");
    m.def("all_bernstein", &all_bernstein, py::arg("n"), py::arg("u"),
          "[B_{0,n}(u), ..., B_{n,n}(u)] (A1.3).");
    m.def(
        "bspline_basis",
        [](int i, int p, const py::object& knots, double u) {
            return bspline_basis(i, p, to_doubles(knots, "knots"), u);
        },
        py::arg("i"), py::arg("p"), py::arg("knots"), py::arg("u"),
        "N_{i,p}(u) by the Cox-de Boor recursion with 0/0 := 0.");
    m.def("bezier_to_power_matrix", &bezier_to_power_matrix, py::arg("n"),
          "The matrix M of Exercise 1.14: [B_{0,n}(u) .. B_{n,n}(u)] = [1 u .. u^n] M.");

    py::class_<BezierCurve>(m, "BezierCurve",
                            "A Bézier curve, polynomial or (with weights) rational, on the domain [0, 1].")
        .def(py::init([](const py::object& points, const py::object& weights) {
                 auto p = to_points(points, "points");
                 if (weights.is_none()) return BezierCurve(std::move(p));
                 return BezierCurve(std::move(p), to_doubles(weights, "weights"));
             }),
             py::arg("points"), py::arg("weights") = py::none())
        .def_property_readonly("degree", &BezierCurve::degree, "The degree n (len(points) - 1).")
        .def_property_readonly("is_rational", &BezierCurve::is_rational, "True when the weights are not all equal.")
        .def_property_readonly(
            "points", [](const BezierCurve& c) { return to_list(c.points()); }, "The control points P_i as (x, y, z) tuples.")
        .def_property_readonly("weights", &BezierCurve::weights, "The weights (all 1.0 for a polynomial curve).")
        .def("point", [](const BezierCurve& c, double u) { return to_tuple(c.point(u)); }, py::arg("u"),
             "C(u) as (x, y, z), u in [0, 1].")
        .def("point_de_casteljau", [](const BezierCurve& c, double u) { return to_tuple(c.point_de_casteljau(u)); },
             py::arg("u"), "C(u) by deCasteljau in homogeneous space (A1.5, Eq. 1.19).")
        .def("homogeneous_point", [](const BezierCurve& c, double u) { return homogeneous_tuple(c.homogeneous_point(u)); },
             py::arg("u"), "C^w(u) = (wx, wy, wz, w).")
        .def(
            "de_casteljau_table",
            [](const BezierCurve& c, double u) {
                py::list rows;
                for (const auto& row : c.de_casteljau_table(u)) {
                    py::list items;
                    for (const auto& p : row) items.append(homogeneous_tuple(p));
                    rows.append(items);
                }
                return rows;
            },
            py::arg("u"), "rows[k][i] = P^w_{k,i}(u), the triangle of Table 1.4.")
        .def("derivative", [](const BezierCurve& c, double u, int order) { return to_tuple(c.derivative(u, order)); },
             py::arg("u"), py::arg("order") = 1, "The order-th derivative C^(order)(u) as a vector (order >= 0).")
        .def("derivatives", &derivative_list<BezierCurve>, py::arg("u"), py::arg("order"),
             "[C(u), C'(u), ..., C^(order)(u)].")
        .def("split", &BezierCurve::split, py::arg("u"), "(left, right): the curve cut at u in (0, 1), each on [0, 1].")
        .def("elevate", &BezierCurve::elevate, "The same curve with degree n + 1 (degree elevation: the shape does not change).")
        .def("reversed", &BezierCurve::reversed, "The same curve traversed from its end: C(1 - u).")
        .def("__repr__", [](const BezierCurve& c) {
            return describe("BezierCurve", c.degree(), c.homogeneous_points().size(), c.is_rational());
        });

    py::class_<BezierSurface>(m, "BezierSurface",
                              "A tensor-product Bézier surface; net[i][j] with i along u and j along v.")
        .def(py::init([](const py::object& net, const py::object& weights) {
                 auto n = to_net(net, "net");
                 if (weights.is_none()) return BezierSurface(std::move(n));
                 return BezierSurface(std::move(n), to_double_rows(weights, "weights"));
             }),
             py::arg("net"), py::arg("weights") = py::none())
        .def_property_readonly("degree_u", &BezierSurface::degree_u, "The degree in u (rows - 1).")
        .def_property_readonly("degree_v", &BezierSurface::degree_v, "The degree in v (columns - 1).")
        .def_property_readonly("is_rational", &BezierSurface::is_rational, "True when the weights are not all equal.")
        .def_property_readonly(
            "points", [](const BezierSurface& s) { return to_list(s.points()); }, "The control net: rows along u of (x, y, z) tuples.")
        .def_property_readonly("weights", &BezierSurface::weights, "The weights, rows along u (all 1.0 when polynomial).")
        .def("point", [](const BezierSurface& s, double u, double v) { return to_tuple(s.point(u, v)); },
             py::arg("u"), py::arg("v"), "S(u, v) as (x, y, z), u and v in [0, 1].")
        .def("point_basis", [](const BezierSurface& s, double u, double v) { return to_tuple(s.point_basis(u, v)); },
             py::arg("u"), py::arg("v"), "S(u, v) from the Bernstein values of each direction (A1.3), row by row then once across.")
        .def("point_u_first", [](const BezierSurface& s, double u, double v) { return to_tuple(s.point_u_first(u, v)); },
             py::arg("u"), py::arg("v"), "S(u, v) by A1.7, deCasteljau in u first.")
        .def("point_v_first", [](const BezierSurface& s, double u, double v) { return to_tuple(s.point_v_first(u, v)); },
             py::arg("u"), py::arg("v"), "S(u, v) by A1.7, deCasteljau in v first.")
        .def("point_one_step",
             [](const BezierSurface& s, double u, double v) { return to_tuple(s.point_one_step(u, v)); },
             py::arg("u"), py::arg("v"), "S(u, v) by the one-step (bilinear) deCasteljau.")
        .def("derivative",
             [](const BezierSurface& s, double u, double v, int du, int dv) { return to_tuple(s.derivative(u, v, du, dv)); },
             py::arg("u"), py::arg("v"), py::arg("du") = 1, py::arg("dv") = 0,
             "The partial derivative d^(du+dv) S / du^du dv^dv at (u, v) as a vector (du, dv >= 0).")
        .def("derivatives", &surface_derivative_list<BezierSurface>, py::arg("u"), py::arg("v"), py::arg("order"),
             "SKL[k][l] = d^(k+l) S / du^k dv^l for k + l <= order.")
        .def("normal", [](const BezierSurface& s, double u, double v) { return to_tuple(s.normal(u, v)); },
             py::arg("u"), py::arg("v"), "The unit normal along S_u x S_v (its limit where that vanishes).")
        .def("isocurve_u", &BezierSurface::isocurve_u, py::arg("u0"), "The curve in v at u = u0.")
        .def("isocurve_v", &BezierSurface::isocurve_v, py::arg("v0"), "The curve in u at v = v0.")
        .def("__repr__", [](const BezierSurface& s) {
            std::ostringstream out;
            out << "<ratbez.BezierSurface degree=(" << s.degree_u() << ", " << s.degree_v() << ")"
                << (s.is_rational() ? " rational" : "") << ">";
            return out.str();
        });

    py::class_<NurbsCurve>(m, "NurbsCurve", "A NURBS curve: degree, knot vector, control points, optional weights.")
        .def(py::init([](const py::object& degree, const py::object& knots, const py::object& points,
                         const py::object& weights) {
                 const int d = to_int(degree, "degree");
                 auto k = to_doubles(knots, "knots");
                 auto p = to_points(points, "points");
                 if (weights.is_none()) return NurbsCurve(d, std::move(k), std::move(p));
                 return NurbsCurve(d, std::move(k), std::move(p), to_doubles(weights, "weights"));
             }),
             py::arg("degree"), py::arg("knots"), py::arg("points"), py::arg("weights") = py::none())
        .def_static("from_bezier", &NurbsCurve::from_bezier, py::arg("curve"),
                    "The same curve as a NurbsCurve on the knots {0..0, 1..1} (degree + 1 each).")
        .def_property_readonly("degree", &NurbsCurve::degree, "The degree p.")
        .def_property_readonly("knots", &NurbsCurve::knots, "The knot vector (nondecreasing, len(points) + degree + 1 values).")
        .def_property_readonly(
            "points", [](const NurbsCurve& c) { return to_list(c.points()); }, "The control points as (x, y, z) tuples.")
        .def_property_readonly("weights", &NurbsCurve::weights, "The weights (all 1.0 for a polynomial curve).")
        .def_property_readonly("is_rational", &NurbsCurve::is_rational, "True when the weights are not all equal.")
        .def_property_readonly(
            "domain", [](const NurbsCurve& c) { return to_tuple(c.domain()); }, "(u_min, u_max): the parameter range.")
        .def_property_readonly(
            "start_point", [](const NurbsCurve& c) { return to_tuple(c.start_point()); }, "C(u_min) as (x, y, z).")
        .def_property_readonly(
            "end_point", [](const NurbsCurve& c) { return to_tuple(c.end_point()); }, "C(u_max) as (x, y, z).")
        .def("point", [](const NurbsCurve& c, double u) { return to_tuple(c.point(u)); }, py::arg("u"),
             "C(u) as (x, y, z), u in the domain.")
        .def("derivative", [](const NurbsCurve& c, double u, int order) { return to_tuple(c.derivative(u, order)); },
             py::arg("u"), py::arg("order") = 1, "The order-th derivative C^(order)(u) as a vector (order >= 0).")
        .def("derivatives", &derivative_list<NurbsCurve>, py::arg("u"), py::arg("order"),
             "[C(u), C'(u), ..., C^(order)(u)].")
        .def("insert_knot", &NurbsCurve::insert_knot, py::arg("u"), py::arg("times") = 1,
             "The same curve with u inserted `times` more times (A5.1); the shape does not change.")
        .def("bezier_segments", &NurbsCurve::bezier_segments, "The curve as Bezier pieces, one per nonzero knot span (by knot insertion).")
        .def("reversed", &NurbsCurve::reversed, "The same curve traversed from its end, on the same domain.")
        .def("reparameterized", &NurbsCurve::reparameterized, py::arg("a"), py::arg("b"),
             "The same curve on the domain [a, b] (a < b), by a linear map of the knots.")
        .def("__repr__", [](const NurbsCurve& c) {
            return describe("NurbsCurve", c.degree(), c.homogeneous_points().size(), c.is_rational());
        });

    py::class_<NurbsSurface>(m, "NurbsSurface", "A tensor-product NURBS surface; net[i][j] with i along u, j along v.")
        .def(py::init([](const py::object& degree_u, const py::object& degree_v, const py::object& knots_u,
                         const py::object& knots_v, const py::object& net, const py::object& weights) {
                 const int du = to_int(degree_u, "degree_u");
                 const int dv = to_int(degree_v, "degree_v");
                 auto ku = to_doubles(knots_u, "knots_u");
                 auto kv = to_doubles(knots_v, "knots_v");
                 auto n = to_net(net, "net");
                 if (weights.is_none()) return NurbsSurface(du, dv, std::move(ku), std::move(kv), std::move(n));
                 return NurbsSurface(du, dv, std::move(ku), std::move(kv), std::move(n),
                                     to_double_rows(weights, "weights"));
             }),
             py::arg("degree_u"), py::arg("degree_v"), py::arg("knots_u"), py::arg("knots_v"), py::arg("net"),
             py::arg("weights") = py::none())
        .def_static("from_bezier", &NurbsSurface::from_bezier, py::arg("surface"),
                    "The same surface as a NurbsSurface on the knots {0..0, 1..1} in u and in v.")
        .def_property_readonly("degree_u", &NurbsSurface::degree_u, "The degree in u.")
        .def_property_readonly("degree_v", &NurbsSurface::degree_v, "The degree in v.")
        .def_property_readonly("knots_u", &NurbsSurface::knots_u, "The knot vector in u.")
        .def_property_readonly("knots_v", &NurbsSurface::knots_v, "The knot vector in v.")
        .def_property_readonly(
            "points", [](const NurbsSurface& s) { return to_list(s.points()); }, "The control net: rows along u of (x, y, z) tuples.")
        .def_property_readonly("weights", &NurbsSurface::weights, "The weights, rows along u (all 1.0 when polynomial).")
        .def_property_readonly("is_rational", &NurbsSurface::is_rational, "True when the weights are not all equal.")
        .def_property_readonly(
            "domain",
            [](const NurbsSurface& s) { return py::make_tuple(to_tuple(s.domain_u()), to_tuple(s.domain_v())); },
            "((u_min, u_max), (v_min, v_max)): the parameter ranges.")
        .def("point", [](const NurbsSurface& s, double u, double v) { return to_tuple(s.point(u, v)); },
             py::arg("u"), py::arg("v"), "S(u, v) as (x, y, z), (u, v) in the domain.")
        .def("derivative",
             [](const NurbsSurface& s, double u, double v, int du, int dv) { return to_tuple(s.derivative(u, v, du, dv)); },
             py::arg("u"), py::arg("v"), py::arg("du") = 1, py::arg("dv") = 0,
             "The partial derivative d^(du+dv) S / du^du dv^dv at (u, v) as a vector (du, dv >= 0).")
        .def("derivatives", &surface_derivative_list<NurbsSurface>, py::arg("u"), py::arg("v"), py::arg("order"),
             "SKL[k][l] = d^(k+l) S / du^k dv^l for k + l <= order.")
        .def("normal", [](const NurbsSurface& s, double u, double v) { return to_tuple(s.normal(u, v)); },
             py::arg("u"), py::arg("v"), "The unit normal along S_u x S_v (its limit where that vanishes).")
        .def("isocurve_u", &NurbsSurface::isocurve_u, py::arg("u0"), "The curve in v at u = u0.")
        .def("isocurve_v", &NurbsSurface::isocurve_v, py::arg("v0"), "The curve in u at v = v0.")
        .def("insert_knot_u", &NurbsSurface::insert_knot_u, py::arg("u"), py::arg("times") = 1,
             "The same surface with u inserted `times` more times in the u knots (A5.3).")
        .def("insert_knot_v", &NurbsSurface::insert_knot_v, py::arg("v"), py::arg("times") = 1,
             "The same surface with v inserted `times` more times in the v knots (A5.3).")
        .def("bezier_patches", &NurbsSurface::bezier_patches, "The surface as Bezier patches, [i][j] per nonzero knot span in u and v.")
        .def("__repr__", [](const NurbsSurface& s) {
            std::ostringstream out;
            out << "<ratbez.NurbsSurface degree=(" << s.degree_u() << ", " << s.degree_v() << ") points=(" << s.rows()
                << ", " << s.columns() << ")" << (s.is_rational() ? " rational" : "") << ">";
            return out.str();
        });
}

}  // namespace ratbez::python
