#pragma once
// The angle between two vectors, for the kernel's angle tests (the tessellator's normal turn, a sweep path's
// bends, continuity's G1 check). Not installed, not part of the public API.

#include <cmath>

#include "ratbez/vec.hpp"

namespace ratbez::detail {

// In [0, pi], for vectors of any length (neither zero). atan2 of |a x b| and a . b stays accurate near 0 and
// pi, where acos of the normalised dot product loses half the digits.
inline double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

}  // namespace ratbez::detail
