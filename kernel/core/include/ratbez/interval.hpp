#pragma once
// A closed interval [min, max] of a real parameter: the domain of a curve, one direction of a
// surface's domain, a knot span.

namespace ratbez {

struct Interval {
    double min = 0, max = 0;

    constexpr double width() const { return max - min; }
    constexpr bool contains(double t) const { return t >= min && t <= max; }
    friend constexpr bool operator==(const Interval&, const Interval&) = default;
};

}  // namespace ratbez
