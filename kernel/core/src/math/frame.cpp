#include "ratbez/frame.hpp"

#include <cmath>
#include <string>

#include "ratbez/error.hpp"

namespace ratbez {

Frame frame_from_axis(const Vec3& origin, const Vec3& axis, const char* argument) {
    const std::string name = argument != nullptr ? argument : "axis";
    require(is_finite(origin), "origin", "must have finite coordinates");
    require(is_finite(axis), name, "must have finite coordinates");
    const double length = norm(axis);
    // A zero (or denormal) axis has no direction; normalising it would divide by zero.
    require(length > 1e-300 && std::isfinite(1.0 / length), name, "must be a non-zero vector");
    const Vec3 z = axis / length;

    // x: the global X axis with its z component removed (Gram–Schmidt). When the axis is within 1e-6
    // of ±X that remainder has lost most of its significant digits, so the global Y axis is used
    // instead; the fixed rule places the seam of every primitive predictably.
    Vec3 x = Vec3{1, 0, 0} - z * z.x;
    if (norm(x) <= 1e-6) x = Vec3{0, 1, 0} - z * z.y;
    x = x / norm(x);
    const Vec3 y = cross(z, x);  // right-handed: x × y = z
    return Frame{origin, x, y, z};
}

}  // namespace ratbez
