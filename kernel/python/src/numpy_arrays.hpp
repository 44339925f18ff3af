#pragma once
// numpy arrays in and out of the bindings: array-likes of real numbers checked into float64 C-contiguous
// arrays (ratbez.Error naming the argument for a wrong shape or dtype), and reopening a bound class from
// another binding source to add methods to it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <string>

#include "initialised.hpp"

namespace ratbez::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// `value` (a numpy array, list, tuple, ...) of real numbers (integer or floating dtype; not bool, complex,
// str or object) as a float64 C-contiguous array with `ndim` dimensions; the last one must be `last`
// when given (>= 0). Throws ratbez::Error naming `argument` otherwise.
DoubleArray real_array(py::handle value, const std::string& argument, int ndim, py::ssize_t last = -1);

inline std::span<const double> values(const DoubleArray& array) {
    return {array.data(), static_cast<std::size_t>(array.size())};
}
inline std::span<double> values(py::array_t<double>& array) {
    return {array.mutable_data(), static_cast<std::size_t>(array.size())};
}

// The py::class_ of a type bound in another binding source, to add methods to it here.
template <class T>
py::class_<T> reopen() {
    return py::class_<T>(py::type::of<T>());
}

}  // namespace ratbez::python
