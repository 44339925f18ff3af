// The Python module `ratbez`: the public contract of DESIGN.md. Bindings only; the math is in kernel/core.

#include <exception>
#include <string_view>

#include "argument_types.hpp"
#include "convert.hpp"
#include "ratbez/error.hpp"

namespace {

namespace py = pybind11;

// ratbez.Error, kept for the life of the process (a deliberately leaked reference: exceptions are
// translated until the interpreter is gone, and no destructor may then touch Python).
PyObject* error_type = nullptr;

// Kernel text as a Python str; bytes that are not UTF-8 (a file name from the system) become U+FFFD
// rather than a UnicodeDecodeError in place of the real error.
py::str python_text(std::string_view text) {
    return py::reinterpret_steal<py::str>(
        PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace"));
}

// Sets a ratbez.Error instance with str() = "argument: reason" and the attributes argument and reason.
void raise_error(std::string_view argument, std::string_view reason) {
    const ratbez::Error e(argument, reason);
    try {
        const py::object instance = py::handle(error_type)(python_text(e.what()));
        instance.attr("argument") = python_text(e.argument());
        instance.attr("reason") = python_text(e.reason());
        PyErr_SetObject(error_type, instance.ptr());
    } catch (py::error_already_set& failure) {
        failure.restore();  // building the instance failed (out of memory): raise that instead
    }
}

// ratbez::Error -> ratbez.Error.
void translate_error(std::exception_ptr error) {
    try {
        if (error) std::rethrow_exception(error);
    } catch (const ratbez::Error& e) {
        raise_error(e.argument(), e.reason());
    }
}

}  // namespace

PYBIND11_MODULE(ratbez, m) {
    m.doc() = "ratbez: exact rational Bezier / NURBS geometry and B-rep solids";
    m.attr("__version__") = RATBEZ_VERSION;
    // ratbez::Error -> ratbez.Error, a ValueError: bad input is a value problem, and `except ValueError` catches it.
    const py::exception<ratbez::Error> error(m, "Error", PyExc_ValueError);
    error.attr("__doc__") =
        "Bad input to ratbez. str(e) is 'argument: reason'; e.argument names the argument at fault (a path "
        "such as 'radius' or 'profile[1]') and e.reason says what is wrong with it (both str; None on an "
        "instance raised from Python).";
    error.attr("argument") = py::none();
    error.attr("reason") = py::none();
    error_type = error.inc_ref().ptr();
    py::register_exception_translator(&translate_error);
    ratbez::python::bind_core(m);
    ratbez::python::bind_solids(m);
    ratbez::python::bind_tessellation(m);
    ratbez::python::bind_io(m);
    ratbez::python::bind_modelling(m);  // adds methods to the classes above
    ratbez::python::bind_curve_tools(m);  // likewise
    ratbez::python::bind_evaluation(m);
    ratbez::python::bind_transforms(m);
    ratbez::python::bind_values(m);
    ratbez::python::name_argument_type_errors(m, &raise_error);  // last: every function is bound
}
