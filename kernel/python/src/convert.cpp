#include "convert.hpp"

#include <Python.h>

#include <optional>

#include "ratbez/bezier_curve.hpp"
#include "ratbez/error.hpp"
#include "ratbez/nurbs_curve.hpp"

namespace ratbez::python {

namespace {

// The items of a list, tuple, numpy array or other sequence; strings are not sequences of numbers.
std::vector<py::object> sequence_items(py::handle value, const std::string& argument, const char* what) {
    if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
        !PySequence_Check(value.ptr()))
        throw Error(argument, std::string("expected ") + what);
    const Py_ssize_t size = PySequence_Size(value.ptr());
    if (size < 0) {
        PyErr_Clear();
        throw Error(argument, std::string("expected ") + what);
    }
    std::vector<py::object> items;
    items.reserve(static_cast<std::size_t>(size));
    for (Py_ssize_t i = 0; i < size; ++i) {
        PyObject* item = PySequence_GetItem(value.ptr(), i);
        if (item == nullptr) throw py::error_already_set();
        items.push_back(py::reinterpret_steal<py::object>(item));
    }
    return items;
}

std::string element(const std::string& argument, std::size_t index) {
    return argument + "[" + std::to_string(index) + "]";
}

// A NurbsCurve as it is, a BezierCurve as the NURBS on {0..0, 1..1}; nothing for anything else.
std::optional<NurbsCurve> curve_of(py::handle value) {
    if (py::isinstance<NurbsCurve>(value)) return value.cast<NurbsCurve>();
    if (py::isinstance<BezierCurve>(value)) return NurbsCurve::from_bezier(value.cast<const BezierCurve&>());
    return std::nullopt;
}

}  // namespace

double to_double(py::handle value, const std::string& argument) {
    // Numbers and anything with __float__ (numpy scalars); not strings, not None.
    if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value))
        throw Error(argument, "expected a number");
    const double result = PyFloat_AsDouble(value.ptr());
    if (result == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        throw Error(argument, "expected a number");
    }
    return result;
}

int to_int(py::handle value, const std::string& argument) {
    // Integers and anything with __index__ (numpy integers); 2.0 is refused rather than truncated.
    if (value.is_none() || py::isinstance<py::bool_>(value) || !PyIndex_Check(value.ptr()))
        throw Error(argument, "expected an integer");
    PyObject* index = PyNumber_Index(value.ptr());
    if (index == nullptr) {
        PyErr_Clear();
        throw Error(argument, "expected an integer");
    }
    const auto owner = py::reinterpret_steal<py::object>(index);
    int overflow = 0;
    const long long result = PyLong_AsLongLongAndOverflow(index, &overflow);
    if (overflow != 0 || result < -1'000'000'000LL || result > 1'000'000'000LL)
        throw Error(argument, "integer out of range");
    return static_cast<int>(result);
}

Vec3 to_vec3(py::handle value, const std::string& argument) {
    const auto items = sequence_items(value, argument, "a point: a sequence of 2 or 3 numbers");
    if (items.size() != 2 && items.size() != 3)
        throw Error(argument, "expected a point of 2 or 3 numbers, got " + std::to_string(items.size()));
    Vec3 point{to_double(items[0], argument), to_double(items[1], argument),
               items.size() == 3 ? to_double(items[2], argument) : 0.0};
    return point;
}

std::vector<double> to_doubles(py::handle value, const std::string& argument) {
    const auto items = sequence_items(value, argument, "a sequence of numbers");
    std::vector<double> result;
    result.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) result.push_back(to_double(items[i], element(argument, i)));
    return result;
}

std::vector<Vec3> to_points(py::handle value, const std::string& argument) {
    const auto items = sequence_items(value, argument, "a sequence of points");
    std::vector<Vec3> result;
    result.reserve(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) result.push_back(to_vec3(items[i], element(argument, i)));
    return result;
}

std::vector<std::vector<Vec3>> to_net(py::handle value, const std::string& argument) {
    const auto rows = sequence_items(value, argument, "a net: a sequence of rows of points");
    std::vector<std::vector<Vec3>> result;
    result.reserve(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) result.push_back(to_points(rows[i], element(argument, i)));
    return result;
}

std::vector<std::vector<double>> to_double_rows(py::handle value, const std::string& argument) {
    const auto rows = sequence_items(value, argument, "a sequence of rows of numbers");
    std::vector<std::vector<double>> result;
    result.reserve(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) result.push_back(to_doubles(rows[i], element(argument, i)));
    return result;
}

std::string to_path(py::handle value, const std::string& argument) {
    constexpr const char* kExpected = "expected a path (str, bytes or os.PathLike)";
    if (!py::isinstance<py::str>(value) && !py::isinstance<py::bytes>(value) &&
        !PyObject_HasAttrString(value.ptr(), "__fspath__"))
        throw Error(argument, kExpected);
    PyObject* fspath = PyOS_FSPath(value.ptr());
    if (fspath == nullptr) {
        PyErr_Clear();
        throw Error(argument, kExpected);
    }
    const auto path = py::reinterpret_steal<py::object>(fspath);
    std::string text;
    if (py::isinstance<py::bytes>(path)) {
        // bytes as open() takes them; UTF-8 only, because the name goes into messages and solids' names as text.
        text = std::string(path.cast<py::bytes>());
        PyObject* decoded = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "strict");
        if (decoded == nullptr) {
            PyErr_Clear();
            throw Error(argument, "is not UTF-8");
        }
        Py_DECREF(decoded);
    } else {
        text = path.cast<std::string>();
    }
    if (text.empty()) throw Error(argument, "must not be empty");
    // A NUL ends the name for the system: "a.stl\0.txt" would pass a check of its extension and write "a.stl".
    if (text.find('\0') != std::string::npos) throw Error(argument, "contains a NUL character");
    return text;
}

py::tuple to_tuple(const Vec3& point) { return py::make_tuple(point.x, point.y, point.z); }

py::list to_list(const std::vector<Vec3>& points) {
    py::list result;
    for (const auto& p : points) result.append(to_tuple(p));
    return result;
}

py::list to_list(const std::vector<std::vector<Vec3>>& net) {
    py::list result;
    for (const auto& row : net) result.append(to_list(row));
    return result;
}

py::tuple to_tuple(const Interval& interval) { return py::make_tuple(interval.min, interval.max); }

NurbsCurve to_curve(py::handle value, const std::string& argument) {
    if (auto curve = curve_of(value)) return std::move(*curve);
    throw Error(argument, "expected a BezierCurve or a NurbsCurve");
}

std::vector<NurbsCurve> to_curves(py::handle value, const std::string& argument) {
    if (auto curve = curve_of(value)) return {std::move(*curve)};
    if (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value))
        throw Error(argument, "expected a BezierCurve, a NurbsCurve or a list of them");
    std::vector<NurbsCurve> curves;
    std::size_t index = 0;
    for (py::handle item : value) {
        auto curve = curve_of(item);
        if (!curve) throw Error(element(argument, index), "expected a BezierCurve or a NurbsCurve");
        curves.push_back(std::move(*curve));
        ++index;
    }
    return curves;
}

Profile to_profile(py::handle value, const std::string& argument) {
    std::vector<NurbsCurve> pieces = to_curves(value, argument);
    try {
        return Profile(std::move(pieces));  // validates: non-empty, pieces joined end to end
    } catch (const Error& e) {
        // Profile names its argument "profile"; name the one given here (profiles[2], path, ...).
        throw e.renamed("profile", argument);
    }
}

void require_finite_vertices(const std::vector<Vec3>& points, const std::string& argument) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!is_finite(points[i])) throw Error(argument + "[" + std::to_string(i) + "]", "coordinates must be finite numbers");
}

}  // namespace ratbez::python
