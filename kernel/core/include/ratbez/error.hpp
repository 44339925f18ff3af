#pragma once
// The one exception type of the kernel: every constructor and function that takes user input
// validates it and throws ratbez::Error naming the offending argument and the reason.

#include <cmath>
#include <concepts>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ratbez {

class Error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

[[noreturn]] inline void fail(std::string_view argument, std::string_view reason) {
    std::string message(argument);
    message += ": ";
    message += reason;
    throw Error(message);
}

// Throws Error("<argument>: <reason>") unless `condition` holds.
inline void require(bool condition, std::string_view argument, std::string_view reason) {
    if (!condition) [[unlikely]] fail(argument, reason);
}

// The same for messages that need formatting: `make_reason()` runs only when the check fails, so
// validation inside evaluation loops costs a comparison, not a string build per call.
template <std::invocable MakeReason>
inline void require(bool condition, std::string_view argument, MakeReason&& make_reason) {
    if (!condition) [[unlikely]] fail(argument, make_reason());
}

inline void require_finite(double value, std::string_view argument) {
    require(std::isfinite(value), argument, "must be a finite number");
}

inline void require_finite(std::span<const double> values, std::string_view argument) {
    for (std::size_t i = 0; i < values.size(); ++i)
        require(std::isfinite(values[i]), argument, [i] { return "element " + std::to_string(i) + " is not a finite number"; });
}

// Parameters outside the domain are an error, not silently clamped: evaluating a Bézier or NURBS
// piece outside [a, b] extrapolates a polynomial the user never drew.
inline void require_in_domain(double t, double a, double b, std::string_view argument) {
    require(std::isfinite(t), argument, "must be a finite number");
    require(t >= a && t <= b, argument, [&] {
        return "parameter " + std::to_string(t) + " is outside the domain [" + std::to_string(a) + ", " +
               std::to_string(b) + "]";
    });
}

}  // namespace ratbez
