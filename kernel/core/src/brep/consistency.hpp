#pragma once
// The tolerance of the B-rep's geometric consistency checks (brep.cpp, trimmed_face.cpp): how far a face's
// edges, vertices and loops may keep from its surface when it is built exactly. Not installed, not part of
// the public API.

#include <limits>

#include "math/solid_scale.hpp"
#include "ratbez/box.hpp"

namespace ratbez::detail {

// A face built from exact constructions matches its edges to ~1e-15 of its size; a gap of 1e-9 of its size
// is a construction error, not rounding.
inline constexpr double kRelativeConsistency = 1e-9;

// The rounding of coordinates as far from the origin as `reach`: 64 ulps of it.
inline double coordinate_rounding(double reach) { return 64 * std::numeric_limits<double>::epsilon() * reach; }

// kRelativeConsistency of the size of the geometry that lies in `box`, and no less than the rounding of
// coordinates as far from the origin as the box reaches (64 ulps of its largest coordinate). Far from the
// origin the second decides: the sample points along a pole of a unit sphere at 1e8 (inside the scale rule
// of limits.hpp) are evaluated about 1e-8 apart, three times 1e-9 of its size, so the pole looked like a side
// of length 1e-7 that "does not collapse to a point" (issue 29). Within the scale rule (size >= 1e-9 of the
// reach) the floor stays below 1.5e-5 of the size.
inline double consistency_tolerance(const Box& box) {
    return kRelativeConsistency * box.diagonal() + coordinate_rounding(reach_of(box));
}

}  // namespace ratbez::detail
