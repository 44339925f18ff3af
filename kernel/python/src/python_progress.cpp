#include "python_progress.hpp"

#include <chrono>
#include <memory>

#include "ratbez/error.hpp"

namespace ratbez::python {

Progress python_progress(const py::object& callback) {
    if (!callback.is_none() && !PyCallable_Check(callback.ptr()))
        fail("progress", "expected a callable taking the fraction done, or None");
    using Clock = std::chrono::steady_clock;
    constexpr auto kInterval = std::chrono::milliseconds(20);
    // Shared by the copies the kernel makes of the function.
    auto last = std::make_shared<Clock::time_point>(Clock::now());
    return [handle = py::handle(callback), last, kInterval](double fraction) {
        const Clock::time_point now = Clock::now();
        if (fraction < 1 && now - *last < kInterval) return;
        *last = now;
        py::gil_scoped_acquire gil;
        if (!handle.is_none()) handle(fraction);
        // After the callback, so that a signal raised while it ran (or by it) is seen now.
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    };
}

}  // namespace ratbez::python
