#pragma once
// Progress and Ctrl-C for the module's long calls (tessellate, volume, area, the exports, check_mesh,
// occt_check): each takes `progress=None` and runs with the GIL released, polling through the kernel's
// Progress (ratbez/progress.hpp).

#include <pybind11/pybind11.h>

#include "ratbez/progress.hpp"

namespace ratbez::python {

namespace py = pybind11;

// The docstring paragraph of the `progress` argument.
inline constexpr const char* progress_doc =
    "progress: optional callable(fraction), fraction in [0, 1] rising to 1.0 (called at most every 20 ms,\n"
    "and at the end); an exception it raises stops the call and propagates. Ctrl-C raises KeyboardInterrupt\n"
    "while the call runs (the GIL is released).";

// The kernel's Progress for a call from Python. Taking the GIL for a moment, it calls `callback` (None: no
// callback) and then runs pending signal handlers (Ctrl-C becomes KeyboardInterrupt); either raising
// throws error_already_set through the kernel, which unwinds and hands back nothing. It does so at most
// every 20 ms, and always for the end (fraction 1): the kernel's loops poll every few thousand items, and
// the GIL and a Python call each time would cost more than the work between. The callback is borrowed:
// the caller's argument keeps it alive for the whole call. Error naming "progress" unless `callback` is
// None or callable.
Progress python_progress(const py::object& callback);

}  // namespace ratbez::python
