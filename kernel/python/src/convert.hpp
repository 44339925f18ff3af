#pragma once
// Conversions between Python objects and the kernel's value types, shared by every binding source.
// Input conversions take the Python argument's name, so that a malformed argument raises ratbez.Error
// ("points[2]: expected 2 or 3 numbers") instead of pybind11's generic TypeError.

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "ratbez/bspline_basis.hpp"
#include "ratbez/nurbs_curve.hpp"
#include "ratbez/profile.hpp"
#include "ratbez/vec.hpp"

#include "initialised.hpp"

namespace ratbez::python {

namespace py = pybind11;

double to_double(py::handle value, const std::string& argument);
int to_int(py::handle value, const std::string& argument);
// A point: a sequence of 2 or 3 numbers; 2D points get z = 0.
Vec3 to_vec3(py::handle value, const std::string& argument);
std::vector<double> to_doubles(py::handle value, const std::string& argument);
std::vector<Vec3> to_points(py::handle value, const std::string& argument);
// Error naming argument[i] for the first point with a coordinate that is not a finite number (a Mesh's
// vertices, from its constructor and from a pickle alike).
void require_finite_vertices(const std::vector<Vec3>& points, const std::string& argument);
// net[i][j]: rows along u, columns along v.
std::vector<std::vector<Vec3>> to_net(py::handle value, const std::string& argument);
std::vector<std::vector<double>> to_double_rows(py::handle value, const std::string& argument);
// A filesystem path: str or os.PathLike.
std::string to_path(py::handle value, const std::string& argument);

// A curve: a NurbsCurve, or a BezierCurve as the NURBS on {0..0, 1..1}.
NurbsCurve to_curve(py::handle value, const std::string& argument);
// One curve, or a list / tuple of curves (pieces joined end to end): their NURBS forms, in order.
std::vector<NurbsCurve> to_curves(py::handle value, const std::string& argument);
// A profile: to_curves(value) joined end to end (Profile validates); errors name `argument`.
Profile to_profile(py::handle value, const std::string& argument);

py::tuple to_tuple(const Vec3& point);
py::list to_list(const std::vector<Vec3>& points);
py::list to_list(const std::vector<std::vector<Vec3>>& net);
py::tuple to_tuple(const Interval& interval);

// One registration function per binding source; module.cpp calls them in dependency order.
void bind_core(py::module_& module);
void bind_solids(py::module_& module);
void bind_tessellation(py::module_& module);
void bind_io(py::module_& module);
void bind_modelling(py::module_& module);
void bind_curve_tools(py::module_& module);
void bind_evaluation(py::module_& module);
void bind_transforms(py::module_& module);
void bind_values(py::module_& module);

}  // namespace ratbez::python
