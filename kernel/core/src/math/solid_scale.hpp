#pragma once
// The scale rule of limits.hpp for solids: a size and a reach the double range can measure and mesh.
// Not installed, not part of the public API.

#include <string_view>

#include "ratbez/box.hpp"

namespace ratbez::detail {

// The scale rule of limits.hpp for a solid of size `size` (its box diagonal, or the length that sets it:
// a radius) whose coordinates reach `reach` in magnitude: Error naming `size_argument` for a size outside
// [min_solid_size, max_solid_coordinate] or below min_relative_solid_size * reach, `position_argument` for a
// reach beyond max_solid_coordinate. Checked before anything is built, so the message names the cause
// instead of whatever check the degenerate geometry would trip first ("collapses to a point", "inward").
void require_solid_scale(double size, double reach, std::string_view size_argument, std::string_view position_argument);
// The largest coordinate magnitude of a box.
double reach_of(const Box& box);

}  // namespace ratbez::detail
