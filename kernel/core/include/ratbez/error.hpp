#pragma once
// The one exception type of the kernel: every constructor and function that takes user input
// validates it and throws ratbez::Error naming the offending argument and the reason.

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace ratbez {

class Error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// Throws Error("<argument>: <reason>") unless `condition` holds.
inline void require(bool condition, const std::string& argument, const std::string& reason) {
    if (!condition) throw Error(argument + ": " + reason);
}

inline void require_finite(double value, const std::string& argument) {
    require(std::isfinite(value), argument, "must be a finite number");
}

inline void require_finite(std::span<const double> values, const std::string& argument) {
    for (std::size_t i = 0; i < values.size(); ++i)
        require(std::isfinite(values[i]), argument, "element " + std::to_string(i) + " is not a finite number");
}

// Parameters outside the domain are an error, not silently clamped: evaluating a Bézier or NURBS
// piece outside [a, b] extrapolates a polynomial the user never drew.
inline void require_in_domain(double t, double a, double b, const std::string& argument) {
    require(std::isfinite(t), argument, "must be a finite number");
    require(t >= a && t <= b, argument,
            "parameter " + std::to_string(t) + " is outside the domain [" + std::to_string(a) + ", " +
                std::to_string(b) + "]");
}

}  // namespace ratbez
