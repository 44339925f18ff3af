// The Python module `ratbez`: the public contract of DESIGN.md. Bindings only; the math is in kernel/core.

#include "convert.hpp"
#include "ratbez/error.hpp"

PYBIND11_MODULE(ratbez, m) {
    namespace py = pybind11;
    m.doc() = "ratbez: exact rational Bezier / NURBS geometry and B-rep solids";
    m.attr("__version__") = RATBEZ_VERSION;
    // ratbez::Error -> ratbez.Error, a ValueError: bad input is a value problem, and `except ValueError` catches it.
    py::register_exception<ratbez::Error>(m, "Error", PyExc_ValueError);
    ratbez::python::bind_core(m);
    ratbez::python::bind_solids(m);
    ratbez::python::bind_io(m);
    ratbez::python::bind_modelling(m);  // adds methods to the classes above
}
