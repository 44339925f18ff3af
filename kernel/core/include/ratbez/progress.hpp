#pragma once
// Progress and cancellation of long computations (tessellation, measurements, deviation, exports).
// A computation that takes a Progress calls it now and then, from the calling thread, with the fraction
// done in [0, 1]. The callback may throw (Cancelled, or anything else) to stop the computation: it
// unwinds and hands back no partial result. This is how Ctrl-C reaches a long call: the Python module's
// callback checks for signals, the CLI's checks a SIGINT flag. An empty Progress costs nothing.

#include <exception>
#include <functional>

namespace ratbez {

using Progress = std::function<void(double fraction)>;

// The Progress of a step that is the part [from, to] of the work `whole` reports: the step's fraction f
// becomes from + (to - from) f. Empty when `whole` is; `whole` must outlive the result.
inline Progress progress_part(const Progress& whole, double from, double to) {
    if (!whole) return {};
    return [&whole, from, to](double fraction) { whole(from + (to - from) * fraction); };
}

// What a progress callback throws to stop a computation on request (not an error in the input).
class Cancelled : public std::exception {
public:
    const char* what() const noexcept override { return "cancelled"; }
};

}  // namespace ratbez
