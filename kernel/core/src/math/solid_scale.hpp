#pragma once
// The scale rule of limits.hpp for solids: a size and a reach the double range can measure and mesh.
// Not installed, not part of the public API.

#include <string_view>

#include "ratbez/box.hpp"
#include "ratbez/limits.hpp"

namespace ratbez::detail {

// The scale rule of limits.hpp for a solid of size `size` (its box diagonal, or the length that sets it:
// a radius) whose coordinates reach `reach` in magnitude: Error naming `size_argument` for a size outside
// [min_solid_size, max_solid_coordinate] or below min_relative_solid_size * reach, `position_argument` for a
// reach beyond max_solid_coordinate. Checked before anything is built, so the message names the cause
// instead of whatever check the degenerate geometry would trip first ("collapses to a point", "inward").
// `largest_size`: the limit of `size`, max_solid_coordinate for a length that sets the size (a radius, a
// distance), largest_box_diagonal for a box's diagonal (a solid of radius 1e100 at the origin has a box
// diagonal of 3.5e100: the same solid must pass both).
void require_solid_scale(double size, double reach, std::string_view size_argument, std::string_view position_argument,
                         double largest_size = limits::max_solid_coordinate);
// The diagonal of the largest box the coordinate limit allows: 2 sqrt(3) max_solid_coordinate (and the
// rounding of computing it: a sphere of radius 1e100 has a box diagonal of 3.46410161514e100).
inline constexpr double largest_box_diagonal = 3.4641016151377544 * (1 + 1e-12) * limits::max_solid_coordinate;
// The feature rule of limits.hpp: Error naming `argument` unless `feature` (a length the caller gave, or one its
// arguments leave, `what` says which) is at least min_relative_feature of `size`.
void require_feature(double feature, double size, std::string_view argument, std::string_view what);
// The same rule for an argument that is too long for the rest: Error naming `argument` (whose value is
// `longest`) unless `shortest` (`what`: "the profile's size") is at least min_relative_feature of it.
void require_feature_ratio(double longest, double shortest, std::string_view argument, std::string_view what);
// The largest coordinate magnitude of a box.
double reach_of(const Box& box);

}  // namespace ratbez::detail
