#pragma once
// Wrong-typed arguments as ratbez.Error naming the argument, for every bound function at once.
// pybind11 answers a call whose arguments its casters refuse (sphere("2")) with a generic TypeError
// listing the signatures; name_argument_type_errors wraps pybind11's dispatcher so that such a call
// raises ratbez.Error("radius: expected a number, got str '2'") instead. Calls with a missing, extra or
// unknown argument keep pybind11's TypeError (they are a wrong call, not a wrong value). No cost on a call
// that succeeds: the wrapper only looks at the arguments once pybind11 has refused them.

#include <pybind11/pybind11.h>

#include <functional>
#include <string_view>

namespace ratbez::python {

// Wraps every pybind11 function of `module`: its functions and the methods, static methods and
// constructors of its classes. `raise(argument, reason)` sets the Python error (ratbez.Error).
void name_argument_type_errors(pybind11::module_& module,
                               void (*raise)(std::string_view argument, std::string_view reason));

}  // namespace ratbez::python
