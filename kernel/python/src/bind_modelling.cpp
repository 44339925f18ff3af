// Bindings of the modelling operations (issue 18): surfaces swept from open or closed curves, ruled
// surfaces, lofts and path sweeps (surfaces and capped solids), continuity and joining, the Hermite form,
// closest points and curvatures on the curve and surface classes, and the power-basis and Bernstein
// helpers. Thin: every check and formula lives in kernel/core.

#include <pybind11/stl.h>

#include <cmath>
#include <string>

#include "convert.hpp"
#include "ratbez/bernstein.hpp"
#include "ratbez/bezier_curve.hpp"
#include "ratbez/bezier_surface.hpp"
#include "ratbez/closest_point.hpp"
#include "ratbez/continuity.hpp"
#include "ratbez/curvature.hpp"
#include "ratbez/error.hpp"
#include "ratbez/extrude.hpp"
#include "ratbez/hermite.hpp"
#include "ratbez/join.hpp"
#include "ratbez/loft.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/nurbs_surface.hpp"
#include "ratbez/power_basis.hpp"
#include "ratbez/revolve.hpp"
#include "ratbez/ruled.hpp"
#include "ratbez/sweep.hpp"

namespace ratbez::python {

namespace {

py::tuple origin() { return py::make_tuple(0.0, 0.0, 0.0); }
py::tuple z_axis() { return py::make_tuple(0.0, 0.0, 1.0); }

NurbsSurface to_surface(py::handle value, const std::string& argument) {
    if (py::isinstance<NurbsSurface>(value)) return value.cast<NurbsSurface>();
    if (py::isinstance<BezierSurface>(value)) return NurbsSurface::from_bezier(value.cast<const BezierSurface&>());
    throw Error(argument, "expected a BezierSurface or a NurbsSurface");
}

bool is_surface(py::handle value) { return py::isinstance<NurbsSurface>(value) || py::isinstance<BezierSurface>(value); }

// A path: one curve, or pieces joined end to end into one (join.hpp).
NurbsCurve to_sweep_path(py::handle value, const std::string& argument) {
    std::vector<NurbsCurve> pieces = to_curves(value, argument);
    if (pieces.size() == 1) return std::move(pieces.front());
    try {
        return join(pieces);
    } catch (const Error& e) {
        throw e.renamed("curves", argument);
    }
}

py::dict continuity_dict(const Continuity& c) {
    py::dict gaps;
    gaps["position"] = c.position;
    gaps["derivative1"] = c.derivative1;
    gaps["derivative2"] = c.derivative2;
    gaps["tangent_angle"] = c.tangent_angle;
    gaps["curvature"] = c.curvature;
    py::dict out;
    out["C"] = c.parametric;
    out["G"] = c.geometric;
    out["gaps"] = gaps;
    return out;
}

py::tuple curve_foot(const CurveFoot& f) { return py::make_tuple(f.u, to_tuple(f.point), f.distance); }
py::tuple surface_foot(const SurfaceFoot& f) {
    return py::make_tuple(py::make_tuple(f.u, f.v), to_tuple(f.point), f.distance);
}

py::tuple foot_tuple(const CurveFoot& f) { return curve_foot(f); }
py::tuple foot_tuple(const SurfaceFoot& f) { return surface_foot(f); }

// The feet of many points: one projector (its pieces and seeds built once), the GIL released meanwhile.
template <class Projector, class Shape>
py::list many_feet(const Shape& shape, const py::object& points) {
    const std::vector<Vec3> ps = to_points(points, "points");
    std::vector<decltype(std::declval<Projector>().closest_point(Vec3{}))> feet;
    {
        py::gil_scoped_release release;
        const Projector projector(shape);
        feet.reserve(ps.size());
        for (const Vec3& p : ps) feet.push_back(projector.closest_point(p));
    }
    py::list out;
    for (const auto& f : feet) out.append(foot_tuple(f));
    return out;
}

py::tuple curvatures_tuple(const PrincipalCurvatures& k) {
    return py::make_tuple(k.k1, k.k2, to_tuple(k.dir1), to_tuple(k.dir2));
}

// A list of numbers (not points): the first item decides.
bool is_number_list(py::handle value) {
    if (py::isinstance<py::str>(value) || !PySequence_Check(value.ptr()) || PySequence_Size(value.ptr()) <= 0) return false;
    const py::object first = py::reinterpret_borrow<py::sequence>(value)[0];
    return PyNumber_Check(first.ptr()) && !PySequence_Check(first.ptr());
}

constexpr const char* kClosestCurveDoc =
    "The nearest point of the curve to p (a 2D or 3D point): (u, point, distance), u in the curve's domain, "
    "distance >= 0 in model units. Global: every span is searched (closest_point.hpp).";
constexpr const char* kClosestSurfaceDoc =
    "The nearest point of the surface to p (a 2D or 3D point): ((u, v), point, distance), (u, v) in the "
    "domain, distance >= 0 in model units. Global: seeds over every span, then Newton (closest_point.hpp).";
constexpr const char* kClosestManyDoc =
    "closest_point for many points at once (a list or N x 3 array of points): the list of their feet, "
    "the curve's or surface's search structure built once (much faster than calling closest_point in a loop).";
constexpr const char* kCurvatureDoc =
    "The curvature at u (1 / model units, >= 0): |C' x C''| / |C'|^3, its limit where C' vanishes, inf at a "
    "cusp (000 Ex1.3), 0 at an inflection.";
constexpr const char* kCurvaturesDoc =
    "Principal curvatures at (u, v): (k1, k2, dir1, dir2) with k1 >= k2 in 1 / model units, signed against "
    "normal(u, v) (a sphere with outward normal has -1/r), dir1, dir2 unit tangent directions. At poles the "
    "limit.";

// The NURBS form the queries run on: the curve or surface itself, or a Bezier piece as a NURBS.
const NurbsCurve& as_nurbs(const NurbsCurve& c) { return c; }
NurbsCurve as_nurbs(const BezierCurve& c) { return NurbsCurve::from_bezier(c); }
const NurbsSurface& as_nurbs(const NurbsSurface& s) { return s; }
NurbsSurface as_nurbs(const BezierSurface& s) { return NurbsSurface::from_bezier(s); }

template <class Curve>
void add_curve_queries(py::module_& m, const char* name) {
    auto cls = py::reinterpret_borrow<py::class_<Curve>>(m.attr(name));
    cls.def(
        "closest_point",
        [](const Curve& c, const py::object& p) { return curve_foot(closest_point(as_nurbs(c), to_vec3(p, "p"))); },
        py::arg("p"), kClosestCurveDoc);
    cls.def(
        "closest_points", [](const Curve& c, const py::object& points) { return many_feet<CurveProjector>(as_nurbs(c), points); },
        py::arg("points"), kClosestManyDoc);
    cls.def("curvature", [](const Curve& c, double u) { return curvature(as_nurbs(c), u); }, py::arg("u"), kCurvatureDoc);
}

template <class Surface>
void add_surface_queries(py::module_& m, const char* name) {
    auto cls = py::reinterpret_borrow<py::class_<Surface>>(m.attr(name));
    cls.def(
        "closest_point",
        [](const Surface& s, const py::object& p) { return surface_foot(closest_point(as_nurbs(s), to_vec3(p, "p"))); },
        py::arg("p"), kClosestSurfaceDoc);
    cls.def(
        "closest_points",
        [](const Surface& s, const py::object& points) { return many_feet<SurfaceProjector>(as_nurbs(s), points); },
        py::arg("points"), kClosestManyDoc);
    cls.def(
        "curvatures",
        [](const Surface& s, double u, double v) { return curvatures_tuple(principal_curvatures(as_nurbs(s), u, v)); },
        py::arg("u"), py::arg("v"), kCurvaturesDoc);
}

}  // namespace

void bind_modelling(py::module_& m) {
    // ---- bases: power basis (A1.1, A1.6, Ex. 1.14) and Bernstein derivatives
    m.def(
        "horner",
        [](const py::object& coefficients, double u, const py::object& v) -> py::object {
            if (!v.is_none()) {
                const auto net = to_net(coefficients, "coefficients");
                return to_tuple(horner(net, u, to_double(v, "v")));
            }
            if (is_number_list(coefficients)) return py::float_(horner(to_doubles(coefficients, "coefficients"), u));
            return to_tuple(horner(to_points(coefficients, "coefficients"), u));
        },
        py::arg("coefficients"), py::arg("u"), py::arg("v") = py::none(),
        "Horner's rule. With u only: a_0 + a_1 u + ... for numbers (A1.1, a float) or points (a point). With u "
        "and v: the power basis surface sum a[i][j] u^i v^j of a net of points (A1.6, Horner2). Any finite u, v.");
    m.def(
        "bezier_to_power",
        [](const py::object& points) { return to_list(bezier_to_power(to_points(points, "control_points"))); },
        py::arg("control_points"), "Power basis coefficients a_i = M P of a Bezier curve's points (Ex. 1.14).");
    m.def(
        "power_to_bezier",
        [](const py::object& coefficients) { return to_list(power_to_bezier(to_points(coefficients, "coefficients"))); },
        py::arg("coefficients"), "Bezier control points P = M^-1 a of a power basis curve (Ex. 1.14).");
    m.def("all_bernstein_derivatives", &all_bernstein_derivatives, py::arg("n"), py::arg("k"), py::arg("u"),
          "[d^k/du^k B_{0,n}(u), ..., d^k/du^k B_{n,n}(u)], k >= 0 (003: B' = n (B_{i-1,n-1} - B_{i,n-1})).");

    // ---- surfaces from curves
    m.def(
        "revolve_surface",
        [](const py::object& curve, const py::object& axis_point, const py::object& axis_dir, double angle) {
            return revolve_surface(to_curve(curve, "curve"), to_vec3(axis_point, "axis_point"),
                                   to_vec3(axis_dir, "axis_dir"), angle);
        },
        py::arg("curve"), py::arg("axis_point") = origin(), py::arg("axis_dir") = z_axis(), py::arg("angle") = 360.0,
        "The exact surface of revolution of any curve (open or closed) about the axis by angle degrees in "
        "(0, 360]: u runs along the rotation over [0, 1], v along the curve (its domain).");
    m.def(
        "extrude_surface",
        [](const py::object& curve, const py::object& direction, double distance) {
            return extrude_surface(to_curve(curve, "curve"), to_vec3(direction, "direction"), distance);
        },
        py::arg("curve"), py::arg("direction"), py::arg("distance"),
        "The exact translational sweep C(u) + v distance direction/|direction| of any curve; distance > 0 in "
        "model units; u along the curve, v over [0, 1].");
    m.def(
        "ruled_surface",
        [](const py::object& a, const py::object& b, bool align) {
            return ruled_surface(to_curve(a, "curve_a"), to_curve(b, "curve_b"), align);
        },
        py::arg("curve_a"), py::arg("curve_b"), py::arg("align") = true,
        "The exact ruled surface between two curves (degrees raised, knots merged): u along both over [0, 1], "
        "v from curve_a (0) to curve_b (1) along straight rulings. align=True (the default) matches the curves "
        "by normalised arc length at their corners and joints (closed ones oriented alike and started at the "
        "points of least twist, open ones end to end), each on its own parameter between them; align=False rules point u of one to point u of the other. A surface whose rulings "
        "cross raises ratbez.Error saying where.");
    m.def(
        "loft_surface",
        [](const py::object& curves, int degree, bool align) {
            return loft_surface(to_curves(curves, "curves"), degree, align);
        },
        py::arg("curves"), py::arg("degree") = 3, py::arg("align") = true,
        "The skinned surface through >= 2 section curves (The NURBS Book 10.3), passing through every section "
        "exactly; degree across >= 1 (at most sections - 1 is used). u along the sections, v across, both [0, 1]. "
        "align=True (the default) matches the sections by normalised arc length at their corners and joints from "
        "the start points of least twist, each on its own parameter between them (align=False: by parameter, as "
        "given). A surface that meets itself raises ratbez.Error.");
    m.def(
        "loft",
        [](const py::object& profiles, int degree, bool ruled, bool align) {
            if (py::isinstance<py::str>(profiles) || !PySequence_Check(profiles.ptr()))
                throw Error("profiles", "expected a list of profiles");
            std::vector<Profile> list;
            std::size_t index = 0;
            for (py::handle p : profiles) list.push_back(to_profile(p, "profiles[" + std::to_string(index++) + "]"));
            return loft(list, degree, ruled, align);
        },
        py::arg("profiles"), py::arg("degree") = 3, py::arg("ruled") = false, py::arg("align") = true,
        "A solid lofted through >= 2 closed planar profiles (each a curve or a list of curves joined end to "
        "end), capped by the first and last; ruled=True uses straight rulings between consecutive profiles. "
        "align=True (the default) matches the profiles by arc length at their corners and joints from the start "
        "points of least twist, each on its own parameter between them (smooth profiles stay smooth); "
        "align=False by their own starts and parameters. One side face per smooth run (cut where every "
        "profile has a corner). A loft whose side surface meets itself raises ratbez.Error saying where.");
    m.def(
        "sweep_surface",
        [](const py::object& curve, const py::object& path, double tolerance) {
            const NurbsCurve c = to_curve(curve, "curve");
            const NurbsCurve p = to_sweep_path(path, "path");
            py::gil_scoped_release release;
            return sweep_surface(c, p, tolerance);
        },
        py::arg("curve"), py::arg("path"), py::arg("tolerance") = 1e-6,
        "The curve swept along the path (a curve or pieces joined end to end) with a rotation-minimising "
        "frame: exact along lines and circular arcs, else within tolerance (model units, > 0) of the true "
        "sweep. u along the curve, v along the path over [0, 1].");
    m.def(
        "sweep",
        [](const py::object& profile, const py::object& path, double tolerance) {
            const Profile pr = to_profile(profile, "profile");
            const NurbsCurve p = to_sweep_path(path, "path");
            py::gil_scoped_release release;
            return sweep(pr, p, tolerance);
        },
        py::arg("profile"), py::arg("path"), py::arg("tolerance") = 1e-6,
        "A closed planar profile swept along the path into a capped Solid (closed on itself along a closed "
        "path), rotation-minimising frame; exact along lines and circular arcs, else within tolerance.");

    // ---- continuity, joining, Hermite form
    m.def(
        "continuity",
        [](const py::object& a, const py::object& b) {
            if (is_surface(a) || is_surface(b)) return continuity_dict(continuity(to_surface(a, "a"), to_surface(b, "b")));
            return continuity_dict(continuity(to_curve(a, "a"), to_curve(b, "b")));
        },
        py::arg("a"), py::arg("b"),
        "How two curves (a's end to b's start) or two patches (along the boundary they share) meet: "
        "{'C': k, 'G': k, 'gaps': {...}} with k in -1 (apart), 0, 1, 2 and the gaps measured (model units; "
        "tangent_angle in radians, curvature in 1 / model units).");
    m.def(
        "join", [](const py::object& curves) { return join(to_curves(curves, "curves")); }, py::arg("curves"),
        "One NurbsCurve from curves meeting end to start: the highest degree, knots of multiplicity p - k at "
        "C^k joints.");
    m.def(
        "hermite_to_bezier",
        [](const py::object& p0, const py::object& t0, const py::object& p1, const py::object& t1) {
            return hermite_to_bezier(to_vec3(p0, "p0"), to_vec3(t0, "t0"), to_vec3(p1, "p1"), to_vec3(t1, "t1"));
        },
        py::arg("p0"), py::arg("t0"), py::arg("p1"), py::arg("t1"),
        "The cubic BezierCurve with C(0) = p0, C'(0) = t0, C(1) = p1, C'(1) = t1 (003's Hermite form).");
    m.def(
        "bezier_to_hermite",
        [](const BezierCurve& curve) {
            const HermiteForm h = bezier_to_hermite(curve);
            return py::make_tuple(to_tuple(h.p0), to_tuple(h.t0), to_tuple(h.p1), to_tuple(h.t1));
        },
        py::arg("curve"), "(p0, t0, p1, t1) of a polynomial Bezier curve of degree <= 3 (the inverse of hermite_to_bezier).");

    // ---- methods on the curve and surface classes (a Bezier piece answers as its NURBS form)
    add_curve_queries<NurbsCurve>(m, "NurbsCurve");
    add_curve_queries<BezierCurve>(m, "BezierCurve");
    add_surface_queries<NurbsSurface>(m, "NurbsSurface");
    add_surface_queries<BezierSurface>(m, "BezierSurface");
}

}  // namespace ratbez::python
