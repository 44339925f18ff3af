// Exact degree trigonometry (degrees.hpp).
#include "math/degrees.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace ratbez::detail {

namespace {

// (cos, sin) of an angle in degrees. The angle is reduced to [0, 360) by fmod (exact), the nearest
// quadrant q is taken off, and only the remainder t in [-45, 45] goes through the radian conversion,
// so multiples of 90 degrees give exactly 0 and ±1 (the ends of every rational quarter circle).
std::pair<double, double> cos_sin_deg(double degrees) {
    double reduced = std::fmod(degrees, 360.0);
    if (reduced < 0) reduced += 360.0;
    const long quadrant = std::lround(reduced / 90.0);
    const double remainder = reduced - 90.0 * static_cast<double>(quadrant);
    double c = 1.0, s = 0.0;
    if (remainder != 0.0) {
        const double radians = remainder * (std::numbers::pi / 180.0);
        c = std::cos(radians);
        s = std::sin(radians);
    }
    switch (quadrant % 4) {
        case 0: return {c, s};
        case 1: return {-s, c};
        case 2: return {-c, -s};
        default: return {s, -c};
    }
}

}  // namespace

double cos_deg(double degrees) { return cos_sin_deg(degrees).first; }
double sin_deg(double degrees) { return cos_sin_deg(degrees).second; }

}  // namespace ratbez::detail
