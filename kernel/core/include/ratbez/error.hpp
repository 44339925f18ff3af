#pragma once
// The one exception type of the kernel: every constructor and function that takes user input
// validates it and throws ratbez::Error naming the offending argument and the reason.

#include <charconv>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "ratbez/text.hpp"

namespace ratbez {

// what() is "<argument>: <reason>"; argument() and reason() are its two parts, kept apart so that a
// caller reporting the error elsewhere (the CLI's JSON paths, Python's ratbez.Error attributes) reads
// them instead of taking the text apart. The argument is a path: "radius", "profile[1]", "options.grid".
// The text is the only storage (two offsets mark the parts), so copying an Error cannot throw. Both parts
// are kept printable (text.hpp): a message quoting user text (a spec field, a file name) carries no
// newline, terminal escape or NUL into a terminal, a log or Python's str(e).
class Error : public std::invalid_argument {
public:
    Error(std::string_view argument, std::string_view reason) : Error(printable(argument), printable(reason), 0) {}

    std::string_view argument() const noexcept { return std::string_view(what(), argument_size_); }
    std::string_view reason() const noexcept { return std::string_view(what()).substr(reason_start_); }

    // The same reason, its argument put under `parent`: an Error about "weights" raised while building
    // shape.profile[1] becomes one about "shape.profile[1].weights". An empty parent changes nothing.
    Error under(std::string_view parent) const {
        if (parent.empty()) return *this;
        std::string path(parent);
        path += '.';
        path += argument();
        return Error(path, reason());
    }

    // The same reason about `to` where the argument is `from` or one of its parts ("from[2]", "from.x"): a
    // callee's name for what the caller calls otherwise (join's "curves" are a loft's "profiles"). Any other
    // argument is kept.
    Error renamed(std::string_view from, std::string_view to) const {
        const std::string_view name = argument();
        if (name.substr(0, from.size()) != from) return *this;
        const std::string_view rest = name.substr(from.size());
        if (!rest.empty() && rest.front() != '[' && rest.front() != '.') return *this;
        std::string path(to);
        path += rest;
        return Error(path, reason());
    }

private:
    Error(const std::string& argument, const std::string& reason, int /*printable*/)
        : std::invalid_argument(join(argument, reason)),
          argument_size_(argument.size()),
          reason_start_(argument.size() + 2) {}

    static std::string join(std::string_view argument, std::string_view reason) {
        std::string message(argument);
        message += ": ";
        message += reason;
        return message;
    }

    std::size_t argument_size_ = 0;
    std::size_t reason_start_ = 0;
};

// A double in an error message: the shortest text that reads back as the same double, so 1e-7 does not read
// "0.000000" and 1.0000000000000002 does not read "1" beside a domain that ends at 1.
inline std::string exact_number(double value) {
    char text[32];  // the longest shortest form of a double is 24 characters
    return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

[[noreturn]] inline void fail(std::string_view argument, std::string_view reason) { throw Error(argument, reason); }

// Throws Error(argument, reason) unless `condition` holds.
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
        return "parameter " + exact_number(t) + " is outside the domain [" + exact_number(a) + ", " + exact_number(b) + "]";
    });
}

}  // namespace ratbez
