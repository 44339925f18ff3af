#pragma once
// The kernel's Progress (progress.hpp) for a long call from Python: with the GIL taken for a moment, runs
// pending signal handlers (Ctrl-C becomes KeyboardInterrupt) and then the caller's callback; either raising
// throws error_already_set through the kernel, which unwinds and hands back nothing. The callback is
// borrowed: the caller's argument keeps it alive for the whole call. Long calls release the GIL and hand
// it to the kernel, which calls it often enough that Ctrl-C stops them within a fraction of a second.

#include <pybind11/pybind11.h>

#include <Python.h>

#include "ratbez/error.hpp"
#include "ratbez/progress.hpp"

namespace ratbez::python {

// `callback` is None or a callable (checked: Error naming "progress" otherwise).
inline Progress python_progress(pybind11::handle callback) {
    if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
        fail("progress", "expected a callable taking the fraction done, or None");
    return [callback](double fraction) {
        pybind11::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
        if (!callback.is_none()) callback(fraction);
    };
}

}  // namespace ratbez::python
