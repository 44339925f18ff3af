#pragma once
// Exact degree trigonometry, shared by the curve builders and the affine maps. Not installed.

namespace ratbez::detail {

// cos and sin of an angle in degrees, exact (0, ±1) at multiples of 90 degrees: the quadrant is
// removed exactly before the radian conversion, so a quarter circle ends exactly on its axis.
double cos_deg(double degrees);
double sin_deg(double degrees);

}  // namespace ratbez::detail
